#include "mesh/topology.hpp"

#include <algorithm>

#include <array>
#include <glm/common.hpp>
#include <limits>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "base/huge_pages.hpp"
#include "mesh/face_match.hpp"
#include "mesh/geometry.hpp"
#include "mesh/tetrahedralize.hpp"

namespace cellproj {
namespace {

FaceKey face_key(const std::int64_t* ids, const FaceDef& face) {
  FaceKey k{0, 0, 0, std::numeric_limits<std::int64_t>::max()};
  for (int i = 0; i < face.size; ++i) k[i] = ids[face.v[i]];
  auto order = [&](int a, int b) {
    if (k[a] > k[b]) std::swap(k[a], k[b]);
  };
  if (face.size == 3) {
    order(0, 1), order(1, 2), order(0, 1);
  } else {  // a 5-comparator sorting network for 4
    order(0, 1), order(2, 3), order(0, 2), order(1, 3), order(1, 2);
  }
  return k;
}

// Positions of one cell face's vertices, in the face's cyclic order.
int face_points(const MeshView& m, std::int64_t cell, int local, glm::dvec3 p[4]) {
  const FaceDef& face = cell_def(m.type(cell)).face[local];
  for (int i = 0; i < face.size; ++i) p[i] = m.point(m.cell(cell)[face.v[i]]);
  return face.size;
}

}  // namespace

std::int64_t FaceTopology::cell_of(std::int64_t cf) const {
  return static_cast<std::int64_t>(std::upper_bound(face_offsets.begin(), face_offsets.end(), cf) -
                                   face_offsets.begin()) -
         1;
}

std::int64_t match_quads_to_triangles(const MeshView& m, FaceTopology& t, const std::vector<std::int64_t>& open,
                                      const std::function<std::int64_t(std::int64_t)>& same,
                                      const std::function<bool(std::int64_t, std::int64_t)>& accept) {
  auto key_of = [&](std::int64_t* ids, int n) {
    for (int i = 0; i < n; ++i) ids[i] = same(ids[i]);
    return face_key_of(ids, n);
  };
  auto ids_of = [&](std::int64_t cf, std::int64_t ids[4]) {
    const std::int64_t c = t.cell_of(cf);
    const FaceDef& face = cell_def(m.type(c)).face[cf - t.face_offsets[c]];
    for (int i = 0; i < face.size; ++i) ids[i] = m.cell(c)[face.v[i]];
    return static_cast<int>(face.size);
  };
  std::vector<std::pair<FaceKey, std::int64_t>> tris;
  std::vector<std::int64_t> quads;
  std::int64_t matched = 0;
  for (const std::int64_t cf : open) {
    std::int64_t ids[4];
    const int n = ids_of(cf, ids);
    if (n == 3)
      tris.emplace_back(key_of(ids, 3), cf);
    else
      quads.push_back(cf);
  }
  if (tris.empty() || quads.empty()) return matched;
  std::sort(tris.begin(), tris.end());
  auto find = [&](std::int64_t tri[3]) -> std::int64_t {  // the only open triangle with tri's key, or -1
    const FaceKey k = key_of(tri, 3);
    const auto it = std::lower_bound(tris.begin(), tris.end(), std::make_pair(k, std::int64_t(-1)));
    if (it == tris.end() || it->first != k || (it + 1 != tris.end() && (it + 1)->first == k)) return -1;
    return t.neighbor[it->second] == kBoundary ? it->second : -1;
  };
  for (const std::int64_t q : quads) {
    std::int64_t ids[4], tri[2][3];
    ids_of(q, ids);
    split_quad(ids, tri);
    const std::int64_t f0 = find(tri[0]), f1 = find(tri[1]), c = t.cell_of(q);
    if (f0 < 0 || f1 < 0 || !accept(q, f0) || !accept(q, f1)) continue;
    t.neighbor[q] = kSplitFace;
    t.neighbor[f0] = t.neighbor[f1] = c;
    t.split_faces.push_back({q, f0, f1});
    ++t.shared_faces;
    ++matched;
  }
  return matched;
}

namespace {

// A face in a bucket: its key, cell face and cell; ordered by key, then cell face.
struct KeyedFace {
  FaceKey key;
  std::int64_t face, cell;
  bool operator<(const KeyedFace& o) const { return key < o.key || (key == o.key && face < o.face); }
};

// What matching the faces of a range of buckets found (summed over buckets in any order).
struct MatchCounts {
  std::int64_t shared = 0, nonmanifold = 0, nonplanar = 0;
  std::int64_t first_nonmanifold_point = -1, first_nonmanifold_cell = -1;  // in the lowest bucket with one
  double max_warp = 0.0, max_relative_warp = 0.0;
  void add(const MatchCounts& o) {
    shared += o.shared, nonmanifold += o.nonmanifold, nonplanar += o.nonplanar;
    max_warp = std::max(max_warp, o.max_warp), max_relative_warp = std::max(max_relative_warp, o.max_relative_warp);
    if (o.first_nonmanifold_point >= 0 &&
        (first_nonmanifold_point < 0 || o.first_nonmanifold_point < first_nonmanifold_point))
      first_nonmanifold_point = o.first_nonmanifold_point, first_nonmanifold_cell = o.first_nonmanifold_cell;
  }
};

// The faces whose lowest vertex is p (cell * 8 + local face each), matched by their keys: runs of
// two equal keys are shared faces, longer runs non-manifold; each quad's warp is measured once.
void match_bucket(const MeshView& m, FaceTopology& t, std::int64_t p, const std::int64_t* faces, std::size_t n,
                  std::vector<KeyedFace>& keyed, MatchCounts& counts) {
  keyed.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t c = faces[i] >> 3, local = faces[i] & 7;
    keyed.push_back({face_key(m.cell(c), cell_def(m.type(c)).face[local]), t.face_offsets[c] + local, c});
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i + 1;
    while (j < n && keyed[j].key == keyed[i].key) ++j;
    const std::int64_t a = keyed[i].face, c = keyed[i].cell;
    if (j - i == 2) {
      t.neighbor[a] = keyed[i + 1].cell;
      t.neighbor[keyed[i + 1].face] = c;
      ++counts.shared;
    } else if (j - i > 2) {
      for (std::size_t k = i; k < j; ++k) t.neighbor[keyed[k].face] = kNonManifold;
      ++counts.nonmanifold;
      if (counts.first_nonmanifold_point < 0 || p < counts.first_nonmanifold_point)  // the lowest bucket's first run
        counts.first_nonmanifold_point = p, counts.first_nonmanifold_cell = c;
    }
    if (keyed[i].key[3] != std::numeric_limits<std::int64_t>::max()) {  // a quad: measure it once
      glm::dvec3 q[4];
      face_points(m, c, static_cast<int>(a - t.face_offsets[c]), q);
      const double warp = quad_warp(q[0], q[1], q[2], q[3]);
      const double diag = 0.5 * (glm::length(q[2] - q[0]) + glm::length(q[3] - q[1]));
      const double rel = diag > 0 ? warp / diag : 0.0;
      counts.max_warp = std::max(counts.max_warp, warp);
      counts.max_relative_warp = std::max(counts.max_relative_warp, rel);
      if (rel > kNonPlanarRelative) ++counts.nonplanar;
    }
    i = j;
  }
}

}  // namespace

FaceTopology build_topology(const MeshView& m) {
  FaceTopology t;
  reserve_in_huge_pages(t.face_offsets, static_cast<std::size_t>(m.n_cells) + 1);
  t.face_offsets.resize(static_cast<std::size_t>(m.n_cells) + 1, 0);
  for (std::int64_t c = 0; c < m.n_cells; ++c) t.face_offsets[c + 1] = t.face_offsets[c] + cell_def(m.type(c)).faces;
  const std::int64_t n_faces = t.face_offsets.back();
  reserve_in_huge_pages(t.neighbor, static_cast<std::size_t>(n_faces));
  t.neighbor.assign(static_cast<std::size_t>(n_faces), kBoundary);

  // A counting sort of the faces by their lowest vertex (a shared face's cells agree on it); the
  // keys are made per bucket, where they stay in cache, instead of 32 bytes a face in memory.
  auto lowest = [&](std::int64_t c, const FaceDef& face) {
    std::int64_t low = m.cell(c)[face.v[0]];
    for (int i = 1; i < face.size; ++i) low = std::min(low, m.cell(c)[face.v[i]]);
    return low;
  };
  std::vector<std::int64_t> start;
  reserve_in_huge_pages(start, static_cast<std::size_t>(m.n_points) + 1);
  start.assign(static_cast<std::size_t>(m.n_points) + 1, 0);
  for (std::int64_t c = 0; c < m.n_cells; ++c) {
    const CellDef& def = cell_def(m.type(c));
    for (int f = 0; f < def.faces; ++f) ++start[lowest(c, def.face[f]) + 1];
  }
  for (std::int64_t p = 0; p < m.n_points; ++p) start[p + 1] += start[p];
  FrameBuffer<std::int64_t> bucketed(static_cast<std::size_t>(n_faces));  // cell * 8 + local face
  {
    std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
    for (std::int64_t c = 0; c < m.n_cells; ++c) {
      const CellDef& def = cell_def(m.type(c));
      for (int f = 0; f < def.faces; ++f) bucketed[fill[lowest(c, def.face[f])]++] = c * 8 + f;
    }
  }
  const MatchCounts counts = tbb::parallel_reduce(
      tbb::blocked_range<std::int64_t>(0, m.n_points, 1024), MatchCounts{},
      [&](const tbb::blocked_range<std::int64_t>& r, MatchCounts counts) {
        std::vector<KeyedFace> keyed;
        for (std::int64_t p = r.begin(); p < r.end(); ++p)
          match_bucket(m, t, p, bucketed.data() + start[p], static_cast<std::size_t>(start[p + 1] - start[p]), keyed,
                       counts);
        return counts;
      },
      [](MatchCounts a, const MatchCounts& b) {
        a.add(b);
        return a;
      });
  t.shared_faces = counts.shared, t.nonmanifold_faces = counts.nonmanifold;
  t.first_nonmanifold_cell = counts.first_nonmanifold_cell;
  t.nonplanar_faces = counts.nonplanar;
  t.max_nonplanarity = counts.max_warp, t.max_relative_nonplanarity = counts.max_relative_warp;
  // Quads whose two triangles are faces of other cells (a neighbour split into tetrahedra,
  // mesh/face_split) are shared with both.
  std::vector<std::int64_t> open;
  for (std::int64_t f = 0; f < n_faces; ++f)
    if (t.neighbor[f] == kBoundary) open.push_back(f);
  match_quads_to_triangles(
      m, t, open, [](std::int64_t p) { return p; }, [](std::int64_t, std::int64_t) { return true; });
  for (const std::int64_t f : open)
    if (t.neighbor[f] == kBoundary) t.boundary.push_back(f);
  glue_seams(m, t);
  return t;
}

BoundaryHull::BoundaryHull(const MeshView& m, const FaceTopology& t) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<char> on_boundary(static_cast<std::size_t>(m.n_points), 0);
  std::vector<K::Point_3> pts;
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (std::int64_t cf : t.boundary) {
    const std::int64_t c = t.cell_of(cf);
    const FaceDef& face = cell_def(m.type(c)).face[cf - t.face_offsets[c]];
    for (int i = 0; i < face.size; ++i) {
      const std::int64_t p = m.cell(c)[face.v[i]];
      if (on_boundary[p]) continue;
      on_boundary[p] = 1;
      const glm::dvec3 x = m.point(p);
      pts.emplace_back(x.x, x.y, x.z);
      lo = glm::min(lo, x);
      hi = glm::max(hi, x);
    }
  }
  if (pts.empty()) return;
  CGAL::Surface_mesh<K::Point_3> hull;
  CGAL::convex_hull_3(pts.begin(), pts.end(), hull);
  if (hull.number_of_faces() == 0) return;  // flat or lower-dimensional: no volume to be convex
  for (auto v : hull.vertices()) {
    const auto& p = hull.point(v);
    vertex_.emplace_back(p.x(), p.y(), p.z());
    adjacent_.emplace_back();
    for (auto u : CGAL::vertices_around_target(hull.halfedge(v), hull)) adjacent_.back().push_back(static_cast<int>(u));
  }
  tol_ = 1e-6 * glm::length(hi - lo);  // float32 files round curved hulls by ~1e-7
}

// On a convex polytope a vertex with no better neighbour maximizes a linear function.
double BoundaryHull::support(const glm::dvec3& n, int& v) const {
  double best = glm::dot(n, vertex_[v]);
  for (bool moved = true; moved;) {
    moved = false;
    for (int u : adjacent_[v])
      if (const double d = glm::dot(n, vertex_[u]); d > best) {
        best = d;
        v = u;
        moved = true;
        break;
      }
  }
  return best;
}

bool BoundaryHull::supports(const glm::dvec3& dir, const glm::dvec3* p, int n, int& up, int& down) const {
  double fmax = -std::numeric_limits<double>::max(), fmin = std::numeric_limits<double>::max();
  for (int i = 0; i < n; ++i) {
    fmax = std::max(fmax, glm::dot(dir, p[i]));
    fmin = std::min(fmin, glm::dot(dir, p[i]));
  }
  // Either side of the face may be the outside (inverted cells are not re-oriented in a view).
  return support(dir, up) <= fmax + tol_ || -support(-dir, down) >= fmin - tol_;
}

HullReport boundary_convexity(const MeshView& m, const FaceTopology& t) {
  return boundary_convexity(m, t, BoundaryHull(m, t));
}

HullReport boundary_convexity(const MeshView& m, const FaceTopology& t, const BoundaryHull& hull) {
  HullReport r;
  if (t.boundary.empty() || hull.empty()) return r;
  int up = 0, down = 0;
  double area = 0.0, off_area = 0.0;
  r.off_hull.assign(t.boundary.size(), 0);
  for (std::size_t b = 0; b < t.boundary.size(); ++b) {
    const std::int64_t cf = t.boundary[b];
    const std::int64_t c = t.cell_of(cf);
    glm::dvec3 p[4];
    const int n = face_points(m, c, static_cast<int>(cf - t.face_offsets[c]), p);
    const glm::dvec3 nn = newell_normal(p, n);
    const double len = glm::length(nn);
    area += 0.5 * len;
    if (len == 0.0) {  // a collapsed face: no area to see, but never assumed on the hull
      r.off_hull[b] = 1;
      continue;
    }
    if (!hull.supports(nn / len, p, n, up, down)) {
      r.off_hull[b] = 1;
      ++r.boundary_faces_off_hull;
      off_area += 0.5 * len;
    }
  }
  r.convex = r.boundary_faces_off_hull == 0;
  r.off_hull_area_share = area > 0 ? off_area / area : 0.0;
  return r;
}

}  // namespace cellproj
