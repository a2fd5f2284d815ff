// The software A-buffer of Cook et al. (MWSC section 3.2): the boundary faces of a non-convex mesh
// that are off its convex hull are sampled at the image's own pixel centres with the rasterizer's
// coverage rule; along each pixel's list, a face where the ray leaves the mesh followed by one where
// it enters again is a gap, and the cell entered is composited before the cell left. The lists are
// kept sparse (fragments sorted by pixel), so no per-pixel memory is touched outside the faces.
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "view/raster.hpp"
#include "visibility/prepared.hpp"

namespace cellproj {
namespace {

struct Fragment {
  double key;           // grows with distance along the pixel's ray (depth, or -1/depth in perspective)
  std::uint32_t pixel;  // j * width + i
  std::uint32_t tagged; // 2 cell + 1 when the face is front-facing (the ray enters the mesh there)
  std::int32_t cell() const { return static_cast<std::int32_t>(tagged >> 1); }
  bool entering() const { return tagged & 1u; }
};

// Front to back; at (nearly) equal distance a leaving face comes first, so a seam of coincident
// faces (duplicated points) still reads as "leave one cell, enter the next".
bool in_front(const Fragment& a, const Fragment& b) {
  const double tol = 1e-9 * std::max(std::abs(a.key), std::abs(b.key));
  if (a.key < b.key - tol) return true;
  if (a.key > b.key + tol) return false;
  return !a.entering() && b.entering();
}

// Stable LSD radix sort of the fragments by pixel, 11 bits a pass.
void sort_by_pixel(std::vector<Fragment>& frags, std::uint32_t pixels) {
  std::vector<Fragment> tmp(frags.size());
  for (int shift = 0; shift < 32 && (pixels - 1) >> shift; shift += 11) {
    std::vector<std::size_t> count(2049, 0);
    for (const Fragment& f : frags) ++count[((f.pixel >> shift) & 2047u) + 1];
    for (int b = 0; b < 2048; ++b) count[b + 1] += count[b];
    for (const Fragment& f : frags) tmp[count[(f.pixel >> shift) & 2047u]++] = f;
    frags.swap(tmp);
  }
}

}  // namespace

Relations gap_relations(const VisibilitySorter::Prepared& p, const ViewFrame& v, const SortView& view, SortStats& stats) {
  const PixelRays rays(v.camera, view.width, view.height);
  const std::size_t nb = p.boundary_tri.size();
  // Far faces first, so that each pixel's fragments come out of the sort by pixel far to near and,
  // read backwards, almost always already front to back.
  std::vector<std::pair<double, std::uint32_t>> by_depth(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    const auto& t = p.boundary_tri[b];
    by_depth[b] = {-v.far_key((p.point(t[0]) + p.point(t[1]) + p.point(t[2])) / 3.0), static_cast<std::uint32_t>(b)};
  }
  std::sort(by_depth.begin(), by_depth.end());

  std::vector<Fragment> frags;
  frags.reserve(4 * nb);
  for (const auto& [order_key, b] : by_depth) {
    const auto& tri = p.boundary_tri[b];
    const glm::dvec3 x[3] = {p.point(tri[0]), p.point(tri[1]), p.point(tri[2])};
    glm::dvec2 s[3];
    double key[3];
    bool visible = true;
    for (int k = 0; k < 3; ++k) {
      visible = visible && rays.project(x[k], s[k].x, s[k].y);
      const double depth = glm::dot(x[k] - v.eye, v.dir);
      key[k] = v.perspective ? -1.0 / depth : depth;  // affine in the image: 1/depth under perspective
    }
    if (!visible) continue;  // crosses the eye plane: a ray from the eye cannot leave through it and come back
    const glm::dvec3 n = glm::cross(x[1] - x[0], x[2] - x[0]);  // outward
    const bool entering = v.perspective ? glm::dot(n, v.eye - x[0]) > 0 : glm::dot(n, v.dir) < 0;
    const double area = (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[2].x - s[0].x) * (s[1].y - s[0].y);
    if (area == 0.0) continue;  // edge-on: no pixel centre is covered
    // key(x, y) = k0 + kx x + ky y through the three projected vertices.
    const double kx = ((key[1] - key[0]) * (s[2].y - s[0].y) - (key[2] - key[0]) * (s[1].y - s[0].y)) / area;
    const double ky = ((key[2] - key[0]) * (s[1].x - s[0].x) - (key[1] - key[0]) * (s[2].x - s[0].x)) / area;
    const double k0 = key[0] - kx * s[0].x - ky * s[0].y;
    const std::uint32_t tagged = 2u * static_cast<std::uint32_t>(p.boundary_cell[b]) + (entering ? 1u : 0u);
    rasterize_triangle(s[0], s[1], s[2], view.width, view.height, [&](int i, int j) {
      frags.push_back({k0 + kx * (i + 0.5) + ky * (j + 0.5),
                       static_cast<std::uint32_t>(j) * static_cast<std::uint32_t>(view.width) + i, tagged});
    });
  }
  stats.abuffer_fragments = static_cast<std::int64_t>(frags.size());
  sort_by_pixel(frags, static_cast<std::uint32_t>(view.width) * static_cast<std::uint32_t>(view.height));

  // Each pixel's list front to back (insertion sort: nearly always nothing to move), then a
  // relation for every "leave, then enter" pair.
  std::vector<std::pair<std::int64_t, std::int64_t>> pairs;
  std::vector<Fragment> list;
  for (std::size_t at = 0; at < frags.size();) {
    std::size_t end = at;
    while (end < frags.size() && frags[end].pixel == frags[at].pixel) ++end;
    list.assign(frags.rbegin() + static_cast<std::ptrdiff_t>(frags.size() - end),
                frags.rbegin() + static_cast<std::ptrdiff_t>(frags.size() - at));
    for (std::size_t k = 1; k < list.size(); ++k) {
      if (in_front(list[k - 1], list[k])) continue;
      ++stats.abuffer_out_of_order;
      for (std::size_t m = k; m > 0 && !in_front(list[m - 1], list[m]); --m) std::swap(list[m - 1], list[m]);
    }
    for (std::size_t k = 0; k + 1 < list.size(); ++k)
      if (!list[k].entering() && list[k + 1].entering() && list[k].cell() != list[k + 1].cell()) {
        const std::pair<std::int64_t, std::int64_t> gap(list[k + 1].cell(), list[k].cell());
        if (pairs.empty() || pairs.back() != gap) pairs.push_back(gap);  // neighbouring pixels mostly repeat it
      }
    at = end;
  }
  Relations rel;
  stats.gap_relations = rel.build(p.mesh.n_cells, pairs);
  return rel;
}

}  // namespace cellproj
