#pragma once
// Maximum (and minimum, and mean) intensity projection: per pixel, one value of the field along
// the ray through the mesh, shown through the transfer function's colour map. No optical model and
// no order: each ray's segments (raycast/cell_ray_tracer.hpp) are reduced as they come.
#include <cstdint>
#include <functional>
#include <vector>

#include "optics/transfer_function.hpp"
#include "raycast/cell_ray_tracer.hpp"
#include "raycast/reduction.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"

namespace cellproj {

struct ReductionStats {
  double seconds = 0.0;
  std::int64_t segments = 0;  // ray-tetrahedron segments reduced
  std::int64_t rays_hit = 0;  // pixels whose ray meets the mesh
};
// Each counter the report shows, with its key (render/report.hpp): f(key, value).
template <class F>
void each_counter(const ReductionStats& s, F&& f) {
  f("segments", s.segments), f("rays_hit", s.rays_hit);
}

// Exact for the field linear in each canonical tetrahedron: a linear segment's extremes are at its
// ends and its mean is the mean of its ends, so no sampling step is involved. A pixel whose ray
// meets the mesh gets tf.color(value), opaque; the others stay empty (the background shows).
Image reduce_rays(const CellRayTracer& tracer, const double* scalar, const TransferFunction& tf, const Camera& camera,
                  int width, int height, RayReduction reduction, ReductionStats* stats = nullptr,
                  const std::function<void(double)>& progress = {});

// The value of each pixel instead of its colour (NaN where the ray misses the mesh), row-major
// from the top: what reduce_rays shows, for tests and for callers who map it themselves.
std::vector<double> reduce_ray_values(const CellRayTracer& tracer, const double* scalar, const Camera& camera,
                                      int width, int height, RayReduction reduction, ReductionStats* stats = nullptr,
                                      const std::function<void(double)>& progress = {});

}  // namespace cellproj
