#include "optics/two_fields.hpp"

#include "optics/linear_segment.hpp"

namespace cellproj {

TwoFieldTransfer::TwoFieldTransfer(const TransferFunction& tf)
    : color(tf.color_points(), {{0.0, 0.0}}), extinction({{0.0, glm::dvec3(1.0)}}, tf.extinction_points()) {}

UnsupportedError two_fields_refused(const std::string& opacity_field, const std::string& by) {
  const std::string from = opacity_field.empty() ? "another field than the colour" : "field '" + opacity_field + "'";
  return UnsupportedError("setting 'opacity-field' (the extinction from " + from +
                          ") is drawn by setting 'method' exact, pt-breakpoints or pt-analytic, not by " + by);
}

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
