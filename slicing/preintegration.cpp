#include "slicing/preintegration.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "optics/linear_segment.hpp"

namespace cellproj {
namespace {
constexpr double kLayerRatio = 1.2;  // neighbouring layers' lengths
constexpr int kMaxLayers = 64;
constexpr double kMaxLengthRatio = 4.0;
}  // namespace

PreintegratedTable::PreintegratedTable(const TransferFunction& tf, double s_lo, double s_hi, double l_lo, double l_hi,
                                       int size)
    : size_(size), s_lo_(s_lo), l_lo_(l_lo) {
  s_scale_ = s_hi > s_lo ? (size - 1) / (s_hi - s_lo) : 0.0;
  // Longer rays than 4x the shortest (nearly along the planes) take the colour of 4x: their
  // opacity is still exact, and the mean colour of a thick slab varies little with its length.
  const double ratio = std::min(l_hi / l_lo, kMaxLengthRatio);
  layers_ =
      ratio > 1.0 + 1e-12 ? std::min(kMaxLayers, 2 + static_cast<int>(std::log(ratio) / std::log(kLayerRatio))) : 1;
  log_ratio_ = layers_ > 1 ? std::log(ratio) / (layers_ - 1) : 0.0;
  const std::size_t n = static_cast<std::size_t>(size_);
  kappa_.resize(n * n);
  color_.resize(static_cast<std::size_t>(layers_) * n * n * 3);
  const double ds = s_scale_ > 0.0 ? 1.0 / s_scale_ : 0.0;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, layers_ * n), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t row = r.begin(); row < r.end(); ++row) {
      const std::size_t layer = row / n, back = row % n;
      const double length = l_lo_ * std::exp(log_ratio_ * static_cast<double>(layer));
      const double sb = s_lo_ + ds * static_cast<double>(back);
      float* out = color_.data() + row * n * 3;
      for (std::size_t front = 0; front < n; ++front) {
        const double sf = s_lo_ + ds * static_cast<double>(front);
        const SegmentLight light = integrate_segment_closed_form(tf, length, sf, sb);
        if (layer == 0) kappa_[back * n + front] = static_cast<float>(light.depth / length);
        const double alpha = light.opacity();
        // Where nothing absorbs, the colour of a thin segment (any: it is multiplied by 0).
        const glm::dvec3 c = alpha > 1e-300 ? light.rgb / alpha : 0.5 * (tf.color(sf) + tf.color(sb));
        out[3 * front] = static_cast<float>(c.r), out[3 * front + 1] = static_cast<float>(c.g);
        out[3 * front + 2] = static_cast<float>(c.b);
      }
    }
  });
}

double PreintegratedTable::layer_of(double length) const {
  if (layers_ == 1) return 0.0;
  return std::clamp(std::log(length / l_lo_) / log_ratio_, 0.0, static_cast<double>(layers_ - 1));
}

void PreintegratedTable::operator()(double s_front, double s_back, double length, double layer, float rgba[4]) const {
  const double u = std::clamp((s_front - s_lo_) * s_scale_, 0.0, size_ - 1.0);
  const double v = std::clamp((s_back - s_lo_) * s_scale_, 0.0, size_ - 1.0);
  const int i = std::min(static_cast<int>(u), size_ - 2), j = std::min(static_cast<int>(v), size_ - 2);
  const int l = std::min(static_cast<int>(layer), std::max(layers_ - 2, 0));
  const double fu = u - i, fv = v - j, fl = layer - l;
  const std::size_t n = static_cast<std::size_t>(size_), at = static_cast<std::size_t>(j) * n + i;
  auto bilinear = [&](const float* a, std::size_t stride, int c) {
    const float* b = a + n * stride;
    return (1 - fv) * ((1 - fu) * a[c] + fu * a[stride + c]) + fv * ((1 - fu) * b[c] + fu * b[stride + c]);
  };
  const double alpha = -std::expm1(-length * bilinear(kappa_.data() + at, 1, 0));
  const float* c0 = color_.data() + (static_cast<std::size_t>(l) * n * n + at) * 3;
  for (int c = 0; c < 3; ++c) {
    double colour = bilinear(c0, 3, c);
    if (layers_ > 1 && fl > 0.0) colour += fl * (bilinear(c0 + n * n * 3, 3, c) - colour);
    rgba[c] = static_cast<float>(colour * alpha);
  }
  rgba[3] = static_cast<float>(alpha);
}

}  // namespace cellproj
