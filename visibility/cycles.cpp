#include "visibility/cycles.hpp"

#include <algorithm>
#include <utility>

namespace cellproj {

CycleBreaker::CycleBreaker(std::vector<std::int64_t> start, std::vector<std::int64_t> to,
                           const std::vector<char>& emitted)
    : start_(std::move(start)), to_(std::move(to)) {
  const std::size_t n = emitted.size();
  comp_.assign(n, -1);
  index_.assign(n, -1);
  low_.assign(n, -1);
  on_stack_.assign(n, 0);
  std::vector<std::int64_t> left;
  for (std::size_t c = 0; c < n; ++c)
    if (!emitted[c]) left.push_back(static_cast<std::int64_t>(c));
  decompose(left, [&](std::int64_t m) { return !emitted[m]; });
}

template <class Inside>
void CycleBreaker::decompose(const std::vector<std::int64_t>& cells, Inside&& inside) {
  const std::int64_t first = comp_count();
  for (std::int64_t c : cells) index_[c] = -1;
  std::vector<std::int64_t> stack;
  std::vector<std::pair<std::int64_t, std::int64_t>> call;  // (cell, its next relation)
  std::int64_t counter = 0;
  auto open = [&](std::int64_t c) {
    index_[c] = low_[c] = counter++;
    stack.push_back(c);
    on_stack_[c] = 1;
    call.push_back({c, start_[c]});
  };
  for (std::int64_t root : cells) {
    if (index_[root] >= 0) continue;
    open(root);
    while (!call.empty()) {
      auto& [c, next] = call.back();
      if (next < start_[c + 1]) {
        const std::int64_t m = to_[next++];
        if (!inside(m)) continue;
        if (index_[m] < 0)
          open(m);
        else if (on_stack_[m])
          low_[c] = std::min(low_[c], index_[m]);
        continue;
      }
      const std::int64_t done = c;
      call.pop_back();
      if (!call.empty()) low_[call.back().first] = std::min(low_[call.back().first], low_[done]);
      if (low_[done] != index_[done]) continue;
      const std::int64_t id = comp_count(), begin = static_cast<std::int64_t>(members_.size());
      std::int64_t m;
      do {
        m = stack.back();
        stack.pop_back();
        on_stack_[m] = 0;
        comp_[m] = id;
        members_.push_back(m);
      } while (m != done);
      range_.push_back({begin, static_cast<std::int64_t>(members_.size())});
    }
  }
  cross_in_.resize(range_.size(), 0);
  broken_.resize(range_.size(), 0);
  for (std::int64_t c : cells)
    for (std::int64_t k = start_[c]; k < start_[c + 1]; ++k)
      if (inside(to_[k]) && comp_[to_[k]] != comp_[c]) ++cross_in_[comp_[to_[k]]];
  for (std::int64_t id = first; id < comp_count(); ++id)
    if (cross_in_[id] == 0) ready_.push_back(id);
}

std::vector<std::int64_t> CycleBreaker::next_cycle(const std::vector<char>& emitted) {
  while (!ready_.empty()) {
    const std::int64_t id = ready_.back();
    ready_.pop_back();
    std::vector<std::int64_t> cells;
    for (std::int64_t k = range_[id].begin; k < range_[id].end; ++k)
      if (!emitted[members_[k]]) cells.push_back(members_[k]);
    if (cells.empty()) continue;
    if (!broken_[id]) {  // still whole: one strongly connected component of the cells left
      broken_[id] = 1;
      ready_.push_back(id);  // still a source: what is left of it once it is broken comes next
      return cells;
    }
    // What is left of a component broken before need not be strongly connected any more: its
    // own components (no relation comes into it from outside, it being a source).
    const std::int64_t first = comp_count();  // the ids decompose gives its cells as it goes
    decompose(cells, [&](std::int64_t m) { return (comp_[m] == id || comp_[m] >= first) && !emitted[m]; });
  }
  return {};
}

}  // namespace cellproj
