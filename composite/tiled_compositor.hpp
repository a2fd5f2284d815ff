#pragma once
// Compositing by image tiles (issue 21; the sort-last tiling of MWSC section 7 on one machine):
// the image is cut into tiles of whole rows, each owned by one task; a tile's task draws, in
// visibility order, every item that reaches its rows, clipped to them, "over" straight onto the
// image. No fragment is stored and there is no serial blend: a pixel is written by one task only,
// in the items' order, so 1 and N threads give the same image bit for bit, and the work of an item
// is repeated only on the tiles it straddles. Items are binned to tiles in parallel first, in order.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "base/huge_pages.hpp"
#include "view/image.hpp"

namespace cellproj {

// Rows per tile for a `height`-row image: about 4 tiles per thread (the workers balance by taking
// whole tiles), at most 64 rows (a 1024-wide tile of 64 float RGBA rows is 1 MB, the size of a
// core's L2 cache), at least 16: a cell straddling tiles is set up once per tile, and a cell h rows
// tall meets about 1 + (h - 1) / rows tiles (1.12 for the 1M box at 1024² with 64 rows, 1.24 with
// 32, 1.61 with 16: docs/methods.md, "Tiles").
inline int tile_rows(int height, int threads) {
  const int rows = height / std::max(1, 4 * threads);
  return std::clamp(rows, 16, 64);
}

// The tile holding an item's first row (clamped to the image): where it is counted.
inline int first_tile(const RowRange& reach, int height, int rows) {
  return std::clamp(reach.begin, 0, height - 1) / rows;
}

// The tiles [t0, t1] an item reaching `reach` is binned to (an empty reach: its first row's tile).
inline void tile_span(const RowRange& reach, int height, int rows, int& t0, int& t1) {
  t0 = first_tile(reach, height, rows);
  t1 = reach.empty() ? t0 : std::max(t0, std::clamp(reach.end - 1, 0, height - 1) / rows);
}

// The items of each tile, in order: tile t holds items[first[t] .. first[t+1]), each given by its
// key (its position in the order, or what key_of made of it).
struct TileBins {
  std::vector<std::size_t> first;     // tiles + 1 offsets
  FrameBuffer<std::size_t> items;     // each tile's items' keys, in order (fresh every frame)
  FrameBuffer<std::uint8_t> counted;  // per entry of items: 1 in the item's first tile
};

// An item's key is its position in the order unless told otherwise.
struct PositionKey {
  std::size_t operator()(std::size_t k) const { return k; }
};

// Whether a Source has prefetch(k, stage): composite_in_tiles' look-ahead.
template <class S, class = void>
struct HasPrefetch : std::false_type {};
template <class S>
struct HasPrefetch<S, std::void_t<decltype(std::declval<const S&>().prefetch(std::size_t{}, 0))>> : std::true_type {};

// Bins items [0, n) to tiles of `rows` rows; rows_of(k) is the RowRange item k may draw on (an
// empty one is binned to the tile of its first row, clamped, so that each item is met at least
// once: its counters count it), key_of(k) what the bins hold for it. Parallel over chunks of the
// order; each tile's list stays in order.
template <class RowsOf, class KeyOf = PositionKey>
TileBins bin_to_tiles(std::size_t n, int height, int rows, const RowsOf& rows_of, const KeyOf& key_of = {}) {
  const int tiles = std::max(1, (height + rows - 1) / rows);
  auto span = [&](std::size_t k, int& t0, int& t1) { tile_span(rows_of(k), height, rows, t0, t1); };
  constexpr std::size_t kChunk = 16384;
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  std::vector<std::size_t> count(chunks * static_cast<std::size_t>(tiles), 0);  // per chunk, per tile
  tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
    std::size_t* here = &count[c * static_cast<std::size_t>(tiles)];
    for (std::size_t k = c * kChunk, e = std::min(n, k + kChunk); k < e; ++k) {
      int t0, t1;
      span(k, t0, t1);
      for (int t = t0; t <= t1; ++t) ++here[t];
    }
  });
  TileBins bins;
  bins.first.assign(static_cast<std::size_t>(tiles) + 1, 0);
  std::size_t at = 0;  // offsets: tile by tile, chunk by chunk (each chunk's start in its tile)
  for (int t = 0; t < tiles; ++t) {
    bins.first[static_cast<std::size_t>(t)] = at;
    for (std::size_t c = 0; c < chunks; ++c) {
      std::size_t& m = count[c * static_cast<std::size_t>(tiles) + static_cast<std::size_t>(t)];
      const std::size_t here = m;
      m = at, at += here;
    }
  }
  bins.first[static_cast<std::size_t>(tiles)] = at;
  bins.items.resize(at), bins.counted.resize(at);
  tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
    std::size_t* next = &count[c * static_cast<std::size_t>(tiles)];
    for (std::size_t k = c * kChunk, e = std::min(n, k + kChunk); k < e; ++k) {
      int t0, t1;
      span(k, t0, t1);
      const std::size_t key = key_of(k);
      for (int t = t0; t <= t1; ++t) bins.counted[next[t]] = t == t0, bins.items[next[t]++] = key;
    }
  });
  return bins;
}

// Composites items [0, n) of the order onto `image` tile by tile. A Source provides
//   Scratch, Counters (as composite_in_order's, composite/ordered_pipeline.hpp), and
//   void composite(std::size_t key, Image& image, RowRange rows, bool first, Scratch&, Counters&) const
//             draws the item of that key (key_of of its position) "over" the image in `rows` only;
//             `first`: the first of its tiles (count the item there, its pixels everywhere);
//             called from many threads, one per tile;
// and may provide
//   void prefetch(std::size_t key, int stage) const
//             a hint that that item comes soon: stages 0 to kStages - 1 are called
//             kAhead items apart, the last kAhead items before it is drawn, so that each stage may
//             read what the one before loaded.
// Returns the sum of the tiles' counters.
// `visits`, when given, receives the number of (item, tile) pairs drawn: n plus the repeats of the
// items that straddle tiles. `front_to_back`: each tile takes its items from the last to the first
// (the source composites "under": early ray termination). A key that is what the source reads
// first (a cell rather than its position in the order) spares each tile a scattered read an item.
template <class Source, class RowsOf, class KeyOf = PositionKey>
typename Source::Counters composite_in_tiles(Image& image, std::size_t n, const RowsOf& rows_of, int rows,
                                             const Source& source, std::size_t* visits = nullptr,
                                             bool front_to_back = false, const KeyOf& key_of = {});

// composite_in_tiles after its binning: the tiles of `rows` rows composited from their bins.
template <class Source>
typename Source::Counters composite_bins(Image& image, const TileBins& bins, int rows, const Source& source,
                                         bool front_to_back = false) {
  const std::size_t tiles = bins.first.size() - 1;
  // The busiest tiles first (most items), taken in that order from one counter by every worker
  // (longest job first): the last tasks to start are short ones. (A parallel_for over the tiles
  // splits their range in halves, so a busy tile could start last: up to a tenth of the phase idle
  // on 2 threads, bench/results/tile_order.txt.)
  std::vector<std::size_t> by_load(tiles);
  std::iota(by_load.begin(), by_load.end(), std::size_t(0));
  std::stable_sort(by_load.begin(), by_load.end(), [&](std::size_t a, std::size_t b) {
    return bins.first[a + 1] - bins.first[a] > bins.first[b + 1] - bins.first[b];
  });
  std::vector<typename Source::Counters> counters(tiles);
  std::atomic<std::size_t> next{0};
  const auto draw_tile = [&](std::size_t t, typename Source::Scratch& s) {
    const RowRange tile{static_cast<int>(t) * rows, std::min(image.height, static_cast<int>(t + 1) * rows)};
    const std::size_t b = bins.first[t], e = bins.first[t + 1];
    const auto at = [&](std::size_t m) { return front_to_back ? e - 1 - (m - b) : m; };
    for (std::size_t m = b; m < e; ++m) {
      if constexpr (HasPrefetch<Source>::value) {
        // Items far apart in the order touch far apart memory: their loads start early.
        constexpr std::size_t kAhead = 4;
        constexpr int kStages = 3;
        for (int stage = 0; stage < kStages; ++stage)
          if (const std::size_t ahead = m + (kStages - stage) * kAhead; ahead < e)
            source.prefetch(bins.items[at(ahead)], stage);
      }
      source.composite(bins.items[at(m)], image, tile, bins.counted[at(m)] != 0, s, counters[t]);
    }
  };
  const int workers = static_cast<int>(std::min<std::size_t>(tiles, tbb::this_task_arena::max_concurrency()));
  tbb::parallel_for(0, workers, [&](int) {
    typename Source::Scratch s;  // (one per worker: a task takes tiles until none is left)
    for (std::size_t q; (q = next.fetch_add(1, std::memory_order_relaxed)) < tiles;) draw_tile(by_load[q], s);
  });
  typename Source::Counters total{};
  for (const auto& c : counters) total.add(c);
  return total;
}

template <class Source, class RowsOf, class KeyOf>
typename Source::Counters composite_in_tiles(Image& image, std::size_t n, const RowsOf& rows_of, int rows,
                                             const Source& source, std::size_t* visits, bool front_to_back,
                                             const KeyOf& key_of) {
  const TileBins bins = bin_to_tiles(n, image.height, rows, rows_of, key_of);
  if (visits) *visits = bins.items.size();
  return composite_bins(image, bins, rows, source, front_to_back);
}

}  // namespace cellproj
