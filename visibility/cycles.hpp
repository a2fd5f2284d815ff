#pragma once
// The visibility cycles a topological sort meets (MWSC section 3.1: possible with non-planar
// faces, intersecting cells or general meshes). Internal to visibility/.
#include <cstdint>
#include <vector>

namespace cellproj {

// When Kahn's sort stalls, every cell left waits on another cell left. CycleBreaker finds the
// strongly connected components of what is left once, and keeps per component the count of
// relations into it from the rest: a component whose count reaches zero is a source, and a source
// whose cells are still waiting holds a cycle. Each stall takes such a component; only one that
// was broken before is decomposed again, and only what is left of it. A sort with cycles so costs
// O(n + relations + the cycles' sizes) instead of a decomposition of the whole rest per cycle.
class CycleBreaker {
 public:
  // The relations among the cells not emitted yet, as successor lists over all n cells (start:
  // n + 1 offsets into to).
  CycleBreaker(std::vector<std::int64_t> start, std::vector<std::int64_t> to, const std::vector<char>& emitted);

  // The sort consumed relation c -> m (c emitted, m not).
  void consumed(std::int64_t c, std::int64_t m) {
    const std::int64_t cm = comp_[m];
    if (comp_[c] != cm && --cross_in_[cm] == 0) ready_.push_back(cm);
  }
  // The cells, not emitted, of a strongly connected component that no cell left outside it
  // waits for, once the sort stalls; the caller breaks it. Empty if there is none (a stall
  // without a cycle cannot happen; the caller treats it as an error).
  std::vector<std::int64_t> next_cycle(const std::vector<char>& emitted);

 private:
  // Tarjan's algorithm (iterative) over `cells`, following relations to the cells `inside` says
  // (before and while their components are numbered, from comp_count() on); counts the relations
  // between the new components, and those with none coming in are ready.
  template <class Inside>
  void decompose(const std::vector<std::int64_t>& cells, Inside&& inside);
  std::int64_t comp_count() const { return static_cast<std::int64_t>(range_.size()); }

  std::vector<std::int64_t> start_, to_;
  std::vector<std::int64_t> comp_, index_, low_;  // per cell
  std::vector<char> on_stack_;
  std::vector<std::int64_t> members_;  // cells by component
  struct Range {
    std::int64_t begin, end;  // the component's cells in members_
  };
  std::vector<Range> range_;            // per component
  std::vector<std::int64_t> cross_in_;  // per component: relations into it from other components left
  std::vector<char> broken_;            // per component: a cell of it was emitted to break a cycle
  std::vector<std::int64_t> ready_;     // components whose cross_in_ is 0
};

}  // namespace cellproj
