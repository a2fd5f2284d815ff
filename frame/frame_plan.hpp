#pragma once
// What a projection frame will do, decided once from its options before any work is done (the
// frame as a plan: where its order comes from, who composites, what is counted when). The
// conductor, ProjectionRenderer::render, then runs the plan in a straight line, and a test can
// ask for the plan without rendering.
#include <functional>

#include "frame/projection_options.hpp"
#include "splat/splat_options.hpp"

namespace cellproj {

struct FramePlan {
  bool software = true;                             // else an OpenGL back end draws the frame
  SmallCells small_cells = SmallCells::draw;        // the small cells' mode that runs (draw on OpenGL)
  double splat_threshold = kDefaultPixelThreshold;  // pixel centres: cells covering fewer are small
  bool by_tiles = true;  // image tiles own the image and draw the cells reaching them; else the ordered stream
  // Nothing reads which cells are small before they are drawn (tiles drawing every cell, a
  // threshold of one pixel centre): they are counted after, from the cells that added no fragment.
  bool count_small_after = true;
  // Each tile orders its own cells by the face relations among them (the sort hands back the
  // relations, no order; frame/tile_orders.hpp).
  bool tile_orders = false;
  // The passes over the cells that need no order (small cells, rows reached) run beside the sort:
  // the cells it sorts are the base mesh's whatever the view (no per-view split).
  bool passes_beside_sort = true;
  int tile_rows = 0;  // rows per image tile
};

// The plan for `options` on a mesh split by `mode`, an image `height` rows tall, `threads`
// threads; `acyclic` is asked (it may cost a check of the whole mesh, once) only where automatic
// tile orders hinge on it.
FramePlan plan_frame(const ProjectionOptions& options, Tetrahedralize mode, int height, int threads,
                     const std::function<bool()>& acyclic);

}  // namespace cellproj
