#include "raycast/reference_renderer.hpp"

#include <atomic>
#include <chrono>

#include "optics/segment_integral.hpp"

namespace cellproj {

Image ExactRenderer::render(const TransferFunction& tf, const Camera& camera, int width, int height, ExactStats* stats,
                            const std::function<void(double)>& progress) const {
  const auto start = std::chrono::steady_clock::now();
  Image img(width, height);
  std::atomic<std::int64_t> segments{0};
  tracer_.trace(camera, width, height, [&](int i, int j, const RaySegment* seg, std::size_t n) {
    SegmentLight acc;
    for (std::size_t k = 0; k < n && acc.depth < kOpaqueDepth; ++k)
      acc = under(acc, integrate_segment_reference(tf, seg[k].t1 - seg[k].t0, seg[k].s0, seg[k].s1));
    float* px = img.pixel(i, j);
    px[0] = static_cast<float>(acc.rgb.r);
    px[1] = static_cast<float>(acc.rgb.g);
    px[2] = static_cast<float>(acc.rgb.b);
    px[3] = static_cast<float>(acc.opacity());
    segments.fetch_add(static_cast<std::int64_t>(n), std::memory_order_relaxed);
  }, progress);
  if (stats) {
    stats->trace_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats->segments = segments;
  }
  return img;
}

}  // namespace cellproj
