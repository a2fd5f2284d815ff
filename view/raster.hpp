#pragma once
// The coverage rule of every rasterizing path (the A-buffer of the visibility sort, the projection
// back ends): a triangle covers the pixel centres (i + 0.5, j + 0.5) strictly inside it, and a
// centre exactly on an edge belongs to the triangle for which that edge is a top or left edge.
// Edge functions are evaluated with the edge's endpoints in a fixed order, so two triangles sharing
// an edge compute exactly opposite values: a centre on a shared edge is covered exactly once.
#include <algorithm>
#include <cmath>

#include <glm/vec2.hpp>

namespace cellproj {

namespace raster_detail {
inline bool before(const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
// (b - a) x (p - a), computed from the lesser endpoint so that edge (b, a) gives exactly the negation.
inline double edge(const glm::dvec2& a, const glm::dvec2& b, double px, double py) {
  if (before(b, a)) return -edge(b, a, px, py);
  return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}
// Whether a centre exactly on edge a->b (of a positively oriented triangle) belongs to it: true for
// exactly one of the two directions of any edge.
inline bool owns(const glm::dvec2& a, const glm::dvec2& b) { return a.y > b.y || (a.y == b.y && a.x < b.x); }

// edge(a, b, x, y) with its differences hoisted: the same operations on the same values, so the
// same bits, evaluated per row (row) and then per pixel (at).
struct EdgeFunction {
  double ax, ay, dx, dy, sign;
  bool own;
  EdgeFunction(const glm::dvec2& a, const glm::dvec2& b) : own(owns(a, b)) {
    const bool flip = before(b, a);
    const glm::dvec2& lo = flip ? b : a;
    const glm::dvec2& hi = flip ? a : b;
    ax = lo.x, ay = lo.y, dx = hi.x - lo.x, dy = hi.y - lo.y, sign = flip ? -1.0 : 1.0;
  }
  double row(double y) const { return dx * (y - ay); }
  double at(double row_value, double x) const { return sign * (row_value - dy * (x - ax)); }
  bool inside(double e) const { return e > 0 || (e == 0 && own); }
  // Narrows [lo, hi] (pixel indices) to where this edge can be non-negative on the row, plus a
  // pixel of margin for rounding.
  void clip(double row_value, double& lo, double& hi) const {
    const double c = sign * dy;  // e = sign * row_value - c (x - ax)
    if (c == 0) return;
    const double x = ax + sign * row_value / c - 0.5;  // pixel index whose centre is the crossing
    if (c > 0) hi = std::min(hi, std::floor(x) + 1);
    else lo = std::max(lo, std::ceil(x) - 1);
  }
};
}  // namespace raster_detail

// Calls covered(i, j, w0, w1, w2) for every pixel of a width x height image whose centre the
// triangle (p0, p1, p2) in pixel coordinates (x right, y down) covers, with the barycentric weights
// of p0, p1 and p2 at that centre. Degenerate triangles cover nothing.
template <class Covered>
void rasterize_triangle_weights(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, int width, int height, Covered&& covered) {
  using namespace raster_detail;
  double area = edge(p0, p1, p2.x, p2.y);
  if (!(area != 0.0) || !std::isfinite(area)) return;
  const bool swapped = area < 0;
  if (swapped) std::swap(p1, p2), area = -area;
  const double xmin = std::min({p0.x, p1.x, p2.x}), xmax = std::max({p0.x, p1.x, p2.x});
  const double ymin = std::min({p0.y, p1.y, p2.y}), ymax = std::max({p0.y, p1.y, p2.y});
  const int i0 = static_cast<int>(std::max(0.0, std::ceil(xmin - 0.5)));
  const int i1 = static_cast<int>(std::min(double(width - 1), std::floor(xmax - 0.5)));
  const int j0 = static_cast<int>(std::max(0.0, std::ceil(ymin - 0.5)));
  const int j1 = static_cast<int>(std::min(double(height - 1), std::floor(ymax - 0.5)));
  const EdgeFunction f0(p0, p1), f1(p1, p2), f2(p2, p0);
  const double inv = 1.0 / area;
  for (int j = j0; j <= j1; ++j) {
    const double y = j + 0.5;
    const double r0 = f0.row(y), r1 = f1.row(y), r2 = f2.row(y);
    // A conservative span of this row (a pixel wider each side); the exact tests decide inside it.
    double lo = i0, hi = i1;
    f0.clip(r0, lo, hi), f1.clip(r1, lo, hi), f2.clip(r2, lo, hi);
    for (int i = static_cast<int>(std::max<double>(i0, lo)), last = static_cast<int>(std::min<double>(i1, hi)); i <= last; ++i) {
      const double x = i + 0.5;
      const double e0 = f0.at(r0, x), e1 = f1.at(r1, x), e2 = f2.at(r2, x);
      if (f0.inside(e0) && f1.inside(e1) && f2.inside(e2)) {
        // e1 is opposite p0, e2 opposite p1, e0 opposite p2 (in the possibly swapped order).
        if (swapped) covered(i, j, e1 * inv, e0 * inv, e2 * inv);
        else covered(i, j, e1 * inv, e2 * inv, e0 * inv);
      }
    }
  }
}

// The same coverage without the weights: covered(i, j).
template <class Covered>
void rasterize_triangle(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, int width, int height, Covered&& covered) {
  rasterize_triangle_weights(p0, p1, p2, width, height, [&](int i, int j, double, double, double) { covered(i, j); });
}

}  // namespace cellproj
