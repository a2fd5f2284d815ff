#pragma once
// A point set relative to the centre of its bounding box, so that huge coordinate offsets lose no
// precision in the differences the geometry is made of. Made from a mesh by recentre()
// (mesh/geometry.hpp); read by the view's projection (view/screen.hpp), which so needs no mesh.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace cellproj {

struct RecentredPoints {
  glm::dvec3 centre{0.0};
  glm::dvec3 lo{0.0}, hi{0.0};  // the bounding box, recentred (the extremes of the recentred points)
  double half_diagonal = 0.0;   // of the bounding box
  std::vector<double> xyz;
  glm::dvec3 operator()(std::int64_t p) const { return {xyz[3 * p], xyz[3 * p + 1], xyz[3 * p + 2]}; }
};

}  // namespace cellproj
