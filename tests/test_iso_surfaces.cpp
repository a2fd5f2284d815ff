// Iso-surfaces with the volume (issue 19, first part): the modes against their closed forms on
// two nested spheres, the volume unchanged by a clear surface, the iso-spectrum opacity and its
// fit, the same bits from 1 and 2 threads, and the options.
#include <gtest/gtest.h>

#include <cmath>

#include <tbb/task_arena.h>

#include "base/error.hpp"
#include "mesh/generate.hpp"
#include "raycast/iso_layers.hpp"
#include "raycast/iso_surfaces.hpp"
#include "raycast/reference_renderer.hpp"
#include "render/settings_table.hpp"
#include "tests/test_util.hpp"

namespace cellproj {
namespace {

// generate box-tets: 1 - |x|^2 / 3, whose iso-values 0.7 and 0.9 are the spheres r = 0.949 and 0.548.
const glm::dvec3 kRed(1.0, 0.2, 0.1), kBlue(0.2, 0.4, 1.0);

IsoOptions two_spheres(IsoMode mode, bool volume, double a_red = 0.4, double a_blue = 0.3) {
  IsoOptions o;
  o.surfaces = {{0.7, kRed, a_red, true}, {0.9, kBlue, a_blue, true}};
  o.mode = mode;
  o.volume = volume;
  return o;
}

Image surfaces(const Mesh& m, const TransferFunction& tf, const Camera& c, int n, const IsoOptions& o) {
  const CellRayTracer tracer(m.view());
  return render_iso_surfaces(tracer, test::field_values(m), m.n_points(), tf, c, n, n, o);
}

TEST(IsoSurfaces, EachModeComposesTheCentreRaysFourCrossingsAsItsFormulaSays) {
  // Down the z axis the ray enters red, enters blue, leaves blue, leaves red, each seen head-on:
  // shade s = base (0.2 + 0.7) + 0.3. ordered is exact front-to-back order; blend2 the submission
  // order (here the same colours, so ordered's value); oit3 sums every emission; oit4 stops the
  // emissions at blue's back face, the front-most back face. The opacity is the same in every mode.
  const Mesh m = generate("box-tets", 32);
  const int n = 21, centre = 10;  // an odd size: the middle pixel's ray is the z axis
  const TransferFunction tf = test::constant_tf(0.0, {0, 0, 0});
  const double ar = 0.4, ab = 0.3;
  const glm::dvec3 r = glm::min(kRed * 0.9 + 0.3, 1.0), b = glm::min(kBlue * 0.9 + 0.3, 1.0);
  const glm::dvec3 ordered = ar * r + (1 - ar) * (ab * b + (1 - ab) * (ab * b + (1 - ab) * ar * r));
  const glm::dvec3 expect[] = {ordered, ordered, 2 * ar * r + 2 * ab * b, ar * r + 2 * ab * b};
  const double opacity = 1 - (1 - ar) * (1 - ar) * (1 - ab) * (1 - ab);
  int k = 0;
  for (IsoMode mode : {IsoMode::ordered, IsoMode::blend2, IsoMode::oit3, IsoMode::oit4}) {
    const Image img = surfaces(m, tf, test::looking_down(2.2), n, two_spheres(mode, false));
    const float* px = img.pixel(centre, centre);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(px[c], expect[k][c], 0.02) << "mode " << k << " channel " << c;
    EXPECT_NEAR(px[3], opacity, 1e-6) << "mode " << k;
    const float* corner = img.pixel(0, 0);  // outside both spheres: nothing
    EXPECT_EQ(corner[3], 0.0f);
    ++k;
  }
}

TEST(IsoSurfaces, AnOpaqueSurfaceHidesWhatIsBehindItInEveryMode) {
  const Mesh m = generate("box-tets", 16);
  const TransferFunction tf = test::constant_tf(0.0, {0, 0, 0});
  for (IsoMode mode : {IsoMode::ordered, IsoMode::blend2, IsoMode::oit3, IsoMode::oit4}) {
    const Image img = surfaces(m, tf, test::looking_down(2.2), 21, two_spheres(mode, false, 1.0, 0.5));
    const float* px = img.pixel(10, 10);
    EXPECT_EQ(px[3], 1.0f);
    EXPECT_GT(px[0], 0.9f) << "red, and no blue from behind it";
    EXPECT_LT(px[2], 0.45f);
  }
}

TEST(IsoSurfaces, AClearSurfaceLeavesTheVolumeAsTheExactRendererDrawsIt) {
  // With the volume on, an opacity-0 surface only splits segments where it crosses them: the
  // picture is the exact renderer's (canonical tetrahedra) to rounding.
  const Mesh m = generate("mixed", 6);
  const TransferFunction tf({{0.0, {0.2, 0.4, 1.0}}, {1.0, {1.0, 0.6, 0.2}}}, {{0.0, 0.5}, {1.0, 6.0}});
  const Camera camera = test::view_from({2.0, -3.0, 2.5}, Projection::Perspective);
  IsoOptions o = two_spheres(IsoMode::ordered, true, 0.0, 0.0);
  const Image with = surfaces(m, tf, camera, 48, o);
  const ExactRenderer exact(m.view());
  const Image reference = exact.render(test::field_values(m), tf, camera, 48, 48, CellInterpolation::canonical_tets);
  const ImageDifference d = compare(with, reference);
  EXPECT_LT(d.max_abs, 1e-6);
  EXPECT_GT(*std::max_element(reference.rgba.begin(), reference.rgba.end()), 0.1f);
}

TEST(IsoSurfaces, TheIsoSpectrumsOpacityAndItsCosinePowerFit) {
  // Roettger section 4: a layer of head-on opacity a seen at |cos t| = c has 1 - (1 - a)^(1/c).
  EXPECT_DOUBLE_EQ(iso_opacity(IsoOpacity::spectrum, 0.4, 1.0), 0.4);
  EXPECT_NEAR(iso_opacity(IsoOpacity::spectrum, 0.5, 0.5), 0.75, 1e-15);
  EXPECT_NEAR(iso_opacity(IsoOpacity::spectrum, 0.5, 1e-9), 1.0, 1e-12);
  EXPECT_EQ(iso_opacity(IsoOpacity::constant, 0.4, 0.1), 0.4);
  // The fit 1 - (1 - a) c^p equals a head-on; its largest error (at grazing views) shrinks as a grows.
  double previous = 1.0;
  for (double a : {0.1, 0.3, 0.5, 0.8, 0.95}) {
    double err = 0.0;
    const double p = spectrum_fit_exponent(a, &err);
    EXPECT_NEAR(iso_opacity(IsoOpacity::spectrum_fit, a, 1.0, p), a, 1e-12);
    EXPECT_GT(p, 0.0);
    EXPECT_LT(err, previous) << "a = " << a;
    previous = err;
    for (double c : {0.2, 0.5, 0.9})
      EXPECT_LE(std::abs(iso_opacity(IsoOpacity::spectrum_fit, a, c, p) - iso_opacity(IsoOpacity::spectrum, a, c)),
                err + 1e-12);
  }
  EXPECT_LT(previous, 0.002) << "a = 0.95 fits to 0.2%";
}

TEST(IsoSurfaces, TheSameBitsFromOneAndTwoThreadsInEveryMode) {
  const Mesh m = generate("swirl-tets", 5);
  const TransferFunction tf({{0.0, {0.2, 0.4, 1.0}}, {1.0, {1.0, 0.6, 0.2}}}, {{0.0, 0.5}, {1.0, 6.0}});
  for (IsoMode mode : {IsoMode::ordered, IsoMode::blend2, IsoMode::oit3, IsoMode::oit4}) {
    IsoOptions o;
    o.surfaces = {{0.3, kRed, 0.5, true}, {0.6, kBlue, 0.5, true}};
    o.mode = mode;
    o.opacity = IsoOpacity::spectrum;
    Image a, b;
    const Camera c = test::view_from({1.6, -2.6, 2.2}, Projection::Perspective);
    tbb::task_arena(1).execute([&] { a = surfaces(m, tf, c, 40, o); });
    tbb::task_arena(2).execute([&] { b = surfaces(m, tf, c, 40, o); });
    EXPECT_EQ(a.rgba, b.rgba);
  }
}

TEST(IsoSurfaces, OptionsAreParsedAndBadOnesRefusedNamingTheOption) {
  RenderOptions o;
  set_option(o, "method", "exact");
  set_option(o, "iso", "0.5:1,0,0,0.25");
  set_option(o, "iso", "0.8");
  set_option(o, "iso-mode", "oit4");
  set_option(o, "volume", "off");
  const RenderSettings s = settings_from(o);
  ASSERT_EQ(s.iso.surfaces.size(), 2u);
  EXPECT_EQ(s.iso.surfaces[0].opacity, 0.25);
  EXPECT_FALSE(s.iso.surfaces[1].color_given);
  EXPECT_EQ(s.iso.mode, IsoMode::oit4);
  EXPECT_FALSE(s.iso.volume);
  const auto refused = [](const std::string& name, const std::string& value, const std::string& says) {
    try {
      RenderOptions bad;
      set_option(bad, "method", "exact");
      set_option(bad, name, value);
      settings_from(bad);
      ADD_FAILURE() << name << " " << value << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  };
  refused("iso", "0.5:1,0,0,1.5", "opacity must be in [0, 1]");
  refused("iso", "0.5:1,0", "give V, V:R,G,B or V:R,G,B,A");
  refused("iso-mode", "oit5", "setting 'iso-mode'");
  refused("iso-opacity", "thick", "setting 'iso-opacity'");
  refused("volume", "maybe", "setting 'volume': expected on or off");
}

}  // namespace
}  // namespace cellproj
