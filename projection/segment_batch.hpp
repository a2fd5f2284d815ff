#pragma once
// The exact methods' fragments of one cell gathered before their light, so that the per-pixel
// work runs over arrays in SIMD lanes (each lane the same bits as the scalar code).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "optics/linear_segment.hpp"
#include "optics/transfer_function.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"

namespace cellproj {

// Colour and extinction as linear functions of s over a cell's scalar range holding no breakpoint.
// Written with selects of values (std::max's comparison), as is segment_between, so that loops over
// many fragments run in SIMD lanes with each lane the same bits as one call.
struct LinearPiece {
  double s0 = 0, ds = 0;  // s0 and 1 / (s1 - s0) (0 for a constant cell)
  double k0 = 0, dk = 0;
  glm::dvec3 c0{0.0}, dc{0.0};
  template <class T>  // double, or a vector of doubles (GCC's extension): the same bits per lane
  T kappa(const T& s) const {
    const T k = k0 + dk * (s - s0) * ds, zero{};
    return zero < k ? k : zero;
  }
  glm::dvec3 color(double s) const { return c0 + dc * ((s - s0) * ds); }
};

// The segment a pixel's ray crosses, from the interpolated ends (depth and scalar, or in
// perspective 1/z and s/z: perspective-correct interpolation, z = 1 / (1/z), s = (s/z) z): its
// length, with per_depth the ray's length per unit of depth there, and the ends' scalars clamped
// to [smin, smax] (as std::clamp). T: double, or a vector of doubles (the fan's lanes), with the
// same operations in the same order, so the same bits per lane.
template <bool perspective, class T>
inline T segment_between(const T& front, const T& back, T& sf, T& sb, const T& per_depth, const T& smin,
                         const T& smax) {
  T zf = front, zb = back;
  if constexpr (perspective) zf = 1.0 / zf, zb = 1.0 / zb, sf *= zf, sb *= zb;
  sf = sf < smin ? smin : smax < sf ? smax : sf, sb = sb < smin ? smin : smax < sb ? smax : sb;
  const T thick = zb - zf, zero{};
  return (zero < thick ? thick : zero) * per_depth;
}

// pt-analytic's and pt-breakpoints' fragments of one cell before their light, so the closed forms
// run over the cell at once: pixel and the interpolated ends (depth and scalar, or 1/z and s/z in
// perspective), then the segments' lengths, end extinctions and weights.
struct SegmentBatch {
  std::size_t n = 0;  // fragments gathered
  std::vector<int> i, j;
  std::vector<double> zf, zb, sf, sb;
  std::vector<double> length, k0, k1;
  std::vector<EndWeights> weights;
  std::vector<double> red, green, blue, opacity;  // opacity < 0: 1 - e^-depth still to compute
  void push(int pi, int pj, double qzf, double qzb, double qsf, double qsb) {
    if (n == i.size()) grow();
    i[n] = pi, j[n] = pj, zf[n] = qzf, zb[n] = qzb, sf[n] = qsf, sb[n] = qsb;
    ++n;
  }
  void reserve(std::size_t m) {  // room for at least m
    while (i.size() < m) grow();
  }
  void grow();  // room for twice as many (64 at first: the arrays' size stays a multiple of 4, for SIMD lanes)
  // Across a breakpoint: the segments' pieces, each linear in kappa and colour (segment_light_cut).
  struct Pieces {
    std::size_t n = 0;
    std::vector<double> length, k0, k1;
    std::vector<glm::dvec3> c0, c1;
    std::vector<EndWeights> weights;
    std::vector<std::size_t> end;  // per segment: one past its last piece
  } pieces;
};

// The lengths, end scalars (clamped to [smin, smax]) and end extinctions of the batch's segments,
// from their interpolated ends: length = (back - front depth) times the ray's length per depth.
void segment_ends(SegmentBatch& b, const PixelRays& rays, double smin, double smax, const LinearPiece& piece);
// The light of the batch's segments from their weights, as integrate_linear_closed_form: the ends'
// colours weighted, premultiplied, and the opacity where the weights brought it.
void segment_light(SegmentBatch& b, const LinearPiece& piece);
// The same for a cell whose scalar range holds a breakpoint, after segment_ends (whatever its piece):
// each segment cut at the breakpoints (`cut`, pt-breakpoints: integrate_segment_closed_form) or
// taken whole with the transfer function's values at its ends (pt-analytic), the pieces' weights
// computed together, composited front to back. The same bits as one segment at a time; opacity is
// always set.
void segment_light_across(SegmentBatch& b, const TransferFunction& tf, bool cut);
// The batch's light composited "over" the image (composite/fragment.hpp's over(), in float), each
// fragment at its pixel in the batch's order; those adding nothing (colour and opacity all 0) are
// skipped and not counted. Opacity < 0 is first set to 1 - e^-depth. Returns the fragments
// composited. The same bits as one fragment at a time; four at a time where the processor has
// AVX2 (`lanes` false: one at a time).
std::int64_t composite_over(SegmentBatch& b, Image& image, bool lanes = true);

}  // namespace cellproj
