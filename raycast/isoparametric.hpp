#pragma once
// Isoparametric interpolation inside hexahedra, wedges and pyramids (VTK's shape functions): the
// natural coordinates of a point are found by Newton's method, the field is then the shape-function
// blend of the vertex values. Tetrahedra are linear and never come here.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"

namespace cellproj {

// Shape-function weights of cell type `type` at natural coordinates xi (VTK's parametric cell:
// [0,1]^3 for a hexahedron, r + s <= 1 with t in [0,1] for a wedge, apex at t = 1 for a pyramid).
// Writes n weights (8, 6 or 5) and, if dw is given, their derivatives d/dr, d/ds, d/dt.
int shape_functions(CellType type, const glm::dvec3& xi, double* w, glm::dvec3* dw = nullptr);

// The shape of the mesh's non-tetrahedral cells, over recentred points (so huge coordinate offsets
// lose nothing), for any point field. Keeps its own copy of those cells' vertex ids.
class IsoparametricField {
 public:
  IsoparametricField(const MeshView& mesh, const double* recentred_points);

  bool linear(std::int64_t cell) const { return first_[cell] < 0; }  // a tetrahedron
  // The point field `scalar` at point p of `cell`; xi is the starting guess for Newton and receives
  // the natural coordinates. Returns false when Newton does not converge (a degenerate cell), leaving
  // value as is.
  bool value(const double* scalar, std::int64_t cell, const glm::dvec3& p, glm::dvec3& xi, double& value) const;
  glm::dvec3 centre_guess(std::int64_t cell) const;

 private:
  const double* points_;
  std::vector<std::int64_t> first_;  // per cell: start in ids_, -1 for a tetrahedron
  std::vector<std::int64_t> ids_;
  std::vector<std::uint8_t> types_;
};

}  // namespace cellproj
