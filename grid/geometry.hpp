#pragma once
// Small geometric quantities of cells and faces.
#include <cmath>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "grid/mesh.hpp"

namespace cellproj {

// Six times the signed volume of tetrahedron (a, b, c, d); positive in VTK's orientation, where
// (a, b, c) turns counter-clockwise seen from d.
inline double tet_volume6(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
  return glm::dot(glm::cross(b - a, c - a), d - a);
}

// Signed volume of any supported cell (divergence theorem over its faces, quads fanned from their
// centroid, so a non-planar face counts as the bilinear-ish surface it approximates).
double cell_signed_volume(const MeshView& mesh, std::int64_t cell);

// The diagonal of the cell's bounding box: a length scale for tolerances.
double cell_size(const MeshView& mesh, std::int64_t cell);

// Non-planarity of quad (a, b, c, d): the distance between its two diagonals (0 when planar).
double quad_warp(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d);

// A cell is degenerate when |volume| is at round-off level for its size (a length).
constexpr double kDegenerateRelativeVolume = 1e-14;
inline bool degenerate_volume(double volume, double size) {
  return std::abs(volume) <= kDegenerateRelativeVolume * size * size * size;
}

}  // namespace cellproj
