// The opacity a mesh gets unasked (--opacity auto): faint at the field's background value, and
// scaled so that the picture is neither an opaque slab nor an invisible haze.
#include <cmath>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "mesh/generate.hpp"
#include "optics/auto_opacity.hpp"
#include "render/renderer.hpp"
#include "scene/prepare.hpp"
#include "scene/quick_scene.hpp"
#include "scene/scene_file.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

double kappa_at(const std::vector<ExtinctionPoint>& shape, double s) {
  return TransferFunction({{0.0, {1, 1, 1}}}, shape).extinction(s);
}

// The share of the footprint (alpha > 0 under a faint flat extinction) whose alpha is in (0.05, 0.95).
double mid_alpha_share(const Image& picture, const Image& footprint) {
  int in = 0, all = 0;
  for (std::size_t i = 3; i < picture.rgba.size(); i += 4)
    if (footprint.rgba[i] > 0) {
      ++all;
      in += picture.rgba[i] > 0.05f && picture.rgba[i] < 0.95f;
    }
  return all ? double(in) / all : 0.0;
}

}  // namespace

TEST(AutoOpacity, TheBackgroundValueIsFaintAndAFeatureBelowItIsNot) {
  // A freestream of 1 filling most of the box, a region of low values (a vortex core) inside it.
  Mesh m = make_box(12, 12, 12, glm::dvec3(-1), glm::dvec3(1), true);
  set_field(m, "rho", [](const glm::dvec3& x) { return 1.0 - 0.8 * std::exp(-12.0 * glm::dot(x, x)); });
  const auto [lo, hi] = std::minmax_element(m.fields[0].values.begin(), m.fields[0].values.end());
  const AutoShape shape = auto_shape(m.view(), m.fields[0].values.data(), *lo, *hi);
  EXPECT_GT(shape.background_share, 0.35);
  EXPECT_LE(shape.background_lo, 1.0);
  EXPECT_GE(shape.background_hi, 1.0 - 1e-9);
  EXPECT_NEAR(kappa_at(shape.points, 1.0), 0.05, 1e-12);  // the freestream: faint
  EXPECT_EQ(kappa_at(shape.points, *lo), 1.0);            // the vortex's core: the most
  // A field with no dominant value gets a ramp over a faint floor.
  set_field(m, "x", [](const glm::dvec3& x) { return x.x; });
  const AutoShape ramp = auto_shape(m.view(), m.fields[1].values.data(), -1.0, 1.0);
  EXPECT_EQ(ramp.points.size(), 2u);
  EXPECT_EQ(kappa_at(ramp.points, -1.0), 0.05);
  EXPECT_EQ(kappa_at(ramp.points, 1.0), 1.0);
}

// A thin plate of constant extinction seen face-on: the optical depth integrated over its cells
// puts its alpha at the middle of (0.05, 0.95) in optical depth, 1 - exp(-sqrt(tau_0.05 tau_0.95)),
// where a fixed depth across the diagonal left a haze.
TEST(AutoOpacity, AThinPlateSeenFaceOnIsNeitherHazeNorSlab) {
  const Mesh m = make_box(16, 16, 2, glm::dvec3(-1, -1, -0.02), glm::dvec3(1, 1, 0.02), true);
  std::vector<double> field(static_cast<std::size_t>(m.n_points()), 1.0);
  const auto [lo, hi] = bounds(m);
  const double diagonal = glm::length(hi - lo);
  const Camera face_on = view_camera("+z", lo, hi, 1.0);
  const std::vector<ExtinctionPoint> flat = opacity_shape("flat", 1.0, 1.0);
  const FootprintScale s = footprint_scale(m.view(), field.data(), flat, {0, 0, -1}, {0, 1, 0});
  EXPECT_GT(s.share, 0.95);
  const double expected = 1.0 - std::exp(-std::sqrt(std::log(0.95) * std::log(0.05)));
  const Image img =
      make_renderer({})->render(Volume(m.view()), {field.data(), m.n_points(), "f"},
                                TransferFunction({{1.0, {1, 1, 1}}}, {{1.0, s.kappa}}), face_on, {64, 64});
  EXPECT_NEAR(img.rgba[(32 * 64 + 32) * 4 + 3], expected, 0.02);
  // Edge-on the plate is deep: the scale is smaller.
  const FootprintScale edge = footprint_scale(m.view(), field.data(), flat, {-1, 0, 0}, {0, 0, 1});
  EXPECT_LT(edge.kappa, 0.2 * s.kappa);
}

// The default picture of generated meshes, rendered: at least half its footprint in (0.05, 0.95).
TEST(AutoOpacity, DefaultPicturesOfGeneratedMeshesAreNeitherSlabNorHaze) {
  const test::TempDir dir;
  for (const char* kind : {"box-tets", "mixed", "swirl"}) {
    SCOPED_TRACE(kind);
    LoadedMesh loaded;
    loaded.mesh = generate(kind, 6);
    loaded.mesh.source = kind;
    QuickLook look;
    look.width = look.height = 96;
    const Scene scene = scene_from_json(quick_scene(loaded, dir.file("m.vtu"), {}, look), kind, dir.file(""));
    const PreparedScene p = prepare_scene(scene, loaded);
    const Volume volume(p.loaded.mesh.view());
    const Field f = field_of(p.loaded.mesh, p.field);
    const auto renderer = make_renderer({});
    const Image picture = renderer->render(volume, f, p.tf, p.camera, {96, 96});
    const Image footprint =
        renderer->render(volume, f, TransferFunction({{0.0, {1, 1, 1}}}, {{0.0, 1e-3}}), p.camera, {96, 96});
    EXPECT_GE(mid_alpha_share(picture, footprint), 0.5);
  }
}
