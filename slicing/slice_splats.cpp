#include "slicing/slice_splats.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include "composite/fragment.hpp"

namespace cellproj {

SliceSplats::SliceSplats(const SliceCells& cells, const std::vector<double>& volume, const CellSweep& sweep,
                         const SplatContext& frame, const SlicePlanes& planes, int visible, double threshold)
    : small_(static_cast<std::size_t>(cells.size()), 0) {
  const double limit = threshold * std::pow(planes.spacing(), 3);
  for (std::int64_t c = 0; c < cells.size(); ++c)
    if (volume[static_cast<std::size_t>(c)] < limit || sweep.last(c) < sweep.first(c))
      small_[static_cast<std::size_t>(c)] = 1, small_cells_.push_back(c);
  counters_.small_cells = static_cast<std::int64_t>(small_cells_.size());
  start_.assign(static_cast<std::size_t>(visible) + 3, 0);
  if (small_cells_.empty() || visible < 1) return;

  // Each small cell's splat and nearest plane, in parallel; then bucketed by plane in cell order.
  std::vector<Footprint> splat(small_cells_.size());
  std::vector<int> plane(small_cells_.size(), 0);  // 0: no splat
  tbb::enumerable_thread_specific<SplatCounters> counts;
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, small_cells_.size(), 1024), [&](const tbb::blocked_range<std::size_t>& r) {
        SplatCounters& n = counts.local();
        for (std::size_t k = r.begin(); k < r.end(); ++k) {
          const std::int64_t c = small_cells_[k];
          const std::int64_t* ids = cells.ids.data() + cells.offsets[static_cast<std::size_t>(c)];
          splat[k] = cell_splat(frame, ids, static_cast<CellType>(cells.types[static_cast<std::size_t>(c)]), n);
          if (!splat[k].visible) continue;
          // The nearest plane: the first above the centre's height less half a spacing.
          const double h = glm::dot(splat[k].world, planes.normal());
          plane[k] = std::clamp(planes.first_above(h - 0.5 * planes.spacing()), 1, visible);
        }
      });
  for (const SplatCounters& n : counts) counters_.add(n);
  for (int j : plane) ++start_[static_cast<std::size_t>(j) + 1];
  for (std::size_t j = 1; j < start_.size(); ++j) start_[j] += start_[j - 1];
  std::vector<std::size_t> at(start_.begin(), start_.end() - 1);
  splats_.resize(splat.size());
  for (std::size_t k = 0; k < splat.size(); ++k) splats_[at[static_cast<std::size_t>(plane[k])]++] = splat[k];
  tbb::parallel_for(1, visible + 1, [&](int j) {  // back to front on each plane: the farthest centre first
    std::stable_sort(splats_.begin() + static_cast<std::ptrdiff_t>(start_[static_cast<std::size_t>(j)]),
                     splats_.begin() + static_cast<std::ptrdiff_t>(start_[static_cast<std::size_t>(j) + 1]),
                     [](const Footprint& a, const Footprint& b) { return a.depth > b.depth; });
  });
}

void splat_layer(const Footprint* begin, const Footprint* end, const SliceImage& slice, int width, int height,
                 SplatLayer& out, SplatCounters& counters) {
  out.x0 = width, out.y0 = height, out.x1 = 0, out.y1 = 0;
  for (const Footprint* f = begin; f != end; ++f) {
    const PixelBox box = f->pixels(width, height);
    if (box.empty()) continue;
    out.x0 = std::min(out.x0, box.i0), out.x1 = std::max(out.x1, box.i1 + 1);
    out.y0 = std::min(out.y0, box.j0), out.y1 = std::max(out.y1, box.j1 + 1);
  }
  if (out.empty()) return;
  out.rgba.assign(4 * static_cast<std::size_t>(out.x1 - out.x0) * static_cast<std::size_t>(out.y1 - out.y0), 0.0f);
  for (const Footprint* f = begin; f != end; ++f) {
    // The stencil: the plane's polygons hold the pixels where the slice is not NaN.
    rasterize_splat_open(
        *f, width, height, [&](int i, int j) { return std::isnan(slice.at(i, j, width)); },
        [&](int i, int j, const glm::dvec3& rgb, double a) {
          const float src[4] = {static_cast<float>(rgb.r), static_cast<float>(rgb.g), static_cast<float>(rgb.b),
                                static_cast<float>(a)};
          over(out.at(i, j), src);
        },
        counters);
  }
}

}  // namespace cellproj
