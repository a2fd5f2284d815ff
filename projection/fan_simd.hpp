#pragma once
// Internal to the AVX kernels of the fan (fan_avx2.cpp, fan_avx512.cpp): a fan's per-tetrahedron
// vectors and a row's values, a pixel's four quantities in an AVX2 vector.
#include <limits>

#include "projection/fan_row.hpp"

#if CELLPROJ_AVX2_DISPATCH
#include <immintrin.h>

namespace cellproj {

#define CELLPROJ_AVX2 __attribute__((target("avx2")))
#define CELLPROJ_AVX2_INLINE __attribute__((target("avx2"), always_inline)) inline

// A fan's per-tetrahedron vectors: its spokes' planes (lane k: spoke k) and triangles left out, and
// each triangle's quantity planes with their lanes in `Order` (a _mm256_permute4x64_pd control).
template <int S, int Order>
struct FanVectors {
  __m256d spoke_c, spoke_gy, spoke_gx, left_out;
  __m256d qc[S], qgy[S], qx[S];
  CELLPROJ_AVX2_INLINE explicit FanVectors(const FanPlanes& f) {
    alignas(32) double pc[4], pgy[4], pgx[4], left[4];
    for (int k = 0; k < 4; ++k) {
      const bool in = k < S;  // a fourth lane for three triangles: never chosen
      pc[k] = in ? f.spoke[k].c : 0.0, pgy[k] = in ? f.spoke[k].gy : 0.0, pgx[k] = in ? f.spoke[k].gx : 0.0;
      left[k] = in ? f.left_out[k] : -std::numeric_limits<double>::infinity();
    }
    spoke_c = _mm256_load_pd(pc), spoke_gy = _mm256_load_pd(pgy), spoke_gx = _mm256_load_pd(pgx);
    left_out = _mm256_load_pd(left);
    for (int a = 0; a < S; ++a)
      qc[a] = _mm256_permute4x64_pd(_mm256_loadu_pd(f.q[a].c), Order),
      qgy[a] = _mm256_permute4x64_pd(_mm256_loadu_pd(f.q[a].gy), Order),
      qx[a] = _mm256_permute4x64_pd(_mm256_loadu_pd(f.q[a].gx), Order);
  }
};

// The triangle whose wedge holds a pixel, from its wedge values w = min(spoke[a], -spoke[a + 1]) +
// left_out[a] (lanes a < S) and `inside`, the mask of those > 0: the one positive inside the
// outline; where none or two are (on a spoke, at the thick vertex, to rounding), fan_rows' rule:
// the first largest. `None` if none is taken (NaN).
template <int S, int None = -1>
CELLPROJ_AVX2_INLINE int wedge_triangle(unsigned inside, __m256d w) {
  if (inside != 0 && (inside & (inside - 1)) == 0) return __builtin_ctz(inside);
  alignas(32) double wa[4];
  _mm256_store_pd(wa, w);
  double best = -std::numeric_limits<double>::infinity();
  int a = None;
  for (int k = 0; k < S; ++k)
    if (wa[k] > best) best = wa[k], a = k;
  return a;
}

// A row's values at its pixel 0: the spokes' and each triangle's quantities'.
template <int S, int Order>
struct FanRow {
  __m256d spoke0, q0[S];
  CELLPROJ_AVX2_INLINE FanRow(const FanVectors<S, Order>& v, double y) {
    const __m256d yy = _mm256_set1_pd(y);
    spoke0 = _mm256_add_pd(v.spoke_c, _mm256_mul_pd(v.spoke_gy, yy));
    for (int a = 0; a < S; ++a) q0[a] = _mm256_add_pd(v.qc[a], _mm256_mul_pd(v.qgy[a], yy));
  }
  // The triangle whose wedge holds the pixels at x (all lanes x): wedge_triangle of their wedge values.
  CELLPROJ_AVX2_INLINE int triangle(const FanVectors<S, Order>& v, __m256d x) const {
    const __m256d spoke = _mm256_add_pd(spoke0, _mm256_mul_pd(v.spoke_gx, x));
    const __m256d next = S == 4 ? _mm256_permute4x64_pd(spoke, 0x39) : _mm256_permute4x64_pd(spoke, 0xC9);
    const __m256d w = _mm256_add_pd(_mm256_min_pd(spoke, _mm256_xor_pd(next, _mm256_set1_pd(-0.0))), v.left_out);
    return wedge_triangle<S>(_mm256_movemask_pd(_mm256_cmp_pd(w, _mm256_setzero_pd(), _CMP_GT_OQ)), w);
  }
  // The quantities at x: those of triangle(v, x), zero if none is taken, as fan_rows.
  CELLPROJ_AVX2_INLINE __m256d at(const FanVectors<S, Order>& v, __m256d x) const {
    const int a = triangle(v, x);
    return a < 0 ? _mm256_setzero_pd() : _mm256_add_pd(q0[a], _mm256_mul_pd(v.qx[a], x));
  }
};

}  // namespace cellproj
#endif
