#pragma once
// Closed forms for one ray segment along which extinction kappa and colour C vary linearly
// (Williams and Max 1992; MWSC section 2). With tau(t) the optical depth from the front,
//   int_0^L C kappa e^-tau dt = C0 (1 - F) + C1 (F - e^-D),   F = (1/L) int_0^L e^-tau dt,
// by parts (d/dt of -e^-tau is kappa e^-tau); only F needs special functions: erfcx when kappa
// grows along the ray, Dawson's integral when it falls.
#include <cstddef>

#include <glm/vec3.hpp>

#include "optics/segment_integral.hpp"

namespace cellproj {

// exp(x^2) erfc(x) for x >= 0, relative error below 1e-13 (no overflow for large x).
double erfcx(double x);
// Dawson's integral exp(-x^2) int_0^x exp(t^2) dt for x >= 0, relative error below 1e-13.
double dawson(double x);

// The weights of the two end colours: light = c0 * front + c1 * back (premultiplied).
struct EndWeights {
  double front = 0.0, back = 0.0;
  double depth = 0.0;     // optical depth of the whole segment
  double opacity = -1.0;  // 1 - e^-depth where it came with the weights (small cells), else -1
};
// kappa from k0 (front) to k1 (back), both >= 0, over length L. Stable from optical depth 1e-300
// (small cells, kappa L <= 0.5 and a change of at most 0.02 along the segment: Taylor series in
// both, relative error ~1e-15) to any depth (asymptotic forms; no NaN, weights -> 1, 0).
EndWeights linear_segment_weights(double L, double k0, double k1);
// The same for n segments (w[k] from L[k], k0[k], k1[k]), to the bit: the small cells, most
// fragments of a fine mesh, four at a time in SIMD registers.
void linear_segment_weights(std::size_t n, const double* L, const double* k0, const double* k1, EndWeights* w);
// The same where the arrays hold n rounded up to a multiple of 4 values: the last n % 4 small cells
// also go in lanes (the padding's values are read, its weights written and meaningless).
void linear_segment_weights_padded(std::size_t n, const double* L, const double* k0, const double* k1, EndWeights* w);

// The whole segment: kappa and colour linear from (k0, c0) at the front to (k1, c1) at the back.
inline SegmentLight integrate_linear_closed_form(double L, double k0, double k1, const glm::dvec3& c0,
                                                 const glm::dvec3& c1) {
  const EndWeights w = linear_segment_weights(L, k0, k1);
  return {c0 * w.front + c1 * w.back, w.depth, w.opacity};
}

// A segment along which the scalar runs linearly from s0 (front) to s1 (back), cut at the transfer
// function's breakpoints and each piece integrated in closed form: exact for any piecewise-linear
// transfer function (MWSC section 4).
SegmentLight integrate_segment_closed_form(const TransferFunction& tf, double length, double s0, double s1);

}  // namespace cellproj
