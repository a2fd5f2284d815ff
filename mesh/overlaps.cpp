#include "mesh/overlaps.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include <CGAL/Bbox_3.h>
#include <CGAL/box_intersection_d.h>
#include <glm/geometric.hpp>

#include "mesh/geometry.hpp"
#include "mesh/tetrahedralize.hpp"

namespace cellproj {
namespace {

constexpr double kTouch = 1e-9;  // overlaps thinner than this share of the tetrahedra's size are contacts

using Corners = std::array<glm::dvec3, 4>;

constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
constexpr int kFace[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};

// Whether the plane normal to n (unnormalized) has a and b on either side, to within tol.
bool separates(const glm::dvec3& n, const Corners& a, const Corners& b, double tol) {
  const double len = glm::length(n);
  if (!(len > 0.0)) return false;
  double amin = glm::dot(n, a[0]), amax = amin, bmin = glm::dot(n, b[0]), bmax = bmin;
  for (int k = 1; k < 4; ++k) {
    const double da = glm::dot(n, a[k]), db = glm::dot(n, b[k]);
    amin = std::min(amin, da), amax = std::max(amax, da), bmin = std::min(bmin, db), bmax = std::max(bmax, db);
  }
  return amax <= bmin + tol * len || bmax <= amin + tol * len;
}

// The separating-axis test of two convex polytopes: their interiors are disjoint exactly when a
// face normal of either, or the cross product of an edge of each, separates them.
bool interiors_overlap(Corners a, Corners b) {
  const glm::dvec3 origin = a[0];  // local coordinates: rounding at the tetrahedra's own size
  double size = 0.0;
  for (int k = 0; k < 4; ++k) a[k] -= origin, b[k] -= origin;
  for (const auto& e : kEdge) size = std::max({size, glm::length(a[e[1]] - a[e[0]]), glm::length(b[e[1]] - b[e[0]])});
  const double tol = kTouch * size;
  for (const Corners* t : {&a, &b})
    for (const auto& f : kFace)
      if (separates(glm::cross((*t)[f[1]] - (*t)[f[0]], (*t)[f[2]] - (*t)[f[0]]), a, b, tol)) return false;
  for (const auto& ea : kEdge)
    for (const auto& eb : kEdge)
      if (separates(glm::cross(a[ea[1]] - a[ea[0]], b[eb[1]] - b[eb[0]]), a, b, tol)) return false;
  return true;
}

}  // namespace

OverlapReport overlapping_cells(const MeshView& mesh) {
  std::vector<Corners> tet;
  std::vector<std::int64_t> cell;  // per tetrahedron
  for (std::int64_t c = 0; c < mesh.n_cells; ++c) {
    Tet t[kMaxTetsPerCell];
    const int n = canonical_tetrahedra(mesh, c, t);
    for (int k = 0; k < n; ++k) {
      const Corners x = {mesh.point(t[k][0]), mesh.point(t[k][1]), mesh.point(t[k][2]), mesh.point(t[k][3])};
      const double volume = glm::dot(glm::cross(x[1] - x[0], x[2] - x[0]), x[3] - x[0]) / 6.0;
      const double size = glm::length(x[1] - x[0]) + glm::length(x[2] - x[0]) + glm::length(x[3] - x[0]);
      if (degenerate_volume(volume, size) || !std::isfinite(volume)) continue;  // no interior
      tet.push_back(x);
      cell.push_back(c);
    }
  }
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::size_t>;
  std::vector<Box> boxes;
  boxes.reserve(tet.size());
  for (std::size_t k = 0; k < tet.size(); ++k) {
    const Corners& x = tet[k];
    CGAL::Bbox_3 b(x[0].x, x[0].y, x[0].z, x[0].x, x[0].y, x[0].z);
    for (int i = 1; i < 4; ++i) b += CGAL::Bbox_3(x[i].x, x[i].y, x[i].z, x[i].x, x[i].y, x[i].z);
    boxes.emplace_back(b, k);
  }
  OverlapReport r;
  std::vector<std::pair<std::int64_t, std::int64_t>> pairs;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    const std::int64_t ca = cell[a.info()], cb = cell[b.info()];
    if (ca == cb) return;  // a cell's own tetrahedra meet at faces
    ++r.candidates;
    if (interiors_overlap(tet[a.info()], tet[b.info()])) pairs.emplace_back(std::min(ca, cb), std::max(ca, cb));
  });
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  r.cell_pairs = static_cast<std::int64_t>(pairs.size());
  if (!pairs.empty()) r.first_a = pairs[0].first, r.first_b = pairs[0].second;
  return r;
}

}  // namespace cellproj
