// Colour by one field, extinction by another: the segment integral against closed forms and
// against the one-field integral, and the renderers against the exact reference.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include "mesh/generate.hpp"
#include "optics/segment_integral.hpp"
#include "optics/two_fields.hpp"
#include "render/renderer.hpp"
#include "render/settings_table.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

// Colour and extinction with steps and ramps over [0, 1], their breakpoints at different values.
TransferFunction stepped() {
  return TransferFunction({{0.0, {0, 0, 0}}, {0.3, {1, 0, 0}}, {0.3, {0, 1, 0}}, {0.8, {0, 0, 1}}, {1.0, {1, 1, 1}}},
                          {{0.0, 0.5}, {0.45, 4.0}, {0.6, 0.0}, {0.6, 2.0}, {1.0, 1.0}});
}

void expect_near(const SegmentLight& a, const SegmentLight& b, double tol) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a.rgb[k], b.rgb[k], tol) << "channel " << k;
  EXPECT_NEAR(a.depth, b.depth, tol);
}

}  // namespace

// f(k, L, v) for 500 random segments of length up to `longest`, v four field values in [-0.2, 1.2]
// (stepped()'s range and beyond it).
template <class F>
void random_segments(unsigned seed, double longest, F&& f) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> s(-0.2, 1.2), length(0.01, longest);
  for (int k = 0; k < 500; ++k) {
    const double L = length(rng), v[4] = {s(rng), s(rng), s(rng), s(rng)};
    f(k, L, v);
  }
}

TEST(TwoFields, OneFieldTwiceIsTheOneFieldIntegral) {
  const TransferFunction tf = stepped();
  const TwoFieldTransfer two(tf);
  random_segments(7, 3.0, [&](int k, double L, const double* v) {
    const double a = v[0], b = k % 10 == 0 ? a : v[1];
    const SegmentLight one = integrate_segment_reference(tf, L, a, b);
    expect_near(integrate_two_fields_reference(two, L, a, b, a, b), one, 1e-13);
    expect_near(integrate_two_fields_closed_form(two, L, a, b, a, b), one, 1e-11);
  });
}

// Extinction constant through the opacity field while the colour field runs over the extinction's
// breakpoints: nothing may be cut there. kappa k, colour C(t) = t / L (grey): the light is
// int_0^L (t / L) k e^{-k t} dt = (1 - e^-d) / d - e^-d with d = k L.
TEST(TwoFields, ExtinctionFollowsItsOwnField) {
  const TransferFunction tf({{0.0, {0, 0, 0}}, {1.0, {1, 1, 1}}}, {{0.0, 0.0}, {0.5, 0.0}, {0.5, 3.0}, {1.0, 3.0}});
  const TwoFieldTransfer two(tf);
  for (double L : {1e-3, 0.2, 1.0, 7.0}) {
    const double d = 3.0 * L, grey = -std::expm1(-d) / d - std::exp(-d);
    for (const SegmentLight& light : {integrate_two_fields_reference(two, L, 0.0, 1.0, 0.75, 0.75),
                                      integrate_two_fields_closed_form(two, L, 0.0, 1.0, 0.75, 0.75)}) {
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(light.rgb[c], grey, 1e-12 * std::max(1.0, grey)) << "L " << L;
      EXPECT_NEAR(light.depth, d, 1e-12 * d);
    }
    // The opacity field below the step: no extinction, no light, whatever the colour field does.
    const SegmentLight none = integrate_two_fields_closed_form(two, L, 0.0, 1.0, 0.25, 0.4);
    EXPECT_EQ(none.depth, 0.0);
    EXPECT_EQ(none.rgb, glm::dvec3(0.0));
  }
}

// Colour constant through the colour field while the opacity field crosses the extinction's step:
// the light is C (1 - e^-D) with D the optical depth of the step's two sides.
TEST(TwoFields, ColourFollowsItsOwnField) {
  const TransferFunction tf({{0.0, {1, 0, 0}}, {0.5, {1, 0, 0}}, {0.5, {0, 0, 1}}, {1.0, {0, 0, 1}}},
                            {{0.0, 1.0}, {0.5, 1.0}, {0.5, 5.0}, {1.0, 5.0}});
  const TwoFieldTransfer two(tf);
  const double L = 0.4;  // s from 0.2 to 0.8: half at kappa 1, half at kappa 5
  const double D = 0.5 * L * 1.0 + 0.5 * L * 5.0;
  for (const SegmentLight& light : {integrate_two_fields_reference(two, L, 0.9, 0.7, 0.2, 0.8),
                                    integrate_two_fields_closed_form(two, L, 0.9, 0.7, 0.2, 0.8)}) {
    EXPECT_NEAR(light.depth, D, 1e-14);
    EXPECT_NEAR(light.rgb.b, -std::expm1(-D), 1e-13);
    EXPECT_EQ(light.rgb.r, 0.0);
  }
}

TEST(TwoFields, ClosedFormMatchesReference) {
  const TwoFieldTransfer two(stepped());
  random_segments(11, 5.0, [&](int, double L, const double* v) {
    expect_near(integrate_two_fields_closed_form(two, L, v[0], v[1], v[2], v[3]),
                integrate_two_fields_reference(two, L, v[0], v[1], v[2], v[3]), 1e-11);
  });
}

// A transfer function with hundreds of breakpoints, met by both fields along one segment.
TEST(TwoFields, ManyBreakpoints) {
  std::vector<ColorPoint> color;
  std::vector<ExtinctionPoint> extinction;
  for (int k = 0; k <= 200; ++k) {
    const double s = k / 200.0;
    color.push_back({s, glm::dvec3(k % 2, 0.5, 1 - k % 2)});
    extinction.push_back({s + 0.001, 1.0 + (k % 3)});
  }
  const TransferFunction tf(color, extinction);
  const TwoFieldTransfer two(tf);
  expect_near(integrate_two_fields_closed_form(two, 0.8, 0.0, 1.0, 0.0, 1.0),
              integrate_segment_reference(tf, 0.8, 0.0, 1.0), 1e-11);
}

namespace {

// A second field beside wavy_grid's "s" (or any mesh's), varying across it another way.
void add_opacity_field(Mesh& m) {
  set_field(m, "q", [](const glm::dvec3& x) { return 0.5 + 0.45 * std::cos(2.5 * x.y + x.z) * std::sin(1.7 * x.x); });
}

// Colour over "s" in [-1.4, 1.4], extinction over "q" in [0, 1], both with steps and ramps.
TransferFunction two_field_tf() {
  return TransferFunction(
      {{-1.4, {0.1, 0.2, 0.9}}, {-0.2, {0.2, 0.9, 0.3}}, {-0.2, {0.9, 0.9, 0.1}}, {1.4, {0.9, 0.1, 0.1}}},
      {{0.0, 0.0}, {0.3, 0.2}, {0.55, 3.0}, {0.55, 1.0}, {1.0, 2.5}});
}

Image render_with(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera,
                  const char* method, int size = 48) {
  RenderOptions o;
  set_option(o, "method", method);
  return render(volume, field, tf, settings_from(o), camera, {size, size});
}

Field two_fields(const Mesh& m) {
  Field f = field_of(m, "s", "q");
  EXPECT_EQ(f.opacity_name, "q");
  return f;
}

}  // namespace

// pt-breakpoints integrates each pixel's segments exactly with both fields' breakpoints: the exact
// renderer's picture to 1e-6, on tetrahedra and on hexahedra (both over the canonical tetrahedra),
// orthographic and perspective, and with the eye inside the mesh.
TEST(TwoFields, BreakpointsEqualExact) {
  const TransferFunction tf = two_field_tf();
  for (bool tets : {true, false}) {
    Mesh m = test::wavy_grid(5, tets);
    add_opacity_field(m);
    const Volume volume(m.view());
    const Field field = two_fields(m);
    std::vector<Camera> cameras = test::views_of_unit_mesh(3);
    cameras.push_back(test::inside_wavy_grid(Projection::Perspective));
    for (std::size_t k = 0; k < cameras.size(); ++k) {
      const Image ex = render_with(volume, field, tf, cameras[k], "exact");
      const ImageDifference d = compare(render_with(volume, field, tf, cameras[k], "pt-breakpoints"), ex);
      EXPECT_LT(d.max_abs, 1e-6) << (tets ? "tetrahedra" : "hexahedra") << ", view " << k;
      EXPECT_GT(*std::max_element(ex.rgba.begin(), ex.rgba.end()), 0.05f) << "an empty picture proves nothing";
      // pt-analytic takes each segment whole: exact where no breakpoint lies inside the ranges.
      const TransferFunction linear({{-1.4, {0.1, 0.2, 0.9}}, {1.4, {0.9, 0.1, 0.1}}}, {{0.0, 0.5}, {1.0, 2.5}});
      EXPECT_LT(compare(render_with(volume, field, linear, cameras[k], "pt-analytic"),
                        render_with(volume, field, linear, cameras[k], "exact"))
                    .max_abs,
                1e-6)
          << "view " << k;
    }
  }
}

// The same field as colour and as extinction is the one-field picture over the canonical
// tetrahedra (drawn another way: each cell ray cast over its tetrahedra instead of projected).
TEST(TwoFields, OneFieldTwiceIsTheOneFieldPicture) {
  Mesh m = test::twisted_mixed(3);
  set_field(m, "s", [](const glm::dvec3& x) { return std::sin(2 * x.x) + x.y * x.z; });
  const Volume volume(m.view());
  Field once = field_of(m, "s"), twice = once;
  twice.opacity = twice.values, twice.opacity_name = twice.name;
  const auto [lo, hi] = std::minmax_element(once.values, once.values + once.size);
  const TransferFunction tf({{*lo, {0, 0, 1}}, {*hi, {1, 0.5, 0}}}, {{*lo, 0.2}, {0.5 * (*lo + *hi), 3.0}, {*hi, 0.5}});
  for (const Camera& c : test::views_of_unit_mesh(2))
    for (const char* method : {"exact", "pt-breakpoints"}) {
      RenderOptions o;
      set_option(o, "method", method);
      set_option(o, "interpolation", "canonical-tets");
      set_option(o, "tetrahedralize", "all");
      const RenderSettings s = settings_from(o);
      const Image a = render(volume, once, tf, s, c, {40, 40}), b = render(volume, twice, tf, s, c, {40, 40});
      EXPECT_LT(compare(a, b).max_abs, std::string(method) == "exact" ? 1e-9 : 1e-6) << method;
    }
}

// Colour constant through its field, extinction varying through the other: every pixel's colour is
// that colour times its opacity (premultiplied), which fails if either field stood in for the other.
TEST(TwoFields, ConstantColourFieldColoursEveryPixelAlike) {
  Mesh m = test::wavy_grid(4, true);
  add_opacity_field(m);
  set_field(m, "s", [](const glm::dvec3&) { return 0.25; });
  const Volume volume(m.view());
  const TransferFunction tf({{0.0, {0, 0, 0}}, {0.5, {1.0, 0.5, 0.0}}}, {{0.0, 0.0}, {1.0, 6.0}});
  const glm::dvec3 rgb = tf.color(0.25);
  for (const char* method : {"exact", "pt-breakpoints", "pt-analytic"}) {
    const Image img = render_with(volume, two_fields(m), tf, test::views_of_unit_mesh(1)[0], method);
    double largest = 0;
    for (std::size_t p = 0; p < img.rgba.size(); p += 4) {
      const double a = img.rgba[p + 3];
      largest = std::max(largest, a);
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(img.rgba[p + c], rgb[c] * a, 1e-6) << method << " pixel " << p / 4;
    }
    EXPECT_GT(largest, 0.2) << method;
  }
}

// The same bits from one thread and from four.
TEST(TwoFields, SameImageFromOneAndFourThreads) {
  Mesh m = test::wavy_grid(5, false);
  add_opacity_field(m);
  const Volume volume(m.view());
  const Camera c = test::views_of_unit_mesh(1)[0];
  for (const char* method : {"exact", "pt-breakpoints"}) {
    const auto frame = [&](int threads) {
      return tbb::task_arena(threads).execute(
          [&] { return render_with(volume, two_fields(m), two_field_tf(), c, method, 64); });
    };
    EXPECT_EQ(frame(1).rgba, frame(4).rgba) << method;
  }
}

// What cannot draw two fields says so, naming the setting; a missing or short field is refused.
TEST(TwoFields, RefusedWhereNotDrawn) {
  Mesh m = test::wavy_grid(3, true);
  add_opacity_field(m);
  const Volume volume(m.view());
  const Camera c = test::views_of_unit_mesh(1)[0];
  for (const char* method : {"pt-linear", "pt-table", "slicing", "mip", "average"}) {
    const std::string e = test::input_error([&] { render_with(volume, two_fields(m), two_field_tf(), c, method); });
    EXPECT_NE(e.find("setting 'opacity-field'"), std::string::npos) << method << ": " << e;
  }
  RenderOptions o;
  set_option(o, "small-cells", "splat");
  EXPECT_NE(test::input_error([&] {
              render(volume, two_fields(m), two_field_tf(), settings_from(o), c, {32, 32});
            }).find("splats"),
            std::string::npos);
  EXPECT_NE(test::input_error([&] { field_of(m, "s", "nope"); }).find("nope"), std::string::npos);
  Field bad = two_fields(m);
  std::vector<double> nan(static_cast<std::size_t>(bad.size), 0.5);
  nan[7] = std::nan("");
  bad.opacity = nan.data(), bad.opacity_name = "q";
  EXPECT_NE(test::input_error([&] {
              render_with(volume, bad, two_field_tf(), c, "exact");
            }).find("field 'q' is not finite at point 7"),
            std::string::npos);
}
