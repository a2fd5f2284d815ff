#include "slicing/slab_compositor.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include "composite/fragment.hpp"
#include "slicing/slice_splats.hpp"
#include "view/raster.hpp"

namespace cellproj {
namespace {

// The polygons of a slice, fanned from their first vertex, into its scalar image.
void scan_convert(const SlicePolygons& p, int width, int height, SliceImage& out, std::int64_t& fragments,
                  std::int64_t& overlaps) {
  for (std::size_t q = 0; q < p.size(); ++q) {
    const std::uint32_t v0 = p.start[q];
    for (std::uint32_t v = v0 + 1; v + 1 < p.start[q + 1]; ++v) {
      const double w[3] = {p.w[v0], p.w[v], p.w[v + 1]}, sw[3] = {p.sw[v0], p.sw[v], p.sw[v + 1]};
      rasterize_triangle_weights({p.x[v0], p.y[v0]}, {p.x[v], p.y[v]}, {p.x[v + 1], p.y[v + 1]}, width, height,
                                 [&](int i, int j, double l0, double l1, double l2) {
                                   const double s = perspective_correct(l0, l1, l2, sw, w);
                                   float& at = out.s[static_cast<std::size_t>(j) * width + i];
                                   overlaps += !std::isnan(at);
                                   at = static_cast<float>(s);
                                   out.x0 = std::min(out.x0, i), out.x1 = std::max(out.x1, i + 1);
                                   out.y0 = std::min(out.y0, j), out.y1 = std::max(out.y1, j + 1);
                                   ++fragments;
                                 });
    }
  }
}

}  // namespace

void scan_convert(const PlanePolygons& plane, int width, int height, SliceImage& out, ScanCounts& st) {
  out.x0 = width, out.y0 = height, out.x1 = 0, out.y1 = 0;
  plane.for_each([&](const SlicePolygons& p) {
    scan_convert(p, width, height, out, st.fragments, st.overlapping_fragments);
    st.polygons += static_cast<std::int64_t>(p.size()), st.clipped_polygons += p.clipped;
  });
  if (out.x1 <= out.x0) out.x0 = out.y0 = out.x1 = out.y1 = 0;
}

void constant_light(const TransferFunction& tf, double s, double length, float rgba[4]) {
  const double alpha = -std::expm1(-tf.extinction(s) * length);
  const glm::dvec3 c = tf.color(s);
  rgba[0] = static_cast<float>(c.r * alpha), rgba[1] = static_cast<float>(c.g * alpha);
  rgba[2] = static_cast<float>(c.b * alpha), rgba[3] = static_cast<float>(alpha);
}

PixelLengths pixel_lengths(const PixelRays& rays, const glm::dvec3& normal, double spacing) {
  PixelLengths p;
  const int w = rays.width(), h = rays.height();
  p.length.resize(static_cast<std::size_t>(w) * h);
  std::vector<int> along(static_cast<std::size_t>(h), 0);
  tbb::parallel_for(0, h, [&](int j) {
    for (int i = 0; i < w; ++i) {
      const double c = -glm::dot(rays.ray(i + 0.5, j + 0.5).dir, normal);  // the normal points to the eye
      along[static_cast<std::size_t>(j)] += !(c > 1e-3);
      p.length[static_cast<std::size_t>(j) * w + i] = static_cast<float>(spacing / std::max(std::abs(c), 1e-6));
    }
  });
  for (int a : along) p.along += a;
  const auto [lo, hi] = std::minmax_element(p.length.begin(), p.length.end());
  p.lo = *lo, p.hi = *hi;
  return p;
}

void Compositor::operator()(Image& image, const SliceImage& behind, const std::vector<const SliceImage*>& slices,
                            const std::vector<const SplatLayer*>& splats, double front) const {
  tbb::parallel_for(tbb::blocked_range<int>(0, height, 4), [&](const tbb::blocked_range<int>& rows) {
    for (int j = rows.begin(); j < rows.end(); ++j)
      for (int i = 0; i < width; ++i) pixel(image, i, j, behind, slices, splats, front);
  });
}

void Compositor::pixel(Image& image, int i, int j, const SliceImage& behind,
                       const std::vector<const SliceImage*>& slices, const std::vector<const SplatLayer*>& splats,
                       double front_height) const {
  const std::size_t at = static_cast<std::size_t>(j) * width + i;
  float* dst = image.pixel(i, j);
  const double length = lengths.length[at], layer = lengths.layer.empty() ? 0.0 : lengths.layer[at];
  const bool sampled = options.integral == SliceIntegral::sampled;
  float back = behind.at(i, j, width), rgba[4], back_half[4], front_half[4];
  double back_height = behind.height;
  if (sampled && !std::isnan(back)) constant_light(tf, back, 0.5 * length, back_half);
  auto slab = [&](float front, double height) {
    const bool f = !std::isnan(front), b = !std::isnan(back);
    if (f && b) {
      if (sampled) {
        constant_light(tf, front, 0.5 * length, front_half);
        over(dst, back_half), over(dst, front_half);
      } else {
        (*table)(front, back, length, layer, rgba);
        over(dst, rgba);
      }
    } else if (f || b) {
      // No crossing in a slab that ends at the eye: inside the mesh up to the eye. None known
      // otherwise (too many, or its face reaches behind the eye): half the slab, on average.
      const double crossing = boundary.between(at, back_height, height, f);
      const double inside = std::isinf(crossing) && height == eye_height ? 1.0
                            : !std::isfinite(crossing)
                                ? 0.5
                                : (f ? height - crossing : crossing - back_height) / (height - back_height);
      constant_light(tf, f ? front : back, inside * length, rgba);
      over(dst, rgba);
      if (sampled && f) constant_light(tf, front, 0.5 * length, front_half);
    }
    back = front, back_height = height;
    if (sampled) std::copy(front_half, front_half + 4, back_half);
  };
  for (std::size_t k = 0; k < slices.size(); ++k) {
    slab(slices[k]->at(i, j, width), slices[k]->height);
    const SplatLayer* layer = splats.empty() ? nullptr : splats[k];
    if (layer && layer->covers(i, j)) over(dst, layer->at(i, j));  // the plane's splats, where it left the pixel empty
  }
  if (!std::isnan(front_height)) slab(kEmpty, front_height);
}

}  // namespace cellproj
