#pragma once
// Kahn's topological sort (MWSC section 3.1) of a subset of the cells over the face relations
// between its members only: an image tile's cells, each tile sorting its own, so that no serial
// sort of the whole mesh stands before the tiles (issue 21's Amdahl share).
//
// Why it is the whole order there: on a convex mesh MPVO is exact, and between two cells that a
// ray through a pixel centre passes through, the ray crosses a chain of cells, each related to the
// next across the face between them. Every cell of that chain holds a point of the ray, so its
// image box holds the pixel centre and its rows reach the tile: the relations among the tile's
// cells order every pair that overlaps at one of its pixels, as the whole mesh's order does, and
// each pixel composites the same cells in the same order (docs/sorting.md, "Each tile its order").
// That holds where the relations have no visibility cycle (VisibilitySorter::acyclic): a cycle
// spread over several tiles is ordered by each tile apart, where the whole mesh's sort breaks it.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "base/huge_pages.hpp"
#include "visibility/sort.hpp"

namespace cellproj {

// One worker's room for order_subset: a count per cell of the mesh, 0 between sorts.
struct SubsetScratch {
  FrameBuffer<std::int8_t> count;
  std::vector<std::size_t> queue;
};

// Orders `cells[0, size)` (distinct cells, the subset) back to front in place: Kahn's FIFO queue
// over the relations whose both cells are members (`member(c)`, true for each of `cells` and for
// no other cell). False, the cells untouched, where the queue stalls: a visibility cycle within
// the subset (then the caller sorts the whole mesh, which breaks it). `n_cells`: the mesh's.
template <class Member>
bool order_subset(const ViewRelations& r, std::int64_t n_cells, std::size_t* cells, std::size_t size,
                  const Member& member, SubsetScratch& s) {
  if (s.count.size() != static_cast<std::size_t>(n_cells)) s.count.assign(static_cast<std::size_t>(n_cells), 0);
  s.queue.clear();
  s.queue.reserve(size);
  for (std::size_t i = 0; i < size; ++i) {  // in-counts: the members right behind each cell
    const auto c = static_cast<std::int64_t>(cells[i]);
    const std::int32_t* across = r.across + r.first_face(c);
    int before = 0;
    for (unsigned bits = r.behind[static_cast<std::size_t>(c)], k = 0; bits; bits >>= 1, ++k)
      if (bits & 1u) before += member(across[k]);
    s.count[static_cast<std::size_t>(c)] = static_cast<std::int8_t>(before);
    if (before == 0) s.queue.push_back(cells[i]);
  }
  for (std::size_t head = 0; head < s.queue.size(); ++head) {
    constexpr std::size_t kAhead = 8;  // the queue is known a few cells ahead: their faces fetched early
    if (head + kAhead < s.queue.size()) {
      const auto next = static_cast<std::int64_t>(s.queue[head + kAhead]);
      __builtin_prefetch(r.across + r.first_face(next)), __builtin_prefetch(&r.ahead[static_cast<std::size_t>(next)]);
    }
    const auto c = static_cast<std::int64_t>(s.queue[head]);
    const std::int32_t* across = r.across + r.first_face(c);
    for (unsigned bits = r.ahead[static_cast<std::size_t>(c)], k = 0; bits; bits >>= 1, ++k)
      if ((bits & 1u) && member(across[k]) && --s.count[static_cast<std::size_t>(across[k])] == 0)
        s.queue.push_back(static_cast<std::size_t>(across[k]));
  }
  if (s.queue.size() < size) {
    for (std::size_t i = 0; i < size; ++i) s.count[cells[i]] = 0;
    return false;
  }
  std::copy(s.queue.begin(), s.queue.end(), cells);
  return true;
}

}  // namespace cellproj
