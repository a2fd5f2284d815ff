#pragma once
// Small cells splatted in cell projection (MWSC section 6), with the projection's analogue of
// slicing's stencil: a splat adds light at a pixel only where that pixel's ray, at the splat's
// depth, is inside no cell drawn by its polygons (in a small cell, or outside the mesh). Where a
// drawn cell holds the ray, its sample at the pixel centre already stands for the whole pixel, and
// a splat there would count the pixel's light twice (the stripes of edge-on slivers).
#include <cstdint>
#include <vector>

#include "raycast/cell_ray_tracer.hpp"
#include "splat/splat.hpp"
#include "view/camera.hpp"

namespace cellproj {

// Per pixel of the image tiles it was made for, the stretches of the ray inside drawn cells.
class SplatStencil {
 public:
  SplatStencil() = default;
  // The rays of the tiles the pixel boxes touch, traced through `tracer`'s cells; drawn[c] per cell
  // of the tracer's mesh says whether it is drawn by its polygons.
  SplatStencil(const CellRayTracer& tracer, const Camera& camera, int width, int height,
               const std::vector<PixelBox>& boxes, const std::vector<std::uint8_t>& drawn);
  // Whether a drawn cell holds pixel (i, j)'s ray at distance t along it (false outside the tiles).
  bool holds(int i, int j, double t) const;
  std::int64_t tiles_traced() const { return static_cast<std::int64_t>(spans_.size()); }

 private:
  static constexpr int kTile = CellRayTracer::View::kTile;
  struct Tile {
    std::vector<std::uint32_t> start;  // per pixel of the tile, into t (kTile^2 + 1)
    std::vector<double> t;             // pairs [t0, t1], front to back, merged where they touch
  };
  int tiles_x_ = 0;
  std::vector<std::int32_t> tile_;  // per image tile: its index in spans_, or -1
  std::vector<Tile> spans_;
};

// The splats of a frame's small cells, made before the pipeline runs (their boxes say which tiles
// the stencil needs), and drawn in their cells' places in the visibility order.
struct ProjectionSplats {
  std::vector<std::int32_t> index;  // per cell of the frame: into footprint, or -1 (not small)
  std::vector<Footprint> footprint;
  SplatStencil stencil;
  const PixelRays* rays = nullptr;
  // Appends cell c's splat through the stencil; counted in `counters`.
  void append(std::int64_t c, FragmentBands& out, SplatCounters& counters) const;
};

}  // namespace cellproj
