#pragma once
// Pre-integrated slabs (Engel, Kraus and Ertl 2001; Kniss et al., ../shared/papers): the light of
// a ray segment between two slices along which the scalar runs linearly from s_front to s_back,
// integrated exactly (optics/linear_segment: cut at the transfer function's breakpoints, closed
// form per piece) and tabulated over (s_front, s_back). Few slices then still catch a thin feature
// of the transfer function that no slice samples.
//
// The segment's length differs per pixel (slanted and perspective rays), so the table is split the
// way the length enters: the optical depth is length times the mean extinction over [s_front,
// s_back] (exact, MWSC eq. for linear kappa), so the opacity 1 - exp(-l mean kappa) is computed per
// pixel; only the segment's mean colour (light over opacity), which varies slowly with the length,
// is tabulated at a few lengths and interpolated between them.
#include <vector>

#include "optics/transfer_function.hpp"

namespace cellproj {

class PreintegratedTable {
 public:
  // Scalars in [s_lo, s_hi] at size x size nodes; lengths in [l_lo, l_hi] at geometrically spaced
  // layers of the mean colour, as many as keep neighbouring layers within 20% of each other (one
  // when l_lo == l_hi: orthographic views). Built in parallel in the caller's task arena.
  PreintegratedTable(const TransferFunction& tf, double s_lo, double s_hi, double l_lo, double l_hi, int size);

  // Where a length falls between the layers (a fractional layer index), computed once per pixel.
  double layer_of(double length) const;
  // The segment's premultiplied light and opacity: mean extinction and colour bilinear in the
  // scalars, the colour linear in the layer.
  void operator()(double s_front, double s_back, double length, double layer, float rgba[4]) const;

  int size() const { return size_; }
  int layers() const { return layers_; }

 private:
  int size_, layers_;
  double s_lo_, s_scale_, l_lo_, log_ratio_;  // log_ratio_: log of the length ratio between layers
  std::vector<float> kappa_;                  // [back][front]: mean extinction
  std::vector<float> color_;                  // [layer][back][front][3]: light over opacity
};

}  // namespace cellproj
