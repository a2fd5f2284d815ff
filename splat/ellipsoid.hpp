#pragma once
// A cell as a Gaussian ellipsoid (MWSC section 6): the centre of gravity and the covariance of its
// volume, taken uniform, from its tetrahedra.
#include <cstdint>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "grid/cell_type.hpp"
#include "grid/geometry.hpp"

namespace cellproj {

struct CellMoments {
  double volume = 0.0;  // signed: negative for an inverted cell
  glm::dvec3 centre{0.0};
  glm::dmat3 covariance{0.0};  // of a point uniform in the cell
  double size = 0.0;           // the longest edge from the first vertex, for the degeneracy test
};

// The moments of the cell with point ids `ids` of `type`: the tetrahedra joining its first vertex to
// the triangles of the faces without it (the quads fanned from their first vertex), each of volume
// V, centroid m = sum(p) / 4 and second moment (sum(p p^T) + sum(p) sum(p)^T) / 20.
CellMoments cell_moments(const std::int64_t* ids, CellType type, const RecentredPoints& points);

// Why a cell has no splat: none (it has one), zero volume (round-off level for its size), inverted.
enum class SplatRefusal { none, degenerate, inverted };
SplatRefusal refusal(const CellMoments& m);

}  // namespace cellproj
