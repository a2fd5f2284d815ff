#pragma once
// Shirley and Tuchman's projected tetrahedra (MWSC section 2): a tetrahedron's image is a triangle
// with one vertex inside it (class 1: three triangles) or a quadrilateral whose diagonals are two
// opposite edges (class 2: four triangles). The triangles fan around the thick vertex, where the
// ray through the cell is longest; along the hull's edges the cell is zero thick. Within each
// triangle the ray enters through one face and leaves through one face, so its ends' depth and
// scalar interpolate exactly (perspective-correctly in perspective).
#include <cmath>
#include <cstdint>

#include "view/screen.hpp"

namespace cellproj {

// One corner of the projected triangles: pixel position, and view depth and scalar where the ray
// through it enters (front) and leaves (back) the tetrahedron.
struct ThickVertex {
  double x = 0, y = 0;
  double zf = 0, zb = 0, sf = 0, sb = 0;
};

struct ProjectedTet {
  int hull_size = 0;        // 3 (class 1), 4 (class 2), 0 (zero projected area: nothing to draw)
  ThickVertex thick;        // the triangles are (thick, hull[k], hull[k+1]), k cyclic
  ThickVertex hull[4];      // tetrahedron vertices (zero thickness) around the projected outline
  int hull_vertex[4] = {};  // which of the four input vertices each hull corner is
  bool edge_on = false;     // a face seen edge-on (its three vertices on one line in the image, exactly)
};

// A screen vertex as a corner of zero thickness.
inline ThickVertex corner(const ScreenVertex& v) { return {v.x, v.y, v.z, v.z, v.s, v.s}; }
inline double area2(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}
// CGAL's exact 2D orientation of (a, b, c) in the image (+1, -1, or 0 when collinear).
int exact_orientation(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c);
// The same, with area2's value in `area`: the sign of the area where its rounding cannot reach
// zero (Shewchuk's orient2d filter: error below (3 + 16 eps) eps (|l| + |r|) for the products l
// and r, eps = 2^-53, while they are far from underflow), else exact_orientation's.
inline int turn_sign(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, double& area) {
  const double l = (b.x - a.x) * (c.y - a.y), r = (b.y - a.y) * (c.x - a.x), size = std::abs(l) + std::abs(r);
  area = l - r;
  if (std::abs(area) > 3.3306690738754727e-16 * size && size > 1e-250) return area > 0 ? 1 : -1;
  return exact_orientation(a, b, c);
}
// Which way (a, b, c) turns in the image, exactly (turn_sign without the area).
inline int exact_sign(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
  double area;
  return turn_sign(a, b, c, area);
}
// Depth and scalar at the image point with weights w over vertices `ids` of v, on the plane (or
// line) through them: linear in orthographic projection, through 1/z in perspective.
void interpolate(const ScreenVertex* v, const int* ids, const double* w, int n, bool perspective, double& z, double& s);

// Classifies by the signs of the four projected face areas (CGAL's exact 2D orientation, so two
// tetrahedra sharing a face always agree and near-degenerate projections never flip). Vertices that
// project onto an edge or onto each other give zero-area triangles, which cover no pixel.
ProjectedTet project_tet(const ScreenVertex v[4], bool perspective);
// The same into out (the hot loop's scratch: no 272-byte copy per tetrahedron). Fields beyond
// out.hull_size are left as they were.
void project_tet(const ScreenVertex v[4], bool perspective, ProjectedTet& out);

}  // namespace cellproj
