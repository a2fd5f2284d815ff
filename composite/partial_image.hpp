#pragma once
// A partial image: what one piece of the volume (an MPI rank's brick, a tile of cells) contributes
// over the box of the screen it covers, with a depth key that orders it among the other pieces.
// Pieces whose boxes overlap are composited in depth order (MWSC section 7: "over" is associative,
// so pieces rendered apart and blended in visibility order give the whole image).
#include <cstdint>
#include <vector>

#include "view/image.hpp"

namespace cellproj {

// The pixels [x0, x1) x [y0, y1).
struct ScreenBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
};

struct PartialImage {
  ScreenBox box;
  double depth = 0.0;       // the piece's distance from the eye: larger is farther (composited first)
  std::vector<float> rgba;  // premultiplied, box.width() x box.height(), row-major from the top

  PartialImage() = default;
  PartialImage(const ScreenBox& b, double d)
      : box(b), depth(d), rgba(b.empty() ? 0 : static_cast<std::size_t>(b.width()) * b.height() * 4, 0.0f) {}
  // Pixel (i, j) of the whole image, which must lie in the box.
  float* pixel(int i, int j) {
    return rgba.data() + (static_cast<std::size_t>(j - box.y0) * box.width() + (i - box.x0)) * 4;
  }
  const float* pixel(int i, int j) const {
    return rgba.data() + (static_cast<std::size_t>(j - box.y0) * box.width() + (i - box.x0)) * 4;
  }
};

// The smallest box holding every pixel of `image` with a non-zero channel (empty for an empty image).
ScreenBox covered_box(const Image& image);

// `image` cut to `box` (clamped to the image), keyed by `depth`.
PartialImage crop(const Image& image, const ScreenBox& box, double depth);

// The pieces "over" each other onto `image`, farthest first (ties: in the order given). Pieces
// reaching outside the image are clipped to it.
void composite_partials(Image& image, std::vector<const PartialImage*> pieces);

}  // namespace cellproj
