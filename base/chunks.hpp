#pragma once
// Joining the results of a parallel loop over fixed-size chunks of one buffer, each chunk having
// written what it keeps at its own start: one allocation, in order, without per-chunk vectors.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace cellproj {

// Moves the first kept[c] items of each chunk c (v's items [c * grain, (c + 1) * grain)) down to
// follow those of the chunks before it, in order, and shrinks v to their total.
template <class Vector>
void join_chunk_heads(Vector& v, const std::vector<std::size_t>& kept, std::size_t grain) {
  std::size_t size = 0;
  for (std::size_t c = 0; c < kept.size(); ++c) {
    const auto from = v.begin() + static_cast<std::ptrdiff_t>(c * grain);
    std::copy(from, from + static_cast<std::ptrdiff_t>(kept[c]), v.begin() + static_cast<std::ptrdiff_t>(size));
    size += kept[c];
  }
  v.resize(size);
}

}  // namespace cellproj
