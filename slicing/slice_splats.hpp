#pragma once
// The small cells of a slice stack as splats (MWSC section 6, internal to slicing/): a slice cell
// whose volume is below the threshold times the spacing cubed, or which no plane crosses (it would
// add nothing, however large), is not cut; its EWA splat is drawn on
// the nearest plane, the splats of a plane back to front into that plane's splat layer, and only
// where the plane's polygons left the pixel empty (the paper's stencil rule), so a splat, enlarged
// by the pre-filter, adds nothing where the slab already holds the full opacity.
#include <cstdint>
#include <vector>

#include "slicing/slab_compositor.hpp"
#include "slicing/slice_cells.hpp"
#include "slicing/slice_cut.hpp"
#include "slicing/slice_planes.hpp"
#include "splat/splat.hpp"

namespace cellproj {

class SliceSplats {
 public:
  // The stack's small cells: volume[c] < threshold spacing^3 (of the slice cells, made once per
  // mesh) or between two planes (the sweep's ranges); their splats (counted) on planes 1..visible
  // (none for 0).
  SliceSplats(const SliceCells& cells, const std::vector<double>& volume, const CellSweep& sweep,
              const SplatContext& frame, const SlicePlanes& planes, int visible, double threshold);
  const std::vector<char>& small() const { return small_; }  // per slice cell: not cut
  bool any() const { return !splats_.empty(); }              // splats to draw
  // The splats of plane j, back to front.
  const Footprint* begin(int j) const { return splats_.data() + start_[static_cast<std::size_t>(j)]; }
  const Footprint* end(int j) const { return splats_.data() + start_[static_cast<std::size_t>(j) + 1]; }
  const SplatCounters& counters() const { return counters_; }

 private:
  std::vector<char> small_;
  std::vector<std::int64_t> small_cells_;
  std::vector<Footprint> splats_;  // by plane, then back to front
  std::vector<std::size_t> start_;
  SplatCounters counters_;
};

// One plane's splats composited, back to front, into premultiplied RGBA over the box they cover,
// except at the pixels the plane's slice covers (counted as masked).
struct SplatLayer {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // the pixels [x0, x1) x [y0, y1)
  std::vector<float> rgba;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  bool covers(int i, int j) const { return i >= x0 && i < x1 && j >= y0 && j < y1; }
  // The pixel's light (covers(i, j) only).
  float* at(int i, int j) { return rgba.data() + 4 * (static_cast<std::size_t>(j - y0) * (x1 - x0) + (i - x0)); }
  const float* at(int i, int j) const { return const_cast<SplatLayer*>(this)->at(i, j); }
};
void splat_layer(const Footprint* begin, const Footprint* end, const SliceImage& slice, int width, int height,
                 SplatLayer& out, SplatCounters& counters);

}  // namespace cellproj
