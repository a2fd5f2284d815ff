// The exact rungs' batch (projection/segment_batch): the light of many segments at once must be
// each segment's own closed form to the bit, across breakpoints too.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace cellproj
