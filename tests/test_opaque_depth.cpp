// Drawing among opaque geometry (view/opaque_depth.hpp): a depth buffer cuts each pixel's ray where
// its surface lies. A plane facing the eye at view depth d is the same cut as the clipping plane
// there (mesh/clip.hpp, exact for the field linear in each tetrahedron), so the two pictures agree.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "base/error.hpp"
#include "mesh/clip.hpp"
#include "mesh/generate.hpp"
#include "render/renderer.hpp"
#include "render/settings_table.hpp"
#include "tests/test_util.hpp"

namespace cellproj {
namespace {

constexpr int kSize = 48;
const TransferFunction kTf({{0.0, {0.2, 0.4, 1.0}}, {0.5, {0.9, 0.9, 0.3}}, {1.0, {1.0, 0.3, 0.1}}},
                           {{0.0, 0.5}, {0.6, 6.0}, {1.0, 2.0}});

// A surface facing the eye at view depth z over the whole image, or over its left half only.
OpaqueDepth plane_at(double z, bool left_half = false) {
  OpaqueDepth d{kSize, kSize, std::vector<float>(kSize * kSize, std::numeric_limits<float>::infinity())};
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < (left_half ? kSize / 2 : kSize); ++i) d.z[j * kSize + i] = static_cast<float>(z);
  return d;
}

Image draw(const Mesh& mesh, const RenderSettings& settings, const Camera& camera, const OpaqueDepth* opaque) {
  const Volume volume(mesh.view());
  const Field field{test::field_values(mesh), mesh.n_points(), "s"};
  const auto renderer = make_renderer(settings);
  return opaque ? renderer->render(volume, field, kTf, camera, {kSize, kSize}, *opaque)
                : renderer->render(volume, field, kTf, camera, {kSize, kSize});
}

// The settings of these words (name, text)..., as a front end gives them.
RenderSettings settings(std::initializer_list<std::pair<const char*, const char*>> words) {
  RenderOptions o;
  for (const auto& [name, text] : words) set_option(o, name, text);
  return settings_from(o);
}
RenderSettings method(const std::string& name) { return settings({{"method", name.c_str()}}); }

// The camera looks along -view from eye; the plane at view depth z is the clip plane through
// eye - z view with normal -view (keeping the eye's side).
struct Cut {
  Camera camera;
  double z;
  ClipPlane plane() const {
    const glm::dvec3 f = glm::normalize(camera.target - camera.eye);
    return {camera.eye + z * f, f};
  }
};

class AmongOpaque : public ::testing::TestWithParam<std::string> {};

// The methods that integrate each pixel's segment exactly draw the cut exactly; the Gouraud ones
// (pt-linear, pt-table) ray cast the cells the surface cuts, exactly, and project the others with
// their own error.
bool integrates_exactly(const std::string& m) { return m != "pt-linear" && m != "pt-table"; }

TEST_P(AmongOpaque, APlaneFacingTheEyeCutsAsTheClippingPlaneThere) {
  const Mesh mesh = generate("swirl-tets", 5);
  const bool exactly = integrates_exactly(GetParam());
  for (const Projection projection : {Projection::Orthographic, Projection::Perspective}) {
    const Camera camera = test::view_from({1.6, -2.6, 2.2}, projection);
    const double centre = glm::length(camera.eye - camera.target);
    for (const double z : {centre - 0.3, centre, centre + 0.4}) {
      const Cut cut{camera, z};
      const OpaqueDepth depth = plane_at(z);
      const Image among = draw(mesh, method(GetParam()), camera, &depth);
      const Mesh kept = clip_mesh(mesh, {cut.plane()});
      const Image clipped = draw(kept, method(GetParam()), camera, nullptr);
      // The Gouraud methods: within their own error on the clipped mesh (against exact).
      const double tolerance =
          exactly ? 2e-5 : 1.2 * compare(clipped, draw(kept, method("exact"), camera, nullptr)).max_abs;
      EXPECT_LT(compare(among, clipped).max_abs, tolerance) << GetParam() << " z " << z;
      EXPECT_GT(compare(among, draw(mesh, method(GetParam()), camera, nullptr)).max_abs, 0.05)
          << "the cut changes the picture";
    }
  }
}

TEST_P(AmongOpaque, NoSurfaceLeavesThePictureAsItWasAndOneInFrontHidesItAll) {
  const Mesh mesh = generate("swirl-tets", 5);
  const Camera camera = test::view_from({1.6, -2.6, 2.2}, Projection::Perspective);
  const Image plain = draw(mesh, method(GetParam()), camera, nullptr);
  const OpaqueDepth none = plane_at(std::numeric_limits<double>::infinity());
  EXPECT_EQ(compare(draw(mesh, method(GetParam()), camera, &none), plain).max_abs, 0.0);
  const OpaqueDepth front = plane_at(0.5);  // the mesh lies from about 2 on
  const Image hidden = draw(mesh, method(GetParam()), camera, &front);
  EXPECT_EQ(compare(hidden, Image(kSize, kSize)).max_abs, 0.0);
  // Over the left half only: the right half is the plain picture's, bit for bit.
  const OpaqueDepth half = plane_at(0.5, true);
  const Image left = draw(mesh, method(GetParam()), camera, &half);
  double right_diff = 0.0, left_alpha = 0.0;
  for (int j = 0; j < kSize; ++j)
    for (int i = 0; i < kSize; ++i) {
      if (i < kSize / 2)
        left_alpha = std::max(left_alpha, double(left.pixel(i, j)[3]));
      else
        right_diff = std::max(right_diff, std::abs(double(left.pixel(i, j)[3] - plain.pixel(i, j)[3])));
    }
  EXPECT_EQ(left_alpha, 0.0);
  if (integrates_exactly(GetParam())) EXPECT_LT(right_diff, 1e-6);  // (Gouraud: the cut cells are integrated exactly)
}

INSTANTIATE_TEST_SUITE_P(Methods, AmongOpaque, ::testing::Values("pt-breakpoints", "pt-linear", "exact"));

TEST(OpaqueDepth, HexahedraAreCutAsTheirClippedTetrahedra) {
  const Mesh mesh = test::wavy_grid(4, false);
  const Camera camera = test::views_of_unit_mesh(3)[1];
  const double z = glm::length(camera.eye - camera.target);
  const OpaqueDepth depth = plane_at(z);
  // Clipping makes the cut cells' canonical tetrahedra: the exact renderer compared with its field
  // linear over them too (its default, isoparametric, cuts the trilinear field instead).
  const Mesh clipped = clip_mesh(mesh, {Cut{camera, z}.plane()});
  for (const RenderSettings& s :
       {method("pt-breakpoints"), settings({{"method", "exact"}, {"interpolation", "canonical-tets"}})})
    EXPECT_LT(compare(draw(mesh, s, camera, &depth), draw(clipped, s, camera, nullptr)).max_abs, 2e-5);
}

TEST(OpaqueDepth, BadDepthsAndRenderersThatCannotCutAreRefused) {
  const Mesh mesh = generate("swirl-tets", 3);
  const Camera camera = test::view_from({1.6, -2.6, 2.2}, Projection::Orthographic);
  OpaqueDepth small = plane_at(3.0);
  small.width = kSize - 1;
  EXPECT_NE(test::input_error([&] { draw(mesh, method("pt-breakpoints"), camera, &small); }).find("opaque depth"),
            std::string::npos);
  OpaqueDepth nan = plane_at(3.0);
  nan.z[kSize * 3 + 5] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(test::input_error([&] { draw(mesh, method("exact"), camera, &nan); }).find("pixel (5, 3)"),
            std::string::npos);
  const OpaqueDepth depth = plane_at(3.0);
  EXPECT_THROW(draw(mesh, method("slicing"), camera, &depth), UnsupportedError);
  EXPECT_THROW(draw(mesh, method("mip"), camera, &depth), UnsupportedError);
  EXPECT_THROW(draw(mesh, settings({{"small-cells", "splat"}}), camera, &depth), UnsupportedError);
  EXPECT_THROW(draw(mesh, settings({{"ssaa", "2"}}), camera, &depth), UnsupportedError);
}

}  // namespace
}  // namespace cellproj
