#pragma once
// Cutting the slice cells by the planes of a frame, into flat arrays of polygons per plane, ready
// to scan convert (internal to slicing/).
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "slicing/slice_cells.hpp"
#include "slicing/slice_planes.hpp"

namespace cellproj {

// Each point in this frame: its height along the planes' normal, and hx, hy, z (PixelRays::
// project_homogeneous, affine in the point) with its scalar s, so that a crossing on an edge is
// interpolated in these four and divided by z only at the end.
struct FramePoints {
  std::vector<double> height;
  std::vector<glm::dvec4> screen;  // hx, hy, z, s
  bool perspective = false;
  double near = 0.0;  // perspective: polygons are clipped to z >= near
};

// An attribute a interpolated perspective-correctly at barycentric weights l: the weighted a / z
// over the weighted 1 / z (aw and w at the three corners).
inline double perspective_correct(double l0, double l1, double l2, const double aw[3], const double w[3]) {
  return (l0 * aw[0] + l1 * aw[1] + l2 * aw[2]) / (l0 * w[0] + l1 * w[1] + l2 * w[2]);
}

// The section polygons of one plane: polygon q's vertices are start[q] <= v < start[q + 1]; pixel
// position x, y, w = 1 / z (1 in orthographic projection) and s w, for perspective-correct
// interpolation of the scalar.
struct SlicePolygons {
  std::vector<double> x, y, w, sw;
  std::vector<std::uint32_t> start{0};
  std::int64_t clipped = 0;  // polygons clipped at the near plane (some of them to nothing)

  std::size_t size() const { return start.size() - 1; }
  std::size_t bytes() const { return x.size() * 4 * sizeof(double) + start.size() * sizeof(std::uint32_t); }
  void clear() { x.clear(), y.clear(), w.clear(), sw.clear(), start.assign(1, 0), clipped = 0; }
  void append(const SlicePolygons& other);
};

// The planes crossing each slice cell in this frame, and the sweep over them (Yagel et al.'s active
// cell list): the cells a run of planes crosses, in an order that does not depend on the threads.
class CellSweep {
 public:
  CellSweep(const SliceCells& cells, const FramePoints& points, const SlicePlanes& planes);
  // Leaves out the cells with skip[c] set (small cells drawn by their splat, or not at all), before
  // the first advance().
  void drop(const std::vector<char>& skip);
  // The cells crossing any plane first <= j < end; runs must come in increasing order.
  const std::vector<std::int64_t>& advance(int first, int end);
  std::int64_t between_planes() const { return between_; }  // cells no plane crosses: thinner than the spacing
  int first(std::int64_t c) const { return range_[static_cast<std::size_t>(c)].first; }
  int last(std::int64_t c) const { return range_[static_cast<std::size_t>(c)].last; }

 private:
  struct Range {
    int first, last;
  };
  std::vector<Range> range_;
  std::vector<std::int64_t> by_first_;  // cells by their first plane (then by index)
  std::size_t entered_ = 0;             // of by_first_, those already in active_ (or passed)
  std::vector<std::int64_t> active_;
  std::int64_t between_ = 0;
};

// The polygons of the cells `active` on planes first <= j < end, for the planes whose
// `wanted[j - first]` is set: blocks[b][j - first] holds those of the b-th block of cells, so a
// plane's polygons are its entries of every block, in the cells' order whatever the thread count.
// `blocks` is kept from call to call (its arrays keep their memory). Each edge crossing is stepped
// from the edge's first plane (Yagel): the same bits for every cell sharing the edge, so
// neighbouring sections meet without cracks.
using CutBlocks = std::vector<std::vector<SlicePolygons>>;
void cut_planes(const SliceCells& cells, const FramePoints& points, const SlicePlanes& planes, const CellSweep& sweep,
                const std::vector<std::int64_t>& active, int first, int end, const std::vector<char>& wanted,
                CutBlocks& blocks);

}  // namespace cellproj
