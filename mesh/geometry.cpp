#include "mesh/geometry.hpp"

#include <algorithm>

#include <cmath>
#include <cstring>
#include <limits>
#include <tuple>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <glm/common.hpp>

namespace cellproj {

double cell_signed_volume(const MeshView& mesh, std::int64_t c) {
  const CellDef& def = cell_def(mesh.type(c));
  const std::int64_t* ids = mesh.cell(c);
  glm::dvec3 o(0.0);
  for (int i = 0; i < def.vertices; ++i) o += mesh.point(ids[i]);
  o /= def.vertices;
  double v6 = 0.0;
  for (int f = 0; f < def.faces; ++f) {
    const FaceDef& face = def.face[f];
    if (face.size == 3) {
      v6 += tet_volume6(mesh.point(ids[face.v[0]]), mesh.point(ids[face.v[1]]), mesh.point(ids[face.v[2]]), o);
      continue;
    }
    glm::dvec3 q[4];
    for (int k = 0; k < 4; ++k) q[k] = mesh.point(ids[face.v[k]]);
    const glm::dvec3 m = 0.25 * (q[0] + q[1] + q[2] + q[3]);
    for (int k = 0; k < 4; ++k) v6 += tet_volume6(q[k], q[(k + 1) % 4], m, o);
  }
  return -v6 / 6.0;  // outward faces see the inner point o on their negative side
}

double cell_size(const MeshView& mesh, std::int64_t c) {
  const int n = mesh.cell_size(c);
  const std::int64_t* ids = mesh.cell(c);
  glm::dvec3 lo = mesh.point(ids[0]), hi = lo;
  for (int i = 1; i < n; ++i) {
    lo = glm::min(lo, mesh.point(ids[i]));
    hi = glm::max(hi, mesh.point(ids[i]));
  }
  return glm::length(hi - lo);
}

glm::dvec3 cell_centroid(const MeshView& mesh, std::int64_t c) {
  const std::int64_t* ids = mesh.cell(c);
  const int n = mesh.cell_size(c);
  glm::dvec3 sum(0.0);
  for (int k = 0; k < n; ++k) sum += mesh.point(ids[k]);
  return sum / double(n);
}

std::pair<glm::dvec3, glm::dvec3> point_bounds(const MeshView& m) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (std::int64_t p = 0; p < m.n_points; ++p) lo = glm::min(lo, m.point(p)), hi = glm::max(hi, m.point(p));
  return {lo, hi};
}

glm::dvec3 newell_normal(const glm::dvec3* p, int n) {
  glm::dvec3 s(0.0);
  for (int i = 0; i < n; ++i) s += glm::cross(p[i], p[(i + 1) % n]);
  return s;
}

RecentredPoints recentre(const MeshView& mesh) {
  RecentredPoints r;
  if (mesh.n_points == 0) return r;
  const auto [lo, hi] = point_bounds(mesh);
  r.centre = 0.5 * (lo + hi);
  r.lo = lo - r.centre, r.hi = hi - r.centre;  // rounding is monotone: the extremes of the recentred points
  r.half_diagonal = 0.5 * glm::length(hi - lo);
  r.xyz.resize(static_cast<std::size_t>(3 * mesh.n_points));
  for (std::int64_t p = 0; p < mesh.n_points; ++p) {
    const glm::dvec3 x = mesh.point(p) - r.centre;
    r.xyz[3 * p] = x.x, r.xyz[3 * p + 1] = x.y, r.xyz[3 * p + 2] = x.z;
  }
  return r;
}

double quad_warp(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
  const glm::dvec3 n = glm::cross(c - a, d - b);
  const double len = glm::length(n);
  if (len == 0.0) return 0.0;  // parallel diagonals: a collapsed face, not a warped one
  return std::abs(glm::dot(b - a, n)) / len;
}

namespace {
std::uint64_t mix(std::uint64_t h) {  // splitmix64's finalizer
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
  return h ^ (h >> 31);
}
}  // namespace

PointGroups coincident_points(const MeshView& m, const std::vector<std::int64_t>& candidates) {
  struct Keyed {
    std::uint64_t hash;
    std::int64_t point;
  };
  auto key = [&m](std::int64_t p) {
    const glm::dvec3 x = m.point(p);
    return std::make_tuple(x.x, x.y, x.z);
  };
  // A non-finite point is left out before any sort: a NaN breaks the coordinates' order.
  std::vector<Keyed> keyed(candidates.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, candidates.size(), 8192), [&](const auto& range) {
    for (std::size_t i = range.begin(); i < range.end(); ++i) {
      const glm::dvec3 x = m.point(candidates[i]) + glm::dvec3(0.0);  // -0 + 0 is +0
      std::uint64_t h = 0;
      for (int k = 0; k < 3; ++k) {
        std::uint64_t bits;
        std::memcpy(&bits, &x[k], sizeof bits);
        h = mix(h ^ bits);
      }
      keyed[i] = {h, std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z) ? candidates[i] : -1};
    }
  });
  keyed.erase(std::remove_if(keyed.begin(), keyed.end(), [](const Keyed& k) { return k.point < 0; }), keyed.end());
  tbb::parallel_sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) {
    return a.hash < b.hash || (a.hash == b.hash && a.point < b.point);
  });
  PointGroups groups;
  for (std::size_t i = 0; i < keyed.size();) {
    std::size_t j = i + 1;
    while (j < keyed.size() && keyed[j].hash == keyed[i].hash) ++j;
    if (j - i > 1) {  // the same place, or a collision: ordered by coordinates, then id
      std::sort(keyed.begin() + i, keyed.begin() + j, [&](const Keyed& a, const Keyed& b) {
        return key(a.point) < key(b.point) || (key(a.point) == key(b.point) && a.point < b.point);
      });
      for (std::size_t s = i, e; s < j; s = e) {
        for (e = s + 1; e < j && key(keyed[e].point) == key(keyed[s].point);) ++e;
        if (e - s < 2) continue;
        for (std::size_t k = s; k < e; ++k) groups.ids.push_back(keyed[k].point);
        groups.start.push_back(static_cast<std::int64_t>(groups.ids.size()));
      }
    }
    i = j;
  }
  return groups;
}

}  // namespace cellproj
