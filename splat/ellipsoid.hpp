#pragma once
// A cell as a Gaussian ellipsoid (MWSC section 6): the centre of gravity and the covariance of its
// volume, taken uniform, from its tetrahedra.
#include <cstdint>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "mesh/cell_type.hpp"
#include "mesh/geometry.hpp"

namespace cellproj {

struct CellMoments {
  double volume = 0.0;  // signed: negative for an inverted cell
  glm::dvec3 centre{0.0};
  glm::dmat3 covariance{0.0};  // of a point uniform in the cell
  double size = 0.0;           // the longest edge from the first vertex, for the degeneracy test
};

// The moments of the cell with point ids `ids` of `type`, summed over the tetrahedra of
// for_each_fan_tet, each of volume V, centroid m = sum(p) / 4 and second moment
// (sum(p p^T) + sum(p) sum(p)^T) / 20.
CellMoments cell_moments(const std::int64_t* ids, CellType type, const RecentredPoints& points);

// Calls tet(q0, q1, q2) for each tetrahedron (ids[0], q0, q1, q2) of the cell's fan: its first
// vertex joined to the triangles of the faces without it, the quads fanned from their first vertex
// (point ids, turning as the face: VTK-positive tetrahedra for a positive convex cell).
template <class Tet>
void for_each_fan_tet(const std::int64_t* ids, CellType type, Tet&& tet) {
  const CellDef& def = cell_def(type);
  for (int f = 0; f < def.faces; ++f) {
    const FaceDef& face = def.face[f];
    bool has_apex = false;
    for (int k = 0; k < face.size; ++k) has_apex = has_apex || face.v[k] == 0;
    if (has_apex) continue;
    for (int k = 1; k + 1 < face.size; ++k) tet(ids[face.v[0]], ids[face.v[k]], ids[face.v[k + 1]]);
  }
}

// Why a cell has no splat: none (it has one), zero volume (round-off level for its size), inverted.
enum class SplatRefusal { none, degenerate, inverted };
SplatRefusal refusal(const CellMoments& m);

}  // namespace cellproj
