#include "slicing/boundary_crossings.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

#include "mesh/tetrahedralize.hpp"
#include "mesh/topology.hpp"
#include "view/raster.hpp"

namespace cellproj {

std::vector<BoundaryTriangle> boundary_triangles(const MeshView& mesh) {
  const FaceTopology topo = build_topology(mesh);
  std::vector<BoundaryTriangle> out;
  out.reserve(topo.boundary.size() * 2);
  for (const std::int64_t cf : topo.boundary) {
    const std::int64_t c = topo.cell_of(cf);
    const FaceDef& f = cell_def(mesh.type(c)).face[cf - topo.face_offsets[static_cast<std::size_t>(c)]];
    const std::int64_t* id = mesh.cell(c);
    std::int64_t v[4];
    for (int k = 0; k < f.size; ++k) v[k] = id[f.v[k]];
    if (f.size == 3) {
      out.push_back({v[0], v[1], v[2]});
      continue;
    }
    std::int64_t tri[2][3];
    split_quad(v, tri);
    out.push_back({tri[0][0], tri[0][1], tri[0][2]}), out.push_back({tri[1][0], tri[1][1], tri[1][2]});
  }
  return out;
}

BoundaryCrossings::BoundaryCrossings(const std::vector<BoundaryTriangle>& triangles, const FramePoints& f, int width,
                                     int height)
    : h_(static_cast<std::size_t>(width) * height * kMax), n_(static_cast<std::size_t>(width) * height, 0) {
  struct Projected {
    glm::dvec2 p[3];
    double w[3], hw[3];  // 1 / z and height / z (perspective-correct interpolation)
    bool drawn;
  };
  std::vector<Projected> tri(triangles.size());
  tbb::parallel_for(std::size_t{0}, triangles.size(), [&](std::size_t t) {
    Projected& q = tri[t];
    q.drawn = true;
    for (int k = 0; k < 3; ++k) {
      const std::size_t v = static_cast<std::size_t>(triangles[t][static_cast<std::size_t>(k)]);
      const glm::dvec4& a = f.screen[v];
      q.drawn = q.drawn && a.z >= f.near;  // in front of the eye (or its plane)
      q.w[k] = f.perspective ? 1.0 / a.z : 1.0;
      q.p[k] = {a.x * q.w[k], a.y * q.w[k]};
      q.hw[k] = f.height[v] * q.w[k];
    }
  });
  // Bands of rows in parallel, each scan converting every triangle over its rows: no two threads
  // write a pixel, and each pixel's crossings are sorted at the end, so the order does not matter.
  constexpr int kBandRows = 16;
  tbb::parallel_for(0, (height + kBandRows - 1) / kBandRows, [&](int band) {
    const int j0 = band * kBandRows, j1 = std::min(height, j0 + kBandRows);
    for (const Projected& q : tri) {
      if (!q.drawn) continue;
      if (std::max({q.p[0].y, q.p[1].y, q.p[2].y}) < j0 || std::min({q.p[0].y, q.p[1].y, q.p[2].y}) > j1) continue;
      rasterize_triangle_weights(q.p[0], q.p[1], q.p[2], width, height, j0, j1,
                                 [&](int i, int j, double l0, double l1, double l2) {
                                   const std::size_t px = static_cast<std::size_t>(j) * width + i;
                                   std::uint8_t& n = n_[px];
                                   if (n < kMax)
                                     h_[px * kMax + n] = static_cast<float>(perspective_correct(l0, l1, l2, q.hw, q.w));
                                   if (n <= kMax) n += 1;
                                 });
    }
    for (int j = j0; j < j1; ++j)
      for (int i = 0; i < width; ++i) {
        const std::size_t px = static_cast<std::size_t>(j) * width + i;
        if (n_[px] <= kMax)
          std::sort(h_.begin() + static_cast<std::ptrdiff_t>(px * kMax),
                    h_.begin() + static_cast<std::ptrdiff_t>(px * kMax + n_[px]));
      }
  });
}

double BoundaryCrossings::between(std::size_t pixel, double lo, double hi, bool from_hi) const {
  const int n = n_[pixel];
  if (n > kMax) return std::numeric_limits<double>::quiet_NaN();
  const float* h = h_.data() + pixel * kMax;
  double found = INFINITY;
  for (int k = 0; k < n; ++k)
    if (h[k] >= lo && h[k] <= hi && (found == INFINITY || from_hi)) found = h[k];  // sorted: the last is nearest hi
  return found;
}

}  // namespace cellproj
