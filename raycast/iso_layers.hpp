#pragma once
// Volumetric depth peeling (Nagy and Klein, "Depth-peeling for texture-based volume rendering"):
// per pixel, the n-th crossing of one iso-value along the ray, interior and exterior boundaries
// alternating; several layers blended; visible and hidden silhouettes. On the field linear in each
// canonical tetrahedron the crossings are the exact roots of each ray segment (no sampling step).
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "optics/transfer_function.hpp"
#include "raycast/cell_ray_tracer.hpp"
#include "raycast/layer_options.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"

namespace cellproj {

// One crossing of the iso-value V along a ray.
struct IsoCrossing {
  double t;           // world distance along the ray, as RaySegment's
  std::uint32_t tet;  // the tracer's tetrahedron whose field gradient is the surface normal there
  bool entering;      // the field goes from below V to above V (Nagy and Klein's exterior boundary)
};

// The crossings of V along one ray's segments (front to back, as CellRayTracer gives them), each
// passed to emit(crossing) in order; returns their number. Values within `tolerance` of V count as
// on it: a ray that touches V and turns back crosses nothing, one that passes through V at a vertex
// or along a face crosses once (at the front of where it is on V). A gap between segments (the ray
// outside a non-convex mesh) starts afresh: the mesh boundary is not a crossing.
int iso_crossings(const RaySegment* segments, std::size_t n, double iso, double tolerance,
                  const std::function<void(const IsoCrossing&)>& emit);

// `tolerance` for iso_crossings on a field: a few thousand ulps of its magnitude.
double iso_tolerance(double iso, double field_min, double field_max);

struct LayerStats {
  double seconds = 0.0;
  std::int64_t segments = 0;           // ray-tetrahedron segments walked
  std::int64_t crossings = 0;          // crossings of V found, on all rays
  std::int64_t rays_with_layer = 0;    // rays reaching at least the first selected layer
  std::int64_t silhouette_pixels = 0;  // pixels drawn as a silhouette
  int max_crossings = 0;               // the most crossings on one ray
};
// Each counter the report shows, with its key (render/report.hpp): f(key, value).
template <class F>
void each_counter(const LayerStats& s, F&& f) {
  f("segments", s.segments), f("crossings", s.crossings), f("rays_with_layer", s.rays_with_layer);
  f("silhouette_pixels", s.silhouette_pixels), f("max_crossings_on_a_ray", std::int64_t{s.max_crossings});
}

// Per pixel (row-major from the top), how many times the ray crosses V, and the depth t of the
// first `keep` crossings (NaN past the count): what layers are drawn from, for tests and callers.
struct LayerDepths {
  int width = 0, height = 0, keep = 0;
  std::vector<int> count;
  std::vector<double> t;  // t[(pixel) * keep + k], crossing k + 1
};
LayerDepths layer_depths(const CellRayTracer& tracer, const double* scalar, double iso, double tolerance,
                         const Camera& camera, int width, int height, int keep);

// The picture of `options`: the selected layers shaded (Blinn-Phong, two-sided, headlight) and
// blended with their weights, silhouettes drawn over them; opaque where the ray reaches a selected
// layer or a silhouette, empty (the background shows) elsewhere.
Image render_layers(const CellRayTracer& tracer, const double* scalar, std::int64_t n_points,
                    const TransferFunction& tf, const Camera& camera, int width, int height,
                    const LayerOptions& options, LayerStats* stats = nullptr,
                    const std::function<void(double)>& progress = {});

// The unit normal of the iso-surface at crossing c: the direction of the points' gradients
// (CellRayTracer::point_gradients) interpolated there, smooth across cells as a texture renderer's
// gradients are; else the tetrahedron's own gradient; where both vanish (cell data, constant over
// each cell, crosses V only at the face between two cells; a field flat on V) the normal of the
// tetrahedron's face the crossing lies on.
glm::dvec3 surface_normal(const CellRayTracer& tracer, const double* scalar, const std::vector<glm::dvec3>& gradients,
                          const IsoCrossing& c, const Ray& ray);

// The shade of a layer at unit normal n (the field's gradient direction, either sign) seen along
// the unit ray direction d with the light at the eye: base (ambient + diffuse |n.d|) + specular.
glm::dvec3 shade_layer(const glm::dvec3& base, const glm::dvec3& n, const glm::dvec3& d);

}  // namespace cellproj
