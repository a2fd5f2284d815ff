// What the cells' renumbering costs (mesh/cell_order.hpp) on a mesh file, and CGAL's Hilbert sort
// of the same centroids beside the Morton keys it was chosen over: the median of `runs` calls of
// each, in seconds, on the threads oneTBB gives (bench/cell_order.sh).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include "io/read_mesh.hpp"
#include "mesh/cell_order.hpp"
#include "mesh/geometry.hpp"

using namespace cellproj;

double median_seconds(int runs, const std::function<void()>& f) {
  std::vector<double> t;
  for (int r = 0; r < runs; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::nth_element(t.begin(), t.begin() + runs / 2, t.end());
  return t[runs / 2];
}

int main(int argc, char** argv) {
  if (argc < 2) return std::fprintf(stderr, "usage: cell_order MESH [RUNS]\n"), 2;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
  const Mesh mesh = read_mesh(argv[1]);
  const MeshView v = mesh.view();
  double spread = 0;
  const double t_spread = median_seconds(runs, [&] { spread = numbering_spread(v); });
  const double t_morton = median_seconds(runs, [&] { morton_cell_order(v); });
  const double t_local = median_seconds(runs, [&] { LocalCells copy(v, 0.0); });  // (renumbered whatever the spread)
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Kernel::Point_3> centres(static_cast<std::size_t>(v.n_cells));
  for (std::int64_t c = 0; c < v.n_cells; ++c) {
    const glm::dvec3 p = cell_centroid(v, c);
    centres[static_cast<std::size_t>(c)] = {p.x, p.y, p.z};
  }
  using Traits = CGAL::Spatial_sort_traits_adapter_3<Kernel, CGAL::Pointer_property_map<Kernel::Point_3>::type>;
  const double t_hilbert = median_seconds(runs, [&] {
    std::vector<std::size_t> order(centres.size());
    for (std::size_t c = 0; c < order.size(); ++c) order[c] = c;
    CGAL::hilbert_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(centres)),
                       CGAL::Hilbert_sort_median_policy());
  });
  std::printf("%s: %lld cells, numbering_spread %.3g\n", argv[1], static_cast<long long>(v.n_cells), spread);
  std::printf("  numbering_spread %.4f s, morton_cell_order %.4f s, LocalCells (spread, order, copy) %.4f s\n",
              t_spread, t_morton, t_local);
  std::printf("  CGAL hilbert_sort of the centroids (one thread, its index map; centroids not counted) %.4f s\n",
              t_hilbert);
}
