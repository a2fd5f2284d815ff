#pragma once
// Each image tile puts its own cells in visibility order (visibility/subset_order.hpp) instead of
// one sort of the whole mesh before the tiles: no serial stage stands between the face relations
// (parallel) and the tiles' compositing (parallel). Where the face relations are the whole order
// (mpvo on a convex mesh; VisibilitySorter::sort with ViewRelations); the same pictures where they
// hold no visibility cycle (VisibilitySorter::acyclic; a cycle within one tile makes it return false).
#include <cstdint>

#include "composite/tiled_compositor.hpp"
#include "visibility/sort.hpp"

namespace cellproj {

// The cells [0, n_cells) binned to tiles of `rows` rows by their reach (ids in the bins), then
// each tile's list ordered in place by the relations among its own cells, and its first-tile flags
// set again. Parallel over the tiles. False where a tile's relations hold a visibility cycle (the
// bins are then in no particular order: the caller sorts the whole mesh).
bool order_tiles(TileBins& bins, const ViewRelations& relations, std::int64_t n_cells,
                 const FrameBuffer<RowRange>& reach, int height, int rows);

}  // namespace cellproj
