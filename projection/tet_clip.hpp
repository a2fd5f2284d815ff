#pragma once
// A tetrahedron as the intersection of its four face planes: what a pixel's ray needs to be
// clipped to it (the field at the ends: mesh/geometry.hpp, linear_gradient) (the cells ray cast
// instead of projected: behind the eye, or coloured by another field than their extinction).
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "mesh/geometry.hpp"
#include "view/camera.hpp"

namespace cellproj {

struct TetClip {
  glm::dvec3 n[4];  // face planes n . x <= c inside, n outward (away from the opposite vertex)
  double c[4];
  TetClip() = default;
  explicit TetClip(const glm::dvec3 p[4]) {
    for (int f = 0; f < 4; ++f) n[f] = tet_face_normal(p, f), c[f] = glm::dot(n[f], p[kTetFace[f][0]]);
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

}  // namespace cellproj
