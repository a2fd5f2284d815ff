#include "grid/face_split.hpp"

#include <algorithm>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "grid/tetrahedralize.hpp"

namespace cellproj {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// Which way triangle (a, b, c) turns seen from the viewpoint: +1 facing it, -1 facing away, 0 edge-on.
int facing(const RecentredPoints& pts, const Viewpoint& view, std::int64_t a, std::int64_t b, std::int64_t c) {
  const glm::dvec3 pa = pts(a), pb = pts(b), pc = pts(c);
  if (view.perspective) {  // exact: the eye above the triangle's plane (counter-clockwise seen from it)
    auto P = [](const glm::dvec3& x) { return K::Point_3(x.x, x.y, x.z); };
    const auto o = CGAL::orientation(P(pa), P(pb), P(pc), P(view.eye));
    return o == CGAL::POSITIVE ? 1 : o == CGAL::NEGATIVE ? -1 : 0;
  }
  const double s = -glm::dot(glm::cross(pb - pa, pc - pa), view.dir);
  return s > 0 ? 1 : s < 0 ? -1 : 0;
}

int reflex(const RecentredPoints& pts, std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d) {
  // d beyond the outward side of triangle (a, b, c): the edge the two triangles share folds inward.
  auto P = [&](std::int64_t i) { const glm::dvec3 x = pts(i); return K::Point_3(x.x, x.y, x.z); };
  return CGAL::orientation(P(a), P(b), P(c), P(d)) == CGAL::POSITIVE;
}

// A ray crosses the cell's surface (its quads split by the lowest-id diagonal) more than twice
// only across a contour edge that folds inward: an edge whose two triangles face opposite ways
// from the viewpoint while the cell is not convex there (figure 3's warped diagonal, or a cell
// bent at one of its own edges).
bool is_problem(const MeshView& mesh, const RecentredPoints& pts, const Viewpoint& view, std::int64_t c) {
  const CellDef& def = cell_def(mesh.type(c));
  const std::int64_t* ids = mesh.cell(c);
  if (def.vertices == 4) return false;
  if (view.perspective)
    for (int k = 0; k < def.vertices; ++k)
      if (!(glm::dot(pts(ids[k]) - view.eye, view.dir) > 0.0)) return true;
  std::int64_t tri[12][3];
  int n = 0;
  for (int f = 0; f < def.faces; ++f) {
    const FaceDef& face = def.face[f];
    std::int64_t q[4];
    for (int k = 0; k < face.size; ++k) q[k] = ids[face.v[k]];
    if (face.size == 3) {
      std::copy(q, q + 3, tri[n++]);
      continue;
    }
    std::int64_t t[2][3];
    split_quad(q, t);
    std::copy(t[0], t[0] + 3, tri[n++]);
    std::copy(t[1], t[1] + 3, tri[n++]);
  }
  int side[12];
  for (int t = 0; t < n; ++t) side[t] = facing(pts, view, tri[t][0], tri[t][1], tri[t][2]);
  for (int t = 0; t < n; ++t)
    for (int e = 0; e < 3; ++e) {
      const std::int64_t a = tri[t][e], b = tri[t][(e + 1) % 3];
      for (int u = t + 1; u < n; ++u) {
        if (side[t] * side[u] >= 0) continue;  // not a contour edge between these two
        for (int g = 0; g < 3; ++g)
          if (tri[u][g] == b && tri[u][(g + 1) % 3] == a &&
              reflex(pts, tri[t][0], tri[t][1], tri[t][2], tri[u][(g + 2) % 3]))
            return true;
      }
    }
  return false;
}

}  // namespace

std::vector<char> problem_cells(const MeshView& mesh, const RecentredPoints& points, const Viewpoint& view,
                                std::int64_t* count) {
  std::vector<char> problem(static_cast<std::size_t>(mesh.n_cells), 0);
  tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, mesh.n_cells, 4096), [&](const tbb::blocked_range<std::int64_t>& r) {
    for (std::int64_t c = r.begin(); c < r.end(); ++c) problem[c] = is_problem(mesh, points, view, c);
  });
  if (count) *count = std::count(problem.begin(), problem.end(), char(1));
  return problem;
}

SplitMesh split_cells(const MeshView& mesh, const std::vector<char>& which) {
  SplitMesh out;
  out.connectivity.reserve(static_cast<std::size_t>(mesh.offsets[mesh.n_cells]));
  out.types.reserve(static_cast<std::size_t>(mesh.n_cells));
  out.parent.reserve(static_cast<std::size_t>(mesh.n_cells));
  Tet tets[kMaxTetsPerCell];
  for (std::int64_t c = 0; c < mesh.n_cells; ++c) {
    const bool tet = mesh.type(c) == CellType::Tetra;
    if (tet || !(which.empty() || which[c])) {
      out.connectivity.insert(out.connectivity.end(), mesh.cell(c), mesh.cell(c) + mesh.cell_size(c));
      out.offsets.push_back(static_cast<std::int64_t>(out.connectivity.size()));
      out.types.push_back(mesh.types[c]);
      out.parent.push_back(c);
      continue;
    }
    ++out.cells_split;
    const int n = canonical_tetrahedra(mesh, c, tets);
    for (int k = 0; k < n; ++k) {
      out.connectivity.insert(out.connectivity.end(), tets[k].begin(), tets[k].end());
      out.offsets.push_back(static_cast<std::int64_t>(out.connectivity.size()));
      out.types.push_back(static_cast<std::uint8_t>(CellType::Tetra));
      out.parent.push_back(c);
    }
  }
  out.view = mesh;
  out.view.connectivity = out.connectivity.data();
  out.view.offsets = out.offsets.data();
  out.view.types = out.types.data();
  out.view.n_cells = static_cast<std::int64_t>(out.types.size());
  return out;
}

}  // namespace cellproj
