#pragma once
// Colour by one field, extinction by another (ParaView's separate opacity array). Both are linear
// over a tetrahedron, so along a ray segment through it the colour field u and the opacity field s
// both run linearly: cut where either meets a breakpoint of its own half of the transfer function,
// each piece has colour and extinction linear in its length, and its light is the one-field
// integral of Williams and Max (MWSC section 4), exact.
#include <algorithm>
#include <cstddef>
#include <string>

#include "base/error.hpp"
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

// The refusal of two fields where `by` (a method, a back end, splats) cannot draw them: the
// opacity field named when known.
UnsupportedError two_fields_refused(const std::string& opacity_field, const std::string& by);

// ---- implementation

namespace detail {
// The breakpoints of one half met by a field running from a (front) to b (back), in the order the
// field meets them, and the breakpoint interval each piece between them lies in (as
// for_each_linear_piece walks them: piece_in, no search per piece).
class HalfCuts {
 public:
  HalfCuts(const TransferFunction& tf, double a, double b)
      : tf_(tf),
        a_(a),
        b_(b),
        first_(tf.breakpoints_not_above(std::min(a, b))),
        last_(tf.breakpoints_below(std::max(a, b))),
        up_(b >= a) {}
  bool more() const { return first_ + passed_ < last_; }  // a breakpoint ahead
  // The fraction of the segment at the next breakpoint (more() only): strictly inside, so b != a.
  double next() const { return (tf_.breakpoints()[up_ ? first_ + passed_ : last_ - 1 - passed_] - a_) / (b_ - a_); }
  void pass() { ++passed_; }
  // The piece [fa, fb] of the segment, between the breakpoints passed and the next.
  TransferFunction::Ends piece(double fa, double fb) const {
    const std::size_t interval = up_ ? first_ + passed_ : std::max(first_, last_) - passed_;
    return tf_.piece_in(interval, a_ + fa * (b_ - a_), a_ + fb * (b_ - a_));
  }

 private:
  const TransferFunction& tf_;
  double a_, b_;
  std::size_t first_, last_;  // breakpoints first_ .. last_ - 1 lie strictly between a and b
  bool up_;
  std::size_t passed_ = 0;
};
}  // namespace detail

template <class Piece>
void for_each_two_field_piece(const TwoFieldTransfer& tf, double u0, double u1, double s0, double s1, Piece&& piece) {
  // Both halves' breakpoints merged as the segment meets them (each half's in order already).
  detail::HalfCuts color(tf.color, u0, u1), extinction(tf.extinction, s0, s1);
  double fa = 0.0;
  for (;;) {
    const bool c = color.more(), e = extinction.more();
    const double fc = c ? color.next() : 1.0, fe = e ? extinction.next() : 1.0, fb = std::min(fc, fe);
    if (fb > fa) {  // (a breakpoint met by both fields at once makes no piece)
      const TransferFunction::Ends ce = color.piece(fa, fb), ke = extinction.piece(fa, fb);
      piece(TransferFunction::Ends{ce.ca, ce.cb, ke.ka, ke.kb}, FieldPieceCut{fa, fb});
      fa = fb;
    }
    if (!c && !e) return;
    (c && (!e || fc <= fe) ? color : extinction).pass();
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
