#pragma once
// Projection of a whole cell (MWSC section 2, image-plane subdivision): seen from the viewpoint, a
// cell whose surface a ray crosses twice has faces turned towards the eye (front) and away (back).
// The projected edges of both divide the cell's image into polygons, each under one front triangle
// and one back triangle; over such a polygon the ray enters and leaves through two planes, so depth
// and scalar at its corners (the thick vertices) interpolate exactly across it. The subdivision is
// the overlay of the front and back triangulations: polygon = front triangle ∩ back triangle.
// Every topological decision (facing, a vertex inside a triangle, two edges crossing) is CGAL's
// exact 2D orientation on the projected vertices, so cells sharing a face agree on it and no
// rounding makes a polygon overlap or miss its neighbour.
#include <cstdint>
#include <vector>

#include "grid/cell_type.hpp"
#include "projection/projected_tet.hpp"

namespace cellproj {

// One triangle of a projected cell; the ray through any point of it enters through one plane and
// leaves through one plane.
struct ProjectedTriangle {
  ThickVertex v[3];
};

// What the subdivision met (per cell).
struct CellProjection {
  int front = 0, back = 0;  // face triangles turned towards the eye / away (edge-on ones count in neither)
  int polygons = 0;         // non-empty front ∩ back polygons
};

// Appends the triangles of the cell's image (polygons fanned from their first corner) to out.
// `v` holds the cell's vertices in its local order, `ids` its point ids (the quad diagonals go from
// the lowest id: the split the neighbours and the tetrahedralization use). `front_sign` is the
// exact_sign of a triangle turned towards the eye (+1 or -1: it depends on the image's handedness).
CellProjection project_cell(const ScreenVertex* v, const std::int64_t* ids, CellType type, bool perspective,
                            int front_sign, std::vector<ProjectedTriangle>& out);

}  // namespace cellproj
