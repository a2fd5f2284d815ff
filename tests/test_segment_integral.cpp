// The segment integral against closed forms (Max 1995, Williams and Max 1992).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "optics/polynomial_segment.hpp"
#include "optics/segment_integral.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

// Independent closed form for kappa and C linear over [0, L]: integrating C kappa e^{-tau} by
// parts gives c0 - c1 T + (c1 - c0)/L * I, with I = int_0^L e^{-tau(t)} dt a Gaussian integral
// (erf when kappa grows along the segment).
glm::dvec3 closed_form_rgb(double L, double k0, double k1, glm::dvec3 c0, glm::dvec3 c1) {
  const double b = (k1 - k0) / L, T = std::exp(-0.5 * (k0 + k1) * L);
  double I;
  if (b > 0) {
    const double r = std::sqrt(2 * b), x0 = k0 / r, x1 = (k0 + b * L) / r;
    I = std::sqrt(M_PI / (2 * b)) * std::exp(x0 * x0) * (std::erf(x1) - std::erf(x0));
  } else {  // b < 0 needs erfi: composite Simpson with 2e5 intervals instead (error ~1e-20)
    const int n = 200000;
    const double h = L / n;
    auto f = [&](double t) { return std::exp(-(k0 * t + 0.5 * b * t * t)); };
    I = f(0) + f(L);
    for (int i = 1; i < n; ++i) I += (i % 2 ? 4 : 2) * f(i * h);
    I *= h / 3;
  }
  return c0 - c1 * T + (c1 - c0) / L * I;
}

}  // namespace

TEST(SegmentIntegral, ConstantKappaConstantColour) {
  for (double depth : {1e-8, 1e-3, 0.5, 3.0, 40.0}) {
    const double L = 2.0, k = depth / L;
    const auto s = integrate_linear_reference(L, k, k, {0.2, 0.5, 0.9}, {0.2, 0.5, 0.9});
    const double a = -std::expm1(-depth);
    EXPECT_NEAR(s.opacity(), a, 1e-15 + 1e-12 * a) << depth;
    EXPECT_NEAR(s.rgb.g, 0.5 * a, 1e-15 + 1e-12 * a) << depth;
  }
}

TEST(SegmentIntegral, LinearKappaConstantColour) {
  // depth = L (k0 + k1) / 2 whatever the slope; light = C (1 - T).
  for (auto [k0, k1] : {std::pair{0.0, 4.0}, {4.0, 0.0}, {1.0, 1.0 + 1e-12}, {0.3, 2.7}, {100.0, 0.0}}) {
    const double L = 0.7, T = std::exp(-0.5 * (k0 + k1) * L);
    const auto s = integrate_linear_reference(L, k0, k1, {1, 1, 1}, {1, 1, 1});
    EXPECT_NEAR(s.transmittance(), T, 1e-14);
    EXPECT_NEAR(s.rgb.r, 1 - T, 1e-12);
  }
}

TEST(SegmentIntegral, LinearKappaLinearColourMatchesGaussianClosedForm) {
  const glm::dvec3 c0{1.0, 0.2, 0.0}, c1{0.0, 0.6, 1.0};
  for (auto [L, k0, k1] :
       {std::tuple{1.0, 0.5, 3.0}, {1.0, 3.0, 0.5}, {0.1, 0.0, 50.0}, {2.0, 5.0, 0.1}, {1e-3, 2.0, 7.0}}) {
    const auto s = integrate_linear_reference(L, k0, k1, c0, c1);
    const auto ref = closed_form_rgb(L, k0, k1, c0, c1);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(s.rgb[i], ref[i], 1e-11) << L << " " << k0 << " " << k1;
  }
}

TEST(SegmentIntegral, HugeDepthIsOpaqueWithoutNaN) {
  const auto s = integrate_linear_reference(1.0, 1e4, 1e4, {0.3, 0.3, 0.3}, {0.9, 0.9, 0.9});
  EXPECT_EQ(s.opacity(), 1.0);
  EXPECT_NEAR(s.rgb.r, 0.3, 1e-4);  // only the front end shows
  const auto g = integrate_linear_reference(1.0, 0.0, 2e4, {0.3, 0.3, 0.3}, {0.9, 0.9, 0.9});
  EXPECT_FALSE(std::isnan(g.rgb.r));
  EXPECT_EQ(g.opacity(), 1.0);
}

TEST(SegmentIntegral, BreakpointsSplitTheSegment) {
  // kappa(s) = 0 below s = 0.5 and 2 above (a step); s runs 0 -> 1 over L = 1: depth = 2 * 0.5.
  const TransferFunction tf({{0.0, {1, 1, 1}}}, {{0.5, 0.0}, {0.5, 2.0}});
  const auto s = integrate_segment_reference(tf, 1.0, 0.0, 1.0);
  EXPECT_NEAR(s.depth, 1.0, 1e-14);
  const auto back = integrate_segment_reference(tf, 1.0, 1.0, 0.0);  // the same segment seen from behind
  EXPECT_NEAR(back.depth, 1.0, 1e-14);
  EXPECT_NEAR(back.rgb.r, 1 - std::exp(-1.0), 1e-12);
  // A tent kappa(s) = 4 min(s, 1 - s): depth = its area, 1, over s in [0, 1].
  const TransferFunction tent({{0.0, {1, 1, 1}}}, {{0.0, 0.0}, {0.5, 2.0}, {1.0, 0.0}});
  EXPECT_NEAR(integrate_segment_reference(tent, 1.0, 0.0, 1.0).depth, 1.0, 1e-14);
}

// --- scalar polynomial along the segment (isoparametric cells) ---

TEST(PolynomialSegment, ChebyshevInterpolantReproducesPolynomialsOfDegreeSeven) {
  auto f = [](double x) { return 0.3 - 1.2 * x + 0.5 * x * x * x - 0.25 * std::pow(x, 7); };
  const ScalarPolynomial p = chebyshev_interpolant(f);
  for (double x = -1.0; x <= 1.0; x += 0.125) EXPECT_NEAR(p(x), f(x), 1e-13) << x;
}

TEST(PolynomialSegment, LinearScalarAgreesWithTheLinearReference) {
  const TransferFunction tf({{0.0, {1, 0, 0}}, {0.4, {0, 1, 0}}, {1.0, {0, 0, 1}}},
                            {{0.0, 0.5}, {0.3, 4.0}, {0.3, 1.0}, {1.0, 2.5}});  // a step at 0.3
  ScalarPolynomial s;
  s.c[0] = 0.5, s.c[1] = 0.45;  // from 0.05 at the front to 0.95 at the back
  const SegmentLight a = integrate_polynomial_reference(tf, 1.7, s);
  const SegmentLight b = integrate_segment_reference(tf, 1.7, 0.05, 0.95);
  EXPECT_NEAR(a.depth, b.depth, 1e-12);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a.rgb[k], b.rgb[k], 1e-12);
}

// s(x) = 0.9 - 0.8 x^2 rises through the breakpoint at 0.5 and falls back through it: both
// crossings must be found. Checked against Simpson on the composed integrand.
TEST(PolynomialSegment, QuadraticScalarCrossingABreakpointTwice) {
  const TransferFunction tf({{0.0, {0.2, 0.4, 1}}, {0.5, {1, 1, 0}}, {1.0, {1, 0, 0}}},
                            {{0.0, 0.0}, {0.5, 3.0}, {1.0, 0.5}});
  ScalarPolynomial s;
  s.c[0] = 0.9, s.c[2] = -0.8;
  const double L = 2.0;
  auto s_at = [&](double t) { return s(t - 1.0); };  // x = t - 1 for L = 2
  const SegmentLight got = integrate_polynomial_reference(tf, L, s);
  const glm::dvec3 want = test::simpson_light(
      L, [&](double t) { return tf.extinction(s_at(t)); }, [&](double t) { return tf.color(s_at(t)); });
  double depth = 0.0;  // Simpson on kappa
  const int n = 200000;
  for (int i = 0; i <= n; ++i) depth += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * tf.extinction(s_at(L * i / n));
  depth *= L / n / 3;
  EXPECT_NEAR(got.depth, depth, 1e-8);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got.rgb[k], want[k], 1e-7);
}

namespace {

// Overlapping media integrated by brute force: composite Simpson on the ray, the optical depth by
// the trapezoid rule on the same fine grid (independent of the Gauss-Legendre pieces).
SegmentLight brute_force_overlap(double L, const std::vector<MediumSegment>& media, int n = 400000) {
  const double h = L / n;
  auto kappa_and_emission = [&](double t, glm::dvec3& e) {
    double k = 0.0;
    e = glm::dvec3(0.0);
    for (const MediumSegment& m : media) {
      const double s = m.s0 + t / L * (m.s1 - m.s0);
      k += m.tf->extinction(s);
      e += m.tf->extinction(s) * m.tf->color(s);
    }
    return k;
  };
  SegmentLight out;
  glm::dvec3 e_prev;
  double k_prev = kappa_and_emission(0.0, e_prev), tau = 0.0;
  glm::dvec3 sum = e_prev * (h / 3);
  for (int i = 1; i <= n; ++i) {
    glm::dvec3 e;
    const double k = kappa_and_emission(i * h, e);
    tau += 0.5 * h * (k + k_prev);
    k_prev = k;
    sum += (i == n ? 1.0 : i % 2 ? 4.0 : 2.0) * (h / 3) * e * std::exp(-tau);
  }
  out.rgb = sum;
  out.depth = tau;
  return out;
}

}  // namespace

TEST(MediaIntegral, OneMediumIsTheLinearReference) {
  const LinearMedium m{0.3, 2.5, {0.1, 0.6, 0.9}, {0.8, 0.2, 0.4}};
  const SegmentLight a = integrate_media_reference(1.7, &m, 1);
  const SegmentLight b = integrate_linear_reference(1.7, m.k0, m.k1, m.c0, m.c1);
  EXPECT_NEAR(a.depth, b.depth, 1e-15);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(a.rgb[c], b.rgb[c], 1e-14);
}

TEST(MediaIntegral, ConstantMediaMatchTheClosedForm) {
  // Two constant media: depth (ka + kb) L, light (ka ca + kb cb) / (ka + kb) (1 - e^-depth).
  for (double L : {1e-6, 0.3, 2.0, 30.0}) {
    const LinearMedium m[2] = {{0.7, 0.7, {1, 0, 0}, {1, 0, 0}}, {2.1, 2.1, {0, 0.5, 1}, {0, 0.5, 1}}};
    const SegmentLight s = integrate_media_reference(L, m, 2);
    const double depth = 2.8 * L, a = -std::expm1(-depth);
    const glm::dvec3 want = (0.7 * glm::dvec3(1, 0, 0) + 2.1 * glm::dvec3(0, 0.5, 1)) / 2.8 * a;
    EXPECT_NEAR(s.depth, depth, 1e-14 * depth);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.rgb[c], want[c], 1e-12 * std::max(a, 1e-300)) << L;
  }
}

TEST(MediaIntegral, OverlapWithBreakpointsMatchesBruteForce) {
  // Two transfer functions with breakpoints at different scalars, the scalars running opposite ways.
  const TransferFunction a({{0, {1, 0, 0}}, {0.4, {1, 1, 0}}, {1, {0, 1, 0}}}, {{0, 0.0}, {0.5, 3.0}, {1, 0.5}});
  const TransferFunction b({{0, {0, 0, 1}}, {1, {1, 1, 1}}}, {{0, 1.0}, {0.25, 0.0}, {0.7, 2.0}, {1, 2.0}});
  const std::vector<MediumSegment> media = {{&a, 0.05, 0.95}, {&b, 0.9, 0.1}};
  for (double L : {0.2, 1.5, 6.0}) {
    const SegmentLight s = integrate_overlap_reference(L, media.data(), media.size());
    const SegmentLight r = brute_force_overlap(L, media);
    EXPECT_NEAR(s.depth, r.depth, 1e-9) << L;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.rgb[c], r.rgb[c], 1e-9) << L;
  }
  // Overlap with one medium is that medium's segment integral.
  const SegmentLight one = integrate_overlap_reference(1.5, media.data(), 1);
  const SegmentLight ref = integrate_segment_reference(a, 1.5, 0.05, 0.95);
  EXPECT_NEAR(one.depth, ref.depth, 1e-13);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(one.rgb[c], ref.rgb[c], 1e-13);
}
