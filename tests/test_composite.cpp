// The compositing stage: over and under agree, and partial images composited in depth order give
// the picture of compositing their whole images in that order.
#include <gtest/gtest.h>

#include "composite/fragment.hpp"
#include "composite/partial_image.hpp"

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
