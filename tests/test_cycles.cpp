// CycleBreaker (visibility/cycles.hpp) against brute force on random relation graphs: at every
// stall of Kahn's sort it hands over exactly one strongly connected component of the cells left
// that nothing else left waits for, and the sort then emits every cell once.
#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "visibility/cycles.hpp"

namespace cellproj {
namespace {

using Graph = std::vector<std::vector<std::int64_t>>;  // successors per cell

// The cells reachable from c through cells not emitted (c itself included).
std::set<std::int64_t> reach(const Graph& g, std::int64_t c, const std::vector<char>& emitted) {
  std::set<std::int64_t> seen{c};
  std::vector<std::int64_t> todo{c};
  while (!todo.empty()) {
    const std::int64_t x = todo.back();
    todo.pop_back();
    for (std::int64_t m : g[x])
      if (!emitted[m] && seen.insert(m).second) todo.push_back(m);
  }
  return seen;
}

// Random graphs: chains and a DAG of forward relations, and back relations that close cycles,
// some of them nested (a cycle inside what is left of a broken one), some far downstream.
Graph random_graph(std::mt19937& rng, int n) {
  Graph g(n);
  std::uniform_int_distribution<int> cell(0, n - 1), coin(0, 99);
  for (int c = 0; c + 1 < n; ++c)
    if (coin(rng) < 70) g[c].push_back(c + 1);
  for (int k = 0; k < n; ++k) {
    int a = cell(rng), b = cell(rng);
    if (a == b) continue;
    if (a > b) std::swap(a, b);
    if (coin(rng) < 85)
      g[a].push_back(b);
    else if (b - a < 12)
      g[b].push_back(a);  // a short cycle back
  }
  return g;
}

TEST(CycleBreaker, BreaksExactlyTheSourceComponentsOfWhatIsLeft) {
  std::mt19937 rng(5);
  int graphs_with_cycles = 0, nested = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 20 + trial % 180;
    const Graph g = random_graph(rng, n);
    std::vector<std::int64_t> in(n, 0), order;
    for (const auto& s : g)
      for (std::int64_t m : s) ++in[m];
    for (int c = 0; c < n; ++c)
      if (in[c] == 0) order.push_back(c);
    std::vector<char> emitted(n, 0);
    std::size_t head = 0;
    CycleBreaker* breaker = nullptr;
    std::unique_ptr<CycleBreaker> owner;
    auto drain = [&] {
      while (head < order.size()) {
        const std::int64_t c = order[head++];
        emitted[c] = 1;
        for (std::int64_t m : g[c]) {
          if (breaker && !emitted[m]) breaker->consumed(c, m);
          if (--in[m] == 0) order.push_back(m);
        }
      }
    };
    drain();
    int breaks = 0;
    while (static_cast<int>(order.size()) < n) {
      if (!breaker) {
        std::vector<std::int64_t> start(n + 1, 0), to;
        for (int c = 0; c < n; ++c) {
          if (!emitted[c])
            for (std::int64_t m : g[c])
              if (!emitted[m]) to.push_back(m);
          start[c + 1] = static_cast<std::int64_t>(to.size());
        }
        owner = std::make_unique<CycleBreaker>(start, to, emitted);
        breaker = owner.get();
      }
      const std::vector<std::int64_t> cells = breaker->next_cycle(emitted);
      ASSERT_FALSE(cells.empty()) << "trial " << trial;
      // Brute force: the cells are one strongly connected component of what is left...
      const std::set<std::int64_t> got(cells.begin(), cells.end());
      EXPECT_EQ(got.size(), cells.size());
      for (std::int64_t c : cells) {
        EXPECT_FALSE(emitted[c]);
        const std::set<std::int64_t> r = reach(g, c, emitted);
        for (std::int64_t d : cells)
          EXPECT_TRUE(r.count(d)) << "trial " << trial << ": " << d << " not reached from " << c;
      }
      EXPECT_GE(cells.size(), 2u);
      // ... and nothing left outside it has a relation into it, nor is reached from it and back.
      for (int c = 0; c < n; ++c) {
        if (emitted[c] || got.count(c)) continue;
        for (std::int64_t m : g[c]) EXPECT_FALSE(got.count(m)) << "trial " << trial << ": " << c << " -> " << m;
      }
      const std::int64_t broken = *std::max_element(cells.begin(), cells.end());
      // A cycle left inside this one once its cell is out is handed over later, by itself.
      std::vector<char> without = emitted;
      without[broken] = 1;
      for (std::int64_t c : cells)
        if (c != broken && reach(g, c, without).size() > 1)
          for (std::int64_t m : g[c])
            if (!without[m] && got.count(m) && reach(g, m, without).count(c)) ++nested;
      in[broken] = 0;
      order.push_back(broken);
      emitted[broken] = 1;
      ++breaks;
      drain();
    }
    std::vector<std::int64_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (int c = 0; c < n; ++c) ASSERT_EQ(sorted[c], c) << "trial " << trial << ": every cell once";
    graphs_with_cycles += breaks > 0;
  }
  EXPECT_GT(graphs_with_cycles, 100);
  EXPECT_GT(nested, 10) << "some cycles must hold another one";
}

}  // namespace
}  // namespace cellproj
