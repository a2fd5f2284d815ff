#include "optics/two_fields.hpp"

#include "optics/linear_segment.hpp"

namespace cellproj {

TwoFieldTransfer::TwoFieldTransfer(const TransferFunction& tf)
    : color(tf.color_points(), {{0.0, 0.0}}), extinction({{0.0, glm::dvec3(1.0)}}, tf.extinction_points()) {}

namespace detail {

std::size_t breakpoints_inside(const TransferFunction& tf, double a, double b) {
  const double lo = std::min(a, b), hi = std::max(a, b);
  const std::size_t first = tf.breakpoints_not_above(lo), last = tf.breakpoints_below(hi);
  return last > first ? last - first : 0;
}

double* breakpoint_fractions(const TransferFunction& tf, double a, double b, double* cuts) {
  const auto& bp = tf.breakpoints();
  const double lo = std::min(a, b), hi = std::max(a, b);
  for (std::size_t k = tf.breakpoints_not_above(lo), last = tf.breakpoints_below(hi); k < last; ++k)
    *cuts++ = (bp[k] - a) / (b - a);  // b != a: a breakpoint lies strictly between them
  return cuts;
}

}  // namespace detail

SegmentLight integrate_two_fields_reference(const TwoFieldTransfer& tf, double length, double u0, double u1, double s0,
                                            double s1) {
  return integrate_two_field_pieces(tf, length, u0, u1, s0, s1, integrate_linear_reference);
}

SegmentLight integrate_two_fields_closed_form(const TwoFieldTransfer& tf, double length, double u0, double u1,
                                              double s0, double s1, bool cut) {
  if (!cut) {  // pt-analytic: the segment whole, from the values at its ends
    if (!(length > 0.0)) return {};
    const glm::dvec3 c0 = tf.color.color(u0), c1 = tf.color.color(u1);
    return integrate_linear_closed_form(length, tf.extinction.extinction(s0), tf.extinction.extinction(s1), c0, c1);
  }
  return integrate_two_field_pieces(tf, length, u0, u1, s0, s1, integrate_linear_closed_form);
}

}  // namespace cellproj
