#include "projection/segment_batch.hpp"

#include <algorithm>
#include <cmath>

namespace cellproj {
namespace {

// segment_ends over n segments, written without branches (std::clamp's and std::max's comparisons
// as selects of values) so that the loop runs in SIMD lanes.
template <bool perspective>
[[gnu::always_inline]] inline void ends(std::size_t n, const int* __restrict pi, const int* __restrict pj,
                                        const double* __restrict u2, const double* __restrict v2,
                                        const double* __restrict zf, const double* __restrict zb,
                                        double* __restrict sf, double* __restrict sb, double* __restrict length,
                                        double* __restrict k0, double* __restrict k1, double smin, double smax,
                                        const LinearPiece& piece) {
  const auto clamp = [smin, smax](double v) { return v < smin ? smin : smax < v ? smax : v; };
  const double ks = piece.k0, kd = piece.dk, s_0 = piece.s0, ds = piece.ds;
  const auto kappa = [=](double s) {  // LinearPiece::kappa
    const double k = ks + kd * (s - s_0) * ds;
    return 0.0 < k ? k : 0.0;
  };
  for (std::size_t k = 0; k < n; ++k) {
    double f = zf[k], e = zb[k], s0 = sf[k], s1 = sb[k], per_depth = 1.0;
    if constexpr (perspective) {  // 1/z and s/z interpolate; PixelRays::length_per_depth_at_pixel
      f = 1.0 / f, e = 1.0 / e, s0 *= f, s1 *= e;
      per_depth = std::sqrt(1.0 + u2[pi[k]] + v2[pj[k]]);
    }
    s0 = clamp(s0), s1 = clamp(s1);
    const double thick = e - f;
    length[k] = (0.0 < thick ? thick : 0.0) * per_depth;
    sf[k] = s0, sb[k] = s1, k0[k] = kappa(s0), k1[k] = kappa(s1);
  }
}

template <bool perspective>
[[gnu::always_inline]] inline void ends(SegmentBatch& b, const PixelRays& rays, double smin, double smax,
                                        const LinearPiece& piece) {
  ends<perspective>(b.n, b.i.data(), b.j.data(), rays.u_squared(), rays.v_squared(), b.zf.data(), b.zb.data(),
                    b.sf.data(), b.sb.data(), b.length.data(), b.k0.data(), b.k1.data(), smin, smax, piece);
}

// One function per projection and target: the build's default, or AVX2 where the processor has it.
__attribute__((target_clones("avx2", "default"))) void perspective_ends(SegmentBatch& b, const PixelRays& rays,
                                                                        double smin, double smax,
                                                                        const LinearPiece& piece) {
  ends<true>(b, rays, smin, smax, piece);
}
__attribute__((target_clones("avx2", "default"))) void orthographic_ends(SegmentBatch& b, const PixelRays& rays,
                                                                         double smin, double smax,
                                                                         const LinearPiece& piece) {
  ends<false>(b, rays, smin, smax, piece);
}

// segment_light over n segments: LinearPiece::color at both ends, weighted.
[[gnu::always_inline]] inline void light(std::size_t n, const EndWeights* __restrict w, const double* __restrict sf,
                                         const double* __restrict sb, double* __restrict red,
                                         double* __restrict green, double* __restrict blue,
                                         double* __restrict opacity, const LinearPiece& piece) {
  const double s0 = piece.s0, ds = piece.ds;
  const double c0[3] = {piece.c0.r, piece.c0.g, piece.c0.b}, dc[3] = {piece.dc.r, piece.dc.g, piece.dc.b};
  for (std::size_t k = 0; k < n; ++k) {
    const double tf = (sf[k] - s0) * ds, tb = (sb[k] - s0) * ds, front = w[k].front, back = w[k].back;
    red[k] = (c0[0] + dc[0] * tf) * front + (c0[0] + dc[0] * tb) * back;
    green[k] = (c0[1] + dc[1] * tf) * front + (c0[1] + dc[1] * tb) * back;
    blue[k] = (c0[2] + dc[2] * tf) * front + (c0[2] + dc[2] * tb) * back;
    opacity[k] = w[k].opacity;
  }
}

__attribute__((target_clones("avx2", "default"))) void light(SegmentBatch& b, const LinearPiece& piece) {
  light(b.n, b.weights.data(), b.sf.data(), b.sb.data(), b.red.data(), b.green.data(), b.blue.data(),
        b.opacity.data(), piece);
}

}  // namespace

void segment_light(SegmentBatch& b, const LinearPiece& piece) { light(b, piece); }

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
