#include "raycast/iso_surfaces.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "base/timing.hpp"
#include "optics/segment_integral.hpp"
#include "raycast/iso_layers.hpp"

namespace cellproj {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One surface met along a ray: where, which, and the light it adds there.
struct SurfaceHit {
  double t;
  int surface;
  std::uint32_t tet;  // its tetrahedron: the order a rasterizer would be sent the surfaces' polygons
  double alpha;
  glm::dvec3 color;  // shaded, not premultiplied
  bool back;         // a back face: the ray leaves the region above the iso-value
  bool opaque() const { return alpha >= 1.0; }
  SegmentLight light() const {  // alpha of colour, as a layer of optical depth -ln(1 - alpha)
    return {alpha * color, opaque() ? 2 * kOpaqueDepth : -std::log1p(-alpha)};
  }
};

// The volume light of a ray's segments [t_from, t_to) clipped (the field linear on each).
void add_volume(const TransferFunction& tf, const RaySegment* seg, std::size_t n, double t_from, double t_to,
                SegmentLight& acc) {
  for (std::size_t k = 0; k < n && acc.depth < kOpaqueDepth; ++k) {
    const double a = std::max(seg[k].t0, t_from), b = std::min(seg[k].t1, t_to);
    if (!(b > a)) continue;
    const double len = seg[k].t1 - seg[k].t0;
    const auto s = [&](double t) {
      return len > 0 ? seg[k].s0 + (t - seg[k].t0) / len * (seg[k].s1 - seg[k].s0) : seg[k].s0;
    };
    acc = under(acc, integrate_segment_reference(tf, b - a, s(a), s(b)));
  }
}

// Front to back in exact order: the volume between the surfaces, each surface at its place.
SegmentLight ordered(const TransferFunction& tf, bool volume, const RaySegment* seg, std::size_t n,
                     const std::vector<SurfaceHit>& hits) {
  SegmentLight acc;
  double from = -kInf;
  for (const SurfaceHit& h : hits) {
    if (acc.depth >= kOpaqueDepth) return acc;
    if (volume) add_volume(tf, seg, n, from, h.t, acc);
    acc = under(acc, h.light());
    from = h.t;
  }
  if (volume) add_volume(tf, seg, n, from, kInf, acc);
  return acc;
}

// libMini's opaque part: the volume up to the nearest opaque surface, and that surface.
SegmentLight opaque_part(const TransferFunction& tf, bool volume, const RaySegment* seg, std::size_t n,
                         const std::vector<SurfaceHit>& hits, double& z_opaque) {
  SegmentLight acc;
  z_opaque = kInf;
  const SurfaceHit* first = nullptr;
  for (const SurfaceHit& h : hits)
    if (h.opaque()) {
      first = &h;
      z_opaque = h.t;
      break;
    }
  if (volume) add_volume(tf, seg, n, -kInf, z_opaque, acc);
  if (first) acc = under(acc, first->light());
  return acc;
}

void check_unit(double v, const std::string& what) {
  if (!(v >= 0.0 && v <= 1.0)) throw InputError("--iso: " + what + " must be in [0, 1], got " + std::to_string(v));
}

}  // namespace

void check(const IsoOptions& o) {
  for (const IsoSurface& s : o.surfaces) {
    if (!std::isfinite(s.value)) throw InputError("--iso: the iso-value must be a finite number");
    for (int c = 0; c < 3; ++c) check_unit(s.color[c], "colour components");
    check_unit(s.opacity, "the opacity");
  }
}

double iso_opacity(IsoOpacity model, double a, double c, double fit_exponent) {
  c = std::clamp(c, 1e-6, 1.0);
  switch (model) {
    case IsoOpacity::constant: return a;
    case IsoOpacity::spectrum:  // Roettger section 4: alpha = 1 - exp(-c d / |cos t|), exp(-c d) = 1 - a head-on
      return a >= 1.0 ? 1.0 : -std::expm1(std::log1p(-a) / c);
    case IsoOpacity::spectrum_fit: return a >= 1.0 ? 1.0 : 1.0 - (1.0 - a) * std::pow(c, fit_exponent);
  }
  return a;
}

double spectrum_fit_exponent(double a, double* max_error) {
  // Least squares over c = (k + 1/2) / 256 of the fit against the formula, by golden section in p.
  const auto error = [a](double p, double* worst) {
    double sum = 0.0;
    for (int k = 0; k < 256; ++k) {
      const double c = (k + 0.5) / 256;
      const double d = (1.0 - a) * std::pow(c, p) - std::exp(std::log1p(-a) / c);
      sum += d * d;
      if (worst) *worst = std::max(*worst, std::abs(d));
    }
    return sum;
  };
  if (a <= 0.0 || a >= 1.0) {
    if (max_error) *max_error = 0.0;
    return 0.0;
  }
  double lo = 0.0, hi = 64.0;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 80; ++it) {
    const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    if (error(m1, nullptr) < error(m2, nullptr))
      hi = m2;
    else
      lo = m1;
  }
  const double p = 0.5 * (lo + hi);
  if (max_error) {
    *max_error = 0.0;
    error(p, max_error);
  }
  return p;
}

Image render_iso_surfaces(const CellRayTracer& tracer, const double* scalar, std::int64_t n_points,
                          const TransferFunction& tf, const Camera& camera, int width, int height, const IsoOptions& o,
                          IsoStats* stats, const std::function<void(double)>& progress) {
  check(o);
  const auto start = std::chrono::steady_clock::now();
  const auto [lo, hi] = std::minmax_element(scalar, scalar + n_points);
  const std::vector<glm::dvec3> gradients = tracer.point_gradients(scalar);
  struct Prepared {
    double value, tolerance, opacity, fit_exponent;
    glm::dvec3 base;
  };
  std::vector<Prepared> surfaces;
  double fit_error = 0.0;
  std::string exponents;
  for (const IsoSurface& s : o.surfaces) {
    double err = 0.0;
    const double p = o.opacity == IsoOpacity::spectrum_fit ? spectrum_fit_exponent(s.opacity, &err) : 0.0;
    fit_error = std::max(fit_error, err);
    exponents += (exponents.empty() ? "" : ",") + std::to_string(p);
    surfaces.push_back({s.value, iso_tolerance(s.value, *lo, *hi), s.opacity, p,
                        s.color_given ? s.color : glm::clamp(tf.color(s.value), 0.0, 1.0)});
  }

  Image img(width, height);
  std::atomic<std::int64_t> segments{0}, crossings{0};
  tracer.trace(
      camera, width, height, scalar,
      [&](int i, int j, const Ray& ray, const RaySegment* seg, std::size_t n) {
        thread_local std::vector<SurfaceHit> hits;  // reused by every pixel of this thread
        hits.clear();
        for (int k = 0; k < static_cast<int>(surfaces.size()); ++k) {
          const Prepared& s = surfaces[k];
          iso_crossings(seg, n, s.value, s.tolerance, [&](const IsoCrossing& c) {
            const glm::dvec3 normal = surface_normal(tracer, scalar, gradients, c, ray);
            const double cosine = std::abs(glm::dot(normal, ray.dir));
            hits.push_back({c.t, k, c.tet, iso_opacity(o.opacity, s.opacity, cosine, s.fit_exponent), shade_layer(s.base, normal, ray.dir), !c.entering});
          });
        }
        std::sort(hits.begin(), hits.end(), [](const SurfaceHit& a, const SurfaceHit& b) {
          return a.t < b.t || (a.t == b.t && a.surface < b.surface);
        });
        glm::dvec3 rgb(0.0);
        double opacity = 0.0;
        if (o.mode == IsoMode::ordered) {
          const SegmentLight acc = ordered(tf, o.volume, seg, n, hits);
          rgb = acc.rgb, opacity = acc.opacity();
        } else {
          double z_opaque = kInf;
          const SegmentLight base = opaque_part(tf, o.volume, seg, n, hits, z_opaque);
          rgb = base.rgb, opacity = base.opacity();
          thread_local std::vector<const SurfaceHit*> semi;  // the semi-transparent surfaces in front of it
          semi.clear();
          for (const SurfaceHit& h : hits)
            if (!h.opaque() && h.t < z_opaque) semi.push_back(&h);
          if (o.mode == IsoMode::blend2) {  // blended over the picture in the order they are sent: by cell
            std::stable_sort(semi.begin(), semi.end(), [](const SurfaceHit* a, const SurfaceHit* b) {
              return a->tet < b->tet || (a->tet == b->tet && a->surface < b->surface);
            });
            for (const SurfaceHit* h : semi) {
              rgb = h->alpha * h->color + (1.0 - h->alpha) * rgb;
              opacity = h->alpha + (1.0 - h->alpha) * opacity;
            }
          } else {                 // oit3, oit4: products and sums, order independent (self-attenuation neglected)
            double z_back = kInf;  // oit4: the front-most back face of the semi-transparent surfaces
            if (o.mode == IsoMode::oit4)
              for (const SurfaceHit* h : semi)
                if (h->back) z_back = std::min(z_back, h->t);
            double transmit = 1.0;
            glm::dvec3 emitted(0.0);
            for (const SurfaceHit* h : semi) {
              transmit *= 1.0 - h->alpha;
              if (h->t <= z_back) emitted += h->alpha * h->color;
            }
            rgb = transmit * rgb + emitted;
            opacity = 1.0 - transmit * (1.0 - opacity);
          }
        }
        float* px = img.pixel(i, j);
        for (int c = 0; c < 3; ++c) px[c] = static_cast<float>(rgb[c]);
        px[3] = static_cast<float>(opacity);
        segments.fetch_add(static_cast<std::int64_t>(n), std::memory_order_relaxed);
        crossings.fetch_add(static_cast<std::int64_t>(hits.size()), std::memory_order_relaxed);
      },
      progress);
  if (stats) {
    stats->seconds = seconds_since(start);
    stats->segments = segments;
    stats->surface_crossings = crossings;
    stats->fit_max_error = fit_error;
    stats->fit_exponents = exponents;
  }
  return img;
}

}  // namespace cellproj
