#include "slicing/slice_cut.hpp"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/partitioner.h>

#include "slicing/cut_table.hpp"

namespace cellproj {
namespace {

// Slice cells per task: about 64 tasks, 256 to 4096 cells each; a function of the cell count alone,
// so the polygons' order does not depend on the thread count.
std::int64_t block_cells(std::int64_t cells) { return std::clamp<std::int64_t>(cells / 64, 256, 4096); }

// An edge's crossings of the planes, stepped: t(j) = t_first + (j - first) dt along lo -> hi
// (lo the lower point id, so both cells sharing the edge compute the same).
struct EdgeCrossings {
  bool ready = false;
  int first = 0;
  double t_first = 0.0, dt = 0.0;
  double h_lo = 0.0, h_hi = 0.0;  // the ends' heights
  std::int64_t lo = 0, hi = 0;
};

// Sutherland-Hodgman against z >= near, in the affine attributes.
int clip_near(const glm::dvec4* in, int n, double near, glm::dvec4* out) {
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const glm::dvec4& a = in[i];
    const glm::dvec4& b = in[(i + 1) % n];
    const bool a_in = a.z >= near, b_in = b.z >= near;
    if (a_in) out[m++] = a;
    if (a_in != b_in) out[m++] = a + (near - a.z) / (b.z - a.z) * (b - a);
  }
  return m;
}

void emit(const glm::dvec4* v, int n, bool perspective, SlicePolygons& out) {
  for (int i = 0; i < n; ++i) {
    const double w = perspective ? 1.0 / v[i].z : 1.0;
    out.x.push_back(v[i].x * w), out.y.push_back(v[i].y * w), out.w.push_back(w), out.sw.push_back(v[i].w * w);
  }
  out.start.push_back(static_cast<std::uint32_t>(out.x.size()));
}

void cut_cell(const SliceCells& cells, std::int64_t c, const FramePoints& f, const SlicePlanes& planes,
              const CellSweep& sweep, int first, int end, const std::vector<char>& wanted,
              std::vector<SlicePolygons>& out) {
  const CutTable& table = cut_table(static_cast<CellType>(cells.types[static_cast<std::size_t>(c)]));
  const std::int64_t* id = cells.ids.data() + cells.offsets[static_cast<std::size_t>(c)];
  double h[8];
  for (int v = 0; v < table.vertices; ++v) h[v] = f.height[static_cast<std::size_t>(id[v])];
  const int j0 = std::max(sweep.first(c), first), j1 = std::min(sweep.last(c), end - 1);
  EdgeCrossings edge[kMaxCellEdges];
  glm::dvec4 poly[kMaxCellEdges], clipped[kMaxCellEdges + 4];
  for (int j = j0; j <= j1; ++j) {
    if (!wanted[static_cast<std::size_t>(j - first)]) continue;
    const double d = planes.height(j);
    unsigned mask = 0;
    for (int v = 0; v < table.vertices; ++v) mask |= static_cast<unsigned>(h[v] < d) << v;
    const CutCase& cut = table.cases[mask];
    SlicePolygons& o = out[static_cast<std::size_t>(j - first)];
    for (int p = 0, k = 0; p < cut.polygons; ++p) {
      const int n = cut.size[p];
      bool near = false;
      for (int i = 0; i < n; ++i, ++k) {
        EdgeCrossings& e = edge[cut.edge[k]];
        if (!e.ready) {
          const CellEdge& ce = table.edges[cut.edge[k]];
          e.lo = std::min(id[ce.a], id[ce.b]), e.hi = std::max(id[ce.a], id[ce.b]);
          const double ha = f.height[static_cast<std::size_t>(e.lo)], hb = f.height[static_cast<std::size_t>(e.hi)];
          e.h_lo = ha, e.h_hi = hb;
          e.first = planes.first_above(std::min(ha, hb));
          e.t_first = (planes.height(e.first) - ha) / (hb - ha);
          e.dt = planes.spacing() / (hb - ha);
          e.ready = true;
        }
        // A plane through an end gives that end itself (every edge meeting there agrees).
        const double t = d == e.h_lo ? 0.0 : d == e.h_hi ? 1.0 : e.t_first + (j - e.first) * e.dt;
        const glm::dvec4& a = f.screen[static_cast<std::size_t>(e.lo)];
        const glm::dvec4& b = f.screen[static_cast<std::size_t>(e.hi)];
        poly[i] = (1.0 - t) * a + t * b;  // exact at both ends
        near = near || !(poly[i].z >= f.near);
      }
      if (!near) {
        emit(poly, n, f.perspective, o);
        continue;
      }
      ++o.clipped;
      const int m = clip_near(poly, n, f.near, clipped);
      if (m >= 3) emit(clipped, m, f.perspective, o);
    }
  }
}

}  // namespace

void SlicePolygons::append(const SlicePolygons& o) {
  const std::uint32_t base = static_cast<std::uint32_t>(x.size());
  x.insert(x.end(), o.x.begin(), o.x.end()), y.insert(y.end(), o.y.begin(), o.y.end());
  w.insert(w.end(), o.w.begin(), o.w.end()), sw.insert(sw.end(), o.sw.begin(), o.sw.end());
  for (std::size_t q = 1; q < o.start.size(); ++q) start.push_back(base + o.start[q]);
  clipped += o.clipped;
}

namespace {

// The planes j crossing slice cell c in this frame: [first, last] (none when last < first).
void planes_crossing(const SliceCells& cells, std::int64_t c, const FramePoints& f, const SlicePlanes& planes,
                     int& first, int& last) {
  double lo = INFINITY, hi = -INFINITY;
  for (std::int64_t k = cells.offsets[c]; k < cells.offsets[c + 1]; ++k) {
    const double h = f.height[static_cast<std::size_t>(cells.ids[static_cast<std::size_t>(k)])];
    lo = std::min(lo, h), hi = std::max(hi, h);
  }
  planes.crossing(lo, hi, first, last);
}

}  // namespace

CellSweep::CellSweep(const SliceCells& cells, const FramePoints& f, const SlicePlanes& planes)
    : range_(static_cast<std::size_t>(cells.size())) {
  tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, cells.size(), 4096),
                    [&](const tbb::blocked_range<std::int64_t>& r) {
                      for (std::int64_t c = r.begin(); c < r.end(); ++c) {
                        Range& x = range_[static_cast<std::size_t>(c)];
                        planes_crossing(cells, c, f, planes, x.first, x.last);
                      }
                    });
  // A counting sort by first plane: the cells enter the sweep in plane order, each run of planes
  // appending those that start in it.
  std::vector<std::int64_t> count(static_cast<std::size_t>(planes.count()) + 3, 0);
  for (const Range& x : range_) {
    if (x.last < x.first)
      ++between_;
    else
      ++count[static_cast<std::size_t>(x.first) + 1];
  }
  for (std::size_t k = 1; k < count.size(); ++k) count[k] += count[k - 1];
  by_first_.resize(static_cast<std::size_t>(count.back()));
  for (std::int64_t c = 0; c < cells.size(); ++c) {
    const Range& x = range_[static_cast<std::size_t>(c)];
    if (x.last >= x.first) by_first_[static_cast<std::size_t>(count[static_cast<std::size_t>(x.first)]++)] = c;
  }
}

void CellSweep::drop(const std::vector<char>& skip) {
  std::size_t kept = 0;  // in their order
  for (std::int64_t c : by_first_)
    if (!skip[static_cast<std::size_t>(c)]) by_first_[kept++] = c;
  by_first_.resize(kept);
  for (std::size_t c = 0; c < range_.size(); ++c)
    if (skip[c]) {
      between_ -= range_[c].last < range_[c].first;
      range_[c] = {1, -1};
    }
}

const std::vector<std::int64_t>& CellSweep::advance(int first, int end) {
  std::size_t kept = 0;  // those still crossing a plane from `first` on, in their order
  for (std::int64_t c : active_)
    if (range_[static_cast<std::size_t>(c)].last >= first) active_[kept++] = c;
  active_.resize(kept);
  for (; entered_ < by_first_.size(); ++entered_) {
    const std::int64_t c = by_first_[entered_];
    const Range& x = range_[static_cast<std::size_t>(c)];
    if (x.first >= end) break;
    if (x.last >= first) active_.push_back(c);
  }
  return active_;
}

void cut_planes(const SliceCells& cells, const FramePoints& points, const SlicePlanes& planes, const CellSweep& sweep,
                const std::vector<std::int64_t>& active, int first, int end, const std::vector<char>& wanted,
                CutBlocks& per_block) {
  const std::size_t planes_here = static_cast<std::size_t>(end - first);
  const std::int64_t n = static_cast<std::int64_t>(active.size());
  const std::int64_t per = block_cells(n), blocks = (n + per - 1) / per;
  if (per_block.size() < static_cast<std::size_t>(blocks)) per_block.resize(static_cast<std::size_t>(blocks));
  tbb::parallel_for(
      tbb::blocked_range<std::int64_t>(0, blocks, 1),
      [&](const tbb::blocked_range<std::int64_t>& r) {
        for (std::int64_t b = r.begin(); b < r.end(); ++b) {
          std::vector<SlicePolygons>& o = per_block[static_cast<std::size_t>(b)];
          o.resize(std::max(o.size(), planes_here));
          for (SlicePolygons& p : o) p.clear();
          for (std::int64_t k = b * per, e = std::min(n, k + per); k < e; ++k)
            cut_cell(cells, active[static_cast<std::size_t>(k)], points, planes, sweep, first, end, wanted, o);
        }
      },
      tbb::simple_partitioner());
  for (std::size_t b = static_cast<std::size_t>(blocks); b < per_block.size(); ++b)
    for (SlicePolygons& p : per_block[b]) p.clear();  // blocks of an earlier, longer list: empty here
}

}  // namespace cellproj
