#include "mesh/cell_order.hpp"

#include <algorithm>
#include <limits>
#include <memory>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_sort.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "mesh/geometry.hpp"

namespace cellproj {
namespace {

// The mean distance from the cell's centroid to its vertices.
double cell_radius(const MeshView& mesh, std::int64_t c, const glm::dvec3& centre) {
  const std::int64_t* id = mesh.cell(c);
  const int n = mesh.cell_size(c);
  double sum = 0.0;
  for (int k = 0; k < n; ++k) sum += glm::distance(mesh.point(id[k]), centre);
  return sum / n;
}

// x's low 21 bits spread to every third bit (bit k to bit 3k): one axis of a Morton code.
std::uint64_t spread_bits(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffff;
  x = (x | x << 16) & 0x1f0000ff0000ff;
  x = (x | x << 8) & 0x100f00f00f00f00f;
  x = (x | x << 4) & 0x10c30c30c30c30c3;
  return (x | x << 2) & 0x1249249249249249;
}

struct Keyed {  // a cell and its Morton code (no initializer: 16 MB for 1M cells, written once)
  std::uint64_t key;
  std::int64_t cell;
  bool operator<(const Keyed& o) const { return key < o.key || (key == o.key && cell < o.cell); }
};

}  // namespace

double numbering_spread(const MeshView& mesh) {
  if (mesh.n_cells < 2) return 0.0;
  // Every 17th pair of neighbours in the numbering (all of them for a small mesh): a mean, cheap; a
  // prime step, so that the period of a structured numbering (6 tetrahedra a cube) does not alias.
  const std::int64_t pairs = mesh.n_cells - 1, step = pairs >= 65536 ? 17 : 1, samples = (pairs + step - 1) / step;
  using Sums = std::pair<double, double>;  // steps between consecutive centroids, cell radii
  const Sums sums = tbb::parallel_deterministic_reduce(
      tbb::blocked_range<std::int64_t>(0, samples, 1024), Sums{0.0, 0.0},
      [&](const tbb::blocked_range<std::int64_t>& r, Sums s) {
        for (std::int64_t k = r.begin(); k < r.end(); ++k) {
          const std::int64_t c = k * step;
          const glm::dvec3 here = cell_centroid(mesh, c);
          s.first += glm::distance(here, cell_centroid(mesh, c + 1)), s.second += cell_radius(mesh, c, here);
        }
        return s;
      },
      [](Sums a, const Sums& b) {
        return Sums{a.first + b.first, a.second + b.second};
      });
  return sums.second > 0.0 ? sums.first / sums.second : 0.0;  // (both sums over the same cells)
}

std::vector<std::int64_t> morton_cell_order(const MeshView& mesh) {
  const auto n = static_cast<std::size_t>(mesh.n_cells);
  // (a pair, not a structured binding: C++17 lambdas may not capture bindings, and clang says so)
  const std::pair<glm::dvec3, glm::dvec3> box = point_bounds(mesh);  // (it holds the centroids)
  const glm::dvec3 lo = box.first, extent = box.second - box.first;
  static constexpr double kTop = 2097151.0;  // 2^21 - 1: 21 bits an axis
  const double unit = std::max({extent.x, extent.y, extent.z}) / kTop;
  const std::unique_ptr<Keyed[]> keyed(new Keyed[n]);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t c) {
    const glm::dvec3 q = unit > 0 ? (cell_centroid(mesh, static_cast<std::int64_t>(c)) - lo) / unit : glm::dvec3(0.0);
    // (NaN, of a trusted mesh's bad point, to 0: a key, not a cast of NaN)
    const auto bits = [](double v) { return spread_bits(v > 0 ? static_cast<std::uint64_t>(std::min(v, kTop)) : 0); };
    keyed[c] = Keyed{bits(q.x) | bits(q.y) << 1 | bits(q.z) << 2, static_cast<std::int64_t>(c)};
  });
  tbb::parallel_sort(keyed.get(), keyed.get() + n);  // (ties in cell order: the same for any thread count)
  std::vector<std::int64_t> order(n);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t k) { order[k] = keyed[k].cell; });
  return order;
}

LocalCells::LocalCells(const MeshView& mesh, double max_spread) : view_(mesh), spread_(numbering_spread(mesh)) {
  if (!(spread_ > max_spread)) return;
  const std::vector<std::int64_t> order = morton_cell_order(mesh);
  const std::size_t n = order.size();
  offsets_.resize(n + 1), types_.resize(n);
  offsets_[0] = 0;
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t k) { offsets_[k + 1] = mesh.cell_size(order[k]); });
  for (std::size_t k = 0; k < n; ++k) offsets_[k + 1] += offsets_[k];  // (the scattered reads above in parallel)
  connectivity_.resize(static_cast<std::size_t>(offsets_[n]));
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t k) {
    const std::int64_t c = order[k];
    std::copy_n(mesh.cell(c), mesh.cell_size(c), connectivity_.begin() + offsets_[k]);
    types_[k] = mesh.types[c];
  });
  view_.connectivity = connectivity_.data(), view_.offsets = offsets_.data(), view_.types = types_.data();
  renumbered_ = true;
}

}  // namespace cellproj
