#include "raycast/volume_union.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
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
  int surface;  // over all parts, part by part
  int part;
  std::uint32_t tet;  // its tetrahedron: the order a rasterizer would be sent the surfaces' polygons
  double alpha;
  glm::dvec3 color;  // shaded, not premultiplied
  bool back;         // a back face: the ray leaves the region above the iso-value
  bool opaque() const { return alpha >= 1.0; }
  SegmentLight light() const {  // alpha of colour, as a layer of optical depth -ln(1 - alpha)
    return {alpha * color, opaque() ? 2 * kOpaqueDepth : -std::log1p(-alpha)};
  }
};

// The scalar of segment g at t (the field linear along it).
double scalar_at(const RaySegment& g, double t) {
  const double len = g.t1 - g.t0;
  return len > 0 ? g.s0 + (t - g.t0) / len * (g.s1 - g.s0) : g.s0;
}

// The volume light of one part's segments [t_from, t_to) clipped (the field linear on each).
void add_volume(const TransferFunction& tf, const RaySegment* seg, std::size_t n, double t_from, double t_to,
                SegmentLight& acc) {
  for (std::size_t k = 0; k < n && acc.depth < kOpaqueDepth; ++k) {
    const double a = std::max(seg[k].t0, t_from), b = std::min(seg[k].t1, t_to);
    if (!(b > a)) continue;
    acc = under(acc, integrate_segment_reference(tf, b - a, scalar_at(seg[k], a), scalar_at(seg[k], b)));
  }
}

// One pixel's ray through every part: its segments per part, and the parts themselves.
struct PixelRay {
  const std::vector<VolumePart>& parts;
  std::vector<const RaySegment*> seg;
  std::vector<std::size_t> n;
  std::int64_t overlap_pieces = 0;

  bool overlaps(std::size_t v, double from, double to) const {
    for (std::size_t k = 0; k < n[v]; ++k)
      if (seg[v][k].t1 > from && seg[v][k].t0 < to) return true;
    return false;
  }

  // The volume light on [from, to): where one part is, its segments as a single volume's; where
  // several overlap, cut at every segment end of each and integrated as overlapping media.
  void add_volumes(double from, double to, SegmentLight& acc) {
    thread_local std::vector<std::size_t> active;
    active.clear();
    for (std::size_t v = 0; v < parts.size(); ++v)
      if (parts[v].volume && overlaps(v, from, to)) active.push_back(v);
    if (active.size() == 1) return add_volume(*parts[active[0]].tf, seg[active[0]], n[active[0]], from, to, acc);
    if (active.empty()) return;
    thread_local std::vector<double> cuts;
    cuts.clear();
    for (std::size_t v : active)
      for (std::size_t k = 0; k < n[v]; ++k) {
        const double a = std::max(seg[v][k].t0, from), b = std::min(seg[v][k].t1, to);
        if (b > a) cuts.push_back(a), cuts.push_back(b);
      }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    thread_local std::vector<std::size_t> at;  // per active part, the segment reached
    at.assign(active.size(), 0);
    thread_local std::vector<MediumSegment> media;
    for (std::size_t c = 0; c + 1 < cuts.size() && acc.depth < kOpaqueDepth; ++c) {
      const double a = cuts[c], b = cuts[c + 1], mid = 0.5 * (a + b);
      media.clear();
      for (std::size_t q = 0; q < active.size(); ++q) {
        const std::size_t v = active[q];
        while (at[q] < n[v] && seg[v][at[q]].t1 <= mid) ++at[q];
        if (at[q] < n[v] && seg[v][at[q]].t0 <= mid)
          media.push_back({parts[v].tf, scalar_at(seg[v][at[q]], a), scalar_at(seg[v][at[q]], b)});
      }
      if (media.size() == 1)
        acc = under(acc, integrate_segment_reference(*media[0].tf, b - a, media[0].s0, media[0].s1));
      else if (media.size() > 1) {
        acc = under(acc, integrate_overlap_reference(b - a, media.data(), media.size()));
        ++overlap_pieces;
      }
    }
  }

  // Front to back in exact order: the volume between the surfaces, each surface at its place.
  SegmentLight ordered(const std::vector<SurfaceHit>& hits) {
    SegmentLight acc;
    double from = -kInf;
    for (const SurfaceHit& h : hits) {
      if (acc.depth >= kOpaqueDepth) return acc;
      add_volumes(from, h.t, acc);
      acc = under(acc, h.light());
      from = h.t;
    }
    add_volumes(from, kInf, acc);
    return acc;
  }

  // libMini's opaque part: the volume up to the nearest opaque surface, and that surface.
  SegmentLight opaque_part(const std::vector<SurfaceHit>& hits, double& z_opaque) {
    SegmentLight acc;
    z_opaque = kInf;
    const SurfaceHit* first = nullptr;
    for (const SurfaceHit& h : hits)
      if (h.opaque()) {
        first = &h;
        z_opaque = h.t;
        break;
      }
    add_volumes(-kInf, z_opaque, acc);
    if (first) acc = under(acc, first->light());
    return acc;
  }
};

// A surface made ready for one frame: its value's tolerance, colour, fitted exponent.
struct PreparedSurface {
  double value, tolerance, opacity, fit_exponent;
  glm::dvec3 base;
  int part;
};

// The light of one pixel's surfaces composited with the volume in `mode`, as (rgb, opacity).
std::pair<glm::dvec3, double> composite(IsoMode mode, PixelRay& ray, const std::vector<SurfaceHit>& hits) {
  if (mode == IsoMode::ordered) {
    const SegmentLight acc = ray.ordered(hits);
    return {acc.rgb, acc.opacity()};
  }
  double z_opaque = kInf;
  const SegmentLight base = ray.opaque_part(hits, z_opaque);
  glm::dvec3 rgb = base.rgb;
  double opacity = base.opacity();
  thread_local std::vector<const SurfaceHit*> semi;  // the semi-transparent surfaces in front of it
  semi.clear();
  for (const SurfaceHit& h : hits)
    if (!h.opaque() && h.t < z_opaque) semi.push_back(&h);
  if (mode == IsoMode::blend2) {  // blended over the picture in the order they are sent: part by part, by cell
    std::stable_sort(semi.begin(), semi.end(), [](const SurfaceHit* a, const SurfaceHit* b) {
      return std::tie(a->part, a->tet, a->surface) < std::tie(b->part, b->tet, b->surface);
    });
    for (const SurfaceHit* h : semi) {
      rgb = h->alpha * h->color + (1.0 - h->alpha) * rgb;
      opacity = h->alpha + (1.0 - h->alpha) * opacity;
    }
    return {rgb, opacity};
  }
  // oit3, oit4: products and sums, order independent (self-attenuation neglected; Roettger section 4)
  double z_back = kInf;  // oit4: the front-most back face of the semi-transparent surfaces
  if (mode == IsoMode::oit4)
    for (const SurfaceHit* h : semi)
      if (h->back) z_back = std::min(z_back, h->t);
  double transmit = 1.0;
  glm::dvec3 emitted(0.0);
  for (const SurfaceHit* h : semi) {
    transmit *= 1.0 - h->alpha;
    if (h->t <= z_back) emitted += h->alpha * h->color;
  }
  return {transmit * rgb + emitted, 1.0 - transmit * (1.0 - opacity)};
}

}  // namespace

Image render_volume_union(const std::vector<VolumePart>& parts, IsoMode mode, IsoOpacity opacity_model,
                          const Camera& camera, int width, int height, IsoStats* stats,
                          const std::function<void(double)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<PreparedSurface> surfaces;
  std::vector<std::vector<glm::dvec3>> gradients(parts.size());
  double fit_error = 0.0;
  std::string exponents;
  for (std::size_t v = 0; v < parts.size(); ++v) {
    const VolumePart& part = parts[v];
    if (!part.tracer || !part.tf || (!part.scalar && part.n_points > 0))
      throw std::invalid_argument("render_volume_union: part " + std::to_string(v) +
                                  " lacks its tracer, field or transfer function");
    if (part.surfaces.empty()) continue;
    const auto [lo, hi] = std::minmax_element(part.scalar, part.scalar + part.n_points);
    gradients[v] = part.tracer->point_gradients(part.scalar);
    for (const IsoSurface& s : part.surfaces) {
      double err = 0.0;
      const double p = opacity_model == IsoOpacity::spectrum_fit ? spectrum_fit_exponent(s.opacity, &err) : 0.0;
      fit_error = std::max(fit_error, err);
      exponents += (exponents.empty() ? "" : ",") + std::to_string(p);
      surfaces.push_back({s.value, iso_tolerance(s.value, *lo, *hi), s.opacity, p,
                          s.color_given ? s.color : glm::clamp(part.tf->color(s.value), 0.0, 1.0),
                          static_cast<int>(v)});
    }
  }

  std::vector<std::unique_ptr<CellRayTracer::View>> views;
  for (const VolumePart& part : parts)
    views.push_back(std::make_unique<CellRayTracer::View>(*part.tracer, camera, width, height));
  constexpr int kTile = CellRayTracer::View::kTile;
  struct Scratch {
    std::vector<std::vector<std::vector<RaySegment>>> lists;  // per part, per pixel of the tile
    std::vector<std::vector<Ray>> rays;                       // per part, per pixel of the tile
    std::vector<SurfaceHit> hits;
  };
  tbb::enumerable_thread_specific<Scratch> scratch([&] {
    Scratch s;
    s.lists.assign(parts.size(), std::vector<std::vector<RaySegment>>(kTile * kTile));
    s.rays.assign(parts.size(), std::vector<Ray>(kTile * kTile));
    return s;
  });
  Image img(width, height);
  std::atomic<std::int64_t> segments{0}, crossings{0}, overlaps{0};
  std::atomic<int> done{0};
  const int n_tiles = views.front()->tiles();
  tbb::parallel_for(0, n_tiles, [&](int tile) {
    Scratch& s = scratch.local();
    for (std::size_t v = 0; v < parts.size(); ++v)
      views[v]->tile_segments(tile, parts[v].scalar, s.lists[v].data(), s.rays[v].data());
    PixelRay ray{parts, std::vector<const RaySegment*>(parts.size()), std::vector<std::size_t>(parts.size())};
    std::int64_t tile_segments = 0;
    views.front()->for_each_pixel(tile, [&](int i, int j, int px) {
      s.hits.clear();
      for (std::size_t v = 0; v < parts.size(); ++v) {
        ray.seg[v] = s.lists[v][px].data();
        ray.n[v] = s.lists[v][px].size();
        tile_segments += static_cast<std::int64_t>(ray.n[v]);
      }
      for (int k = 0; k < static_cast<int>(surfaces.size()); ++k) {
        const PreparedSurface& f = surfaces[k];
        const VolumePart& part = parts[f.part];
        const Ray& r = s.rays[f.part][px];
        iso_crossings(ray.seg[f.part], ray.n[f.part], f.value, f.tolerance, [&](const IsoCrossing& c) {
          const glm::dvec3 normal = surface_normal(*part.tracer, part.scalar, gradients[f.part], c, r);
          const double cosine = std::abs(glm::dot(normal, r.dir));
          s.hits.push_back({c.t, k, f.part, c.tet, iso_opacity(opacity_model, f.opacity, cosine, f.fit_exponent),
                            shade_layer(f.base, normal, r.dir), !c.entering});
        });
      }
      std::sort(s.hits.begin(), s.hits.end(), [](const SurfaceHit& a, const SurfaceHit& b) {
        return a.t < b.t || (a.t == b.t && a.surface < b.surface);
      });
      const auto [rgb, opacity] = composite(mode, ray, s.hits);
      float* out = img.pixel(i, j);
      for (int c = 0; c < 3; ++c) out[c] = static_cast<float>(rgb[c]);
      out[3] = static_cast<float>(opacity);
      crossings.fetch_add(static_cast<std::int64_t>(s.hits.size()), std::memory_order_relaxed);
    });
    segments.fetch_add(tile_segments, std::memory_order_relaxed);
    overlaps.fetch_add(ray.overlap_pieces, std::memory_order_relaxed);
    if (progress) progress(double(++done) / n_tiles);
  });
  if (stats) {
    stats->seconds = seconds_since(start);
    stats->segments = segments;
    stats->surface_crossings = crossings;
    stats->fit_max_error = fit_error;
    stats->fit_exponents = exponents;
    stats->overlap_pieces = overlaps;
  }
  return img;
}

}  // namespace cellproj
