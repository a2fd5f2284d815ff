#include "optics/auto_opacity.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "mesh/geometry.hpp"

namespace cellproj {
namespace {

constexpr int kBins = 64;                   // of the histogram, and of the picture's longer side
constexpr double kFloor = 0.05;             // auto's relative extinction at the background's values
constexpr double kDominant = 0.35;          // the share of the volume that makes a value the background
constexpr std::int64_t kSampled = 1 << 20;  // cells looked at, at most (every k-th beyond)
const double kFaint = -std::log(0.95), kOpaque = -std::log(0.05);  // optical depths of alpha 0.05, 0.95

// Every k-th cell, so that at most kSampled are looked at, each standing for k (its weight): its
// field (the mean of its vertices') and its volume, found once for the shape and the scale.
struct SampledCells {
  std::int64_t step = 1;
  double weight = 1.0;
  std::vector<double> mean, volume;  // of cells 0, step, 2 step, ...
};
SampledCells sample_cells(const MeshView& mesh, const double* field) {
  SampledCells s;
  s.step = std::max<std::int64_t>(1, mesh.n_cells / kSampled), s.weight = static_cast<double>(s.step);
  for (std::int64_t c = 0; c < mesh.n_cells; c += s.step) {
    const std::int64_t* ids = mesh.cell(c);
    double sum = 0;
    for (int k = 0; k < mesh.cell_size(c); ++k) sum += field[ids[k]];
    s.mean.push_back(sum / mesh.cell_size(c));
    s.volume.push_back(std::abs(cell_signed_volume(mesh, c)));
  }
  return s;
}

double shape_at(const std::vector<ExtinctionPoint>& shape, double s) {
  if (s <= shape.front().s) return shape.front().kappa;
  for (std::size_t i = 1; i < shape.size(); ++i)
    if (s <= shape[i].s) {
      const double w = shape[i].s > shape[i - 1].s ? (s - shape[i - 1].s) / (shape[i].s - shape[i - 1].s) : 1.0;
      return shape[i - 1].kappa + w * (shape[i].kappa - shape[i - 1].kappa);
    }
  return shape.back().kappa;
}

// 17 points of f(t), t in [0, 1], over [lo, hi], scaled so that the largest is 1.
template <class F>
std::vector<ExtinctionPoint> sampled(double lo, double hi, F f) {
  std::vector<ExtinctionPoint> out;
  for (int k = 0; k <= 16; ++k) out.push_back({lo + k / 16.0 * (hi - lo), f(k / 16.0)});
  const double top =
      std::max_element(out.begin(), out.end(), [](auto& a, auto& b) { return a.kappa < b.kappa; })->kappa;
  for (auto& p : out) p.kappa /= top;
  return out;
}

}  // namespace

std::string opacity_names() { return "auto, ramp, reverse, flat, sigmoid, geometric"; }

std::vector<ExtinctionPoint> opacity_shape(const std::string& name, double lo, double hi) {
  if (name == "ramp") return {{lo, 0.0}, {hi, 1.0}};
  if (name == "reverse") return {{lo, 1.0}, {hi, 0.0}};
  if (name == "flat") return {{lo, 1.0}, {hi, 1.0}};
  if (name == "sigmoid") return sampled(lo, hi, [](double t) { return 1.0 / (1.0 + std::exp(-12.0 * (t - 0.5))); });
  if (name == "geometric") return sampled(lo, hi, [](double t) { return (std::pow(100.0, t) - 1.0) / 99.0; });
  return {};
}

namespace {

AutoShape shape_of(const SampledCells& cells, double lo, double hi) {
  AutoShape out;
  out.background_lo = hi, out.background_hi = lo;
  if (!(hi > lo)) {
    out.points = {{lo, 1.0}};
    return out;
  }
  // The field's histogram over the mesh's volume (each cell at its vertices' mean).
  std::vector<double> h(kBins, 0.0);
  for (std::size_t k = 0; k < cells.mean.size(); ++k)
    h[std::clamp(static_cast<int>((cells.mean[k] - lo) / (hi - lo) * kBins), 0, kBins - 1)] += cells.volume[k];
  double total = 0;
  for (double v : h) total += v;
  const int mode = static_cast<int>(std::max_element(h.begin(), h.end()) - h.begin());
  int a = mode, b = mode;  // the peak around the mode: the bins above a fifth of its height
  while (a > 0 && h[a - 1] >= 0.2 * h[mode]) --a;
  while (b + 1 < kBins && h[b + 1] >= 0.2 * h[mode]) ++b;
  double share = 0;
  for (int k = a; k <= b; ++k) share += h[k];
  share = total > 0 ? share / total : 0;
  const double bin = (hi - lo) / kBins, from = lo + a * bin, to = lo + (b + 1) * bin;
  if (share < kDominant || (a == 0 && b == kBins - 1)) {  // no background: a ramp over a faint floor
    out.points = {{lo, kFloor}, {hi, 1.0}};
    return out;
  }
  out.background_lo = from, out.background_hi = to, out.background_share = share;
  // Faint over the background's values, rising to 1 at whichever ends of the range lie beyond them.
  if (a > 0) out.points.push_back({lo, 1.0});
  out.points.push_back({from, kFloor});
  out.points.push_back({to, kFloor});
  if (b + 1 < kBins) out.points.push_back({hi, 1.0});
  return out;
}

FootprintScale scale_of(const MeshView& mesh, const SampledCells& cells, const std::vector<ExtinctionPoint>& shape,
                        const glm::dvec3& from, const glm::dvec3& up) {
  // The mesh seen orthographically from `from`, in bins, kBins along the longer side of its
  // projected box; each bin's optical depth at scale 1 is the extinction integrated over the cells
  // behind it (kappa V, spread over the bins their corners span) over its area.
  const glm::dvec3 w = glm::normalize(from), e1 = glm::normalize(glm::cross(up, w)), e2 = glm::cross(w, e1);
  const auto [blo, bhi] = point_bounds(mesh);
  const double diagonal = glm::length(bhi - blo);
  double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 p{k & 1 ? bhi.x : blo.x, k & 2 ? bhi.y : blo.y, k & 4 ? bhi.z : blo.z};
    u0 = std::min(u0, glm::dot(p, e1)), u1 = std::max(u1, glm::dot(p, e1));
    v0 = std::min(v0, glm::dot(p, e2)), v1 = std::max(v1, glm::dot(p, e2));
  }
  const double bin = std::max(u1 - u0, v1 - v0) / kBins;
  if (!(bin > 0) || mesh.n_cells == 0) return {20.0 / (diagonal > 0 ? diagonal : 1.0), 0.0};
  const int nu = std::clamp(static_cast<int>(std::ceil((u1 - u0) / bin)), 1, kBins),
            nv = std::clamp(static_cast<int>(std::ceil((v1 - v0) / bin)), 1, kBins);
  std::vector<double> tau(static_cast<std::size_t>(nu) * nv, 0.0);
  std::vector<char> covered(tau.size(), 0);
  for (std::size_t n = 0; n < cells.mean.size(); ++n) {
    const std::int64_t c = static_cast<std::int64_t>(n) * cells.step;
    double cu0 = u1, cu1 = u0, cv0 = v1, cv1 = v0;
    const std::int64_t* ids = mesh.cell(c);
    for (int k = 0; k < mesh.cell_size(c); ++k) {
      const glm::dvec3 p = mesh.point(ids[k]);
      const double pu = glm::dot(p, e1), pv = glm::dot(p, e2);
      cu0 = std::min(cu0, pu), cu1 = std::max(cu1, pu), cv0 = std::min(cv0, pv), cv1 = std::max(cv1, pv);
    }
    // The bins the cell's box overlaps (one at least): [floor(a), ceil(b) - 1].
    const int i0 = std::clamp(static_cast<int>((cu0 - u0) / bin), 0, nu - 1),
              i1 = std::clamp(static_cast<int>(std::ceil((cu1 - u0) / bin)) - 1, i0, nu - 1);
    const int j0 = std::clamp(static_cast<int>((cv0 - v0) / bin), 0, nv - 1),
              j1 = std::clamp(static_cast<int>(std::ceil((cv1 - v0) / bin)) - 1, j0, nv - 1);
    const double depth =
        shape_at(shape, cells.mean[n]) * cells.volume[n] * cells.weight / (bin * bin * (i1 - i0 + 1) * (j1 - j0 + 1));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        tau[static_cast<std::size_t>(j) * nu + i] += depth;
        covered[static_cast<std::size_t>(j) * nu + i] = 1;
      }
  }
  std::vector<double> seen;
  std::size_t footprint = 0;
  for (std::size_t k = 0; k < tau.size(); ++k)
    if (covered[k]) {
      ++footprint;
      if (tau[k] > 0) seen.push_back(tau[k]);
    }
  if (seen.empty()) return {20.0 / (diagonal > 0 ? diagonal : 1.0), 0.0};
  // The window of depths [t, t * kOpaque / kFaint) holding the most bins; the scale puts its median
  // bin at the geometric middle of (kFaint, kOpaque), as far as the window's ends stay inside.
  std::sort(seen.begin(), seen.end());
  std::size_t best = 0, best_i = 0, best_j = 1;
  for (std::size_t i = 0, j = 0; i < seen.size(); ++i) {
    j = std::max(j, i + 1);
    while (j < seen.size() && seen[j] < seen[i] * (kOpaque / kFaint)) ++j;
    if (j - i > best) best = j - i, best_i = i, best_j = j;
  }
  const double median = seen[(best_i + best_j - 1) / 2];
  const double kappa = std::clamp(std::sqrt(kFaint * kOpaque) / median, kFaint / seen[best_i],
                                  std::max(kFaint / seen[best_i], kOpaque / seen[best_j - 1]));
  return {kappa, static_cast<double>(best) / static_cast<double>(footprint)};
}

}  // namespace

AutoShape auto_shape(const MeshView& mesh, const double* field, double lo, double hi) {
  return shape_of(sample_cells(mesh, field), lo, hi);
}

FootprintScale footprint_scale(const MeshView& mesh, const double* field, const std::vector<ExtinctionPoint>& shape,
                               const glm::dvec3& from, const glm::dvec3& up) {
  return scale_of(mesh, sample_cells(mesh, field), shape, from, up);
}

std::vector<ExtinctionPoint> auto_extinction(const MeshView& mesh, const double* field, const glm::dvec3& from,
                                             const glm::dvec3& up) {
  const auto [lo, hi] = std::minmax_element(field, field + mesh.n_points);
  const SampledCells cells = sample_cells(mesh, field);
  std::vector<ExtinctionPoint> points = shape_of(cells, *lo, *hi).points;
  const double kappa = scale_of(mesh, cells, points, from, up).kappa;
  for (ExtinctionPoint& p : points) p.kappa *= kappa;
  return points;
}

}  // namespace cellproj
