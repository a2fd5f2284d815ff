#include "view/screen.hpp"

#include <atomic>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace cellproj {

ScreenPoints project_points(const RecentredPoints& points, const double* scalar, const PixelRays& rays) {
  const std::int64_t n = static_cast<std::int64_t>(points.xyz.size() / 3);
  ScreenPoints s;
  s.v.resize(static_cast<std::size_t>(n));
  std::atomic<std::int64_t> behind{0};
  tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, n, 4096), [&](const tbb::blocked_range<std::int64_t>& r) {
    std::int64_t local = 0;
    for (std::int64_t p = r.begin(); p < r.end(); ++p) {
      ScreenVertex& v = s.v[static_cast<std::size_t>(p)];
      rays.project(points(p), v.x, v.y, v.z);
      v.s = scalar ? scalar[p] : 0.0;
      local += behind_eye(v.z);
    }
    behind += local;
  });
  s.behind_eye = behind;
  return s;
}

}  // namespace cellproj
