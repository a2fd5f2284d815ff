#include "raycast/cell_ray_tracer.hpp"

#include <algorithm>

#include <atomic>
#include <cmath>
#include <glm/common.hpp>
#include <limits>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include "mesh/geometry.hpp"

namespace cellproj {
namespace {

// Tetrahedron faces (outward for a positive tetrahedron), each listed opposite its vertex.
constexpr int kFace[4][3] = {{1, 2, 3}, {2, 0, 3}, {0, 1, 3}, {0, 2, 1}};

// The clipped tetrahedron along one ray, with barycentric planes for the scalar.
struct TetPlanes {
  glm::dvec3 n[4];  // face normals, outward; face k is opposite vertex k
  double d[4];      // n[k] . x = d[k] on face k
  double volume6;
  double s[4];

  std::int64_t sorted[4][3];  // face k's vertex ids, increasing
  bool flipped[4];            // whether that order turns against the outward orientation
  const double* xyz;

  bool clip(const Ray& r, double& t0, double& t1) const {
    t0 = 0.0;
    t1 = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k) {
      const double nd = glm::dot(n[k], r.dir);
      if (nd == 0) {  // the ray runs parallel to the face: which side it is on decides it all
        if (!inside_parallel(k, r.origin)) return false;
        continue;
      }
      const double gap = d[k] - glm::dot(n[k], r.origin);
      if (nd > 0)
        t1 = std::min(t1, gap / nd);
      else
        t0 = std::max(t0, gap / nd);
    }
    return t1 > t0;
  }

  // Exact side test (CGAL): every face through one edge is asked about the same point exactly, so
  // a ray along an edge lies in exactly one tetrahedron of the fan around it. A ray in the face's
  // plane goes to the side a fixed symbolic perturbation of the origin falls on (owns_face).
  bool inside_parallel(int k, const glm::dvec3& o) const {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    auto P = [&](std::int64_t i) { return K::Point_3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]); };
    const auto side = CGAL::orientation(P(sorted[k][0]), P(sorted[k][1]), P(sorted[k][2]), K::Point_3(o.x, o.y, o.z));
    if (side == CGAL::COPLANAR) return owns_face(n[k]);
    return (side == CGAL::NEGATIVE) != flipped[k];
  }
  // A ray lying exactly in a face belongs to one of its two cells: the one whose outward normal
  // has its first non-zero component negative (the neighbour's normal points the other way).
  static bool owns_face(const glm::dvec3& n) { return n.x != 0 ? n.x < 0 : n.y != 0 ? n.y < 0 : n.z < 0; }

  // Face k's plane, computed from its vertices in increasing global id, then signed outward: the
  // two tetrahedra sharing a face get bit-identical planes of opposite sign, so a ray grazing the
  // face is inside exactly one of them and their segments meet without gap or overlap.
  void set_face(int k, const Tet& tet, const double* xyz) {
    std::int64_t id[3] = {tet[kFace[k][0]], tet[kFace[k][1]], tet[kFace[k][2]]};
    const bool flip = sort_triangle_ids(id);
    auto P = [&](std::int64_t i) { return glm::dvec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]); };
    const glm::dvec3 a = P(id[0]);
    n[k] = glm::cross(P(id[1]) - a, P(id[2]) - a);
    d[k] = glm::dot(n[k], a);
    if (flip) n[k] = -n[k], d[k] = -d[k];
    std::copy(id, id + 3, sorted[k]);
    flipped[k] = flip;
    this->xyz = xyz;
  }
  double scalar_at(const glm::dvec3& x) const {
    double s_ = 0.0;
    for (int k = 0; k < 4; ++k) s_ += (d[k] - glm::dot(n[k], x)) * s[k];
    return s_ / volume6;
  }
};

}  // namespace

CellRayTracer::CellRayTracer(const MeshView& mesh) : points_(recentre(mesh)) {
  const RecentredPoints& P = points_;
  for (std::int64_t c = 0; c < mesh.n_cells; ++c) {
    Tet tets[kMaxTetsPerCell];
    const int n = canonical_tetrahedra(mesh, c, tets);
    for (int k = 0; k < n; ++k) {
      Tet t = tets[k];
      const glm::dvec3 a = P(t[0]), b = P(t[1]), cc = P(t[2]), d = P(t[3]);
      double v6 = tet_volume6(a, b, cc, d);
      const double size = std::max({glm::length(b - a), glm::length(cc - a), glm::length(d - a)});
      if (degenerate_volume(v6, size)) {
        ++dropped_;
        continue;
      }
      if (v6 < 0) std::swap(t[1], t[2]);
      tets_.push_back(t);
      parent_.push_back(c);
    }
  }
}

glm::dvec3 CellRayTracer::gradient(std::uint32_t tet, const double* scalar) const {
  const Tet& t = tets_[tet];
  const glm::dvec3 p[4] = {points_(t[0]), points_(t[1]), points_(t[2]), points_(t[3])};
  const double s[4] = {scalar[t[0]], scalar[t[1]], scalar[t[2]], scalar[t[3]]};
  return linear_gradient(p, s, edges_triple_product(p));
}

std::vector<glm::dvec3> CellRayTracer::point_gradients(const double* scalar) const {
  std::vector<glm::dvec3> g(points_.xyz.size() / 3, glm::dvec3(0.0));
  std::vector<double> weight(g.size(), 0.0);
  for (std::uint32_t t = 0; t < tets_.size(); ++t) {
    const Tet& tet = tets_[t];
    const double v = tet_volume6(points_(tet[0]), points_(tet[1]), points_(tet[2]), points_(tet[3]));
    const glm::dvec3 gt = gradient(t, scalar);
    for (std::int64_t p : tet) g[p] += v * gt, weight[p] += v;
  }
  for (std::size_t p = 0; p < g.size(); ++p)
    if (weight[p] > 0) g[p] /= weight[p];
  return g;
}

namespace {
// The barycentric weights of x in the tetrahedron p (the volume of the tetrahedron with x in vertex
// k's place, over the whole), vertices 1 to 3; vertex 0's is 1 minus their sum.
glm::dvec3 barycentric(const glm::dvec3 p[4], const glm::dvec3& x) {
  const double v = tet_volume6(p[0], p[1], p[2], p[3]);
  return {tet_volume6(p[0], x, p[2], p[3]) / v, tet_volume6(p[0], p[1], x, p[3]) / v,
          tet_volume6(p[0], p[1], p[2], x) / v};
}
}  // namespace

glm::dvec3 CellRayTracer::interpolate(const std::vector<glm::dvec3>& per_point, std::uint32_t tet,
                                      const glm::dvec3& x) const {
  const Tet& t = tets_[tet];
  const glm::dvec3 p[4] = {points_(t[0]), points_(t[1]), points_(t[2]), points_(t[3])};
  const glm::dvec3 w = barycentric(p, x);
  return (1.0 - w[0] - w[1] - w[2]) * per_point[t[0]] + w[0] * per_point[t[1]] + w[1] * per_point[t[2]] +
         w[2] * per_point[t[3]];
}

glm::dvec3 CellRayTracer::face_normal(std::uint32_t tet, const glm::dvec3& x) const {
  const Tet& t = tets_[tet];
  const glm::dvec3 p[4] = {points_(t[0]), points_(t[1]), points_(t[2]), points_(t[3])};
  const glm::dvec3 w = barycentric(p, x);
  const double weight[4] = {1.0 - w[0] - w[1] - w[2], w[0], w[1], w[2]};
  int opposite = 0;  // the vertex whose weight is nearest 0: x is on (or nearest) the face without it
  for (int k = 1; k < 4; ++k)
    if (std::abs(weight[k]) < std::abs(weight[opposite])) opposite = k;
  return glm::normalize(tet_face_normal(p, opposite));
}

double CellRayTracer::value(std::uint32_t tet, const double* scalar, const glm::dvec3& x) const {
  const Tet& t = tets_[tet];
  const glm::dvec3 p[4] = {points_(t[0]), points_(t[1]), points_(t[2]), points_(t[3])};
  const glm::dvec3 w = barycentric(p, x);
  return (1.0 - w[0] - w[1] - w[2]) * scalar[t[0]] + w[0] * scalar[t[1]] + w[1] * scalar[t[2]] + w[2] * scalar[t[3]];
}

CellRayTracer::View::View(const CellRayTracer& tracer, const Camera& camera, int width, int height)
    : tracer_(&tracer),
      rays_(recentred(camera, tracer.points_.centre), width, height),
      width_(width),
      height_(height),
      tiles_x_((width + kTile - 1) / kTile),
      tiles_y_((height + kTile - 1) / kTile) {
  const RecentredPoints& P = tracer.points_;
  const auto& tets = tracer.tets_;
  // Pixel boxes of the tetrahedra: the pixel centres their projection may cover, one pixel wider.
  const std::size_t nt = tets.size();
  box_.resize(nt);
  tbb::parallel_for(std::size_t(0), nt, [&](std::size_t t) {
    double x0 = std::numeric_limits<double>::max(), x1 = -x0, y0 = x0, y1 = -x0;
    bool all_in_front = true;
    for (int k = 0; k < 4; ++k) {
      double x, y;
      if (!rays_.project(P(tets[t][k]), x, y)) {
        all_in_front = false;
        break;
      }
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    if (!all_in_front) {  // crosses the eye plane: any pixel may see it
      box_[t] = {0, width - 1, 0, height - 1};
      return;
    }
    auto lo = [](double v, int n) { return static_cast<int>(std::clamp(std::ceil(v - 0.5) - 1.0, 0.0, double(n))); };
    auto hi = [](double v, int n) {
      return static_cast<int>(std::clamp(std::floor(v - 0.5) + 1.0, -1.0, double(n - 1)));
    };
    box_[t] = {lo(x0, width), hi(x1, width), lo(y0, height), hi(y1, height)};
  });

  // Tetrahedra binned by image tile (counting sort).
  start_.assign(static_cast<std::size_t>(tiles_x_) * tiles_y_ + 1, 0);
  auto for_tiles = [&](const PixelBox& b, auto&& f) {
    if (b.x0 > b.x1 || b.y0 > b.y1) return;
    for (int ty = b.y0 / kTile; ty <= b.y1 / kTile; ++ty)
      for (int tx = b.x0 / kTile; tx <= b.x1 / kTile; ++tx) f(static_cast<std::size_t>(ty) * tiles_x_ + tx);
  };
  for (std::size_t t = 0; t < nt; ++t) for_tiles(box_[t], [&](std::size_t tile) { ++start_[tile + 1]; });
  for (std::size_t i = 1; i < start_.size(); ++i) start_[i] += start_[i - 1];
  binned_.resize(static_cast<std::size_t>(start_.back()));
  std::vector<std::int64_t> fill(start_.begin(), start_.end() - 1);
  for (std::size_t t = 0; t < nt; ++t)
    for_tiles(box_[t], [&](std::size_t tile) { binned_[fill[tile]++] = static_cast<std::uint32_t>(t); });
}

void CellRayTracer::View::tile_segments(int tile, const double* scalar, std::vector<RaySegment>* lists,
                                        Ray* rays) const {
  const CellRayTracer& tr = *tracer_;
  const RecentredPoints& P = tr.points_;
  const int tx0 = (tile % tiles_x_) * kTile, ty0 = (tile / tiles_x_) * kTile;
  for (int p = 0; p < kTile * kTile; ++p) lists[p].clear();
  for (int j = ty0; j < std::min(ty0 + kTile, height_); ++j)
    for (int i = tx0; i < std::min(tx0 + kTile, width_); ++i)
      rays[(j - ty0) * kTile + (i - tx0)] = rays_.ray(i + 0.5, j + 0.5);
  for (std::int64_t b = start_[tile]; b < start_[tile + 1]; ++b) {
    const std::uint32_t t = binned_[b];
    const Tet& tet = tr.tets_[t];
    TetPlanes tp;
    glm::dvec3 p[4];
    for (int k = 0; k < 4; ++k) p[k] = P(tet[k]), tp.s[k] = scalar ? scalar[tet[k]] : 0.0;
    for (int k = 0; k < 4; ++k) tp.set_face(k, tet, P.xyz.data());
    tp.volume6 = tet_volume6(p[0], p[1], p[2], p[3]);
    const PixelBox& bx = box_[t];
    for (int j = std::max(bx.y0, ty0); j <= std::min(bx.y1, ty0 + kTile - 1); ++j)
      for (int i = std::max(bx.x0, tx0); i <= std::min(bx.x1, tx0 + kTile - 1); ++i) {
        const int px = (j - ty0) * kTile + (i - tx0);
        const Ray& r = rays[px];
        double t0, t1;
        if (!tp.clip(r, t0, t1)) continue;
        lists[px].push_back(
            {t0, t1, tp.scalar_at(r.origin + t0 * r.dir), tp.scalar_at(r.origin + t1 * r.dir), tr.parent_[t], t});
      }
  }
  for (int p = 0; p < kTile * kTile; ++p)
    std::sort(lists[p].begin(), lists[p].end(),
              [](const RaySegment& a, const RaySegment& b) { return a.t0 < b.t0 || (a.t0 == b.t0 && a.t1 < b.t1); });
}

void CellRayTracer::trace(const Camera& camera, int width, int height, const double* scalar, const Visitor& visit,
                          const std::function<void(double)>& progress) const {
  const View view(*this, camera, width, height);
  constexpr int kTile = View::kTile;
  tbb::enumerable_thread_specific<std::vector<std::vector<RaySegment>>> lists(
      [] { return std::vector<std::vector<RaySegment>>(kTile * kTile); });
  std::atomic<int> done{0};
  const int n_tiles = view.tiles();
  tbb::parallel_for(0, n_tiles, [&](int tile) {
    auto& pixel_lists = lists.local();
    Ray tile_rays[kTile * kTile];
    view.tile_segments(tile, scalar, pixel_lists.data(), tile_rays);
    view.for_each_pixel(tile, [&](int i, int j, int px) {
      visit(i, j, tile_rays[px], pixel_lists[px].data(), pixel_lists[px].size());
    });
    if (progress) progress(double(++done) / n_tiles);
  });
}

}  // namespace cellproj
