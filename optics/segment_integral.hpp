#pragma once
// The optical model along one ray segment (absorption plus emission, Max 1995 section 4; Williams
// and Max 1992): T = exp(-int kappa dt), emitted light = int C kappa T dt, premultiplied.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include <glm/vec3.hpp>

#include "optics/transfer_function.hpp"

namespace cellproj {

// Behind this optical depth nothing shows: exp(-60) ~ 1e-26.
constexpr double kOpaqueDepth = 60.0;

struct SegmentLight {
  glm::dvec3 rgb{0.0};  // premultiplied light leaving the front end
  double depth = 0.0;   // optical depth; kept instead of 1 - alpha so tiny opacities stay exact
  // 1 - e^-depth when the integrator had it already, to full precision (a small cell's series),
  // else negative and opacity() computes it.
  double known_opacity = -1.0;

  double transmittance() const { return std::exp(-depth); }
  double opacity() const { return known_opacity >= 0.0 ? known_opacity : -std::expm1(-depth); }
};

// Front-to-back "under": `back` seen through `front`.
inline SegmentLight under(const SegmentLight& front, const SegmentLight& back) {
  return {front.rgb + front.transmittance() * back.rgb, front.depth + back.depth};
}

// kappa and colour varying linearly from the front (k0, c0) to the back (k1, c1) over `length`.
// Reference quality: the segment is cut where the optical depth grows by 1/4 and each piece is
// integrated with 8-point Gauss-Legendre, relative error below 1e-12; light behind an optical depth
// of 60 is dropped (below 1e-26).
SegmentLight integrate_linear_reference(double length, double k0, double k1, const glm::dvec3& c0,
                                        const glm::dvec3& c1);

// One of several media overlapping on a piece of ray (several volumes of a scene): kappa and colour
// linear from the front (k0, c0) to the back (k1, c1).
struct LinearMedium {
  double k0, k1;
  glm::dvec3 c0, c1;
};
// Overlapping media over `length`: the extinction is their sum and each emits its own kappa C, all
// of it attenuated by the sum; the quadrature of integrate_linear_reference.
SegmentLight integrate_media_reference(double length, const LinearMedium* media, std::size_t n);

// Calls piece(ends, fraction) for each piece of a segment along which the scalar runs linearly from
// s0 (front) to s1 (back), cut at the transfer function's breakpoints, front to back: `ends` holds
// kappa and colour at the piece's ends, `fraction` its share of the segment's length.
template <class Piece>
void for_each_linear_piece(const TransferFunction& tf, double s0, double s1, Piece&& piece) {
  const auto& bp = tf.breakpoints();
  const double lo = std::min(s0, s1), hi = std::max(s0, s1);
  // Breakpoints first .. last - 1 lie strictly between s0 and s1; the piece ending at breakpoint
  // b lies in interval b going up, b + 1 going down (TransferFunction::piece_in).
  const std::size_t first = tf.breakpoints_not_above(lo), last = tf.breakpoints_below(hi);
  double sa = s0, ta = 0.0;
  auto cut = [&](std::size_t interval, double sb) {
    const double tb = s1 == s0 ? 1.0 : (sb - s0) / (s1 - s0);
    piece(tf.piece_in(interval, sa, sb), tb - ta);
    sa = sb;
    ta = tb;
  };
  if (s1 >= s0) {
    for (std::size_t b = first; b < last; ++b) cut(b, bp[b]);
    cut(std::max(first, last), s1);  // (s1 == s0 on a breakpoint: last < first, the interval above)
  } else {
    for (std::size_t b = last; b > first; --b) cut(b, bp[b - 1]);
    cut(first, s1);
  }
}

// The light of such a segment: each piece integrated by integrate(L, k0, k1, c0, c1), composited.
template <class Integrate>
SegmentLight integrate_pieces(const TransferFunction& tf, double length, double s0, double s1, Integrate&& integrate) {
  SegmentLight acc;
  if (!(length > 0.0)) return acc;
  bool first = true;  // the first piece as it is (under() of it behind nothing is the same light)
  for_each_linear_piece(tf, s0, s1, [&](const TransferFunction::Ends& e, double fraction) {
    const SegmentLight piece = integrate(length * fraction, e.ka, e.kb, e.ca, e.cb);
    acc = first ? piece : under(acc, piece);
    first = false;
  });
  return acc;
}

// A segment along which the scalar runs linearly from s0 (front) to s1 (back): cut at the transfer
// function's breakpoints, each piece integrated with integrate_linear_reference.
SegmentLight integrate_segment_reference(const TransferFunction& tf, double length, double s0, double s1);

// A medium on a piece of ray shared with others: its transfer function, its scalar linear from s0
// (front) to s1 (back).
struct MediumSegment {
  const TransferFunction* tf;
  double s0, s1;
};
// Overlapping media over `length`, cut at every breakpoint of each one's transfer function, each
// piece integrated with integrate_media_reference.
SegmentLight integrate_overlap_reference(double length, const MediumSegment* media, std::size_t n);

}  // namespace cellproj
