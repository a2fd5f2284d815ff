#include "frame/tile_orders.hpp"

#include <algorithm>
#include <atomic>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "visibility/subset_order.hpp"

namespace cellproj {

namespace {

// One worker's room: the subset sort's, and a bit per cell of the mesh for the tile's members
// (a bitmap an eighth of a byte a cell stays in cache where the cells' rows would not).
struct TileScratch {
  SubsetScratch subset;
  std::vector<std::uint64_t> member;
};

}  // namespace

bool order_tiles(TileBins& bins, const ViewRelations& relations, std::int64_t n_cells,
                 const FrameBuffer<RowRange>& reach, int height, int rows) {
  const std::size_t tiles = bins.first.size() - 1;
  tbb::enumerable_thread_specific<TileScratch> scratch;
  std::atomic<bool> ordered{true};
  tbb::parallel_for(std::size_t(0), tiles, [&](std::size_t t) {
    if (!ordered.load(std::memory_order_relaxed)) return;  // a tile stalled: the whole mesh is sorted instead
    TileScratch& s = scratch.local();
    s.member.resize((static_cast<std::size_t>(n_cells) + 63) / 64, 0);
    std::size_t* const cells = bins.items.data() + bins.first[t];
    const std::size_t count = bins.first[t + 1] - bins.first[t];
    for (std::size_t k = 0; k < count; ++k) s.member[cells[k] / 64] |= std::uint64_t{1} << (cells[k] % 64);
    const auto member = [&](std::int32_t c) {
      return (s.member[static_cast<std::size_t>(c) / 64] >> (static_cast<std::size_t>(c) % 64)) & 1u;
    };
    if (!order_subset(relations, n_cells, cells, count, member, s.subset))
      ordered.store(false, std::memory_order_relaxed);
    const int lo = static_cast<int>(t) * rows;  // each cell counted in its first tile (bin_to_tiles)
    for (std::size_t k = 0; k < count; ++k) {
      s.member[cells[k] / 64] = 0;
      bins.counted[bins.first[t] + k] = std::clamp(reach[cells[k]].begin, 0, height - 1) >= lo;
    }
  });
  return ordered.load();
}

}  // namespace cellproj
