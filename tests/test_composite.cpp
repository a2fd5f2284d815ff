// The compositing stage: over and under agree, and partial images composited in depth order give
// the picture of compositing their whole images in that order.
#include <gtest/gtest.h>

#include "composite/fragment.hpp"
#include "composite/ordered_pipeline.hpp"
#include "composite/partial_image.hpp"

#include <algorithm>
#include <cstdint>
#include <random>

#include <tbb/task_arena.h>

using namespace cellproj;

namespace {

// A layer covering the pixels of `box` with a premultiplied colour of opacity a.
Image layer(int w, int h, const ScreenBox& box, float r, float a) {
  Image img(w, h);
  for (int j = box.y0; j < box.y1; ++j)
    for (int i = box.x0; i < box.x1; ++i) {
      float* p = img.pixel(i, j);
      p[0] = r * a, p[1] = 0.5f * a, p[2] = (1 - r) * a, p[3] = a;
    }
  return img;
}

}  // namespace

TEST(Composite, UnderFrontToBackEqualsOverBackToFront) {
  const float back[4] = {0.1f, 0.2f, 0.3f, 0.5f}, mid[4] = {0.2f, 0.0f, 0.1f, 0.4f},
              front[4] = {0.05f, 0.3f, 0.0f, 0.6f};
  float o[4] = {0, 0, 0, 0}, u[4] = {0, 0, 0, 0};
  for (const float* f : {back, mid, front}) over(o, f);
  for (const float* f : {front, mid, back}) under(u, f);
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(o[c], u[c], 1e-7);
}

TEST(Composite, PartialImagesInDepthOrderGiveTheWholePicture) {
  const int w = 40, h = 30;
  const ScreenBox near_box{5, 4, 25, 20}, far_box{15, 10, 38, 28};
  const Image near_img = layer(w, h, near_box, 0.9f, 0.6f), far_img = layer(w, h, far_box, 0.2f, 0.7f);
  Image whole(w, h);
  for (const Image* img : {&far_img, &near_img})
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) over(whole.pixel(i, j), img->pixel(i, j));
  EXPECT_EQ(covered_box(near_img).x0, near_box.x0);
  EXPECT_EQ(covered_box(far_img).y1, far_box.y1);
  const PartialImage near_piece = crop(near_img, covered_box(near_img), 1.0);
  const PartialImage far_piece = crop(far_img, covered_box(far_img), 2.0);
  Image pieces(w, h);
  composite_partials(pieces, {&near_piece, &far_piece});  // given nearest first: sorted by depth
  EXPECT_EQ(pieces.rgba, whole.rgba);
  Image wrong(w, h);
  const PartialImage near_as_far = crop(near_img, near_box, 3.0);
  composite_partials(wrong, {&near_as_far, &far_piece});
  EXPECT_NE(wrong.rgba, whole.rgba);  // the depth key decides the order
}

namespace cellproj {
namespace {

// Items that are rectangles of one translucent colour: a source for the ordered pipeline.
struct Rectangles {
  struct Item {
    int x0, y0, x1, y1;
    float rgba[4];
  };
  struct Scratch {};
  struct Counters {
    void add(const Counters&) {}
  };
  const std::vector<Item>& items;
  void fragments(std::size_t k, FragmentBands& out, Scratch&, Counters&) const {
    const Item& r = items[k];
    for (int j = r.y0; j < r.y1; ++j)
      for (int i = r.x0; i < r.x1; ++i) out.append(i, j, r.rgba[0], r.rgba[1], r.rgba[2], r.rgba[3]);
  }
  void composite(std::size_t k, Image& image, Scratch&, Counters&) const {
    const Item& r = items[k];
    for (int j = r.y0; j < r.y1; ++j)
      for (int i = r.x0; i < r.x1; ++i) over(image.pixel(i, j), r.rgba);
  }
};

TEST(OrderedPipeline, BandsAndDirectItemsBlendInOrderForAnyThreadCount) {
  // Rectangles of random size and colour, some large enough to be drawn directly by the
  // compositor in between the buffered ones: the picture must be the serial "over" of all of them,
  // bit for bit, on 1, 2, 4 and 8 threads (4 and more blend bands of rows in parallel).
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> pos(0, 90), size(1, 40);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<Rectangles::Item> items;
  for (int k = 0; k < 3000; ++k) {
    const int x = pos(rng), y = pos(rng);
    const float a = 0.3f * u(rng);
    items.push_back(
        {x, y, std::min(120, x + size(rng)), std::min(100, y + size(rng)), {a * u(rng), a * u(rng), a * u(rng), a}});
  }
  Image serial(120, 100);
  for (const auto& r : items)
    for (int j = r.y0; j < r.y1; ++j)
      for (int i = r.x0; i < r.x1; ++i) over(serial.pixel(i, j), r.rgba);
  const auto area = [&](std::size_t k) { return double(items[k].x1 - items[k].x0) * (items[k].y1 - items[k].y0); };
  PipelineLimits limits;
  limits.batch_items = 50;
  limits.direct_pixels = 900;  // the rectangles above 30 x 30 are drawn directly
  int direct = 0;
  for (std::size_t k = 0; k < items.size(); ++k) direct += area(k) > limits.direct_pixels;
  ASSERT_GT(direct, 50);
  for (int threads : {1, 2, 4, 8}) {
    Image image(120, 100);
    tbb::task_arena(threads).execute([&] { composite_in_order(image, items.size(), area, limits, Rectangles{items}); });
    EXPECT_EQ(image.rgba, serial.rgba) << threads << " threads";
  }
}

TEST(HugePageAllocator, LargeBlocksSitOnHugePageBoundariesAndKeepTheirValuesAsTheyGrow) {
  Fragments f;
  for (std::uint32_t k = 0; k < 300000; ++k) f.push_back({k, {float(k), 0.0f, 0.0f, 1.0f}});  // 6 MB
  ASSERT_GE(f.capacity() * sizeof(Fragment), kHugePage);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(f.data()) % kHugePage, 0u);
  for (std::uint32_t k = 0; k < 300000; k += 997) ASSERT_EQ(f[k].pixel, k);
  Fragments small(10);  // below 2 MB: the plain allocator
  EXPECT_EQ(small.size(), 10u);
  const Image image(1024, 1024);  // 16 MB, zeroed
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(image.rgba.data()) % kHugePage, 0u);
  EXPECT_EQ(*std::max_element(image.rgba.begin(), image.rgba.end()), 0.0f);
}

}  // namespace
}  // namespace cellproj
