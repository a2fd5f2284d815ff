// The closed-form segment integral (pt-analytic) against the reference quadrature and analytic
// limits, from optical depth 1e-8 to 1e4.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "optics/linear_segment.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

double rel(double got, double want) { return std::abs(got - want) / std::max(std::abs(want), 1e-300); }

}  // namespace

TEST(SpecialFunctions, ErfcxAndDawsonAgreeAcrossTheirBranches) {
  // Each function is computed by different series on either side of a switch point; both sides
  // must meet. Known values: erfcx(0) = 1, dawson's maximum 0.5410442246 at 0.9241388730.
  EXPECT_DOUBLE_EQ(erfcx(0.0), 1.0);
  EXPECT_NEAR(dawson(0.9241388730), 0.5410442246, 1e-10);
  EXPECT_NEAR(dawson(2.0), 0.3013403889237920, 1e-15);
  EXPECT_NEAR(erfcx(1.0), 0.4275835761558070, 1e-15);
  EXPECT_NEAR(dawson(0.5), 0.4244363835020223, 1e-15);
  EXPECT_NEAR(dawson(5.0), 0.1021340744242768, 1e-15);
  for (double x : {0.2, 10.0}) EXPECT_LT(rel(dawson(x * (1 - 1e-15)), dawson(x * (1 + 1e-15))), 1e-13) << x;
  EXPECT_LT(rel(erfcx(25.0 * (1 - 1e-15)), erfcx(25.0)), 1e-13);
  // Large x: both ~ 1/(2x) and 1/(x sqrt(pi)) with the first correction.
  EXPECT_LT(rel(dawson(1e4), (1 + 0.5e-8) / 2e4), 1e-14);
  EXPECT_LT(rel(erfcx(1e4), (1 - 0.5e-8) / (1e4 * std::sqrt(M_PI))), 1e-14);
}

TEST(LinearSegment, ClosedFormMatchesReferenceQuadrature) {
  const glm::dvec3 c0{0.9, 0.2, 0.1}, c1{0.1, 0.5, 1.0};
  int cases = 0;
  for (double depth : {1e-8, 1e-5, 1e-3, 0.02, 0.3, 1.0, 3.0, 10.0, 40.0})
    for (double ratio : {0.0, 1e-3, 0.2, 0.9, 1.0, 1.0 + 1e-12, 1.04, 1.5, 5.0, 1e3, -1.0}) {
      // kappa at the back = ratio * kappa at the front; ratio -1 means kappa = 0 at the front.
      const double L = 0.7;
      double k0 = ratio < 0 ? 0.0 : 2 * depth / (L * (1 + ratio));
      double k1 = ratio < 0 ? 2 * depth / L : ratio * k0;
      const SegmentLight ref = integrate_linear_reference(L, k0, k1, c0, c1);
      const SegmentLight got = integrate_linear_closed_form(L, k0, k1, c0, c1);
      ASSERT_LT(rel(got.depth, ref.depth), 1e-14);
      for (int k = 0; k < 3; ++k)
        ASSERT_LT(rel(got.rgb[k], ref.rgb[k]), 2e-11) << "depth " << depth << " ratio " << ratio << " channel " << k;
      // Swapping the ends is a different segment; it must match too.
      const SegmentLight ref2 = integrate_linear_reference(L, k1, k0, c0, c1);
      const SegmentLight got2 = integrate_linear_closed_form(L, k1, k0, c0, c1);
      for (int k = 0; k < 3; ++k) ASSERT_LT(rel(got2.rgb[k], ref2.rgb[k]), 2e-11) << depth << " " << ratio;
      ++cases;
    }
  EXPECT_EQ(cases, 99);
}

TEST(LinearSegment, TheSeriesInTheSlopeMatchesTheReferenceWhereItIsUsed) {
  // kappa nearly constant along the segment (|b| <= 0.03 (1 + a), tau = a u + b u^2): the series of
  // moments M_2n(a), whose downward recursion starts from the top moment's own series.
  const glm::dvec3 c0{0.9, 0.2, 0.1}, c1{0.1, 0.5, 1.0};
  for (int i = 0; i <= 40; ++i) {
    const double a = 1e-3 * std::pow(8e3, i / 40.0);  // 1e-3 .. 8
    for (double share : {-0.029, -0.01, -1e-4, 0.0, 1e-6, 1e-3, 0.01, 0.029}) {
      const double b = share * (1 + a), L = 0.5;
      const double k0 = a / L, k1 = (a + 2 * b) / L;  // tau = k0 L u + (k1 - k0) L u^2 / 2
      if (k1 < 0) continue;
      const SegmentLight ref = integrate_linear_reference(L, k0, k1, c0, c1);
      const SegmentLight got = integrate_linear_closed_form(L, k0, k1, c0, c1);
      for (int k = 0; k < 3; ++k) ASSERT_LT(rel(got.rgb[k], ref.rgb[k]), 2e-11) << "a " << a << " b " << b;
    }
  }
}

TEST(LinearSegment, TheSmallCellSeriesMeetsTheMomentSeriesAtItsBounds) {
  // Small cells (tau = a u + b u^2 with a <= 0.5, |b| <= 0.01) take a Taylor series in (a, b) with
  // no exp; just beyond its bounds the moments' series takes over. Both are accurate to ~1e-15, so
  // at the bounds they meet to 1e-14 (4e-15 measured): three terms fewer or a wrong coefficient fails.
  // Each pair is a few ulps of k0 or k1 apart, on either side of a bound (b = (k1 - k0) / 2 over L = 1).
  const auto meet = [](double k0, double k1, double k0_out, double k1_out) {
    const EndWeights in = linear_segment_weights(1.0, k0, k1), out = linear_segment_weights(1.0, k0_out, k1_out);
    EXPECT_LT(rel(in.front, out.front), 1e-14) << "k0 " << k0 << " k1 " << k1;
    EXPECT_LT(rel(in.back, out.back), 1e-14) << "k0 " << k0 << " k1 " << k1;
  };
  for (double b : {-0.01, -0.003, -1e-6, 0.0, 1e-6, 0.004, 0.01}) {
    const double a = std::nextafter(0.5, 0.0);  // a + 2b rounds so that |b| stays within 0.01
    meet(a, a + 2 * b, 0.5 + 1e-15, 0.5 + 1e-15 + 2 * b);
  }
  for (double k0 : {0.03, 0.1, 0.3, 0.5})
    for (double sign : {-1.0, 1.0}) {
      double k1 = k0 + sign * 0.02;  // b = +-0.01, up to rounding: step k1 to the last value inside
      while (std::abs(0.5 * (k1 - k0)) > 0.01) k1 = std::nextafter(k1, k0);
      meet(k0, k1, k0, std::nextafter(k1, sign * 1e9));
    }
  // And inside, against the reference quadrature (1e-12) and the limits of tiny depth.
  const glm::dvec3 c0{0.9, 0.2, 0.1}, c1{0.1, 0.5, 1.0};
  for (double a : {0.0, 1e-9, 1e-4, 0.03, 0.2, 0.49})
    for (double b : {-0.0099, -1e-5, 0.0, 1e-7, 0.002, 0.0099}) {
      if (a + 2 * b < 0 || a + b <= 0) continue;
      const SegmentLight ref = integrate_linear_reference(1.0, a, a + 2 * b, c0, c1);
      const SegmentLight got = integrate_linear_closed_form(1.0, a, a + 2 * b, c0, c1);
      for (int k = 0; k < 3; ++k) EXPECT_LT(rel(got.rgb[k], ref.rgb[k]), 2e-12) << "a " << a << " b " << b;
    }
}

TEST(LinearSegment, ASmallCellsOpacityComesWithItsWeightsToFullPrecision) {
  // A small cell's series gives 1 - e^-D with its weights; the segment passes it on instead of
  // computing expm1 again. It must equal expm1's to a few ulps, down to tiny depths, and a
  // segment outside the series' bounds must still get expm1's value.
  for (double a : {1e-300, 1e-12, 1e-5, 0.01, 0.2, 0.49})
    for (double b : {-0.0099, -1e-7, 0.0, 3e-4, 0.0099}) {
      if (a + 2 * b < 0 || a + b <= 0) continue;
      const SegmentLight got = integrate_linear_closed_form(1.0, a, a + 2 * b, glm::dvec3(1.0), glm::dvec3(0.5));
      ASSERT_GE(got.known_opacity, 0.0) << "a " << a << " b " << b;
      EXPECT_LT(rel(got.opacity(), -std::expm1(-(a + b))), 1e-15) << "a " << a << " b " << b;
      EXPECT_LE(got.opacity(), 1.0);
    }
  const SegmentLight thick = integrate_linear_closed_form(1.0, 3.0, 5.0, glm::dvec3(1.0), glm::dvec3(0.5));
  EXPECT_LT(thick.known_opacity, 0.0);
  EXPECT_EQ(thick.opacity(), -std::expm1(-4.0));
}

TEST(LinearSegment, TinyDepthKeepsRelativeAccuracy) {
  // Opacity kappa L for kappa L = 1e-8 (constant kappa), relative 1e-6 as issue 6 asks; colour C A.
  for (double d : {1e-8, 1e-12, 1e-300}) {
    const SegmentLight s = integrate_linear_closed_form(1.0, d, d, glm::dvec3(0.5), glm::dvec3(0.5));
    EXPECT_LT(rel(s.opacity(), -std::expm1(-d)), 1e-12) << d;
    EXPECT_LT(rel(s.rgb.r, 0.5 * -std::expm1(-d)), 1e-12) << d;
  }
}

TEST(LinearSegment, HugeDepthIsOpaqueWithoutNaN) {
  // Optical depth 1e4: opacity exactly 1; light is the front colour (the front layer emits it all).
  for (double ratio : {0.0, 0.5, 1.0, 2.0, 1e6}) {
    const double k0 = 1e4, k1 = ratio * 1e4;
    const SegmentLight s = integrate_linear_closed_form(1.0, k0, k1, {1, 0, 0}, {0, 0, 1});
    EXPECT_EQ(s.opacity(), 1.0);
    EXPECT_TRUE(std::isfinite(s.rgb.r) && std::isfinite(s.rgb.b));
    EXPECT_NEAR(s.rgb.r, 1.0, 2e-4) << ratio;  // the front colour, to within the layer's thickness
    EXPECT_NEAR(s.rgb.b, 0.0, 2e-4) << ratio;
  }
  // kappa = k t from 0 at the front (k = 1e5): tau = k t^2 / 2, the light comes from a layer at
  // mean depth sqrt(pi / 2k), where C(t) = (1 - t, 0, t).
  const SegmentLight s = integrate_linear_closed_form(1.0, 0.0, 1e5, {1, 0, 0}, {0, 0, 1});
  EXPECT_EQ(s.opacity(), 1.0);
  EXPECT_LT(rel(s.rgb.b, std::sqrt(M_PI / 2e5)), 1e-12);
  EXPECT_LT(rel(s.rgb.r, 1.0 - std::sqrt(M_PI / 2e5)), 1e-12);
}

TEST(LinearSegment, BreakpointsCutExactly) {
  // A transfer function with a step and a kink: the closed form cut at breakpoints matches the
  // reference to 1e-11 whichever way the scalar runs.
  const TransferFunction tf({{0, {1, 0, 0}}, {0.4, {0, 1, 0}}, {0.4, {0, 0, 1}}, {1, {1, 1, 1}}},
                            {{0, 0.1}, {0.3, 5.0}, {0.6, 0.5}, {1, 2.0}});
  for (auto [s0, s1] : std::vector<std::pair<double, double>>{{0, 1}, {1, 0}, {0.35, 0.45}, {0.4, 0.4}, {0.9, 0.1}}) {
    const SegmentLight ref = integrate_segment_reference(tf, 1.3, s0, s1);
    const SegmentLight got = integrate_segment_closed_form(tf, 1.3, s0, s1);
    EXPECT_LT(rel(got.depth, ref.depth), 1e-13);
    for (int k = 0; k < 3; ++k) EXPECT_LT(std::abs(got.rgb[k] - ref.rgb[k]), 1e-11) << s0 << " " << s1;
  }
}

TEST(LinearSegment, ManySegmentsAtOnceGiveEachSegmentsBits) {
  // The batch evaluates small cells four at a time in SIMD lanes and the rest one by one; every
  // segment must get exactly linear_segment_weights' values, whatever its neighbours in the batch
  // (small, thick, empty, zero length), and whatever the batch's length (a tail of 1 to 3).
  std::vector<double> L, k0, k1;
  const double lengths[] = {0.0, 1e-9, 0.01, 0.3, 1.0, 7.0};
  const double kappas[] = {0.0, 1e-300, 1e-6, 0.05, 0.4, 0.45, 2.0, 50.0};
  for (double l : lengths)
    for (double a : kappas)
      for (double b : kappas) L.push_back(l), k0.push_back(a), k1.push_back(b);
  // The padded form reads and writes up to n rounded up to 4: the tail goes in lanes too, whatever
  // the padding holds (here the next segments' values, or a NaN).
  L.resize(L.size() + 3, std::nan("")), k0.resize(L.size(), 1.0), k1.resize(L.size(), 1.0);
  const std::size_t all = L.size() - 3;
  using Batch = void (*)(std::size_t, const double*, const double*, const double*, EndWeights*);
  for (const Batch batch : {Batch(linear_segment_weights), Batch(linear_segment_weights_padded)})
    for (std::size_t n : {all, all - 1, all - 2, all - 3, std::size_t(3), std::size_t(1), std::size_t(0)}) {
      std::vector<EndWeights> w((n + 3) / 4 * 4);
      batch(n, L.data(), k0.data(), k1.data(), w.data());
      int small = 0;
      for (std::size_t k = 0; k < n; ++k) {
        const EndWeights one = linear_segment_weights(L[k], k0[k], k1[k]);
        small += one.opacity >= 0.0;
        EXPECT_EQ(w[k].front, one.front) << k;
        EXPECT_EQ(w[k].back, one.back) << k;
        EXPECT_EQ(w[k].depth, one.depth) << k;
        EXPECT_EQ(w[k].opacity, one.opacity) << k;
      }
      if (n > 100) EXPECT_GT(small, 50);  // the vector path ran
    }
}
