#pragma once
// Semi-transparent iso-surfaces with the volume, per pixel on the exact renderer's rays. The
// surfaces are those of the field linear in each canonical tetrahedron: the marching-tetrahedra
// surface on the canonical split, met exactly where each ray crosses it (raycast/iso_layers.hpp),
// so neighbouring cells agree on their shared faces. Normals from the points' gradients.
#include <cstdint>
#include <functional>
#include <string>

#include "optics/transfer_function.hpp"
#include "raycast/cell_ray_tracer.hpp"
#include "raycast/iso_options.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"

namespace cellproj {

struct IsoStats {
  double seconds = 0.0;
  std::int64_t segments = 0;           // ray-tetrahedron segments walked
  std::int64_t surface_crossings = 0;  // crossings of the surfaces, on all rays
  double fit_max_error = 0.0;          // spectrum-fit: the largest opacity error of the fit, over the surfaces
  std::string fit_exponents;           // spectrum-fit: each surface's exponent p, comma-separated
  std::int64_t overlap_pieces = 0;     // several volumes: pieces of ray inside two or more of them
};
// Each counter the report shows, with its key (render/report.hpp): f(key, value).
template <class F>
void each_counter(const IsoStats& s, F&& f) {
  f("segments", s.segments), f("surface_crossings", s.surface_crossings);
}

// The picture of `options` (premultiplied RGBA without background, as every renderer's). The
// volume, when on, is the exact integral of the transfer function along each segment of the
// canonical tetrahedra (hexahedra's field linear in each, as --interpolation canonical-tets).
Image render_iso_surfaces(const CellRayTracer& tracer, const double* scalar, std::int64_t n_points,
                          const TransferFunction& tf, const Camera& camera, int width, int height,
                          const IsoOptions& options, IsoStats* stats = nullptr,
                          const std::function<void(double)>& progress = {});

}  // namespace cellproj
