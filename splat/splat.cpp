#include "splat/splat.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace cellproj {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Where a splat's tau has fallen to this, it is cut off: its light beyond is below 1e-4 of the
// total for any peak (the cutoff grows with the peak's logarithm).
constexpr double kTailTau = 1e-5;
// The kernel is the cell's covariance times this: a uniform cell of length L has variance L^2 / 12,
// and Gaussians that narrow, one per cell of a row, sum to a ripple of 38%; at L^2 / 4 the ripple
// is 1.5% (2 exp(-2 pi^2 sigma^2 / L^2), Poisson summation), the "sum to near unity" of MWSC
// section 6.
constexpr double kKernelScale = 3.0;
constexpr double kMinCutoff = 18.4;  // exp(-18.4 / 2) = 1e-4: the share of the light cut off when thin

}  // namespace

SplatOptics splat_optics(const std::int64_t* ids, CellType type, const RecentredPoints& points, const double* scalar,
                         const TransferFunction& tf) {
  const glm::dvec3 o = points(ids[0]);
  auto value = [&](std::int64_t p) { return scalar ? scalar[p] : 0.0; };  // null: zeros, as ScreenPoints
  const double s0 = value(ids[0]);
  double depth = 0.0;
  glm::dvec3 light(0.0);
  constexpr double kA = 0.5854101966249685, kB = 0.1381966011250105;  // Keast's 4-point rule
  for_each_fan_tet(ids, type, [&](std::int64_t q0, std::int64_t q1, std::int64_t q2) {
    const glm::dvec3 a = points(q0) - o, b = points(q1) - o, c = points(q2) - o;
    const double v = std::abs(glm::dot(a, glm::cross(b, c))) / 6.0;
    const double s[4] = {s0, value(q0), value(q1), value(q2)};
    for (int q = 0; q < 4; ++q) {
      double sq = 0.0;
      for (int k = 0; k < 4; ++k) sq += (k == q ? kA : kB) * s[k];
      const double kappa = tf.extinction(sq);
      depth += 0.25 * v * kappa, light += (0.25 * v * kappa) * tf.color(sq);
    }
  });
  SplatOptics out;
  out.optical_depth = depth;
  out.color = depth > 0.0 ? light / depth : glm::dvec3(0.0);
  return out;
}

Footprint project_splat(const CellMoments& m, const SplatOptics& optics, const PixelRays& rays, double prefilter) {
  Footprint f;
  double x, y, z;
  rays.project(m.centre, x, y, z);
  f.depth = z, f.world = m.centre;
  f.behind_eye = behind_eye(z);
  if (f.behind_eye || !(optics.optical_depth > 0.0)) return f;
  const std::array<glm::dvec3, 3> j = rays.ray_space_jacobian(m.centre);
  const glm::dmat3 sigma = kKernelScale * m.covariance;
  const glm::dvec3 s0 = sigma * j[0], s1 = sigma * j[1];  // Sigma is symmetric
  const double h = prefilter * prefilter;
  f.covariance = glm::dmat2(glm::dot(j[0], s0) + h, glm::dot(j[1], s0), glm::dot(j[0], s1), glm::dot(j[1], s1) + h);
  const double det = glm::determinant(f.covariance);
  if (!(det > 0.0) || !std::isfinite(det)) return f;
  f.conic = glm::inverse(f.covariance);
  f.centre = glm::dvec2(x, y);
  // The ellipsoid's kappa V over the ray-space volume per world volume, |det J|: the integral of
  // tau over the image in pixels (Zwicker et al. section 4: a Gaussian stays normalised under the
  // affine map, so its marginal along t integrates to the total).
  f.total = optics.optical_depth * std::abs(glm::dot(j[0], glm::cross(j[1], j[2])));
  f.peak = f.total / (2.0 * kPi * std::sqrt(det));
  f.cutoff = std::max(kMinCutoff, 2.0 * std::log(f.peak / kTailTau));
  f.color = optics.color;
  f.visible = std::isfinite(f.peak) && f.peak > 0.0;
  return f;
}

PixelBox Footprint::pixels(int width, int height) const {
  PixelBox box;
  if (!visible) return box;
  const double rx = std::sqrt(cutoff * covariance[0][0]), ry = std::sqrt(cutoff * covariance[1][1]);
  box.i0 = std::max(PixelBox::clamped(std::ceil(centre.x - rx - 0.5), width), 0);
  box.i1 = std::min(PixelBox::clamped(std::floor(centre.x + rx - 0.5), width), width - 1);
  box.j0 = std::max(PixelBox::clamped(std::ceil(centre.y - ry - 0.5), height), 0);
  box.j1 = std::min(PixelBox::clamped(std::floor(centre.y + ry - 0.5), height), height - 1);
  return box;
}

Footprint cell_splat(const SplatContext& frame, const std::int64_t* ids, CellType type, SplatCounters& c) {
  const CellMoments m = cell_moments(ids, type, frame.points);
  const SplatRefusal why = refusal(m);
  if (why != SplatRefusal::none) {
    ++(why == SplatRefusal::inverted ? c.refused_inverted : c.refused_degenerate);
    return {};
  }
  const Footprint f =
      project_splat(m, splat_optics(ids, type, frame.points, frame.scalar, frame.tf), frame.rays, frame.prefilter);
  c.behind_eye += f.behind_eye, c.splats += f.visible;
  return f;
}

}  // namespace cellproj
