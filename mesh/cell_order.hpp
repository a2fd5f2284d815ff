#pragma once
// Cells renumbered for memory locality. The visibility order sweeps through space, so the cells it
// visits one after another are near each other; in a mesh numbered at random their connectivity,
// offsets and types sit on cache lines far apart, one miss each. Measured on the 1M box with its
// cells shuffled (docs/methods.md, "Cell numbering"): the sort took 1.7 to 4 times as long and
// pt-linear's frame 1.4 to 1.5 times. A renderer renumbers its copy of such a mesh's cells along a
// Z-order (Morton) curve through their centroids; points keep their numbers (the face splits'
// diagonals go from each face's lowest-numbered vertex, so the picture stays the same).
#include <cstdint>
#include <vector>

#include "mesh/mesh.hpp"

namespace cellproj {

// Above this numbering_spread a mesh's cells are renumbered: a mesh numbered along a sweep or a
// curve through space stays near 1 (the generated 1M box: 1.08), one numbered at random reaches
// about half its cells' count to the power 1/3 (47 for the 1M box shuffled; 8 at some 4,000 cells,
// whose arrays the caches hold anyway, so renumbering them costs little and changes little).
constexpr double kLocalSpread = 8.0;

// How far apart consecutive cells lie: the mean distance between the centroids of cells c and c + 1,
// over the mean distance from a cell's centroid to its vertices. 0 for fewer than two cells.
double numbering_spread(const MeshView& mesh);

// The cells in the order of a Z-order (Morton) curve through their centroids, 21 bits an axis over
// the points' box, ties in cell order: the same for any number of threads. (CGAL's hilbert_sort
// of the 1M box's centroids took 0.31-0.34 s on one thread through its index map, these keys and a
// parallel sort 0.03-0.07 s: bench/cell_order.sh.)
std::vector<std::int64_t> morton_cell_order(const MeshView& mesh);

// The mesh with its cells renumbered along morton_cell_order where numbering_spread exceeds
// max_spread (the arrays owned here), else the mesh itself (a view of the caller's arrays).
class LocalCells {
 public:
  explicit LocalCells(const MeshView& mesh, double max_spread = kLocalSpread);
  LocalCells(const LocalCells&) = delete;  // view() points into this object's arrays,
  LocalCells& operator=(const LocalCells&) = delete;
  LocalCells(LocalCells&&) noexcept = default;  // which a move hands over in place
  LocalCells& operator=(LocalCells&&) noexcept = default;
  const MeshView& view() const { return view_; }
  bool renumbered() const { return renumbered_; }
  double spread() const { return spread_; }  // the input's numbering_spread

 private:
  std::vector<std::int64_t> offsets_, connectivity_;
  std::vector<std::uint8_t> types_;
  MeshView view_;
  bool renumbered_ = false;
  double spread_ = 0.0;
};

}  // namespace cellproj
