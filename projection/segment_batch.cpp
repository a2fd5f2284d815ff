#include "projection/segment_batch.hpp"

#include <algorithm>
#include <cmath>

#include "base/simd.hpp"
#include "composite/fragment.hpp"
#include "optics/segment_integral.hpp"

#if CELLPROJ_AVX2_DISPATCH
#include <immintrin.h>
#endif

namespace cellproj {
namespace {

// segment_ends over n segments: segment_between and LinearPiece::kappa in SIMD lanes.
template <bool perspective>
[[gnu::always_inline]] inline void ends(std::size_t n, const int* __restrict pi, const int* __restrict pj,
                                        const double* __restrict u2, const double* __restrict v2,
                                        const double* __restrict zf, const double* __restrict zb, double* __restrict sf,
                                        double* __restrict sb, double* __restrict length, double* __restrict k0,
                                        double* __restrict k1, double smin, double smax, const LinearPiece piece) {
  for (std::size_t k = 0; k < n; ++k) {
    const double per_depth = perspective ? PixelRays::length_per_depth_from(u2[pi[k]], v2[pj[k]]) : 1.0;
    double s0 = sf[k], s1 = sb[k];
    length[k] = segment_between<perspective>(zf[k], zb[k], s0, s1, per_depth, smin, smax);
    sf[k] = s0, sb[k] = s1, k0[k] = piece.kappa(s0), k1[k] = piece.kappa(s1);
  }
}

template <bool perspective>
[[gnu::always_inline]] inline void ends(SegmentBatch& b, const PixelRays& rays, double smin, double smax,
                                        const LinearPiece& piece) {
  ends<perspective>(b.n, b.i.data(), b.j.data(), rays.u_squared(), rays.v_squared(), b.zf.data(), b.zb.data(),
                    b.sf.data(), b.sb.data(), b.length.data(), b.k0.data(), b.k1.data(), smin, smax, piece);
}

// One function per projection and target: the build's default, or AVX2 where the processor has it.
CELLPROJ_AVX2_CLONES void perspective_ends(SegmentBatch& b, const PixelRays& rays, double smin, double smax,
                                           const LinearPiece& piece) {
  ends<true>(b, rays, smin, smax, piece);
}
CELLPROJ_AVX2_CLONES void orthographic_ends(SegmentBatch& b, const PixelRays& rays, double smin, double smax,
                                            const LinearPiece& piece) {
  ends<false>(b, rays, smin, smax, piece);
}

// segment_light over n segments: LinearPiece::color at both ends, weighted (as
// integrate_linear_closed_form).
[[gnu::always_inline]] inline void light(std::size_t n, const EndWeights* __restrict w, const double* __restrict sf,
                                         const double* __restrict sb, double* __restrict red, double* __restrict green,
                                         double* __restrict blue, double* __restrict opacity, const LinearPiece piece) {
  for (std::size_t k = 0; k < n; ++k) {
    const glm::dvec3 c = piece.color(sf[k]) * w[k].front + piece.color(sb[k]) * w[k].back;
    red[k] = c.r, green[k] = c.g, blue[k] = c.b, opacity[k] = w[k].opacity;
  }
}

CELLPROJ_AVX2_CLONES void light(SegmentBatch& b, const LinearPiece& piece) {
  light(b.n, b.weights.data(), b.sf.data(), b.sb.data(), b.red.data(), b.green.data(), b.blue.data(), b.opacity.data(),
        piece);
}

// composite_over's fragment k, one at a time (as CompositeFragments).
inline bool over_one(const SegmentBatch& b, std::size_t k, Image& image) {
  return over_fragment(image.pixel(b.i[k], b.j[k]), {b.red[k], b.green[k], b.blue[k]}, b.opacity[k]);
}

#if CELLPROJ_AVX2_DISPATCH
// Four fragments at a time: their colour and opacity converted to float in lanes and transposed to
// one (r, g, b, opacity) vector each, then "over" one fragment after another (a pixel may come
// twice: each reads what the one before wrote).
__attribute__((target("avx2"))) std::int64_t over_avx2(const SegmentBatch& b, Image& image) {
  std::int64_t added = 0;
  std::size_t k = 0;
  const __m256d zero = _mm256_setzero_pd();
  const __m128 one = _mm_set1_ps(1.0f);
  for (; k + 4 <= b.n; k += 4) {
    const __m256d r = _mm256_loadu_pd(&b.red[k]), g = _mm256_loadu_pd(&b.green[k]), bl = _mm256_loadu_pd(&b.blue[k]),
                  a = _mm256_loadu_pd(&b.opacity[k]);
    // adds: not all four +-0 (NaN adds), as over_fragment's adds_nothing
    const __m256d some =
        _mm256_or_pd(_mm256_or_pd(_mm256_cmp_pd(r, zero, _CMP_NEQ_UQ), _mm256_cmp_pd(g, zero, _CMP_NEQ_UQ)),
                     _mm256_or_pd(_mm256_cmp_pd(bl, zero, _CMP_NEQ_UQ), _mm256_cmp_pd(a, zero, _CMP_NEQ_UQ)));
    const unsigned adds = static_cast<unsigned>(_mm256_movemask_pd(some));
    __m128 f0 = _mm256_cvtpd_ps(r), f1 = _mm256_cvtpd_ps(g), f2 = _mm256_cvtpd_ps(bl), f3 = _mm256_cvtpd_ps(a);
    _MM_TRANSPOSE4_PS(f0, f1, f2, f3);
    const __m128 src[4] = {f0, f1, f2, f3};
    for (int l = 0; l < 4; ++l)
      if (adds >> l & 1u) {
        float* dst = image.pixel(b.i[k + l], b.j[k + l]);
        const __m128 t = _mm_sub_ps(one, _mm_shuffle_ps(src[l], src[l], 0xFF));
        _mm_storeu_ps(dst, _mm_add_ps(src[l], _mm_mul_ps(t, _mm_loadu_ps(dst))));
      }
    added += __builtin_popcount(adds);
  }
  for (; k < b.n; ++k) added += over_one(b, k, image);
  return added;
}
#endif

}  // namespace

void segment_light(SegmentBatch& b, const LinearPiece& piece) { light(b, piece); }

std::int64_t composite_over(SegmentBatch& b, Image& image, bool lanes) {
  for (std::size_t k = 0; k < b.n; ++k)  // SegmentLight::opacity()'s
    if (!(b.opacity[k] >= 0.0)) b.opacity[k] = -std::expm1(-b.weights[k].depth);
#if CELLPROJ_AVX2_DISPATCH
  if (lanes && __builtin_cpu_supports("avx2")) return over_avx2(b, image);
#endif
  std::int64_t added = 0;
  for (std::size_t k = 0; k < b.n; ++k) added += over_one(b, k, image);
  return added;
}

void segment_light_across(SegmentBatch& b, const TransferFunction& tf, bool cut) {
  SegmentBatch::Pieces& p = b.pieces;
  p.n = 0;
  p.end.resize(b.n);
  const auto push = [&p](double length, double ka, double kb, const glm::dvec3& ca, const glm::dvec3& cb) {
    if (p.n == p.length.size()) {  // a multiple of 4, for linear_segment_weights_padded
      const std::size_t m = std::max<std::size_t>(64, 2 * p.n);
      p.length.resize(m), p.k0.resize(m), p.k1.resize(m), p.c0.resize(m), p.c1.resize(m), p.weights.resize(m);
    }
    p.length[p.n] = length, p.k0[p.n] = ka, p.k1[p.n] = kb, p.c0[p.n] = ca, p.c1[p.n] = cb;
    ++p.n;
  };
  for (std::size_t k = 0; k < b.n; ++k) {
    const double l = b.length[k], s0 = b.sf[k], s1 = b.sb[k];
    if (!cut)
      push(l, tf.extinction(s0), tf.extinction(s1), tf.color(s0), tf.color(s1));
    else if (l > 0.0)  // as integrate_pieces: no light from an empty segment
      for_each_linear_piece(tf, s0, s1, [&](const TransferFunction::Ends& e, double fraction) {
        push(l * fraction, e.ka, e.kb, e.ca, e.cb);
      });
    p.end[k] = p.n;
  }
  linear_segment_weights_padded(p.n, p.length.data(), p.k0.data(), p.k1.data(), p.weights.data());
  std::size_t m = 0;
  for (std::size_t k = 0; k < b.n; ++k) {
    SegmentLight acc;
    for (const std::size_t first = m; m < p.end[k]; ++m) {  // as integrate_linear_closed_form, then under()
      const EndWeights& w = p.weights[m];
      const SegmentLight piece{p.c0[m] * w.front + p.c1[m] * w.back, w.depth, w.opacity};
      acc = m == first ? piece : under(acc, piece);
    }
    b.red[k] = acc.rgb.r, b.green[k] = acc.rgb.g, b.blue[k] = acc.rgb.b, b.opacity[k] = acc.opacity();
  }
}

void SegmentBatch::grow() {
  const std::size_t m = std::max<std::size_t>(64, 2 * i.size());
  i.resize(m), j.resize(m), zf.resize(m), zb.resize(m), sf.resize(m), sb.resize(m);
  length.resize(m), k0.resize(m), k1.resize(m), weights.resize(m);
  red.resize(m), green.resize(m), blue.resize(m), opacity.resize(m);
}

void segment_ends(SegmentBatch& b, const PixelRays& rays, double smin, double smax, const LinearPiece& piece) {
  (rays.perspective() ? perspective_ends : orthographic_ends)(b, rays, smin, smax, piece);
}

}  // namespace cellproj
