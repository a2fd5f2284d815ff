#include "projection/screen.hpp"

#include <atomic>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace cellproj {

ScreenMap::ScreenMap(const Camera& camera, int width, int height, const glm::dvec3& centre)
    : perspective_(camera.projection == Projection::Perspective), width_(width), height_(height) {
  const PixelRays rays(camera, width, height);  // checks the camera and the size
  eye_ = camera.eye - centre;
  forward_ = rays.forward();
  right_ = glm::normalize(glm::cross(forward_, camera.up));
  up_ = glm::cross(right_, forward_);
  half_h_ = perspective_ ? std::tan(0.5 * camera.fov_y * 3.14159265358979323846 / 180.0) : 0.5 * camera.height;
  half_w_ = half_h_ * double(width) / height;
}

ScreenPoints project_points(const RecentredPoints& points, const double* scalar, const ScreenMap& map) {
  const std::int64_t n = static_cast<std::int64_t>(points.xyz.size() / 3);
  ScreenPoints s;
  s.v.resize(static_cast<std::size_t>(n));
  std::atomic<std::int64_t> behind{0};
  tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, n, 4096), [&](const tbb::blocked_range<std::int64_t>& r) {
    std::int64_t local = 0;
    for (std::int64_t p = r.begin(); p < r.end(); ++p) {
      ScreenVertex& v = s.v[static_cast<std::size_t>(p)];
      map.project(points(p), v.x, v.y, v.z);
      v.s = scalar ? scalar[p] : 0.0;
      local += map.perspective() && !(v.z > 0.0);
    }
    behind += local;
  });
  s.behind_eye = behind;
  return s;
}

}  // namespace cellproj
