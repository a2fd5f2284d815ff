// Williams' MPVO (MWSC section 3.1): a relation across every shared face from the side the
// viewpoint is on, then Kahn's topological sort; visibility cycles found and broken.
#include <algorithm>
#include <cmath>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <glm/geometric.hpp>

#include "visibility/prepared.hpp"

namespace cellproj {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// Which side of shared face f the viewpoint is on: > 0 outside face_a (so face_a is behind).
int viewpoint_side(const VisibilitySorter::Prepared& p, const ViewFrame& v, std::size_t f) {
  const glm::dvec3& n = p.normal[f];  // unit length
  if (!v.perspective) {
    const double s = -(n.x * v.dir.x + n.y * v.dir.y + n.z * v.dir.z);
    return s > 1e-14 ? 1 : s < -1e-14 ? -1 : 0;
  }
  const double s = n.x * v.eye.x + n.y * v.eye.y + n.z * v.eye.z - p.offset[f];
  if (std::abs(s) > 1e-9 * v.eye_scale || p.face_tri[f][0] < 0) return s > 0 ? 1 : s < 0 ? -1 : 0;
  // Nearly in the face's plane: CGAL's exact orientation decides.
  auto P = [&](std::int64_t i) { const glm::dvec3 x = p.point(i); return K::Point_3(x.x, x.y, x.z); };
  const auto& t = p.face_tri[f];
  const auto o = CGAL::orientation(P(t[0]), P(t[1]), P(t[2]), K::Point_3(v.eye.x, v.eye.y, v.eye.z));
  return o == CGAL::POSITIVE ? -1 : o == CGAL::NEGATIVE ? 1 : 0;  // POSITIVE: below the plane, inside a
}

}  // namespace

FaceOrder face_relations(const VisibilitySorter::Prepared& p, const ViewFrame& v) {
  const std::size_t n = p.centroid.size();
  FaceOrder out;
  out.ahead.assign(n, 0);
  out.in.assign(n, 0);
  std::vector<std::pair<std::int64_t, std::int64_t>> split;
  for (std::size_t f = 0; f < p.face_a.size(); ++f) {
    const int side = viewpoint_side(p, v, f);
    if (side > 0) {  // the viewpoint is beyond face_a's face: face_a is behind, face_b comes after it
      out.ahead[p.face_a[f]] |= static_cast<std::uint8_t>(1u << p.local_a[f]);
      ++out.in[p.face_b[f]];
    } else if (side < 0 && p.local_b[f] == kNoLocalFace) {
      split.emplace_back(p.face_b[f], p.face_a[f]);  // counted in topological_order, as every list
    } else if (side < 0) {
      out.ahead[p.face_b[f]] |= static_cast<std::uint8_t>(1u << p.local_b[f]);
      ++out.in[p.face_a[f]];
    }
    out.relations += side != 0;
  }
  if (!split.empty()) out.split.build(static_cast<std::int64_t>(n), split);
  return out;
}

namespace {

// Iterative Tarjan over the cells not yet emitted; returns the component of each (-1 elsewhere).
template <class Successors>
std::vector<std::int64_t> components(std::int64_t n, const std::vector<char>& emitted, Successors&& successors) {
  std::vector<std::int64_t> comp(static_cast<std::size_t>(n), -1), index(static_cast<std::size_t>(n), -1), low(index);
  std::vector<char> on_stack(static_cast<std::size_t>(n), 0);
  std::vector<std::int64_t> stack, succ;
  std::vector<std::pair<std::int64_t, std::size_t>> call;  // (cell, next successor)
  std::vector<std::vector<std::int64_t>> succ_of;          // successors of the cells on the call stack
  std::int64_t counter = 0, n_comp = 0;
  for (std::int64_t root = 0; root < n; ++root) {
    if (emitted[root] || index[root] >= 0) continue;
    auto open = [&](std::int64_t c) {
      index[c] = low[c] = counter++;
      stack.push_back(c);
      on_stack[c] = 1;
      succ.clear();
      successors(c, [&](std::int64_t m) {
        if (!emitted[m]) succ.push_back(m);
      });
      call.push_back({c, 0});
      succ_of.push_back(succ);
    };
    open(root);
    while (!call.empty()) {
      auto& [c, next] = call.back();
      if (next < succ_of.back().size()) {
        const std::int64_t m = succ_of.back()[next++];
        if (index[m] < 0) open(m);
        else if (on_stack[m]) low[c] = std::min(low[c], index[m]);
        continue;
      }
      const std::int64_t done = c;
      if (low[done] == index[done]) {
        std::int64_t m;
        do {
          m = stack.back();
          stack.pop_back();
          on_stack[m] = 0;
          comp[m] = n_comp;
        } while (m != done);
        ++n_comp;
      }
      call.pop_back();
      succ_of.pop_back();
      if (!call.empty()) low[call.back().first] = std::min(low[call.back().first], low[done]);
    }
  }
  return comp;
}

}  // namespace

std::vector<std::int64_t> topological_order(const VisibilitySorter::Prepared& p, const ViewFrame& v, FaceOrder& faces,
                                            const std::vector<const Relations*>& extra, SortStats& stats) {
  const std::int64_t n = p.mesh.n_cells;
  const auto& fo = p.topo->face_offsets;
  std::vector<const Relations*> lists;
  if (!faces.split.start.empty()) lists.push_back(&faces.split);
  for (const Relations* r : extra)
    if (!r->start.empty()) lists.push_back(r);
  // successors(c, visit): every cell that must be composited after c.
  auto successors = [&](std::int64_t c, auto&& visit) {
    if (!faces.ahead.empty())
      for (unsigned bits = faces.ahead[c], k = 0; bits; bits >>= 1, ++k)
        if (bits & 1u) visit(static_cast<std::int64_t>(p.across[(p.all_tetrahedra ? 4 * c : fo[c]) + k]));
    for (const Relations* rel : lists)
      for (std::int64_t k = rel->start[c]; k < rel->start[c + 1]; ++k) visit(rel->to[k]);
  };
  std::vector<std::int32_t>& in = faces.in;
  in.resize(static_cast<std::size_t>(n), 0);
  for (const Relations* rel : lists)
    for (std::int64_t m : rel->to) ++in[m];

  std::vector<std::int64_t> order;  // doubles as Kahn's FIFO queue
  order.reserve(static_cast<std::size_t>(n));
  for (std::int64_t c = 0; c < n; ++c)
    if (in[c] == 0) order.push_back(c);
  std::size_t head = 0;
  std::vector<char> emitted;
  while (static_cast<std::int64_t>(order.size()) < n || head < order.size()) {
    while (head < order.size()) {
      // The queue is known a few cells ahead: fetch their face bits and neighbours early (the
      // sort is bound by these scattered reads).
      constexpr std::size_t kAhead = 8;
      if (head + kAhead < order.size() && !faces.ahead.empty()) {
        const std::int64_t c = order[head + kAhead];
        __builtin_prefetch(&faces.ahead[c]);
        __builtin_prefetch(&p.across[p.all_tetrahedra ? 4 * c : fo[c]]);
      }
      successors(order[head++], [&](std::int64_t m) {
        if (--in[m] == 0) order.push_back(m);
      });
    }
    if (static_cast<std::int64_t>(order.size()) == n) break;
    // Stalled: every cell left waits on another one left. Find the cycles and break one.
    emitted.assign(static_cast<std::size_t>(n), 0);
    for (std::int64_t c : order) emitted[c] = 1;
    const auto comp = components(n, emitted, successors);
    std::int64_t n_comp = 0;
    for (std::int64_t c = 0; c < n; ++c) n_comp = std::max(n_comp, comp[c] + 1);
    std::vector<char> has_in(static_cast<std::size_t>(n_comp), 0);
    for (std::int64_t c = 0; c < n; ++c)
      if (!emitted[c])
        successors(c, [&](std::int64_t m) {
          if (!emitted[m] && comp[m] != comp[c]) has_in[comp[m]] = 1;
        });
    std::int64_t source = 0;
    while (source < n_comp && has_in[source]) ++source;
    VisibilityCycle cycle;
    double farthest = -std::numeric_limits<double>::infinity();
    for (std::int64_t c = 0; c < n; ++c) {
      if (comp[c] != source) continue;
      ++cycle.size;
      if (cycle.cells.size() < VisibilityCycle::kMaxCycleCells) cycle.cells.push_back(c);
      if (const double k = v.far_key(p.centroid[c]); k > farthest) farthest = k, cycle.broken_at = c;
    }
    cycle.relations_dropped = in[cycle.broken_at];
    in[cycle.broken_at] = 0;
    order.push_back(cycle.broken_at);
    stats.cycles.push_back(std::move(cycle));
  }
  return order;
}

}  // namespace cellproj
