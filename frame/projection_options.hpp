#pragma once
// The settings of cell projection: the rung of the method ladder, where it is drawn, how cells are
// sorted. Light enough for a settings struct (render/settings.hpp) to hold.
#include "projection/method.hpp"
#include "splat/splat_options.hpp"
#include "visibility/methods.hpp"

namespace cellproj {

// How the software back end composites the cells in order: image tiles owned by tasks, each
// drawing the cells that reach it straight onto the image (composite/tiled_compositor.hpp), or the
// ordered stream of buffered fragments blended by bands (composite/ordered_pipeline.hpp; always
// used when small cells are splatted).
enum class Compositing { tiles, stream };

enum class TileOrders { automatic, on, off };
inline constexpr int kTileOrdersFromThreads = 4;

struct ProjectionOptions {
  ProjectionMethod method = ProjectionMethod::pt_breakpoints;
  Backend backend = Backend::software;  // the OpenGL ones draw the Gouraud methods
  SortMethod sort = SortMethod::automatic;
  GapMethod gaps = GapMethod::automatic;  // how mpvo-abuffer finds the relations across gaps
  int table_size = 256;                   // pt-table: nodes per axis of the opacity table
  int batch_cells = 0;                    // cells per pipeline token; 0: about 16 tokens per thread, 64 to 2048
  SplatOptions splat;                     // cells whose projection covers few pixel centres: splatted
  bool cull_transparent = true;           // cells with extinction 0 over their scalar range not drawn (same picture)
  Compositing compositing = Compositing::tiles;
  int tile_rows = 0;  // rows per tile (tiles); 0: tile_rows(), about 4 tiles per thread, 16 to 64 rows
  // Tiles: each orders its own cells by the face relations among them where those are the whole
  // order (mpvo on a convex mesh; frame/tile_orders.hpp), instead of one sort of every cell
  // before them (the serial stage of Amdahl's law). The same picture where no view makes a
  // visibility cycle; a cycle within a tile falls back to the one sort, but one spread over
  // several tiles is ordered by each apart, unlike the one sort, which breaks it. Automatic: from
  // kTileOrdersFromThreads threads, where the tiles' orders (about 4 times the work of the one
  // sort, in parallel) take less time than the serial sort (docs/methods.md, "Each tile its
  // order"), on a mesh no view can make a cycle in (VisibilitySorter::acyclic).
  TileOrders tile_orders = TileOrders::automatic;
  // Tiles composited front to back, each pixel closed once within kOpaqueWithin (1e-6) of opaque
  // and cells wholly behind closed pixels not projected (composite/opaque_mask.hpp). Not the same
  // bits as back to front: the sums round in another order.
  bool early_termination = false;
  WholeCells whole_cells = WholeCells::automatic;  // pt-linear and pt-table on whole cells, software
};
// Throws InputError for options that do not go together (a method the back end cannot draw) or a
// table size outside [2, 8192]: before a frame starts, never in the middle of one.
void check_options(const ProjectionOptions& options);

}  // namespace cellproj
