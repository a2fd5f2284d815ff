// Williams' MPVO (MWSC section 3.1): a relation across every shared face from the side the
// viewpoint is on, then Kahn's topological sort; visibility cycles found and broken.
#include <algorithm>

#include <cmath>
#include <cstring>
#include <functional>
#include <iterator>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "visibility/cycles.hpp"
#include "visibility/prepared.hpp"

namespace cellproj {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// The viewpoint nearly in shared face f's plane (perspective): CGAL's exact orientation decides
// for a triangle; a quad, which may be warped, keeps the sign of s. Out of line: it is rare.
[[gnu::noinline]] int side_near_plane(const VisibilitySorter::Prepared& p, const ViewFrame& v, std::size_t f,
                                      double s) {
  std::int64_t t[3];
  if (!p.face_triangle(f, t)) return s > 0 ? 1 : s < 0 ? -1 : 0;
  auto P = [&](std::int64_t i) {
    const glm::dvec3 x = p.point(i);
    return K::Point_3(x.x, x.y, x.z);
  };
  const auto o = CGAL::orientation(P(t[0]), P(t[1]), P(t[2]), K::Point_3(v.eye.x, v.eye.y, v.eye.z));
  return o == CGAL::POSITIVE ? 1 : o == CGAL::NEGATIVE ? -1 : 0;  // POSITIVE: on the normal side, outside a
}

// Which side of a shared face the viewpoint is on: > 0 outside face_a (so face_a is behind). The
// view and the arrays are copied in: byte stores between calls could alias them otherwise.
struct ViewpointSide {
  const VisibilitySorter::Prepared& p;
  const ViewFrame& v;
  const glm::dvec3* normal = p.normal.data();  // unit length
  const double* offset = p.offset.data();
  bool perspective = v.perspective;
  glm::dvec3 dir = v.dir, eye = v.eye;
  double plane_tolerance = 1e-9 * v.eye_scale;

  int operator()(std::size_t f) const {
    const glm::dvec3& n = normal[f];
    if (!perspective) {
      const double s = -(n.x * dir.x + n.y * dir.y + n.z * dir.z);
      return s > 1e-14 ? 1 : s < -1e-14 ? -1 : 0;
    }
    const double s = n.x * eye.x + n.y * eye.y + n.z * eye.z - offset[f];
    if (std::abs(s) > plane_tolerance) return s > 0 ? 1 : -1;
    return side_near_plane(p, v, f, s);
  }
};

// Kahn's loop over the face relations of a mesh of tetrahedra alone, with no branch on a cell's
// face bits or on a successor's in-count (on an irregular mesh both look like coin tosses to the
// branch predictor). Every face of the cell at the head is visited; one without a relation counts
// down a spare count of 1 by nothing (the spares of 16 cells in turn, so that no chain of stores
// runs through one). The queue's next slot is written whether or not a cell is appended, so the
// queue grows ahead of its tail a block at a time (zeroed while in cache, not all at once). The
// same order as the loop with branches: the successors in face order, each appended when its
// count reaches zero (tests/test_visibility.cpp, TheTetrahedraQueueKeepsTheGeneralOrder).
void drain_tetrahedra(const VisibilitySorter::Prepared& p, FaceOrder& faces, std::vector<std::int64_t>& order,
                      std::size_t& head) {
  constexpr std::size_t kSpares = 16;
  std::int32_t spares[4 * kSpares];
  std::fill(std::begin(spares), std::end(spares), 1);
  std::int32_t* const in = faces.in.data();
  const std::size_t room = faces.ahead.size() + 4;  // (a cell's four writes past the last one)
  std::size_t tail = order.size();
  for (; head < tail; ++head) {
    if (tail + 4 > order.size()) order.resize(std::min(room, order.size() + 4096));
    constexpr std::size_t kAhead = 8;  // the sort is bound by these scattered reads: started early
    if (head + kAhead < tail) {
      const std::int64_t c = order[head + kAhead];
      __builtin_prefetch(&faces.ahead[c]);
      __builtin_prefetch(&p.across[4 * c]);
    }
    const std::int64_t c = order[head];
    const unsigned bits = faces.ahead[c];
    const std::int32_t* across = &p.across[4 * c];
    std::int32_t* const spare = &spares[4 * (head % kSpares)];
    for (int k = 0; k < 4; ++k) {
      const bool relation = bits >> k & 1u;
      std::int32_t* const count = relation ? in + across[k] : spare + k;
      order[tail] = across[k], tail += (*count -= relation) == 0;
    }
  }
  order.resize(tail);
}

}  // namespace

// The face relations in two parallel passes with no two writes to one place (what is left serial
// is Amdahl's s): each shared face writes its side into its two cells' face slots, +1 for the cell
// composited first, -1 for the other (a split quad's side has no slot: `split_faces` below); then
// each cell turns its slots into its ahead bits and in-count.
FaceOrder face_relations(const VisibilitySorter::Prepared& p, const ViewFrame& v, bool behind) {
  const std::size_t n = p.centroid.size(), n_faces = p.face_a.size();
  const bool tetrahedra = p.all_tetrahedra;  // (copied: the byte stores below could alias p's members)
  const std::int64_t* const fo = p.topo->face_offsets.data();
  auto first_slot = [=](std::size_t c) { return tetrahedra ? 4 * c : static_cast<std::size_t>(fo[c]); };
  FrameBuffer<std::int8_t> slots(p.across.size(), 0);
  FaceOrder out;
  out.relations = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n_faces, 16384), std::int64_t{0},
      [&](const tbb::blocked_range<std::size_t>& r, std::int64_t count) {
        const ViewpointSide side{p, v};
        const std::int32_t *a = p.face_a.data(), *b = p.face_b.data();
        const std::uint8_t *local_a = p.local_a.data(), *local_b = p.local_b.data();
        std::int8_t* const slot = slots.data();
        for (std::size_t f = r.begin(); f < r.end(); ++f) {
          const int s = side(f);  // > 0: face_a first
          const bool split = local_b[f] == kNoLocalFace;
          slot[first_slot(a[f]) + local_a[f]] = static_cast<std::int8_t>(split && s < 0 ? 0 : s);
          if (!split) slot[first_slot(b[f]) + local_b[f]] = static_cast<std::int8_t>(-s);
          count += s != 0;
        }
        return count;
      },
      std::plus<>());
  out.ahead.resize(n);
  out.in.resize(n);
  if (behind) out.behind.resize(n);
  std::uint8_t* const ahead = out.ahead.data();
  std::uint8_t* const before_bits = behind ? out.behind.data() : nullptr;
  std::int32_t* const in = out.in.data();
  const std::int8_t* const slot = slots.data();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 8192), [=](const tbb::blocked_range<std::size_t>& r) {
    if (tetrahedra) {  // a cell's four slots as one word: bytes of 1 (ahead), 0 or 0xff (one more before it)
      for (std::size_t c = r.begin(); c < r.end(); ++c) {
        std::uint32_t w;
        std::memcpy(&w, slot + 4 * c, 4);
        const std::uint32_t first = w & ~(w >> 7) & 0x01010101u;            // bit 8 k set: byte k is 1
        ahead[c] = static_cast<std::uint8_t>((first * 0x01020408u) >> 24);  // (bit 8 k to bit 24 + k)
        in[c] = __builtin_popcount(w & 0x80808080u);
        if (before_bits) before_bits[c] = static_cast<std::uint8_t>((((w >> 7) & 0x01010101u) * 0x01020408u) >> 24);
      }
      return;
    }
    for (std::size_t c = r.begin(); c < r.end(); ++c) {
      const std::int8_t* s = slot + first_slot(c);
      const std::size_t faces = tetrahedra ? 4 : static_cast<std::size_t>(fo[c + 1] - fo[c]);
      unsigned bits = 0, back = 0;
      for (std::size_t k = 0; k < faces; ++k)
        bits |= static_cast<unsigned>(s[k] > 0) << k, back |= static_cast<unsigned>(s[k] < 0) << k;
      ahead[c] = static_cast<std::uint8_t>(bits), in[c] = __builtin_popcount(back);
      if (before_bits) before_bits[c] = static_cast<std::uint8_t>(back);
    }
  });
  // A split quad's cell has no slot for its triangles' faces: its in-count and relations from here.
  std::vector<std::pair<std::int64_t, std::int64_t>> split;
  for (const std::int32_t f : p.split_faces) {
    const int s = ViewpointSide{p, v}(static_cast<std::size_t>(f));
    if (s > 0) ++out.in[p.face_b[f]];
    if (s < 0) split.emplace_back(p.face_b[f], p.face_a[f]);  // counted in topological_order, as every list
  }
  if (!split.empty()) out.split.build(static_cast<std::int64_t>(n), split);
  return out;
}

std::vector<std::int64_t> topological_order(const VisibilitySorter::Prepared& p, const ViewFrame& v, FaceOrder& faces,
                                            const std::vector<const Relations*>& extra, SortStats& stats,
                                            const Relations* gaps) {
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
  FrameBuffer<std::int32_t>& in = faces.in;
  in.resize(static_cast<std::size_t>(n), 0);
  for (const Relations* rel : lists)
    for (std::int64_t m : rel->to) ++in[m];

  // Kahn's FIFO queue is the order itself (4 more for drain_tetrahedra's writes past its tail).
  std::vector<std::int64_t> order;
  reserve_in_huge_pages(order, static_cast<std::size_t>(n) + 4);
  for (std::int64_t c = 0; c < n; ++c)
    if (in[c] == 0) order.push_back(c);
  std::size_t head = 0;
  if (lists.empty() && p.all_tetrahedra && !faces.ahead.empty()) drain_tetrahedra(p, faces, order, head);
  // Kahn's loop; `release(c, m)` for each relation c -> m it consumes.
  auto drain = [&](auto&& release) {
    while (head < order.size()) {
      // The queue is known a few cells ahead: fetch their face bits and neighbours early (the
      // sort is bound by these scattered reads).
      constexpr std::size_t kAhead = 8;
      if (head + kAhead < order.size() && !faces.ahead.empty()) {
        const std::int64_t c = order[head + kAhead];
        __builtin_prefetch(&faces.ahead[c]);
        __builtin_prefetch(&p.across[p.all_tetrahedra ? 4 * c : fo[c]]);
      }
      const std::int64_t c = order[head++];
      successors(c, [&](std::int64_t m) {
        release(c, m);
        if (--in[m] == 0) order.push_back(m);
      });
    }
  };
  drain([](std::int64_t, std::int64_t) {});
  if (static_cast<std::int64_t>(order.size()) == n) return order;

  // Stalled: every cell left waits on another one left. The strongly connected components of
  // what is left, once; then each stall breaks a cycle at its farthest cell and goes on.
  std::vector<char> emitted(static_cast<std::size_t>(n), 0);
  for (std::int64_t c : order) emitted[c] = 1;
  std::vector<std::int64_t> start(static_cast<std::size_t>(n + 1), 0), to;
  for (std::int64_t c = 0; c < n; ++c) {
    if (!emitted[c])
      successors(c, [&](std::int64_t m) {
        if (!emitted[m]) to.push_back(m);
      });
    start[c + 1] = static_cast<std::int64_t>(to.size());
  }
  CycleBreaker breaker(std::move(start), std::move(to), emitted);
  std::vector<char> inside(gaps ? static_cast<std::size_t>(n) : 0, 0);  // the cells of the cycle at hand
  while (static_cast<std::int64_t>(order.size()) < n) {
    const std::vector<std::int64_t> cells = breaker.next_cycle(emitted);
    if (cells.empty()) throw InternalError("topological sort stalled without a visibility cycle");
    VisibilityCycle cycle;
    cycle.size = static_cast<std::int64_t>(cells.size());
    double farthest = -std::numeric_limits<double>::infinity();
    for (std::int64_t c : cells) {
      if (cycle.cells.size() < VisibilityCycle::kMaxCycleCells) cycle.cells.push_back(c);
      if (const double k = v.far_key(p.centroid[c]); k > farthest) farthest = k, cycle.broken_at = c;
    }
    if (gaps && !gaps->start.empty()) {
      for (std::int64_t c : cells) inside[c] = 1;
      for (std::int64_t c : cells)
        for (std::int64_t k = gaps->start[c]; k < gaps->start[c + 1] && !cycle.across_gap; ++k)
          cycle.across_gap = inside[gaps->to[k]];
      for (std::int64_t c : cells) inside[c] = 0;
    }
    cycle.relations_dropped = in[cycle.broken_at];
    in[cycle.broken_at] = 0;
    order.push_back(cycle.broken_at);
    emitted[cycle.broken_at] = 1;
    stats.cycles.push_back(std::move(cycle));
    drain([&](std::int64_t c, std::int64_t m) {
      if (!emitted[m]) breaker.consumed(c, m);
    });
    // The cells the drain queued after the broken one are out too.
    for (std::size_t k = order.size(); k-- > 0 && !emitted[order[k]];) emitted[order[k]] = 1;
  }
  return order;
}

}  // namespace cellproj
