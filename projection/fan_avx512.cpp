// pt-linear's fan, and the exact rungs' (segments_pairs), two pixels at a time where the processor
// has AVX-512. pt-linear's: lanes 0-3 of a vector hold
// pixel i's four quantities (r, g, b, opacity), lanes 4-7 pixel i + 1's. Each lane gets the
// operations fan_avx2.cpp's kernel gives it one pixel at a time, so the same bits; a pair's wedge
// test, interpolation, finish and "over" are one instruction each where the AVX2 kernel spends one
// per pixel (a small tetrahedron's rows are a few pixels: four pixels a vector would spend most
// lanes past a row's end).
#include "projection/fan_simd.hpp"

#if CELLPROJ_AVX2_DISPATCH
// GCC 12's AVX-512 intrinsics start some results from an "undefined" vector that its own warnings
// then call uninitialized (GCC bug 105593).
#pragma GCC diagnostic ignored "-Wuninitialized"
#if !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

namespace cellproj {
namespace {

#define CELLPROJ_AVX512 __attribute__((target("avx512f,avx512vl,avx512dq")))
#define CELLPROJ_AVX512_INLINE __attribute__((target("avx512f,avx512vl,avx512dq"), always_inline)) inline

// Planes a and c side by side: pixel i's triangle in lanes 0-3, pixel i + 1's in lanes 4-7.
CELLPROJ_AVX512_INLINE __m512d pair(const __m256d* planes, int a, int c) {
  return _mm512_insertf64x4(_mm512_castpd256_pd512(planes[a]), planes[c], 1);
}

// A fan two pixels at a time: the AVX2 kernel's per-tetrahedron vectors (FanVectors, quantity
// lanes in `Order`), the spokes' in both halves, each triangle's quantity planes with a plane S of
// zeros (no triangle taken: quantities 0, as the AVX2 kernel's); row(y) sets a row's values at its
// pixel 0 (FanRow's), at(x) gives the quantities of the pixels at x (lanes 0-3 and 4-7).
template <int S, int Order>
struct FanPairs {
  FanVectors<S, Order> fan;
  __m512d spoke_c, spoke_gy, spoke_gx, left_out, spoke0;
  __m256d qx[S + 1], q0[S + 1];
  CELLPROJ_AVX512_INLINE explicit FanPairs(const FanPlanes& f) : fan(f) {
    spoke_c = _mm512_broadcast_f64x4(fan.spoke_c), spoke_gy = _mm512_broadcast_f64x4(fan.spoke_gy);
    spoke_gx = _mm512_broadcast_f64x4(fan.spoke_gx), left_out = _mm512_broadcast_f64x4(fan.left_out);
    for (int a = 0; a < S; ++a) qx[a] = fan.qx[a];
    qx[S] = q0[S] = _mm256_setzero_pd();
  }
  CELLPROJ_AVX512_INLINE void row(double y) {
    spoke0 = _mm512_add_pd(spoke_c, _mm512_mul_pd(spoke_gy, _mm512_set1_pd(y)));
    const __m256d yy = _mm256_set1_pd(y);
    for (int a = 0; a < S; ++a) q0[a] = _mm256_add_pd(fan.qc[a], _mm256_mul_pd(fan.qgy[a], yy));
  }
  CELLPROJ_AVX512_INLINE __m512d at(__m512d x) const {
    // The wedge values min(spoke[a], -spoke[a + 1]) + left_out[a] of both pixels, their triangles.
    const __m512d spoke = _mm512_add_pd(spoke0, _mm512_mul_pd(spoke_gx, x));
    const __m512d next = _mm512_permutex_pd(spoke, S == 4 ? 0x39 : 0xC9);
    const __m512d w = _mm512_add_pd(_mm512_min_pd(spoke, _mm512_xor_pd(next, _mm512_set1_pd(-0.0))), left_out);
    const unsigned inside = _mm512_cmp_pd_mask(w, _mm512_setzero_pd(), _CMP_GT_OQ);
    const int a = wedge_triangle<S, S>(inside & 0xF, _mm512_castpd512_pd256(w)),
              c = wedge_triangle<S, S>(inside >> 4, _mm512_extractf64x4_pd(w, 1));
    return _mm512_add_pd(pair(q0, a, c), _mm512_mul_pd(pair(qx, a, c), x));
  }
};

// The first pixels of a row's pairs: b in lanes 0-3, b + 1 in lanes 4-7 (integers: exact).
CELLPROJ_AVX512_INLINE __m512d pair_x(int b) {
  return _mm512_add_pd(_mm512_set1_pd(static_cast<double>(b)), _mm512_set_pd(1, 1, 1, 1, 0, 0, 0, 0));
}

template <int S>
CELLPROJ_AVX512 std::int64_t over_pairs(const FanPlanes& f, Image& image, int i0, int j0, int row0, int rows,
                                        int width) {
  FanPairs<S, 0x39> fan(f);  // quantity lanes in the image's order (r, g, b, opacity)
  const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1.0), two = _mm512_set1_pd(2.0);
  // The pixels that add something, counted in the opacity lanes: the colour lanes are u times the
  // opacity, u clamped to >= 0 (never NaN), so they are not all 0 only where the opacity is not.
  __m512i added = _mm512_setzero_si512();
  RowSpans<S> spans{f, row0, rows, width};
  for (int b, e; spans.next(b, e);) {
    float* line = image.pixel(i0, j0 + row0 + spans.r);
    fan.row(row0 + spans.r);
    __m512d x = pair_x(b);
    for (int i = b; i <= e; i += 2, x = _mm512_add_pd(x, two)) {
      // finish_linear: opacity clamped to [0, 1], colour clamped to >= 0 times it
      const __m512d u = _mm512_max_pd(fan.at(x), zero);
      const __m512d alpha = _mm512_min_pd(_mm512_permutex_pd(u, 0xFF), one);
      const __m512d src = _mm512_mask_blend_pd(0x88, _mm512_mul_pd(u, alpha), alpha);
      // "over" (composite/fragment.hpp's, in float), pixel i + 1 only where the row holds it
      const __mmask8 in_row = i < e ? 0xFF : 0x0F;
      const __m256 s = _mm512_cvtpd_ps(src), t = _mm256_sub_ps(_mm256_set1_ps(1.0f), _mm256_shuffle_ps(s, s, 0xFF));
      float* dst = line + 4 * i;
      _mm256_mask_storeu_ps(dst, in_row, _mm256_add_ps(s, _mm256_mul_ps(t, _mm256_maskz_loadu_ps(in_row, dst))));
      const __mmask8 adds = _mm512_mask_cmp_pd_mask(in_row & 0x88, src, zero, _CMP_NEQ_UQ);
      added = _mm512_mask_add_epi64(added, adds, added, _mm512_set1_epi64(1));
    }
  }
  return _mm512_reduce_add_epi64(added);
}

// The exact rungs' fan two pixels at a time: fan_avx2.cpp's segments_pixels with pixel i's
// quantities (front, back end; depth and scalar, or 1/z and s/z) in lanes 0-3 and pixel i + 1's in
// lanes 4-7, then each quantity of both pixels side by side (the pair of batch entries it fills):
// each lane gets segments_pixels' operations, so the same bits. Where a row's last pixel is alone,
// the pair's second entry is written past it and overwritten by the next row's first (the batch
// has room: fan_segments).
template <int S, bool Perspective>
CELLPROJ_AVX512 void segments_pairs(const FanPlanes& f, const FanSegments& at, SegmentBatch& b) {
  FanPairs<S, 0xE4> fan(f);
  const __m512d two = _mm512_set1_pd(2.0);
  // (zf, zb, sf, sb of pixel i | of pixel i + 1) -> (zf zf', zb zb', sf sf', sb sb')
  const __m512i by_quantity = _mm512_set_epi64(7, 3, 6, 2, 5, 1, 4, 0);
  const __m256d smin = _mm256_set1_pd(at.smin), smax = _mm256_set1_pd(at.smax), s0 = _mm256_set1_pd(at.piece.s0),
                ds = _mm256_set1_pd(at.piece.ds), k0 = _mm256_set1_pd(at.piece.k0), dk = _mm256_set1_pd(at.piece.dk),
                zero4 = _mm256_setzero_pd(), ones4 = _mm256_set1_pd(1.0);
  const __m128d one2 = _mm_set1_pd(1.0), zero2 = _mm_setzero_pd();
  const double* u2 = at.rays.u_squared() + at.i0;
  RowSpans<S> spans{f, at.row0, at.rows, at.width};
  for (int first, last; spans.next(first, last);) {
    const int j = at.j0 + at.row0 + spans.r;
    const __m128d v2 = _mm_set1_pd(Perspective ? at.rays.v_squared()[j] : 0.0);
    const std::size_t base = b.n - static_cast<std::size_t>(first);
    fan.row(at.row0 + spans.r);
    __m512d x = pair_x(first);
    for (int i = first; i <= last; i += 2, x = _mm512_add_pd(x, two)) {
      const std::size_t k = base + static_cast<std::size_t>(i);
      b.i[k] = at.i0 + i, b.i[k + 1] = at.i0 + i + 1, b.j[k] = j, b.j[k + 1] = j;
      const __m512d q = _mm512_permutexvar_pd(by_quantity, fan.at(x));
      __m256d ends = _mm512_castpd512_pd256(q), s = _mm512_extractf64x4_pd(q, 1);  // (zf zf' zb zb'), (sf sf' sb sb')
      if constexpr (Perspective) ends = _mm256_div_pd(ones4, ends), s = _mm256_mul_pd(s, ends);
      // std::clamp's order: below smin, smin; else above smax, smax
      s = _mm256_blendv_pd(_mm256_blendv_pd(s, smax, _mm256_cmp_pd(smax, s, _CMP_LT_OQ)), smin,
                           _mm256_cmp_pd(s, smin, _CMP_LT_OQ));
      const __m128d thick = _mm_sub_pd(_mm256_extractf128_pd(ends, 1), _mm256_castpd256_pd128(ends));
      const __m128d per_depth =
          Perspective ? _mm_sqrt_pd(_mm_add_pd(_mm_add_pd(one2, _mm_loadu_pd(u2 + i)), v2)) : one2;
      _mm_storeu_pd(&b.length[k], _mm_mul_pd(_mm_blendv_pd(zero2, thick, _mm_cmplt_pd(zero2, thick)), per_depth));
      const __m256d kappa = _mm256_add_pd(k0, _mm256_mul_pd(_mm256_mul_pd(dk, _mm256_sub_pd(s, s0)), ds));
      const __m256d kept = _mm256_blendv_pd(zero4, kappa, _mm256_cmp_pd(zero4, kappa, _CMP_LT_OQ));
      _mm_storeu_pd(&b.sf[k], _mm256_castpd256_pd128(s)), _mm_storeu_pd(&b.sb[k], _mm256_extractf128_pd(s, 1));
      _mm_storeu_pd(&b.k0[k], _mm256_castpd256_pd128(kept)), _mm_storeu_pd(&b.k1[k], _mm256_extractf128_pd(kept, 1));
    }
    b.n += static_cast<std::size_t>(last - first + 1);
  }
}

}  // namespace

std::int64_t fan_over_avx512(const FanPlanes& f, Image& image, int i0, int j0, int row0, int rows, int width) {
  return (f.sectors == 4 ? over_pairs<4> : over_pairs<3>)(f, image, i0, j0, row0, rows, width);
}

void fan_segments_avx512(const FanPlanes& f, const FanSegments& at, SegmentBatch& out) {
  const bool four = f.sectors == 4;
  if (at.rays.perspective())
    (four ? segments_pairs<4, true> : segments_pairs<3, true>)(f, at, out);
  else
    (four ? segments_pairs<4, false> : segments_pairs<3, false>)(f, at, out);
}

}  // namespace cellproj
#endif
