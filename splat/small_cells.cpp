#include "splat/small_cells.hpp"

#include <algorithm>
#include <cmath>

#include <glm/vec2.hpp>

#include "view/raster.hpp"

namespace cellproj {
namespace {

double cross(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Andrew's monotone chain: the hull of p[0..n) counter-clockwise into h, returns its size.
int convex_hull(glm::dvec2* p, int n, glm::dvec2* h) {
  auto less = [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
  for (int i = 1; i < n; ++i)  // insertion sort: at most 8 points
    for (int j = i; j > 0 && less(p[j], p[j - 1]); --j) std::swap(p[j], p[j - 1]);
  int k = 0;
  for (int i = 0; i < n; ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (int i = n - 2, lower = k + 1; i >= 0; --i) {
    while (k >= lower && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  return std::max(k - 1, 1);
}

// Whether the pixel centre (px, py) lies inside the hull h[0..m) (each turn positive) by more than
// the rounding of any edge function's evaluation: then every rasterizer of the fanned hull covers
// it, whatever the coverage rule decides on edges (a centre inside is on one fan triangle's inner
// side of each hull edge, and a fan diagonal's two triangles compute exactly opposite values).
bool holds_centre(const glm::dvec2* h, int m, double px, double py) {
  for (int k = 0; k < m; ++k) {
    const glm::dvec2 &a = h[k], &b = h[(k + 1) % m];
    const double dx = b.x - a.x, dy = b.y - a.y, ex = px - a.x, ey = py - a.y;
    const double size = std::abs(dx) + std::abs(dy);  // the products' magnitude, from either endpoint
    if (!(dx * ey - dy * ex > 1e-12 * size * (size + std::abs(ex) + std::abs(ey)))) return false;
  }
  return true;
}

// Whether the centre (px, py) lies inside one of the triangles of four points (a tetrahedron's
// image is the union of its faces': any three of its corners) by a margin past any rounding: its
// distance to each of that triangle's edges over 3e-12 times the points' box size D (|x| + |y|
// extents). Then its distance to each edge of the hull, which holds the triangle, is too, and
// holds_centre's test passes (an edge function there is distance times length, and its margin
// 1e-12 S (S + |ex| + |ey|) is at most 2e-12 D S, S the edge's |dx| + |dy| <= sqrt 2 times its
// length). Cheaper than the hull: the usual answer for a tetrahedron.
bool quad_holds_centre(const glm::dvec2* p, double px, double py) {
  const double lo_x = std::min({p[0].x, p[1].x, p[2].x, p[3].x}), hi_x = std::max({p[0].x, p[1].x, p[2].x, p[3].x}),
               lo_y = std::min({p[0].y, p[1].y, p[2].y, p[3].y}), hi_y = std::max({p[0].y, p[1].y, p[2].y, p[3].y});
  const double margin = 1e-11 * ((hi_x - lo_x) + (hi_y - lo_y));
  static constexpr int kFaces[4][3] = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  for (const auto& f : kFaces) {
    const glm::dvec2 &a = p[f[0]], &b = p[f[1]], &c = p[f[2]];
    const double turn = cross(a, b, c);
    if (!(turn != 0.0)) continue;
    const double sign = turn > 0 ? 1.0 : -1.0;
    // Edge u -> v: its function at the centre, signed to be positive inside, against the margin
    // times the edge's |dx| + |dy| (>= its length).
    const auto inside = [&](const glm::dvec2& u, const glm::dvec2& v) {
      const double dx = v.x - u.x, dy = v.y - u.y;
      return sign * (dx * (py - u.y) - dy * (px - u.x)) > margin * (std::abs(dx) + std::abs(dy));
    };
    if (inside(a, b) && inside(b, c) && inside(c, a)) return true;
  }
  return false;
}

}  // namespace

int covered_pixels(const ScreenVertex* const* v, int n, int width, int height, int limit) {
  glm::dvec2 p[8], h[17];
  n = std::min(n, 8);
  for (int k = 0; k < n; ++k) {
    if (behind_eye(v[k]->z)) return -1;
    p[k] = glm::dvec2(v[k]->x, v[k]->y);
  }
  glm::dvec2 mean(0.0);
  for (int k = 0; k < n; ++k) mean += p[k];
  mean /= static_cast<double>(n);
  // Most cells hold the centre nearest their vertices' mean: with a limit of 1 (the default rule,
  // "covers no centre") that answers without rasterizing. (NaN or far off the image: not tried.)
  const double i = std::floor(mean.x), j = std::floor(mean.y);
  const bool try_mean = limit <= 1 && i >= 0 && i < width && j >= 0 && j < height;
  if (try_mean && n == 4 && quad_holds_centre(p, i + 0.5, j + 0.5)) return 1;
  const int m = convex_hull(p, n, h);
  if (try_mean && m >= 3 && holds_centre(h, m, i + 0.5, j + 0.5)) return 1;
  // A hull whose area, less its perimeter, is over the limit covers more centres than that: any
  // convex region holds more than area - perimeter / 2 lattice points (Nosarzewska). The bound has
  // a factor 2 to spare, so the edge lengths need no hypot (an overflow to inf only means counting).
  double area = 0.0, perimeter = 0.0;
  for (int k = 0; k < m; ++k) {
    const glm::dvec2 &a = h[k], &b = h[(k + 1) % m];
    const glm::dvec2 d = b - a;
    area += a.x * b.y - a.y * b.x, perimeter += std::sqrt(d.x * d.x + d.y * d.y);
  }
  if (0.5 * std::abs(area) - perimeter > limit) return limit;
  int count = 0;
  for (int k = 1; k + 1 < m && count < limit; ++k)  // the hull fanned: its triangles cover each centre once
    rasterize_triangle_runs(h[0], h[k], h[k + 1], width, height, [&](int, int b, int e) { count += e - b; });
  return std::min(count, limit);
}

void SplatCounters::add(const SplatCounters& o) {
  small_cells += o.small_cells, covering_no_pixel += o.covering_no_pixel, splats += o.splats;
  splat_fragments += o.splat_fragments, masked_fragments += o.masked_fragments;
  refused_degenerate += o.refused_degenerate, refused_inverted += o.refused_inverted, behind_eye += o.behind_eye;
}

}  // namespace cellproj
