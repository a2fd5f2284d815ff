#include "frame/frame_plan.hpp"

#include "composite/tiled_compositor.hpp"

namespace cellproj {

FramePlan plan_frame(const ProjectionOptions& o, Tetrahedralize mode, int height, int threads,
                     const std::function<bool()>& acyclic) {
  FramePlan p;
  p.software = !is_opengl(o.backend);
  p.small_cells = resolve(o.splat, o.backend);
  p.splat_threshold = threshold_or(o.splat, kDefaultPixelThreshold);
  p.by_tiles = o.compositing == Compositing::tiles && p.small_cells != SmallCells::splat;
  p.count_small_after = p.by_tiles && p.small_cells == SmallCells::draw && p.splat_threshold <= 1.0;
  // Automatically only where no view can make a visibility cycle, which tiles could order apart.
  p.tile_orders = p.software && p.by_tiles &&
                  (o.tile_orders == TileOrders::on ||
                   (o.tile_orders == TileOrders::automatic && threads >= kTileOrdersFromThreads && acyclic()));
  p.passes_beside_sort = p.software && mode != Tetrahedralize::problem;
  p.tile_rows = o.tile_rows > 0 ? o.tile_rows : tile_rows(height, threads);
  return p;
}

}  // namespace cellproj
