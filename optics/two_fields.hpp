#pragma once
// Colour by one field, extinction by another (ParaView's separate opacity array). Both are linear
// over a tetrahedron, so along a ray segment through it the colour field u and the opacity field s
// both run linearly: cut where either meets a breakpoint of its own half of the transfer function,
// each piece has colour and extinction linear in its length, and its light is the one-field
// integral of Williams and Max (MWSC section 4), exact.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "optics/segment_integral.hpp"
#include "optics/transfer_function.hpp"

namespace cellproj {

// A transfer function's two halves apart: its colour over the colour field's values, its
// extinction over the opacity field's. Each half keeps only its own breakpoints.
struct TwoFieldTransfer {
  explicit TwoFieldTransfer(const TransferFunction& tf);
  TransferFunction color, extinction;  // the other half constant (white, kappa 0)
};

// The ends of one piece: its share [fa, fb] of the segment's length.
struct FieldPieceCut {
  double fa, fb;
};
// Calls piece(ends, fraction) for each piece of a segment along which the colour field runs from u0
// to u1 and the opacity field from s0 to s1 (front to back), cut at either half's breakpoints, front
// to back: `ends` holds the colour (from u) and the extinction (from s) at the piece's ends.
template <class Piece>
void for_each_two_field_piece(const TwoFieldTransfer& tf, double u0, double u1, double s0, double s1, Piece&& piece);

// Each piece integrated by integrate(L, k0, k1, c0, c1), composited front to back (as
// integrate_pieces for one field).
template <class Integrate>
SegmentLight integrate_two_field_pieces(const TwoFieldTransfer& tf, double length, double u0, double u1, double s0,
                                        double s1, Integrate&& integrate);

// Each piece with integrate_linear_reference (the exact renderer's).
SegmentLight integrate_two_fields_reference(const TwoFieldTransfer& tf, double length, double u0, double u1, double s0,
                                            double s1);
// Each piece in closed form (pt-breakpoints'); with `cut` false the segment is taken whole with
// the colour and extinction at its ends (pt-analytic's approximation).
SegmentLight integrate_two_fields_closed_form(const TwoFieldTransfer& tf, double length, double u0, double u1,
                                              double s0, double s1, bool cut = true);

// ---- implementation

namespace detail {
// How many breakpoints of tf lie strictly between a and b (either order).
std::size_t breakpoints_inside(const TransferFunction& tf, double a, double b);
// The fractions of [0, 1] where a field running from a to b meets them, written to `cuts`;
// returns one past the last written.
double* breakpoint_fractions(const TransferFunction& tf, double a, double b, double* cuts);
}  // namespace detail

template <class Piece>
void for_each_two_field_piece(const TwoFieldTransfer& tf, double u0, double u1, double s0, double s1, Piece&& piece) {
  // The cuts of both fields, merged: on the stack for the few a segment through one cell meets.
  constexpr std::size_t kOnStack = 64;
  const std::size_t inside =
      detail::breakpoints_inside(tf.color, u0, u1) + detail::breakpoints_inside(tf.extinction, s0, s1);
  double on_stack[kOnStack + 2];
  std::vector<double> on_heap(inside > kOnStack ? inside + 2 : 0);
  double* const cuts = inside > kOnStack ? on_heap.data() : on_stack;
  cuts[0] = 0.0;
  double* end = detail::breakpoint_fractions(tf.color, u0, u1, cuts + 1);
  end = detail::breakpoint_fractions(tf.extinction, s0, s1, end);
  std::sort(cuts + 1, end);
  *end++ = 1.0;
  const std::size_t n = static_cast<std::size_t>(end - cuts);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double fa = cuts[k], fb = cuts[k + 1];
    if (!(fb > fa)) continue;  // a breakpoint met by both fields at once
    const double ua = u0 + fa * (u1 - u0), ub = u0 + fb * (u1 - u0);
    const double sa = s0 + fa * (s1 - s0), sb = s0 + fb * (s1 - s0);
    const TransferFunction::Ends c = tf.color.piece(ua, ub), k2 = tf.extinction.piece(sa, sb);
    piece(TransferFunction::Ends{c.ca, c.cb, k2.ka, k2.kb}, FieldPieceCut{fa, fb});
  }
}

template <class Integrate>
SegmentLight integrate_two_field_pieces(const TwoFieldTransfer& tf, double length, double u0, double u1, double s0,
                                        double s1, Integrate&& integrate) {
  SegmentLight acc;
  if (!(length > 0.0)) return acc;
  bool first = true;
  for_each_two_field_piece(tf, u0, u1, s0, s1, [&](const TransferFunction::Ends& e, FieldPieceCut cut) {
    if (acc.depth >= kOpaqueDepth) return;
    const SegmentLight piece = integrate(length * (cut.fb - cut.fa), e.ka, e.kb, e.ca, e.cb);
    acc = first ? piece : under(acc, piece);
    first = false;
  });
  return acc;
}

}  // namespace cellproj
