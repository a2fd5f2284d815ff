#pragma once
// Fragments and the compositing operators (MWSC section 7; Porter and Duff): premultiplied RGBA,
// "over" for back-to-front order and "under" for front-to-back.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "view/image.hpp"

namespace cellproj {

// A pixel's premultiplied light and opacity from one cell (or one slice polygon, one splat).
struct Fragment {
  std::uint32_t pixel;  // j * width + i
  float rgba[4];
};

// Appends pixel (i, j)'s fragment of a `width`-wide image. Written field by field into the vector:
// a fragment built on the stack and copied whole showed in perf as a store-forwarding stall.
inline void append_fragment(std::vector<Fragment>& out, int width, int i, int j, double r, double g, double b,
                            double alpha) {
  Fragment& f = out.emplace_back();
  f.pixel = static_cast<std::uint32_t>(j) * static_cast<std::uint32_t>(width) + static_cast<std::uint32_t>(i);
  f.rgba[0] = static_cast<float>(r), f.rgba[1] = static_cast<float>(g), f.rgba[2] = static_cast<float>(b);
  f.rgba[3] = static_cast<float>(alpha);
}

// Back to front: src in front of what dst holds.
inline void over(float* dst, const float src[4]) {
  const float t = 1.0f - src[3];
  for (int c = 0; c < 4; ++c) dst[c] = src[c] + t * dst[c];
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
