#include "frame/splat_stencil.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

namespace cellproj {

SplatStencil::SplatStencil(const CellRayTracer& tracer, const Camera& camera, int width, int height,
                           const std::vector<PixelBox>& boxes, const std::vector<std::uint8_t>& drawn)
    : tiles_x_((width + kTile - 1) / kTile) {
  const int tiles_y = (height + kTile - 1) / kTile;
  tile_.assign(static_cast<std::size_t>(tiles_x_) * static_cast<std::size_t>(tiles_y), -1);
  std::vector<int> traced;
  for (const PixelBox& b : boxes)
    for (int ty = b.j0 / kTile; b.j0 <= b.j1 && ty <= b.j1 / kTile; ++ty)
      for (int tx = b.i0 / kTile; b.i0 <= b.i1 && tx <= b.i1 / kTile; ++tx) {
        std::int32_t& slot = tile_[static_cast<std::size_t>(ty * tiles_x_ + tx)];
        if (slot < 0) slot = static_cast<std::int32_t>(traced.size()), traced.push_back(ty * tiles_x_ + tx);
      }
  spans_.resize(traced.size());
  if (traced.empty()) return;

  const CellRayTracer::View view(tracer, camera, width, height);
  struct Scratch {
    std::vector<std::vector<RaySegment>> lists = std::vector<std::vector<RaySegment>>(kTile * kTile);
    std::vector<Ray> rays = std::vector<Ray>(kTile * kTile);
  };
  tbb::enumerable_thread_specific<Scratch> scratch;
  tbb::parallel_for(std::size_t(0), traced.size(), [&](std::size_t k) {
    Scratch& s = scratch.local();
    view.tile_segments(traced[k], nullptr, s.lists.data(), s.rays.data());
    Tile& tile = spans_[k];
    tile.start.assign(kTile * kTile + 1, 0);
    for (int p = 0; p < kTile * kTile; ++p) {
      tile.start[static_cast<std::size_t>(p)] = static_cast<std::uint32_t>(tile.t.size());
      const std::size_t first = tile.t.size();
      for (const RaySegment& seg : s.lists[static_cast<std::size_t>(p)]) {
        if (!drawn[static_cast<std::size_t>(seg.cell)]) continue;
        // Neighbouring cells share a face: the next segment starts where the last ended, to round-off.
        const bool touches = tile.t.size() > first && seg.t0 <= tile.t.back() + 1e-9 * (1.0 + std::abs(seg.t0));
        if (touches)
          tile.t.back() = std::max(tile.t.back(), seg.t1);
        else
          tile.t.push_back(seg.t0), tile.t.push_back(seg.t1);
      }
    }
    tile.start[kTile * kTile] = static_cast<std::uint32_t>(tile.t.size());
  });
}

bool SplatStencil::holds(int i, int j, double t) const {
  const std::int32_t k = tile_[static_cast<std::size_t>((j / kTile) * tiles_x_ + i / kTile)];
  if (k < 0) return false;
  const Tile& tile = spans_[static_cast<std::size_t>(k)];
  const int p = (j % kTile) * kTile + i % kTile;
  for (std::uint32_t q = tile.start[static_cast<std::size_t>(p)]; q < tile.start[static_cast<std::size_t>(p) + 1];
       q += 2)
    if (t >= tile.t[q] && t <= tile.t[q + 1]) return true;
  return false;
}

void ProjectionSplats::append(std::int64_t c, FragmentBands& out, SplatCounters& counters) const {
  const Footprint& f = footprint[static_cast<std::size_t>(index[static_cast<std::size_t>(c)])];
  if (!f.visible) return;
  append_fragments(
      f, rays->width(), rays->height(),
      [&](int i, int j) { return !stencil.holds(i, j, f.depth * rays->length_per_depth_at_pixel(i, j)); }, out,
      counters);
}

}  // namespace cellproj
