#include "mesh/face_split.hpp"

#include <algorithm>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include "mesh/tetrahedralize.hpp"

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
  auto P = [&](std::int64_t i) {
    const glm::dvec3 x = pts(i);
    return K::Point_3(x.x, x.y, x.z);
  };
  return CGAL::orientation(P(a), P(b), P(c), P(d)) == CGAL::POSITIVE;
}

// reflex() in doubles where they are sure of it: 1 or 0, or -1 when d is too near the plane of
// (a, b, c) for the determinant's rounding (Shewchuk's bound for orient3d, 7.8e-16 of its
// permanent; here with a margin), where only the exact test can tell. Nearly coplanar pairs (the two
// halves of a planar quad) are common, and the exact test is slow on them.
int surely_reflex(const RecentredPoints& pts, std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d) {
  const glm::dvec3 pa = pts(a), u = pts(b) - pa, v = pts(c) - pa, w = pts(d) - pa;
  const double det = u.x * (v.y * w.z - v.z * w.y) + u.y * (v.z * w.x - v.x * w.z) + u.z * (v.x * w.y - v.y * w.x);
  const double permanent = std::abs(u.x) * (std::abs(v.y * w.z) + std::abs(v.z * w.y)) +
                           std::abs(u.y) * (std::abs(v.z * w.x) + std::abs(v.x * w.z)) +
                           std::abs(u.z) * (std::abs(v.x * w.y) + std::abs(v.y * w.x));
  const double bound = 2e-15 * permanent;
  return det > bound ? 1 : det < -bound ? 0 : -1;
}

// The triangles of a cell's surface (mesh/tetrahedralize) as the cell's own vertex indices.
int surface_triangles(const MeshView& mesh, std::int64_t c, std::uint8_t tri[kMaxSurfaceTriangles][3]) {
  const std::int64_t* ids = mesh.cell(c);
  std::int64_t global[kMaxSurfaceTriangles][3];
  const int n = surface_triangles(mesh, c, global);
  for (int t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k)
      tri[t][k] = static_cast<std::uint8_t>(std::find(ids, ids + mesh.cell_size(c), global[t][k]) - ids);
  return n;
}

// Appends the folds of cell c to out: pairs of its surface triangles across an edge (the
// triangle with the edge a -> b and the one with b -> a) whose dihedral angle is reflex, or too
// near flat for doubles to tell (left to the exact test, in the views that need it).
void cell_folds(const MeshView& mesh, const RecentredPoints& pts, std::int64_t c, std::vector<CellFolds::Fold>& out) {
  if (mesh.type(c) == CellType::Tetra) return;
  const std::int64_t* ids = mesh.cell(c);
  std::uint8_t tri[kMaxSurfaceTriangles][3];
  const int n = surface_triangles(mesh, c, tri);
  // A triangle with a repeated vertex (a collapsed cell) has no area and makes no fold.
  auto flat = [&](int t) { return tri[t][0] == tri[t][1] || tri[t][1] == tri[t][2] || tri[t][2] == tri[t][0]; };
  std::int8_t owner[8][8];  // owner[a][b]: the triangle with the directed edge a -> b
  std::fill(&owner[0][0], &owner[0][0] + 64, std::int8_t(-1));
  for (int t = 0; t < n; ++t)
    if (!flat(t))
      for (int e = 0; e < 3; ++e) owner[tri[t][e]][tri[t][(e + 1) % 3]] = static_cast<std::int8_t>(t);
  for (int t = 0; t < n; ++t)
    for (int e = 0; e < 3 && !flat(t); ++e) {
      const int u = owner[tri[t][(e + 1) % 3]][tri[t][e]];
      if (u <= t) continue;  // each pair once, from its lower triangle
      int far = 0;           // u's vertex off the shared edge (u has three distinct vertices)
      while (tri[u][far] == tri[t][e] || tri[u][far] == tri[t][(e + 1) % 3]) ++far;
      const int sure = surely_reflex(pts, ids[tri[t][0]], ids[tri[t][1]], ids[tri[t][2]], ids[tri[u][far]]);
      if (sure != 0)
        out.push_back({{tri[t][0], tri[t][1], tri[t][2]}, {tri[u][0], tri[u][1], tri[u][2]}, tri[u][far], sure < 0});
    }
}

}  // namespace

CellFolds::CellFolds(const MeshView& mesh, std::shared_ptr<const RecentredPoints> points)
    : mesh_(mesh), points_(std::move(points)), start_(static_cast<std::size_t>(mesh.n_cells) + 1, 0) {
  // Found per chunk of cells in parallel, then laid end to end in cell order.
  constexpr std::int64_t kChunk = 4096;
  const std::int64_t chunks = (mesh.n_cells + kChunk - 1) / kChunk;
  std::vector<std::vector<Fold>> found(static_cast<std::size_t>(chunks));
  tbb::parallel_for(std::int64_t(0), chunks, [&](std::int64_t k) {
    for (std::int64_t c = k * kChunk; c < std::min(mesh.n_cells, (k + 1) * kChunk); ++c) {
      const std::size_t before = found[k].size();
      cell_folds(mesh_, *points_, c, found[k]);
      start_[c + 1] = static_cast<std::int64_t>(found[k].size() - before);
    }
  });
  for (std::int64_t c = 0; c < mesh.n_cells; ++c) start_[c + 1] += start_[c];
  folds_.reserve(static_cast<std::size_t>(start_.back()));
  for (const auto& f : found) folds_.insert(folds_.end(), f.begin(), f.end());
}

std::vector<char> CellFolds::problem_cells(const Viewpoint& view, std::int64_t* count) const {
  const RecentredPoints& pts = *points_;
  std::vector<char> problem(static_cast<std::size_t>(mesh_.n_cells), 0);
  tbb::parallel_for(
      tbb::blocked_range<std::int64_t>(0, mesh_.n_cells, 4096), [&](const tbb::blocked_range<std::int64_t>& r) {
        for (std::int64_t c = r.begin(); c < r.end(); ++c) {
          if (mesh_.type(c) == CellType::Tetra) continue;
          const std::int64_t* ids = mesh_.cell(c);
          bool behind = false;  // at or behind the eye, or the orthographic eye's plane
          for (int k = 0; k < mesh_.cell_size(c) && !behind; ++k)
            behind = !(glm::dot(pts(ids[k]) - view.eye, view.dir) > 0.0);
          bool folded = false;
          for (std::int64_t f = start_[c]; f < start_[c + 1] && !behind && !folded; ++f) {
            const Fold& fold = folds_[f];
            folded = facing(pts, view, ids[fold.t[0]], ids[fold.t[1]], ids[fold.t[2]]) *
                             facing(pts, view, ids[fold.u[0]], ids[fold.u[1]], ids[fold.u[2]]) <
                         0 &&
                     (!fold.unsure || reflex(pts, ids[fold.t[0]], ids[fold.t[1]], ids[fold.t[2]], ids[fold.far]));
          }
          problem[c] = behind || folded;
        }
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
