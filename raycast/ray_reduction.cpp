#include "raycast/ray_reduction.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>

#include <glm/common.hpp>

#include "base/timing.hpp"

namespace cellproj {

std::vector<double> reduce_ray_values(const CellRayTracer& tracer, const double* scalar, const Camera& camera,
                                      int width, int height, RayReduction reduction, ReductionStats* stats,
                                      const std::function<void(double)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<double> values(static_cast<std::size_t>(width) * height, std::numeric_limits<double>::quiet_NaN());
  std::atomic<std::int64_t> segments{0}, hit{0};
  tracer.trace(
      camera, width, height, scalar,
      [&](int i, int j, const Ray&, const RaySegment* seg, std::size_t n) {
        if (n == 0) return;
        double v = 0.0;
        if (reduction == RayReduction::average) {
          double length = 0.0, integral = 0.0;  // the integral of a linear segment: its mean end value times its length
          for (std::size_t k = 0; k < n; ++k) {
            const double l = seg[k].t1 - seg[k].t0;
            length += l;
            integral += 0.5 * (seg[k].s0 + seg[k].s1) * l;
          }
          v = length > 0 ? integral / length : 0.5 * (seg[0].s0 + seg[0].s1);  // a grazing ray: its one point
        } else {
          const bool max = reduction == RayReduction::maximum;
          v = seg[0].s0;
          for (std::size_t k = 0; k < n; ++k)
            v = max ? std::max({v, seg[k].s0, seg[k].s1}) : std::min({v, seg[k].s0, seg[k].s1});
        }
        values[static_cast<std::size_t>(j) * width + i] = v;
        segments.fetch_add(static_cast<std::int64_t>(n), std::memory_order_relaxed);
        hit.fetch_add(1, std::memory_order_relaxed);
      },
      progress);
  if (stats) {
    stats->seconds = seconds_since(start);
    stats->segments = segments;
    stats->rays_hit = hit;
  }
  return values;
}

Image reduce_rays(const CellRayTracer& tracer, const double* scalar, const TransferFunction& tf, const Camera& camera,
                  int width, int height, RayReduction reduction, ReductionStats* stats,
                  const std::function<void(double)>& progress) {
  const std::vector<double> values =
      reduce_ray_values(tracer, scalar, camera, width, height, reduction, stats, progress);
  Image img(width, height);
  for (std::size_t p = 0; p < values.size(); ++p) {
    if (std::isnan(values[p])) continue;
    const glm::dvec3 c = glm::clamp(tf.color(values[p]), 0.0, 1.0);
    float* px = img.rgba.data() + 4 * p;
    px[0] = static_cast<float>(c.r);
    px[1] = static_cast<float>(c.g);
    px[2] = static_cast<float>(c.b);
    px[3] = 1.0f;
  }
  return img;
}

}  // namespace cellproj
