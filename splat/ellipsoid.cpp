#include "splat/ellipsoid.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace cellproj {

CellMoments cell_moments(const std::int64_t* ids, CellType type, const RecentredPoints& points) {
  const CellDef& def = cell_def(type);
  const glm::dvec3 o = points(ids[0]);  // the apex, and the origin of the sums (small numbers)
  double v_sum = 0.0, size = 0.0;
  glm::dvec3 m1(0.0);
  glm::dmat3 m2(0.0);
  for_each_fan_tet(ids, type, [&](std::int64_t q0, std::int64_t q1, std::int64_t q2) {
    const glm::dvec3 a = points(q0) - o, b = points(q1) - o, c = points(q2) - o;  // (0, a, b, c): apex at 0
    const double v = glm::dot(a, glm::cross(b, c)) / 6.0;
    const glm::dvec3 s = a + b + c;
    v_sum += v, m1 += v * (s / 4.0);
    m2 += (v / 20.0) *
          (glm::outerProduct(a, a) + glm::outerProduct(b, b) + glm::outerProduct(c, c) + glm::outerProduct(s, s));
  });
  for (int k = 1; k < def.vertices; ++k) size = std::max(size, glm::distance(points(ids[k]), o));
  CellMoments m;
  m.volume = v_sum, m.size = size;
  if (v_sum == 0.0) {
    m.centre = o;
    return m;
  }
  const glm::dvec3 c = m1 / v_sum;
  m.centre = o + c;
  m.covariance = m2 / v_sum - glm::outerProduct(c, c);
  return m;
}

SplatRefusal refusal(const CellMoments& m) {
  if (!std::isfinite(m.volume) || degenerate_volume(m.volume, m.size)) return SplatRefusal::degenerate;
  return m.volume < 0.0 ? SplatRefusal::inverted : SplatRefusal::none;
}

}  // namespace cellproj
