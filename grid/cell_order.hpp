#pragma once
// Cells renumbered for memory locality. The visibility order sweeps through space, so the cells it
// visits one after another are near each other; in a mesh numbered at random their connectivity,
// offsets and types sit on cache lines far apart, one miss each. Measured on the 1M box with its
// cells shuffled (docs/methods.md, "Cell numbering"): the sort took 1.7 to 4 times as long and
// pt-linear's frame 1.4 to 1.5 times. A renderer renumbers its copy of such a mesh's cells along a
// Z-order (Morton) curve through their centroids. Points keep their numbers (the face splits'
// diagonals go from each face's lowest-numbered vertex, so the picture stays the same), except in
// a mesh of tetrahedra, which has no face split: there the projection renderer renumbers scattered
// points too (a Delaunay cloud's: 0.8 of pt-linear's frame).
#include <cstdint>
#include <vector>

#include "grid/mesh.hpp"

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

// The same for points: the mean distance between consecutive points over the mean cell radius.
double point_numbering_spread(const MeshView& mesh);
std::vector<std::int64_t> morton_point_order(const MeshView& mesh);

// The mesh with its cells renumbered along morton_cell_order where numbering_spread exceeds
// max_spread, and with `points` its points along morton_point_order where
// point_numbering_spread does, for a mesh of tetrahedra only (other cells' face splits go by point
// numbers: renumbered points would move them); the arrays owned here. Else the mesh itself (a
// view of the caller's arrays). With points renumbered, a point field must be read through
// point_order(): the renderer gathers each frame's field.
class LocalCells {
 public:
  explicit LocalCells(const MeshView& mesh, double max_spread = kLocalSpread, bool points = false);
  LocalCells(const LocalCells&) = delete;  // view() points into this object's arrays,
  LocalCells& operator=(const LocalCells&) = delete;
  LocalCells(LocalCells&&) noexcept = default;  // which a move hands over in place
  LocalCells& operator=(LocalCells&&) noexcept = default;
  const MeshView& view() const { return view_; }
  bool renumbered() const { return renumbered_; }  // the cells
  double spread() const { return spread_; }        // the input's numbering_spread
  bool points_renumbered() const { return !point_order_.empty(); }
  double point_spread() const { return point_spread_; }  // 0 unless points were considered
  // Point k here is the input's point_order()[k] (points renumbered only).
  const std::vector<std::int64_t>& point_order() const { return point_order_; }

 private:
  std::vector<std::int64_t> offsets_, connectivity_, point_order_;
  std::vector<std::uint8_t> types_;
  std::vector<double> points_;
  MeshView view_;
  bool renumbered_ = false;
  double spread_ = 0.0, point_spread_ = 0.0;
};

}  // namespace cellproj
