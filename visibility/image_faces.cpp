#include "visibility/image_faces.hpp"

#include <algorithm>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include "base/chunks.hpp"

namespace cellproj {
namespace {

// Points or faces per task: fewer are not worth waking a worker thread for (on this project's
// 2-core machine, a second thread made angular_sector's 2,475 faces slower to project).
constexpr std::size_t kGrain = 8192;

// Keeps the faces whose flag is set, in order.
void keep_flagged(ProjectedFaces& faces, const std::vector<char>& keep) {
  std::size_t kept = 0;
  for (std::size_t k = 0; k < faces.size(); ++k)
    if (keep[k]) faces[kept++] = faces[k];
  faces.resize(kept);
}

// Only a face that has the other kind of face behind it (a leaving face) or in front of it (an
// entering face) somewhere can be one side of a gap; dropping the others changes no pixel's
// "leave, then enter" pairs (a face between such a pair would itself be one of its sides). The
// test is conservative, on 16 x 16 tiles: a leaving face is kept where a tile it touches has an
// entering face that reaches as deep there, an entering face where a tile has a leaving face as
// near there. A face's keys in a tile lie between its plane's extremes over the part of its
// bounding box in the tile (and within its keys over the whole face).
void cull_faces_without_gaps(ProjectedFaces& faces, int width, int height) {
  constexpr int kTile = 16;
  const int tw = (width + kTile - 1) / kTile, th = (height + kTile - 1) / kTile;
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> nearest_leaving(static_cast<std::size_t>(tw) * th, inf),
      deepest_entering(nearest_leaving.size(), -inf);
  // visit(tile, lowest key, highest key) for each tile the face's bounding box touches.
  auto each_tile = [&](const ProjectedFace& f, auto&& visit) {
    const ImageFace& g = f.face;
    const auto [i0, i1, j0, j1] = f.box;
    for (int ty = j0 / kTile; ty <= j1 / kTile; ++ty) {
      const double y0 = g.ky * (std::max(j0, ty * kTile) + 0.5),
                   y1 = g.ky * (std::min(j1, ty * kTile + kTile - 1) + 0.5);
      for (int tx = i0 / kTile; tx <= i1 / kTile; ++tx) {
        const double x0 = g.kx * (std::max(i0, tx * kTile) + 0.5),
                     x1 = g.kx * (std::min(i1, tx * kTile + kTile - 1) + 0.5);
        const double lo = std::max(f.kmin, g.k0 + std::min(x0, x1) + std::min(y0, y1) - f.rounding);
        const double hi = std::min(f.kmax, g.k0 + std::max(x0, x1) + std::max(y0, y1) + f.rounding);
        if (visit(static_cast<std::size_t>(ty) * tw + tx, lo, hi)) return true;
      }
    }
    return false;
  };
  for (const ProjectedFace& f : faces)
    each_tile(f, [&](std::size_t t, double lo, double hi) {
      if (f.face.entering())
        deepest_entering[t] = std::max(deepest_entering[t], hi);
      else
        nearest_leaving[t] = std::min(nearest_leaving[t], lo);
      return false;
    });
  std::vector<char> keep(faces.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, faces.size(), kGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t k = r.begin(); k < r.end(); ++k) {
                        const ProjectedFace& f = faces[k];
                        keep[k] = each_tile(f, [&](std::size_t t, double lo, double hi) {
                          return f.face.entering() ? nearest_leaving[t] <= hi + key_slack(nearest_leaving[t], hi)
                                                   : deepest_entering[t] + key_slack(deepest_entering[t], lo) >= lo;
                        });
                      }
                    });
  keep_flagged(faces, keep);
}

// A boundary point in the image: its position, its depth key and whether it is in front of the eye.
struct ImagePoint {
  glm::dvec2 s;
  double key;  // affine in the image: view depth, or -1/depth under perspective
  bool visible;
};

std::vector<ImagePoint> project_points(const VisibilitySorter::Prepared& p, const ViewFrame& v, const PixelRays& rays) {
  std::vector<ImagePoint> out(p.boundary_point.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out.size(), kGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t k = r.begin(); k < r.end(); ++k) {
                        const glm::dvec3 x = p.point(p.boundary_point[k]);
                        ImagePoint& q = out[k];
                        q.visible = rays.project(x, q.s.x, q.s.y);
                        const double depth = glm::dot(x - v.eye, v.dir);
                        q.key = v.perspective ? -1.0 / depth : depth;
                      }
                    });
  return out;
}

// Boundary face b (off the hull) in the image: false when it covers no pixel centre or crosses the
// eye plane.
bool project_face(const VisibilitySorter::Prepared& p, const ViewFrame& v, const SortView& view,
                  const std::vector<ImagePoint>& points, std::size_t b, ProjectedFace& f) {
  const auto& tri = p.boundary_tri[b];
  const ImagePoint* q[3] = {&points[tri[0]], &points[tri[1]], &points[tri[2]]};
  // Crosses the eye plane: a ray from the eye cannot leave through it and come back.
  if (!q[0]->visible || !q[1]->visible || !q[2]->visible) return false;
  glm::dvec2* s = f.s;
  for (int k = 0; k < 3; ++k) s[k] = q[k]->s;
  const double key[3] = {q[0]->key, q[1]->key, q[2]->key};
  const double area = (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[2].x - s[0].x) * (s[1].y - s[0].y);
  if (area == 0.0) return false;  // edge-on: no pixel centre is covered
  f.box = PixelBox(s[0], s[1], s[2], view.width, view.height);
  if (f.box.empty()) return false;  // no pixel centre in its bounding box
  const glm::dvec3 x[3] = {p.point(p.boundary_point[tri[0]]), p.point(p.boundary_point[tri[1]]),
                           p.point(p.boundary_point[tri[2]])};
  const glm::dvec3 n = glm::cross(x[1] - x[0], x[2] - x[0]);  // outward
  const bool entering = v.perspective ? glm::dot(n, v.eye - x[0]) > 0 : glm::dot(n, v.dir) < 0;
  // key(x, y) = k0 + kx x + ky y through the three projected vertices.
  ImageFace& g = f.face;
  g.kx = ((key[1] - key[0]) * (s[2].y - s[0].y) - (key[2] - key[0]) * (s[1].y - s[0].y)) / area;
  g.ky = ((key[2] - key[0]) * (s[1].x - s[0].x) - (key[1] - key[0]) * (s[2].x - s[0].x)) / area;
  g.k0 = key[0] - g.kx * s[0].x - g.ky * s[0].y;
  g.tagged = 2u * static_cast<std::uint32_t>(p.boundary_cell[b]) + (entering ? 1u : 0u);
  // The key's range at the pixel centres it covers, widened by the plane's rounding there.
  f.rounding = 1e-12 * (std::abs(g.k0) + std::abs(g.kx) * view.width + std::abs(g.ky) * view.height);
  f.kmin = std::min({key[0], key[1], key[2]}) - f.rounding;
  f.kmax = std::max({key[0], key[1], key[2]}) + f.rounding;
  return true;
}

}  // namespace

ProjectedFaces project_faces(const VisibilitySorter::Prepared& p, const ViewFrame& v, const SortView& view, bool cull) {
  const std::vector<ImagePoint> points = project_points(p, v, PixelRays(v.camera, view.width, view.height));
  const std::size_t nb = p.boundary_tri.size();
  // In chunks of kGrain faces, each written at the start of its own range of one buffer, then
  // moved down after the chunks before it: the faces in the image, in order, with one allocation.
  ProjectedFaces projected(nb);
  std::vector<std::size_t> kept((nb + kGrain - 1) / kGrain);
  tbb::parallel_for(std::size_t(0), kept.size(), [&](std::size_t c) {
    std::size_t n = c * kGrain;
    for (std::size_t b = c * kGrain; b < std::min(nb, (c + 1) * kGrain); ++b)
      n += project_face(p, v, view, points, b, projected[n]);
    kept[c] = n - c * kGrain;
  });
  join_chunk_heads(projected, kept, kGrain);
  if (cull) cull_faces_without_gaps(projected, view.width, view.height);
  return projected;
}

}  // namespace cellproj
