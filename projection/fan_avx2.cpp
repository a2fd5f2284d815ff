// A small tetrahedron's fan one pixel at a time, the pixel's four quantities in one AVX2 vector
// (pt-table's fifth beside it; projection/tet_fan.hpp's FanLanes::quantities): a row's set-up is
// one vector per triangle, and no lane is spent past a row's end (a row of a small tetrahedron is
// a few pixels, where four pixels at a time spend most lanes and set-up on nothing). Each value
// gets the same operations as in tet_fan.cpp's four-pixel kernels, so the same bits.
#include <algorithm>

#include "projection/fan_simd.hpp"

#if CELLPROJ_AVX2_DISPATCH

namespace cellproj {
namespace {

// A float pixel's "over" of src (r, g, b, opacity, premultiplied; composite/fragment.hpp's over:
// the same operations, so the same bits); true if src adds something (not all +-0).
CELLPROJ_AVX2_INLINE bool over_pixel(float* dst, __m256d src) {
  const __m128 s = _mm256_cvtpd_ps(src), t = _mm_sub_ps(_mm_set1_ps(1.0f), _mm_shuffle_ps(s, s, 0xFF));
  _mm_storeu_ps(dst, _mm_add_ps(s, _mm_mul_ps(t, _mm_loadu_ps(dst))));
  return _mm256_movemask_pd(_mm256_cmp_pd(src, _mm256_setzero_pd(), _CMP_NEQ_UQ)) != 0;
}

// Each pixel of the fan inside the outline, rows [row0, row0 + rows) of the box, composited "over"
// the image (whose pixel (i0, j0) is the box's first) with what `source` gives: source.row(y) at
// each row y with pixels, then source.pixel(fan, row, i, x) for each of its columns i (x: all
// lanes i), (r, g, b, opacity) premultiplied, from the planes' lanes in `Order`. Returns the pixels
// composited that add something.
template <int S, int Order, class Source>
CELLPROJ_AVX2_INLINE std::int64_t over_each_pixel(const FanPlanes& f, Image& image, int i0, int j0, int row0, int rows,
                                                  int width, Source& source) {
  const FanVectors<S, Order> fan(f);
  const __m256d one = _mm256_set1_pd(1.0);
  std::int64_t added = 0;
  RowSpans<S> spans{f, row0, rows, width};
  for (int b, e; spans.next(b, e);) {
    const double y = row0 + spans.r;
    float* line = image.pixel(i0, j0 + row0 + spans.r);
    const FanRow<S, Order> row(fan, y);
    source.row(y);
    __m256d x = _mm256_set1_pd(static_cast<double>(b));
    for (int i = b; i <= e; ++i, x = _mm256_add_pd(x, one))  // (integers: x is exactly i)
      added += over_pixel(line + 4 * i, source.pixel(fan, row, i, x));
  }
  return added;
}

// pt-linear: opacity and colour, finished as CompositeOver does; the planes' lanes as (r, g, b,
// opacity), the image's order.
template <int S>
struct LinearSource {
  CELLPROJ_AVX2_INLINE void row(double) {}
  CELLPROJ_AVX2_INLINE __m256d pixel(const FanVectors<S, 0x39>& fan, const FanRow<S, 0x39>& row, int, __m256d x) const {
    // finish_linear: opacity clamped to [0, 1], colour clamped to >= 0 times it
    const __m256d u = _mm256_max_pd(row.at(fan, x), _mm256_setzero_pd());
    const __m256d alpha = _mm256_min_pd(_mm256_permute4x64_pd(u, 0xFF), _mm256_set1_pd(1.0));
    return _mm256_blend_pd(_mm256_mul_pd(u, alpha), alpha, 0x8);
  }
};

template <int S>
CELLPROJ_AVX2 std::int64_t over_pixels(const FanPlanes& f, Image& image, int i0, int j0, int row0, int rows,
                                       int width) {
  LinearSource<S> source;
  return over_each_pixel<S, 0x39>(f, image, i0, j0, row0, rows, width, source);
}

// pt-table: kappa_avg, thickness and the colour's red and green in the planes' lanes, its blue
// beside them; each pixel's opacity from the table and its colour clamped to >= 0 times it, as
// tet_fan.cpp's CompositeTable (the same operations, so the same bits).
template <int S>
struct TableSource {
  const FanPlanes& f;
  const OpacityTable& table;
  double blue0[S];  // the fifth quantity at the row's pixel 0, as fan_rows evaluates it
  CELLPROJ_AVX2_INLINE void row(double y) {
    for (int a = 0; a < S; ++a) blue0[a] = f.q[a].c[4] + f.q[a].gy[4] * y;
  }
  CELLPROJ_AVX2_INLINE __m256d pixel(const FanVectors<S, 0xE4>& fan, const FanRow<S, 0xE4>& row, int i,
                                     __m256d x) const {
    const __m256d zero = _mm256_setzero_pd();
    const int a = row.triangle(fan, x);
    // std::max(q, 0.0) lane by lane: _mm256_max_pd keeps its second operand's NaN and -0 as it does
    const __m256d q = _mm256_max_pd(zero, a < 0 ? zero : _mm256_add_pd(row.q0[a], _mm256_mul_pd(fan.qx[a], x)));
    const double blue = a < 0 ? 0.0 : std::max(blue0[a] + f.q[a].gx[4] * i, 0.0);
    const __m128d kl = _mm256_castpd256_pd128(q);
    const double alpha = table(_mm_cvtsd_f64(kl), _mm_cvtsd_f64(_mm_unpackhi_pd(kl, kl)));
    const __m128d rg = _mm_mul_pd(_mm256_extractf128_pd(q, 1), _mm_set1_pd(alpha));
    return _mm256_insertf128_pd(_mm256_castpd128_pd256(rg), _mm_set_pd(alpha, blue * alpha), 1);
  }
};

template <int S>
CELLPROJ_AVX2 std::int64_t table_pixels(const FanPlanes& f, const OpacityTable& table, Image& image, int i0, int j0,
                                        int row0, int rows, int width) {
  TableSource<S> source{f, table, {}};
  return over_each_pixel<S, 0xE4>(f, image, i0, j0, row0, rows, width, source);
}

// The exact rungs: each pixel's segment appended to the batch as AppendSegments does
// (segment_between and LinearPiece::kappa), its quantities (front, back end: depth and scalar, or
// 1/z and s/z in perspective) in the planes' own lane order.
template <int S, bool Perspective>
CELLPROJ_AVX2 void segments_pixels(const FanPlanes& f, const FanSegments& at, SegmentBatch& b) {
  const FanVectors<S, 0xE4> fan(f);
  const __m128d zero = _mm_setzero_pd(), smin = _mm_set1_pd(at.smin), smax = _mm_set1_pd(at.smax),
                s0 = _mm_set1_pd(at.piece.s0), ds = _mm_set1_pd(at.piece.ds), k0 = _mm_set1_pd(at.piece.k0),
                dk = _mm_set1_pd(at.piece.dk), ones = _mm_set1_pd(1.0);
  const double* u2 = at.rays.u_squared() + at.i0;
  RowSpans<S> spans{f, at.row0, at.rows, at.width};
  for (int first, last; spans.next(first, last);) {
    const double y = at.row0 + spans.r;
    const int j = at.j0 + at.row0 + spans.r;
    const double v2 = Perspective ? at.rays.v_squared()[j] : 0.0;
    const std::size_t base = b.n - static_cast<std::size_t>(first);
    const FanRow<S, 0xE4> row(fan, y);
    __m256d x = _mm256_set1_pd(static_cast<double>(first));
    for (int i = first; i <= last; ++i, x = _mm256_add_pd(x, _mm256_set1_pd(1.0))) {
      const std::size_t k = base + static_cast<std::size_t>(i);
      b.i[k] = at.i0 + i, b.j[k] = j;
      const __m256d q = row.at(fan, x);
      __m128d ends = _mm256_castpd256_pd128(q), s = _mm256_extractf128_pd(q, 1);  // (front, back)
      if constexpr (Perspective) ends = _mm_div_pd(ones, ends), s = _mm_mul_pd(s, ends);
      // std::clamp's order: below smin, smin; else above smax, smax
      s = _mm_blendv_pd(_mm_blendv_pd(s, smax, _mm_cmplt_pd(smax, s)), smin, _mm_cmplt_pd(s, smin));
      const double thick = _mm_cvtsd_f64(_mm_unpackhi_pd(ends, ends)) - _mm_cvtsd_f64(ends);
      const double per_depth = Perspective ? std::sqrt(1.0 + u2[i] + v2) : 1.0;
      b.length[k] = (0.0 < thick ? thick : 0.0) * per_depth;
      const __m128d kappa = _mm_add_pd(k0, _mm_mul_pd(_mm_mul_pd(dk, _mm_sub_pd(s, s0)), ds));
      const __m128d kept = _mm_blendv_pd(zero, kappa, _mm_cmplt_pd(zero, kappa));
      _mm_storel_pd(&b.sf[k], s), _mm_storeh_pd(&b.sb[k], s);
      _mm_storel_pd(&b.k0[k], kept), _mm_storeh_pd(&b.k1[k], kept);
    }
    b.n += static_cast<std::size_t>(last - first + 1);
  }
}

}  // namespace

std::int64_t fan_over_avx2(const FanPlanes& f, Image& image, int i0, int j0, int row0, int rows, int width) {
  return (f.sectors == 4 ? over_pixels<4> : over_pixels<3>)(f, image, i0, j0, row0, rows, width);
}

std::int64_t fan_table_avx2(const FanPlanes& f, const OpacityTable& table, Image& image, int i0, int j0, int row0,
                            int rows, int width) {
  return (f.sectors == 4 ? table_pixels<4> : table_pixels<3>)(f, table, image, i0, j0, row0, rows, width);
}

void fan_segments_avx2(const FanPlanes& f, const FanSegments& at, SegmentBatch& out) {
  const bool four = f.sectors == 4;
  if (at.rays.perspective())
    (four ? segments_pixels<4, true> : segments_pixels<3, true>)(f, at, out);
  else
    (four ? segments_pixels<4, false> : segments_pixels<3, false>)(f, at, out);
}

}  // namespace cellproj
#endif
