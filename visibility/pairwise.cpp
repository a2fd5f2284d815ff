// Newell, Newell and Sancha's ordering extended to polyhedra (Stein, Becker and Max; MWSC section
// 3): every two cells whose projections overlap are tested, cheap rejections first (screen boxes,
// disjoint depth ranges), then the exact occlusion test: a ray through a point of the overlap of
// their projections, crossing both cells' surfaces. O(n^2) in the worst case: the ground truth for
// small meshes.
#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/container/small_vector.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "mesh/tetrahedralize.hpp"
#include "view/raster.hpp"
#include "visibility/prepared.hpp"

namespace cellproj {
namespace {

// Projections of cells: at most 8 vertices, their intersections at most 16; kept off the heap,
// since every overlapping pair makes several.
using Polygon = boost::container::small_vector<glm::dvec2, 16>;

double cross(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Andrew's monotone chain: the convex hull, counter-clockwise (in x-right, y-up terms).
Polygon hull(Polygon pts) {
  std::sort(pts.begin(), pts.end(),
            [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  Polygon h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  h.resize(k > 1 ? k - 1 : k);
  return h;
}

// Sutherland-Hodgman: the part of convex polygon a inside convex polygon b (both counter-clockwise).
Polygon clip(Polygon a, const Polygon& b) {
  for (std::size_t e = 0; e < b.size() && !a.empty(); ++e) {
    const glm::dvec2 &p = b[e], &q = b[(e + 1) % b.size()];
    Polygon out;
    for (std::size_t i = 0; i < a.size(); ++i) {
      const glm::dvec2 &u = a[i], &w = a[(i + 1) % a.size()];
      const double su = cross(p, q, u), sw = cross(p, q, w);
      if (su >= 0) out.push_back(u);
      if ((su >= 0) != (sw >= 0)) out.push_back(u + (w - u) * (su / (su - sw)));
    }
    a.swap(out);
  }
  return a;
}

double area(const Polygon& p, glm::dvec2& centroid) {
  double a = 0.0;
  glm::dvec2 c(0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::dvec2 &u = p[i], &w = p[(i + 1) % p.size()];
    const double k = u.x * w.y - w.x * u.y;
    a += k;
    c += (u + w) * k;
  }
  if (a != 0.0) centroid = c / (3.0 * a);
  return 0.5 * a;
}

// A cell's surface as triangles (mesh/tetrahedralize: quads split by the diagonal from their
// lowest id, as the rasterizers, the A-buffer and the exact renderer see a warped face).
struct CellSurface {
  int count = 0;
  std::int64_t tri[kMaxSurfaceTriangles][3];
};

CellSurface cell_surface(const VisibilitySorter::Prepared& p, std::int64_t c) {
  CellSurface s;
  s.count = surface_triangles(p.mesh, c, s.tri);
  return s;
}

// The ray's interval [t0, t1] through the cell: from the first to the last of its surface
// triangles the ray crosses (Moller-Trumbore); false if it crosses none.
bool ray_interval(const VisibilitySorter::Prepared& p, const CellSurface& s, const Ray& r, double& t0, double& t1) {
  t0 = std::numeric_limits<double>::infinity();
  t1 = -t0;
  for (int k = 0; k < s.count; ++k) {
    const glm::dvec3 a = p.point(s.tri[k][0]), e1 = p.point(s.tri[k][1]) - a, e2 = p.point(s.tri[k][2]) - a;
    const glm::dvec3 h = glm::cross(r.dir, e2);
    const double det = glm::dot(e1, h);
    if (det == 0.0) continue;  // the ray runs in the triangle's plane
    const glm::dvec3 o = r.origin - a;
    const double u = glm::dot(o, h) / det;
    if (u < 0.0 || u > 1.0) continue;
    const glm::dvec3 q = glm::cross(o, e1);
    const double w = glm::dot(r.dir, q) / det;
    if (w < 0.0 || u + w > 1.0) continue;
    const double t = glm::dot(e2, q) / det;
    t0 = std::min(t0, t), t1 = std::max(t1, t);
  }
  return t1 >= t0;
}

// Calls visit(centre) for the pixel centres (y up, as the hulls) that convex polygon `poly` covers
// in the image (its fan of triangles, with the rasterizers' coverage rule), at most kMaxCentres of
// them, until visit returns false.
template <class Visit>
void for_each_centre(const Polygon& poly, int width, int height, Visit&& visit) {
  constexpr int kMaxCentres = 4096;
  int visited = 0;
  bool go = true;
  auto image = [](const glm::dvec2& q) { return glm::dvec2(q.x, -q.y); };
  for (std::size_t k = 1; k + 1 < poly.size() && go; ++k)
    rasterize_triangle_runs(image(poly[0]), image(poly[k]), image(poly[k + 1]), width, height,
                            [&](int j, int b, int e) {
                              for (int i = b; i < e && go; ++i)
                                go = ++visited <= kMaxCentres && visit(glm::dvec2(i + 0.5, -(j + 0.5)));
                            });
}

struct CellShadow {
  Polygon hull;
  double x0, x1, y0, y1;  // screen box
  double z0, z1;          // depth range along the view direction
  bool usable = false;    // false when the cell crosses the eye plane
  CellSurface surface;
};

}  // namespace

Relations pairwise_relations(const VisibilitySorter::Prepared& p, const ViewFrame& v, const SortView& view,
                             SortStats& stats) {
  const std::int64_t n = p.mesh.n_cells;
  const PixelRays rays(v.camera, view.width, view.height);
  std::vector<CellShadow> sh(static_cast<std::size_t>(n));
  double gx0 = std::numeric_limits<double>::max(), gx1 = -gx0, gy0 = gx0, gy1 = -gx0;
  for (std::int64_t c = 0; c < n; ++c) {
    CellShadow& s = sh[c];
    Polygon pts;
    s.surface = cell_surface(p, c);
    s.z0 = std::numeric_limits<double>::max(), s.z1 = -s.z0;
    s.usable = true;
    for (int k = 0; k < p.mesh.cell_size(c); ++k) {
      const glm::dvec3 x = p.point(p.mesh.cell(c)[k]);
      glm::dvec2 q;
      if (!rays.project(x, q.x, q.y)) s.usable = false;
      pts.push_back({q.x, -q.y});  // y up, so the hulls turn counter-clockwise
      const double z = glm::dot(x - v.eye, v.dir);
      s.z0 = std::min(s.z0, z), s.z1 = std::max(s.z1, z);
    }
    if (!s.usable) continue;
    s.hull = hull(pts);
    s.x0 = s.y0 = std::numeric_limits<double>::max(), s.x1 = s.y1 = -s.x0;
    for (const auto& q : s.hull)
      s.x0 = std::min(s.x0, q.x), s.x1 = std::max(s.x1, q.x), s.y0 = std::min(s.y0, q.y), s.y1 = std::max(s.y1, q.y);
    gx0 = std::min(gx0, s.x0), gx1 = std::max(gx1, s.x1), gy0 = std::min(gy0, s.y0), gy1 = std::max(gy1, s.y1);
  }
  // Candidate pairs from a grid over the screen boxes; a pair is tested in one tile only.
  const int g = std::clamp(static_cast<int>(std::sqrt(double(n)) / 2), 1, 256);
  const double wx = std::max(gx1 - gx0, 1e-300) / g, wy = std::max(gy1 - gy0, 1e-300) / g;
  auto tile = [&](double x, double w, double o) { return std::clamp(static_cast<int>((x - o) / w), 0, g - 1); };
  std::vector<std::vector<std::int64_t>> bins(static_cast<std::size_t>(g) * g);
  for (std::int64_t c = 0; c < n; ++c) {
    if (!sh[c].usable) continue;
    for (int ty = tile(sh[c].y0, wy, gy0); ty <= tile(sh[c].y1, wy, gy0); ++ty)
      for (int tx = tile(sh[c].x0, wx, gx0); tx <= tile(sh[c].x1, wx, gx0); ++tx) bins[ty * g + tx].push_back(c);
  }
  std::vector<std::pair<std::int64_t, std::int64_t>> pairs;
  for (int ty = 0; ty < g; ++ty)
    for (int tx = 0; tx < g; ++tx) {
      const auto& bin = bins[ty * g + tx];
      for (std::size_t i = 0; i < bin.size(); ++i)
        for (std::size_t j = i + 1; j < bin.size(); ++j) {
          const CellShadow &a = sh[bin[i]], &b = sh[bin[j]];
          if (a.x1 <= b.x0 || b.x1 <= a.x0 || a.y1 <= b.y0 || b.y1 <= a.y0) continue;
          if (tile(std::max(a.x0, b.x0), wx, gx0) != tx || tile(std::max(a.y0, b.y0), wy, gy0) != ty) continue;
          const Polygon overlap = clip(a.hull, b.hull);
          glm::dvec2 centre(0.0);
          if (overlap.size() < 3 ||
              area(overlap, centre) <= 1e-12 * (a.x1 - a.x0 + b.x1 - b.x0) * (a.y1 - a.y0 + b.y1 - b.y0))
            continue;
          const std::int64_t ca = bin[i], cb = bin[j];
          bool a_front = false;
          if (a.z1 <= b.z0)
            a_front = true;
          else if (b.z1 <= a.z0)
            a_front = false;
          else {  // the exact test: along a ray through the overlap, which is met first
            // The overlap of the hulls may hold parts of it that one shadow leaves out (a warped
            // cell's shadow need not be convex): its centre first, then points pulled in from its
            // corners, until a ray crosses both.
            bool hit = false;
            auto try_ray = [&](const glm::dvec2& at) {  // at: a point of the overlap (y up)
              const Ray r = rays.ray(at.x, -at.y);
              double ta0, ta1, tb0, tb1;
              hit = ray_interval(p, a.surface, r, ta0, ta1) && ray_interval(p, b.surface, r, tb0, tb1);
              if (hit) a_front = ta0 + ta1 < tb0 + tb1;
            };
            for (std::size_t k = 0; k <= overlap.size() && !hit; ++k)
              try_ray(k == 0 ? centre : centre + 0.5 * (overlap[k - 1] - centre));
            // Still none: the shadows may meet in a sliver only; the pixel centres inside the
            // overlap are where the picture (and the oracle) can tell, up to kMaxCentres of them.
            for_each_centre(overlap, view.width, view.height, [&](const glm::dvec2& at) {
              if (!hit) try_ray(at);
              return !hit;
            });
            if (!hit) continue;  // no ray through a pixel centre crosses both: nothing to relate
          }
          pairs.emplace_back(a_front ? cb : ca, a_front ? ca : cb);  // the one behind first
        }
    }
  Relations rel;
  stats.pair_relations = rel.build(n, pairs);
  return rel;
}

}  // namespace cellproj
