// The exact rungs' batch (projection/segment_batch): the light of many segments at once must be
// each segment's own closed form to the bit, across breakpoints too.
#include <cmath>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "composite/fragment.hpp"
#include "optics/linear_segment.hpp"
#include "projection/segment_batch.hpp"

namespace cellproj {
namespace {

// A batch of n segments with the given lengths and end scalars (segment_ends' output).
SegmentBatch batch_of(const std::vector<double>& length, const std::vector<double>& s0, const std::vector<double>& s1) {
  SegmentBatch b;
  for (std::size_t k = 0; k < length.size(); ++k) b.push(0, 0, 0.0, 0.0, 0.0, 0.0);
  for (std::size_t k = 0; k < length.size(); ++k) b.length[k] = length[k], b.sf[k] = s0[k], b.sb[k] = s1[k];
  return b;
}

TEST(SegmentBatch, AcrossBreakpointsEachSegmentGetsItsClosedFormsBits) {
  // Breakpoints at 0.3 (kink in extinction), 0.5 (colour), 0.8: segments crossing none, one or
  // several, either way along the ray, tiny to thick, and empty ones.
  const TransferFunction tf({{0.0, {0.2, 0.4, 1}}, {0.5, {1, 1, 0}}, {1.0, {1, 0, 0}}},
                            {{0.0, 0.1}, {0.3, 4.0}, {0.8, 0.5}, {1.0, 9.0}});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> s(0.0, 1.0), loglen(-9.0, 1.0);
  std::vector<double> length, s0, s1;
  for (int k = 0; k < 997; ++k) {
    length.push_back(k % 50 == 0 ? 0.0 : std::pow(10.0, loglen(rng)));
    s0.push_back(s(rng)), s1.push_back(k % 7 == 0 ? s0.back() : s(rng));
  }
  for (const bool cut : {true, false}) {
    SegmentBatch b = batch_of(length, s0, s1);
    segment_light_across(b, tf, cut);
    int several = 0;
    for (std::size_t k = 0; k < length.size(); ++k) {
      const double l = length[k], a = s0[k], z = s1[k];
      const SegmentLight one =
          cut ? integrate_segment_closed_form(tf, l, a, z)
              : integrate_linear_closed_form(l, tf.extinction(a), tf.extinction(z), tf.color(a), tf.color(z));
      EXPECT_EQ(b.red[k], one.rgb.r) << k;
      EXPECT_EQ(b.green[k], one.rgb.g) << k;
      EXPECT_EQ(b.blue[k], one.rgb.b) << k;
      EXPECT_EQ(b.opacity[k], one.opacity()) << k;
      several += cut && b.pieces.end[k] - (k ? b.pieces.end[k - 1] : 0) > 1;
    }
    if (cut) EXPECT_GT(several, 300);  // most segments were cut
  }
}

TEST(SegmentBatch, CompositedFourAtATimeAsOneAtATime) {
  // Fragments on a 5x3 image, pixels repeated (each must see what the one before wrote), some
  // adding nothing (+-0: skipped, not counted), NaN, an opacity still to compute from the depth,
  // and a count that is no multiple of 4: the lanes give the bits of CompositeFragments' loop.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> px(0, 14);
  for (const std::size_t n : {1u, 3u, 4u, 7u, 64u, 203u}) {
    SegmentBatch b;
    for (std::size_t k = 0; k < n; ++k) {
      const int p = px(rng);
      b.push(p % 5, p / 5, 0.0, 0.0, 0.0, 0.0);
      const double a = u(rng);
      b.red[k] = a * u(rng), b.green[k] = a * u(rng), b.blue[k] = a * u(rng), b.opacity[k] = a;
      b.weights[k].depth = 3.0 * u(rng);
      if (k % 5 == 1) b.red[k] = b.green[k] = b.blue[k] = b.opacity[k] = k % 2 ? 0.0 : -0.0;
      if (k % 9 == 2) b.opacity[k] = -1.0;  // 1 - e^-depth still to compute
      if (k == 6) b.green[k] = std::nan("");
    }
    Image expected(5, 3), image(5, 3);
    std::int64_t added = 0;
    for (std::size_t k = 0; k < n; ++k) {  // CompositeFragments, fragment by fragment
      const SegmentLight light{{b.red[k], b.green[k], b.blue[k]}, b.weights[k].depth, b.opacity[k]};
      const double alpha = light.opacity();
      if (adds_nothing(light.rgb, alpha)) continue;
      const float src[4] = {float(light.rgb.r), float(light.rgb.g), float(light.rgb.b), float(alpha)};
      over(expected.pixel(b.i[k], b.j[k]), src), ++added;
    }
    SegmentBatch one = b;
    Image by_one(5, 3);
    EXPECT_EQ(composite_over(b, image), added) << n;
    EXPECT_EQ(composite_over(one, by_one, /*lanes=*/false), added) << n;
    if (n > 1) EXPECT_LT(added, static_cast<std::int64_t>(n)) << n;  // fragment 1 adds nothing
    for (std::size_t c = 0; c < image.rgba.size(); ++c) {
      const float e = expected.rgba[c];
      if (std::isnan(e)) {
        EXPECT_TRUE(std::isnan(image.rgba[c]) && std::isnan(by_one.rgba[c])) << n << " " << c;
        continue;
      }
      EXPECT_EQ(std::memcmp(&image.rgba[c], &e, sizeof e), 0) << n << " " << c << ": " << image.rgba[c] << " " << e;
      EXPECT_EQ(std::memcmp(&by_one.rgba[c], &e, sizeof e), 0) << n << " " << c;
    }
  }
}

}  // namespace
}  // namespace cellproj
