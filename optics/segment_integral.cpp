#include "optics/segment_integral.hpp"

#include <algorithm>
#include <cmath>

namespace cellproj {
namespace {

// 8-point Gauss-Legendre nodes and weights on [-1, 1] (positive half).
constexpr double kNode[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
constexpr double kWeight[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

constexpr double kDepthStep = 0.25;  // optical depth per quadrature piece

}  // namespace

SegmentLight integrate_linear_reference(double L, double k0, double k1, const glm::dvec3& c0, const glm::dvec3& c1) {
  if (!(L > 0.0) || (k0 == 0.0 && k1 == 0.0)) return {};
  const double depth = 0.5 * (k0 + k1) * L;
  SegmentLight out;
  out.depth = depth;
  if (k0 == k1) {  // constant kappa, C linear: int_0^L C k e^{-kt} dt = c0 g(d) + c1 h(d), d = kL,
    // g = 1 - (1 - e^-d)/d and h = (1 - e^-d)/d - e^-d, by series where the closed form cancels.
    const double d = depth;
    double g, h;
    if (d < 1e-3) {
      g = d * (0.5 - d * (1.0 / 6 - d * (1.0 / 24 - d / 120)));
      h = d * (0.5 - d * (1.0 / 3 - d * (1.0 / 8 - d / 30)));
    } else {
      const double a = -std::expm1(-d) / d;
      g = 1.0 - a;
      h = a - std::exp(-d);
    }
    out.rgb = c0 * g + c1 * h;
    return out;
  }
  // tau(u) = L (k0 u + (k1 - k0) u^2 / 2) for u in [0, 1].
  auto tau = [&](double u) { return L * u * (k0 + 0.5 * (k1 - k0) * u); };
  const int pieces = std::max(1, static_cast<int>(std::ceil(depth / kDepthStep)));
  glm::dvec3 sum(0.0);
  for (int p = 0; p < pieces; ++p) {
    const double u0 = double(p) / pieces, u1 = double(p + 1) / pieces, half = 0.5 * (u1 - u0), mid = 0.5 * (u0 + u1);
    if (tau(u0) > kOpaqueDepth) break;
    for (int i = 0; i < 8; ++i) {
      const double u = mid + (i < 4 ? -kNode[i] : kNode[i - 4]) * half;
      const double w = kWeight[i < 4 ? i : i - 4] * half;
      const double k = k0 + (k1 - k0) * u;
      sum += w * k * std::exp(-tau(u)) * (c0 + (c1 - c0) * u);
    }
  }
  out.rgb = sum * L;
  return out;
}

SegmentLight integrate_segment_reference(const TransferFunction& tf, double length, double s0, double s1) {
  return integrate_pieces(tf, length, s0, s1, integrate_linear_reference);
}

}  // namespace cellproj
