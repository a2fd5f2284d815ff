#pragma once
// A tetrahedron as the intersection of its four face planes, and a field linear over it: what a
// pixel's ray needs to be clipped to it and to read the field at the ends (the cells ray cast
// instead of projected: behind the eye, or coloured by another field than their extinction).
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "view/camera.hpp"

namespace cellproj {

struct TetClip {
  glm::dvec3 n[4];  // face planes n . x <= c inside, n outward (away from the opposite vertex)
  double c[4];
  TetClip() = default;
  explicit TetClip(const glm::dvec3 p[4]) {
    static constexpr int kFace[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
    for (int f = 0; f < 4; ++f) {
      const glm::dvec3& a = p[kFace[f][0]];
      n[f] = glm::cross(p[kFace[f][1]] - a, p[kFace[f][2]] - a);
      if (glm::dot(n[f], p[f] - a) > 0) n[f] = -n[f];
      c[f] = glm::dot(n[f], a);
    }
  }
  // The part [t0, t1] of ray r (t >= 0: from the eye on) inside; false when there is none.
  bool clip(const Ray& r, double& t0, double& t1) const {
    const glm::dvec3 &eye = r.origin, &d = r.dir;
    t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    for (int f = 0; f < 4 && t0 < t1; ++f) {
      const double den = glm::dot(n[f], d), num = c[f] - glm::dot(n[f], eye);
      if (den > 0)
        t1 = std::min(t1, num / den);
      else if (den < 0)
        t0 = std::max(t0, num / den);
      else if (num < 0)
        t1 = -1.0;  // parallel and outside
    }
    return t1 > t0;
  }
};

// The gradient g of the field linear over the tetrahedron p with values s at its vertices,
// s(x) = s[0] + g . (x - p[0]), from the three edges out of p[0]; `det` is the edges' triple product
// (non-zero).
inline glm::dvec3 linear_gradient(const glm::dvec3 p[4], const double s[4], double det) {
  const glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0], e3 = p[3] - p[0];
  return (glm::cross(e2, e3) * (s[1] - s[0]) + glm::cross(e3, e1) * (s[2] - s[0]) +
          glm::cross(e1, e2) * (s[3] - s[0])) /
         det;
}
inline double edges_triple_product(const glm::dvec3 p[4]) {
  return glm::dot(p[1] - p[0], glm::cross(p[2] - p[0], p[3] - p[0]));
}

}  // namespace cellproj
