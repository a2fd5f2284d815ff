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
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "mesh/cell_type.hpp"
#include "projection/projected_tet.hpp"

namespace cellproj {

// One triangle of a projected cell; the ray through any point of it enters through one plane and
// leaves through one plane.
struct ProjectedTriangle {
  ThickVertex v[3];
};

// How one corner of a front ∩ back polygon is made from the cell's (local) vertices.
struct CornerRecipe {
  enum Kind : std::uint8_t { shared, front_vertex, back_vertex, crossing };
  std::uint8_t kind;
  // shared: v[0]; front_vertex: v[0] over the back triangle v[2..4]; back_vertex: v[0] under the
  // front triangle v[2..4]; crossing: front edge (v[0], v[1]) and back edge (v[2], v[3]).
  std::uint8_t v[5];
};
struct PolygonRecipe {
  std::uint8_t n = 0;
  CornerRecipe corner[12];  // in order around the polygon
};
// A cell's whole subdivision, as recipes: valid for every cell with the same key.
struct SubdivisionRecipe {
  std::vector<PolygonRecipe> polygons;
};
// The projection topology of a cell: its type, the diagonal each quad takes and the exact
// orientation of every triple of its projected vertices. Two cells with the same key have the
// same subdivision (which pairs overlap, which corners, in which order): only the coordinates and
// values of the corners differ.
using SubdivisionKey = std::array<std::uint64_t, 3>;
struct SubdivisionKeyHash {
  std::size_t operator()(const SubdivisionKey& k) const;
};
// The fast path (MWSC section 2: look up the standard subdivisions of the common projection
// topologies): recipes by key, learnt from the general path as cells are met. One per worker.
struct SubdivisionCache {
  static constexpr std::size_t kMaxRecipes = 1 << 14;  // then cleared
  std::unordered_map<SubdivisionKey, SubdivisionRecipe, SubdivisionKeyHash> recipes;
  std::int64_t hits = 0, misses = 0;
};

// What the subdivision made (per cell).
struct CellProjection {
  int polygons = 0;        // non-empty front ∩ back polygons
  bool looked_up = false;  // taken from the cache (the fast path)
};

// Appends the triangles of the cell's image (polygons fanned from their first corner) to out.
// `v` holds the cell's vertices in its local order, `ids` its point ids (the quad diagonals go from
// the lowest id: the split the neighbours and the tetrahedralization use). `front_sign` is the
// exact_sign of a triangle turned towards the eye (+1 or -1: it depends on the image's handedness).
// With a cache, a cell whose key is known takes the looked-up subdivision (same bits as the general
// path: the corners are made by the same arithmetic, fanned from the same corner).
CellProjection project_cell(const ScreenVertex* v, const std::int64_t* ids, CellType type, bool perspective,
                            int front_sign, std::vector<ProjectedTriangle>& out, SubdivisionCache* cache = nullptr);

// The cell's face triangles (quads split as project_cell splits them) in local vertex numbers,
// sorted by the exact orientation of their image into those turned towards the eye (front) and
// away (back); edge-on ones are left out. Over a cell no ray crosses more than twice, the front
// triangles tile its image once and so do the back ones: each ray enters through one and leaves
// through one (MWSC section 2).
struct FaceLayers {
  std::array<std::uint8_t, 3> front[12], back[12];
  int n_front = 0, n_back = 0;
};
FaceLayers face_layers(const ScreenVertex* v, const std::int64_t* ids, CellType type, int front_sign);

}  // namespace cellproj
