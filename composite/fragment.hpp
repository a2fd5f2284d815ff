#pragma once
// Fragments and the compositing operators (MWSC section 7; Porter and Duff): premultiplied RGBA,
// "over" for back-to-front order and "under" for front-to-back.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "base/huge_pages.hpp"
#include "view/image.hpp"

namespace cellproj {

// A pixel's premultiplied light and opacity from one cell (or one slice polygon, one splat).
struct Fragment {
  std::uint32_t pixel;  // j * width + i
  float rgba[4];
};

// A batch's fragments: a buffer written once per batch, on huge pages once it is large.
using Fragments = FrameBuffer<Fragment>;

// Appends pixel (i, j)'s fragment of a `width`-wide image. Written field by field into the vector:
// a fragment built on the stack and copied whole showed in perf as a store-forwarding stall.
inline void append_fragment(Fragments& out, int width, int i, int j, double r, double g, double b, double alpha) {
  Fragment& f = out.emplace_back();
  f.pixel = static_cast<std::uint32_t>(j) * static_cast<std::uint32_t>(width) + static_cast<std::uint32_t>(i);
  f.rgba[0] = static_cast<float>(r), f.rgba[1] = static_cast<float>(g), f.rgba[2] = static_cast<float>(b);
  f.rgba[3] = static_cast<float>(alpha);
}

// A batch's fragments kept by band of 2^shift image rows, each band in the order they were made:
// bands are composited in parallel, each pixel still seeing its fragments in order. A rasterizer
// emits row by row, so a fragment goes to its band for the price of a shift.
class FragmentBands {
 public:
  FragmentBands(int width, int height, int shift) { reset(width, height, shift); }
  void reset(int width, int height, int shift) {
    width_ = width, shift_ = shift;
    bands_.resize(height > 0 ? static_cast<std::size_t>(((height - 1) >> shift) + 1) : 1);
    clear();
  }
  void clear() {
    for (auto& b : bands_) b.clear();
  }
  void append(int i, int j, double r, double g, double b, double alpha) {
    append_fragment(bands_[static_cast<std::size_t>(j >> shift_)], width_, i, j, r, g, b, alpha);
  }
  std::size_t bands() const { return bands_.size(); }
  const Fragments& band(std::size_t b) const { return bands_[b]; }

 private:
  int width_ = 0, shift_ = 0;
  std::vector<Fragments> bands_;
};

// A fragment that neither adds light nor hides anything (a ray grazing a cell): not composited,
// not counted.
inline bool adds_nothing(const glm::dvec3& rgb, double alpha) {
  return alpha == 0.0 && rgb.r == 0.0 && rgb.g == 0.0 && rgb.b == 0.0;
}

// Back to front: src in front of what dst holds.
inline void over(float* dst, const float src[4]) {
  const float t = 1.0f - src[3];
  for (int c = 0; c < 4; ++c) dst[c] = src[c] + t * dst[c];
}

// A fragment's premultiplied colour and opacity (double) "over" a float pixel, unless it adds
// nothing; true if composited.
inline bool over_fragment(float* dst, const glm::dvec3& rgb, double alpha) {
  if (adds_nothing(rgb, alpha)) return false;
  const float src[4] = {static_cast<float>(rgb.r), static_cast<float>(rgb.g), static_cast<float>(rgb.b),
                        static_cast<float>(alpha)};
  over(dst, src);
  return true;
}

// Front to back: src behind what dst holds.
inline void under(float* dst, const float src[4]) {
  const float t = 1.0f - dst[3];
  for (int c = 0; c < 4; ++c) dst[c] += t * src[c];
}

// Back-to-front "over" of fragments onto a premultiplied image.
inline void composite_over(Image& image, const Fragment* f, std::size_t n) {
  float* px = image.rgba.data();
  constexpr std::size_t kAhead = 16;  // the framebuffer is far larger than the caches: fetch ahead
  for (std::size_t k = 0; k < n; ++k) {
    if (k + kAhead < n) __builtin_prefetch(px + std::size_t(f[k + kAhead].pixel) * 4, 1);
    over(px + std::size_t(f[k].pixel) * 4, f[k].rgba);
  }
}

}  // namespace cellproj
