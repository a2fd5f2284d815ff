#pragma once
// The image-plane positions of a mesh's points for one view: pixel x, y (the coverage rule's
// coordinates) and view depth z (distance along the view direction from the eye, or from the
// eye's plane in orthographic projection).
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "grid/geometry.hpp"
#include "projection/projected_tet.hpp"
#include "view/camera.hpp"

namespace cellproj {

// A camera fixed to an image, in the frame of recentred points (centre subtracted), so that huge
// coordinate offsets cost no precision.
class ScreenMap {
 public:
  ScreenMap(const Camera& camera, int width, int height, const glm::dvec3& centre);

  // Pixel position and view depth of a recentred point; in perspective z must be > 0 for x, y.
  void project(const glm::dvec3& p, double& x, double& y, double& z) const {
    const glm::dvec3 d = p - eye_;
    double u = glm::dot(d, right_), v = glm::dot(d, up_);
    z = glm::dot(d, forward_);
    if (perspective_) u /= z, v /= z;
    x = (u / half_w_ + 1.0) * 0.5 * width_;
    y = (1.0 - v / half_h_) * 0.5 * height_;
  }
  // Ray length per unit of view depth through pixel position (x, y): 1 / cos of the ray's angle
  // with the view direction (1 in orthographic projection).
  double length_per_depth(double x, double y) const {
    if (!perspective_) return 1.0;
    const double u = (2.0 * x / width_ - 1.0) * half_w_, v = (1.0 - 2.0 * y / height_) * half_h_;
    return std::sqrt(1.0 + u * u + v * v);
  }
  // The unit direction of the ray through pixel position (x, y), and the eye (perspective), in the
  // recentred frame.
  glm::dvec3 ray_direction(double x, double y) const {
    const double u = (2.0 * x / width_ - 1.0) * half_w_, v = (1.0 - 2.0 * y / height_) * half_h_;
    return glm::normalize(forward_ + u * right_ + v * up_);
  }
  const glm::dvec3& eye() const { return eye_; }
  bool perspective() const { return perspective_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  bool perspective_;
  int width_, height_;
  glm::dvec3 eye_, forward_, right_, up_;
  double half_w_, half_h_;
};

// Every point projected once per frame, with its scalar: one 32-byte record per point, since a
// tetrahedron gathers all four values of each of its four vertices.
struct ScreenPoints {
  std::vector<ScreenVertex> v;
  std::int64_t behind_eye = 0;  // perspective: points with z <= 0 (their cells are not drawn)
};
// Parallel over points (oneTBB, in the caller's task arena); `scalar` may be null (zeros).
ScreenPoints project_points(const RecentredPoints& points, const double* scalar, const ScreenMap& map);

}  // namespace cellproj
