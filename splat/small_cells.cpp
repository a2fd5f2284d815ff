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
  const int m = convex_hull(p, n, h);
  // Most cells hold the centre nearest their vertices' mean: with a limit of 1 (the default rule,
  // "covers no centre") that answers without rasterizing. (NaN or far off the image: not tried.)
  const double i = std::floor(mean.x), j = std::floor(mean.y);
  if (limit <= 1 && m >= 3 && i >= 0 && i < width && j >= 0 && j < height && holds_centre(h, m, i + 0.5, j + 0.5))
    return 1;
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
