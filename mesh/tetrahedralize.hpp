#pragma once
// The canonical tetrahedralization of MWSC section 4: every quadrilateral face is split by the
// diagonal from its lowest-index vertex, and a cell becomes the tetrahedra joining its lowest-index
// vertex to the triangles of the faces that do not contain it. Two cells sharing a face split it
// the same way, so any subset of cells can be tetrahedralized and the mesh stays conforming.
#include <array>
#include <cstdint>

#include "mesh/mesh.hpp"

namespace cellproj {

using Tet = std::array<std::int64_t, 4>;
constexpr int kMaxTetsPerCell = 6;  // a hexahedron: 3 faces without the apex, 2 triangles each

// Splits quad q (in its cyclic order) into two triangles by the diagonal from its lowest id.
void split_quad(const std::int64_t q[4], std::int64_t tri[2][3]);

constexpr int kMaxSurfaceTriangles = 12;  // a hexahedron's six quads, two triangles each

// Writes the triangles of cell c's surface (global point ids, each turning as its face, outward
// for a positive cell) into out, its quads split by split_quad; returns how many.
int surface_triangles(const MeshView& mesh, std::int64_t c, std::int64_t out[kMaxSurfaceTriangles][3]);
int surface_triangles(const std::int64_t* ids, CellType type, std::int64_t out[kMaxSurfaceTriangles][3]);

// Writes the tetrahedra of cell c (global point ids, VTK-positive when the cell is) into out and
// returns how many (1 for a tetrahedron): the lowest-index vertex joined to each surface triangle
// that does not contain it.
int canonical_tetrahedra(const MeshView& mesh, std::int64_t c, Tet out[kMaxTetsPerCell]);
int canonical_tetrahedra(const std::int64_t* ids, CellType type, Tet out[kMaxTetsPerCell]);  // the same of a cell's ids

}  // namespace cellproj
