// pt-linear's fan two pixels at a time where the processor has AVX-512: lanes 0-3 of a vector hold
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

template <int S>
CELLPROJ_AVX512 std::int64_t over_pairs(const FanPlanes& f, Image& image, int i0, int j0, int row0, int rows,
                                        int width) {
  // The AVX2 kernel's per-tetrahedron vectors, the spokes' in both halves; each triangle's
  // quantity planes in the image's lane order (r, g, b, opacity), planes S zero (no triangle taken:
  // quantities 0, as the AVX2 kernel's).
  const FanVectors<S, 0x39> fan(f);
  const __m512d spoke_c = _mm512_broadcast_f64x4(fan.spoke_c), spoke_gy = _mm512_broadcast_f64x4(fan.spoke_gy),
                spoke_gx = _mm512_broadcast_f64x4(fan.spoke_gx), left_out = _mm512_broadcast_f64x4(fan.left_out);
  __m256d qx[S + 1], q0[S + 1];
  for (int a = 0; a < S; ++a) qx[a] = fan.qx[a];
  qx[S] = q0[S] = _mm256_setzero_pd();
  const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1.0), two = _mm512_set1_pd(2.0),
                sign = _mm512_set1_pd(-0.0), pixel_pair = _mm512_set_pd(1, 1, 1, 1, 0, 0, 0, 0);
  std::int64_t added = 0;
  RowSpans<S> spans{f, row0, rows, width};
  for (int b, e; spans.next(b, e);) {
    const double y = row0 + spans.r;
    float* line = image.pixel(i0, j0 + row0 + spans.r);
    // FanRow's values, the spokes' in both halves
    const __m512d spoke0 = _mm512_add_pd(spoke_c, _mm512_mul_pd(spoke_gy, _mm512_set1_pd(y)));
    const __m256d yy = _mm256_set1_pd(y);
    for (int a = 0; a < S; ++a) q0[a] = _mm256_add_pd(fan.qc[a], _mm256_mul_pd(fan.qgy[a], yy));
    __m512d x = _mm512_add_pd(_mm512_set1_pd(static_cast<double>(b)), pixel_pair);  // (integers: exact)
    for (int i = b; i <= e; i += 2, x = _mm512_add_pd(x, two)) {
      // The wedge values min(spoke[a], -spoke[a + 1]) + left_out[a] of both pixels.
      const __m512d spoke = _mm512_add_pd(spoke0, _mm512_mul_pd(spoke_gx, x));
      const __m512d next = _mm512_permutex_pd(spoke, S == 4 ? 0x39 : 0xC9);
      const __m512d w = _mm512_add_pd(_mm512_min_pd(spoke, _mm512_xor_pd(next, sign)), left_out);
      const unsigned inside = _mm512_cmp_pd_mask(w, zero, _CMP_GT_OQ);
      const int a = wedge_triangle<S, S>(inside & 0xF, _mm512_castpd512_pd256(w)),
                c = wedge_triangle<S, S>(inside >> 4, _mm512_extractf64x4_pd(w, 1));
      const __m512d q = _mm512_add_pd(pair(q0, a, c), _mm512_mul_pd(pair(qx, a, c), x));
      // finish_linear: opacity clamped to [0, 1], colour clamped to >= 0 times it
      const __m512d u = _mm512_max_pd(q, zero);
      const __m512d alpha = _mm512_min_pd(_mm512_permutex_pd(u, 0xFF), one);
      const __m512d src = _mm512_mask_blend_pd(0x88, _mm512_mul_pd(u, alpha), alpha);
      // "over" (composite/fragment.hpp's, in float), pixel i + 1 only where the row holds it
      const __mmask8 in_row = i < e ? 0xFF : 0x0F;
      const __m256 s = _mm512_cvtpd_ps(src), t = _mm256_sub_ps(_mm256_set1_ps(1.0f), _mm256_shuffle_ps(s, s, 0xFF));
      float* dst = line + 4 * i;
      _mm256_mask_storeu_ps(dst, in_row, _mm256_add_ps(s, _mm256_mul_ps(t, _mm256_maskz_loadu_ps(in_row, dst))));
      const unsigned adds = _mm512_mask_cmp_pd_mask(in_row, src, zero, _CMP_NEQ_UQ);
      added += ((adds & 0xF) != 0) + ((adds >> 4) != 0);
    }
  }
  return added;
}

}  // namespace

std::int64_t fan_over_avx512(const FanPlanes& f, Image& image, int i0, int j0, int row0, int rows, int width) {
  return (f.sectors == 4 ? over_pairs<4> : over_pairs<3>)(f, image, i0, j0, row0, rows, width);
}

}  // namespace cellproj
#endif
