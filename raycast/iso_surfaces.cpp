#include "raycast/iso_surfaces.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "base/timing.hpp"
#include "optics/segment_integral.hpp"
#include "raycast/volume_union.hpp"

namespace cellproj {
namespace {

void check_unit(double v, const std::string& what) {
  if (!(v >= 0.0 && v <= 1.0))
    throw InputError("setting 'iso': " + what + " must be in [0, 1], got " + std::to_string(v));
}

}  // namespace

void check(const IsoOptions& o) {
  for (const IsoSurface& s : o.surfaces) {
    if (!std::isfinite(s.value)) throw InputError("setting 'iso': the iso-value must be a finite number");
    for (int c = 0; c < 3; ++c) check_unit(s.color[c], "colour components");
    check_unit(s.opacity, "the opacity");
  }
}

double iso_opacity(IsoOpacity model, double a, double c, double fit_exponent) {
  c = std::clamp(c, 1e-6, 1.0);
  switch (model) {
    case IsoOpacity::constant: return a;
    case IsoOpacity::spectrum:  // Roettger section 4: alpha = 1 - exp(-c d / |cos t|), exp(-c d) = 1 - a head-on
      return a >= 1.0 ? 1.0 : -std::expm1(std::log1p(-a) / c);
    case IsoOpacity::spectrum_fit: return a >= 1.0 ? 1.0 : 1.0 - (1.0 - a) * std::pow(c, fit_exponent);
  }
  return a;
}

double spectrum_fit_exponent(double a, double* max_error) {
  // Least squares over c = (k + 1/2) / 256 of the fit against the formula, by golden section in p.
  const auto error = [a](double p, double* worst) {
    double sum = 0.0;
    for (int k = 0; k < 256; ++k) {
      const double c = (k + 0.5) / 256;
      const double d = (1.0 - a) * std::pow(c, p) - std::exp(std::log1p(-a) / c);
      sum += d * d;
      if (worst) *worst = std::max(*worst, std::abs(d));
    }
    return sum;
  };
  if (a <= 0.0 || a >= 1.0) {
    if (max_error) *max_error = 0.0;
    return 0.0;
  }
  double lo = 0.0, hi = 64.0;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 80; ++it) {
    const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    if (error(m1, nullptr) < error(m2, nullptr))
      hi = m2;
    else
      lo = m1;
  }
  const double p = 0.5 * (lo + hi);
  if (max_error) {
    *max_error = 0.0;
    error(p, max_error);
  }
  return p;
}

Image render_iso_surfaces(const CellRayTracer& tracer, const double* scalar, std::int64_t n_points,
                          const TransferFunction& tf, const Camera& camera, int width, int height, const IsoOptions& o,
                          IsoStats* stats, const std::function<void(double)>& progress) {
  check(o);
  const std::vector<VolumePart> one{{&tracer, scalar, n_points, &tf, o.surfaces, o.volume}};
  return render_volume_union(one, o.mode, o.opacity, camera, width, height, stats, progress);
}

}  // namespace cellproj
