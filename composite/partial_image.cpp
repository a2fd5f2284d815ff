#include "composite/partial_image.hpp"

#include <algorithm>

#include "composite/fragment.hpp"

namespace cellproj {

ScreenBox covered_box(const Image& image) {
  ScreenBox b{image.width, image.height, 0, 0};
  for (int j = 0; j < image.height; ++j)
    for (int i = 0; i < image.width; ++i) {
      const float* p = image.pixel(i, j);
      if (p[0] == 0 && p[1] == 0 && p[2] == 0 && p[3] == 0) continue;
      b.x0 = std::min(b.x0, i), b.x1 = std::max(b.x1, i + 1), b.y0 = std::min(b.y0, j), b.y1 = std::max(b.y1, j + 1);
    }
  return b.empty() ? ScreenBox{} : b;
}

namespace {
ScreenBox clip(const ScreenBox& b, int width, int height) {
  return {std::clamp(b.x0, 0, width), std::clamp(b.y0, 0, height), std::clamp(b.x1, 0, width),
          std::clamp(b.y1, 0, height)};
}
}  // namespace

PartialImage crop(const Image& image, const ScreenBox& box, double depth) {
  PartialImage p(clip(box, image.width, image.height), depth);
  for (int j = p.box.y0; j < p.box.y1; ++j)
    std::copy(image.pixel(p.box.x0, j), image.pixel(p.box.x0, j) + 4 * p.box.width(), p.pixel(p.box.x0, j));
  return p;
}

void composite_partials(Image& image, std::vector<const PartialImage*> pieces) {
  std::stable_sort(pieces.begin(), pieces.end(),
                   [](const PartialImage* a, const PartialImage* b) { return a->depth > b->depth; });
  for (const PartialImage* p : pieces) {
    const ScreenBox b = clip(p->box, image.width, image.height);
    for (int j = b.y0; j < b.y1; ++j)
      for (int i = b.x0; i < b.x1; ++i) over(image.pixel(i, j), p->pixel(i, j));
  }
}

}  // namespace cellproj
