#pragma once
// Small geometric quantities of cells and faces.
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "base/recentred_points.hpp"
#include "mesh/mesh.hpp"

namespace cellproj {

// Six times the signed volume of tetrahedron (a, b, c, d); positive in VTK's orientation, where
// (a, b, c) turns counter-clockwise seen from d.
inline double tet_volume6(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
  return glm::dot(glm::cross(b - a, c - a), d - a);
}

// The vertices of tetrahedron p's face opposite vertex f, and that face's normal (not unit) pointing
// out of the tetrahedron, away from p[f].
inline constexpr int kTetFace[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
inline glm::dvec3 tet_face_normal(const glm::dvec3 p[4], int f) {
  const glm::dvec3& a = p[kTetFace[f][0]];
  const glm::dvec3 n = glm::cross(p[kTetFace[f][1]] - a, p[kTetFace[f][2]] - a);
  return glm::dot(n, p[f] - a) > 0 ? -n : n;
}

// The triple product of tetrahedron p's edges out of p[0], e1 . (e2 x e3): tet_volume6's value, in
// the order linear_gradient divides by it.
inline double edges_triple_product(const glm::dvec3 p[4]) {
  return glm::dot(p[1] - p[0], glm::cross(p[2] - p[0], p[3] - p[0]));
}
// The gradient g of the field linear over tetrahedron p with values s at its vertices,
// s(x) = s[0] + g . (x - p[0]), from the three edges out of p[0]; `det` is edges_triple_product(p)
// (non-zero).
inline glm::dvec3 linear_gradient(const glm::dvec3 p[4], const double s[4], double det) {
  const glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0], e3 = p[3] - p[0];
  return (glm::cross(e2, e3) * (s[1] - s[0]) + glm::cross(e3, e1) * (s[2] - s[0]) +
          glm::cross(e1, e2) * (s[3] - s[0])) /
         det;
}

// Signed volume of any supported cell (divergence theorem over its faces, quads fanned from their
// centroid, so a non-planar face counts as the bilinear-ish surface it approximates).
double cell_signed_volume(const MeshView& mesh, std::int64_t cell);

// The diagonal of the cell's bounding box: a length scale for tolerances.
double cell_size(const MeshView& mesh, std::int64_t cell);

// The mean of the cell's vertices.
glm::dvec3 cell_centroid(const MeshView& mesh, std::int64_t cell);

// The box of the mesh's points: its lower and upper corner (lower above upper for no points).
std::pair<glm::dvec3, glm::dvec3> point_bounds(const MeshView& mesh);

// Non-planarity of quad (a, b, c, d): the distance between its two diagonals (0 when planar).
double quad_warp(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d);

// Newell's normal: twice the vector area of a (possibly non-planar) polygon, turning with its order.
glm::dvec3 newell_normal(const glm::dvec3* p, int n);

// Sorts a triangle's three vertex ids increasingly; returns true when that reversed its turning.
// Planes built from the sorted ids are bit-identical for every cell sharing the face.
inline bool sort_triangle_ids(std::int64_t id[3]) {
  bool flip = false;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2 - i; ++j)
      if (id[j] > id[j + 1]) std::swap(id[j], id[j + 1]), flip = !flip;
  return flip;
}

// The mesh's points recentred on their bounding box (base/recentred_points.hpp).
RecentredPoints recentre(const MeshView& mesh);

// The groups of points at the same place (coordinates equal as doubles: -0 is 0; a non-finite
// point is never in one) among `candidates` (each listed once), as a flat list: group g's ids,
// increasing, are ids[start[g]] to ids[start[g + 1]]. Found by a sort of a hash of the
// coordinates (flat keys, no indirection in the sort), then each run of equal hashes by
// coordinates. Validation's duplicate points and the seams' glued points are these groups.
struct PointGroups {
  std::vector<std::int64_t> ids;
  std::vector<std::int64_t> start{0};
};
PointGroups coincident_points(const MeshView& mesh, const std::vector<std::int64_t>& candidates);

// A cell is degenerate when |volume| is at round-off level for its size (a length).
constexpr double kDegenerateRelativeVolume = 1e-14;
inline bool degenerate_volume(double volume, double size) {
  return std::abs(volume) <= kDegenerateRelativeVolume * size * size * size;
}

}  // namespace cellproj
