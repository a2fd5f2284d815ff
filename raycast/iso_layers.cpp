#include "raycast/iso_layers.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "base/timing.hpp"

namespace cellproj {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Blinn-Phong weights and exponent of the layers' shading (Nagy and Klein, figure 1, step 3).
constexpr double kAmbient = 0.2, kDiffuse = 0.7, kSpecular = 0.3, kShininess = 40.0;

// The grey of a hidden silhouette of layer k >= 2: brighter with depth (Nagy and Klein, section 4).
double hidden_grey(int k) { return std::min(0.85, 0.35 + 0.15 * (k - 2)); }

bool wants_silhouette(Silhouettes mode, int layer) {
  return mode == Silhouettes::both || (mode == Silhouettes::visible && layer == 1) ||
         (mode == Silhouettes::hidden && layer > 1);
}

}  // namespace

void check(const LayerOptions& o) {
  if (!std::isfinite(o.iso)) throw InputError("setting 'iso': the iso-value must be a finite number");
  if (o.layers.empty() || o.layers.front() < 1)
    throw InputError("setting 'layer': layers are numbered from 1 (the nearest crossing of the iso-value)");
  for (std::size_t k = 1; k < o.layers.size(); ++k)
    if (o.layers[k] <= o.layers[k - 1])
      throw InputError("setting 'layer': give the layers in increasing order, each once");
  if (o.layers.back() > 1000) throw InputError("setting 'layer': at most layer 1000");
  if (!o.weights.empty()) {
    if (o.weights.size() != o.layers.size())
      throw InputError("setting 'layer-weights': " + std::to_string(o.weights.size()) + " weights for " +
                       std::to_string(o.layers.size()) + " layers; give one per layer");
    double sum = 0.0;
    for (double w : o.weights) {
      if (!(w >= 0.0) || !std::isfinite(w))
        throw InputError("setting 'layer-weights': weights must be finite and >= 0");
      sum += w;
    }
    if (!(sum > 0.0)) throw InputError("setting 'layer-weights': at least one weight must be positive");
  }
  if (!(o.silhouette_epsilon > 0.0 && o.silhouette_epsilon <= 1.0))
    throw InputError("setting 'silhouette-epsilon': expected a number in (0, 1], got " +
                     std::to_string(o.silhouette_epsilon));
}

int iso_crossings(const RaySegment* seg, std::size_t n, double iso, double tolerance,
                  const std::function<void(const IsoCrossing&)>& emit) {
  int count = 0;
  int last = 0;              // the side of V the ray was last on: +1 above, -1 below, 0 none yet
  double on_since = kNaN;    // where the ray came onto V (within tolerance) since it left `last`
  std::uint32_t on_tet = 0;  // and in which tetrahedron
  double reached = -std::numeric_limits<double>::infinity();
  const auto side = [&](double s) { return s > iso + tolerance ? 1 : s < iso - tolerance ? -1 : 0; };
  const auto arrive = [&](double t, int g, std::uint32_t tet) {  // the ray is at t, on side g
    if (g == 0) {
      if (std::isnan(on_since)) on_since = t, on_tet = tet;
      return;
    }
    if (last != 0 && g != last) {
      const bool on = !std::isnan(on_since);
      emit({on ? on_since : t, on ? on_tet : tet, g > 0});
      ++count;
    }
    last = g;
    on_since = kNaN;
  };
  for (std::size_t k = 0; k < n; ++k) {
    const RaySegment& s = seg[k];
    if (s.t0 > reached + 1e-12 * (1.0 + std::abs(reached))) {  // a gap: the ray was outside the mesh
      last = 0;
      on_since = kNaN;
    }
    reached = std::max(reached, s.t1);
    const int g0 = side(s.s0), g1 = side(s.s1);
    arrive(s.t0, g0, s.tet);
    if (g0 != 0 && g1 != 0 && g0 != g1)  // the field is linear on the segment: its one root
      arrive(s.t0 + (iso - s.s0) / (s.s1 - s.s0) * (s.t1 - s.t0), 0, s.tet);
    arrive(s.t1, g1, s.tet);
  }
  return count;
}

double iso_tolerance(double iso, double field_min, double field_max) {
  const double scale = std::max({std::abs(iso), std::abs(field_min), std::abs(field_max)});
  return 1e-10 * scale;
}

LayerDepths layer_depths(const CellRayTracer& tracer, const double* scalar, double iso, double tolerance,
                         const Camera& camera, int width, int height, int keep) {
  LayerDepths d;
  d.width = width, d.height = height, d.keep = keep;
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  d.count.assign(pixels, 0);
  d.t.assign(pixels * keep, kNaN);
  tracer.trace(camera, width, height, scalar, [&](int i, int j, const Ray&, const RaySegment* seg, std::size_t n) {
    const std::size_t p = static_cast<std::size_t>(j) * width + i;
    int k = 0;
    d.count[p] = iso_crossings(seg, n, iso, tolerance, [&](const IsoCrossing& c) {
      if (k < keep) d.t[p * keep + k] = c.t;
      ++k;
    });
  });
  return d;
}

glm::dvec3 surface_normal(const CellRayTracer& tracer, const double* scalar, const std::vector<glm::dvec3>& gradients,
                          const IsoCrossing& c, const Ray& ray) {
  for (const glm::dvec3& g :
       {tracer.interpolate(gradients, c.tet, ray.origin + c.t * ray.dir), tracer.gradient(c.tet, scalar)}) {
    const double length = glm::length(g);
    if (length > 0 && std::isfinite(length)) return g / length;
  }
  // The field is flat there: constant cells (cell data) meet V only across the face between two
  // cells, a flat field on V begins at a face. That face is the surface.
  const glm::dvec3 n = tracer.face_normal(c.tet, ray.origin + c.t * ray.dir);
  return std::isfinite(n.x + n.y + n.z) ? n : -ray.dir;
}

glm::dvec3 shade_layer(const glm::dvec3& base, const glm::dvec3& n, const glm::dvec3& d) {
  // The light at the eye: its direction and the halfway vector are both -d, so n.h = n.l (two-sided).
  const double c = std::abs(glm::dot(n, d));
  return glm::clamp(base * (kAmbient + kDiffuse * c) + glm::dvec3(kSpecular * std::pow(c, kShininess)), 0.0, 1.0);
}

Image render_layers(const CellRayTracer& tracer, const double* scalar, std::int64_t n_points,
                    const TransferFunction& tf, const Camera& camera, int width, int height, const LayerOptions& o,
                    LayerStats* stats, const std::function<void(double)>& progress) {
  check(o);
  const auto start = std::chrono::steady_clock::now();
  const auto [lo, hi] = std::minmax_element(scalar, scalar + n_points);
  const double tolerance = iso_tolerance(o.iso, *lo, *hi);
  const glm::dvec3 base = o.color ? *o.color : glm::clamp(tf.color(o.iso), 0.0, 1.0);
  const std::vector<double> weights = o.weights.empty() ? std::vector<double>(o.layers.size(), 1.0) : o.weights;
  const int deepest = o.layers.back();
  const std::vector<glm::dvec3> gradients = tracer.point_gradients(scalar);

  Image img(width, height);
  std::atomic<std::int64_t> segments{0}, crossings{0}, with_layer{0}, silhouettes{0};
  std::atomic<int> most{0};
  tracer.trace(
      camera, width, height, scalar,
      [&](int i, int j, const Ray& ray, const RaySegment* seg, std::size_t n) {
        glm::dvec3 sum(0.0);
        double weight = 0.0;
        int k = 0, silhouette = 0;  // the layer of the first silhouette met, 0: none
        const int total = iso_crossings(seg, n, o.iso, tolerance, [&](const IsoCrossing& c) {
          if (++k > deepest) return;
          const auto at = std::lower_bound(o.layers.begin(), o.layers.end(), k);
          const bool drawn = at != o.layers.end() && *at == k;
          const bool wanted = silhouette == 0 && wants_silhouette(o.silhouettes, k);
          if (!drawn && !wanted) return;
          const glm::dvec3 normal = surface_normal(tracer, scalar, gradients, c, ray);
          if (drawn) {  // Nagy and Klein's blending of layers, with weights (equal: their running mean)
            const double w = weights[static_cast<std::size_t>(at - o.layers.begin())];
            sum += w * shade_layer(base, normal, ray.dir);
            weight += w;
          }
          if (wanted && std::abs(glm::dot(normal, ray.dir)) < o.silhouette_epsilon) silhouette = k;
        });
        segments.fetch_add(static_cast<std::int64_t>(n), std::memory_order_relaxed);
        crossings.fetch_add(total, std::memory_order_relaxed);
        for (int m = most.load(); total > m && !most.compare_exchange_weak(m, total);) {
        }
        if (weight <= 0.0 && silhouette == 0) return;
        glm::dvec3 c = weight > 0.0 ? sum / weight : glm::dvec3(0.0);
        if (weight > 0.0) with_layer.fetch_add(1, std::memory_order_relaxed);
        if (silhouette) {
          c = glm::dvec3(silhouette == 1 ? 0.0 : hidden_grey(silhouette));
          silhouettes.fetch_add(1, std::memory_order_relaxed);
        }
        float* px = img.pixel(i, j);
        px[0] = static_cast<float>(c.r), px[1] = static_cast<float>(c.g), px[2] = static_cast<float>(c.b);
        px[3] = 1.0f;
      },
      progress);
  if (stats) {
    stats->seconds = seconds_since(start);
    stats->segments = segments;
    stats->crossings = crossings;
    stats->rays_with_layer = with_layer;
    stats->silhouette_pixels = silhouettes;
    stats->max_crossings = most;
  }
  return img;
}

}  // namespace cellproj
