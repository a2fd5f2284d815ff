// The OpenGL back end (OSMesa): the same picture as the software back end on a float target; on
// an 8-bit target faint layers round away, and alpha dithering brings them back on average.
#include <cmath>

#include <gtest/gtest.h>

#include "base/error.hpp"
#include "frame/projection_renderer.hpp"
#include "render/names.hpp"
#include "render/renderer.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

Image render(const Mesh& m, const TransferFunction& tf, const Camera& c, int size, ProjectionMethod method,
             Backend backend) {
  ProjectionOptions o;
  o.method = method;
  o.backend = backend;
  o.whole_cells = WholeCells::polygons;  // the software back end draws whole cells as OpenGL does
  return test::project(m, "s", tf, c, size, o);
}

double mean_alpha(const Image& img) {
  double sum = 0;
  for (std::size_t k = 3; k < img.rgba.size(); k += 4) sum += img.rgba[k];
  return sum / (img.rgba.size() / 4);
}

}  // namespace

TEST(GLBackend, FloatTargetMatchesSoftware) {
  // Tetrahedra, and a twisted mixed mesh whose hexahedra, wedges and pyramids are projected whole
  // (the polygons of their image-plane subdivision).
  for (int kind = 0; kind < 2; ++kind) {
    Mesh m = kind == 0 ? make_box(6, 6, 6, glm::dvec3(-1), glm::dvec3(1), true) : generate("mixed", 4);
    set_field(m, "s", [](const glm::dvec3& x) { return std::sin(2 * x.x) * std::cos(1.5 * x.y) + 0.4 * x.z; });
    const TransferFunction tf({{-1, {0.1, 0.2, 0.9}}, {0.0, {0.9, 0.9, 0.2}}, {1, {1, 1, 1}}},
                              {{-1, 0.2}, {-0.3, 3.0}, {0.6, 6.0}, {1, 1.0}});
    Camera c;
    c.projection = Projection::Perspective;
    c.eye = {1.5, -3.5, 2.2};
    c.up = {0, 0, 1};
    c.fov_y = 40;
    for (ProjectionMethod method : {ProjectionMethod::pt_table, ProjectionMethod::pt_linear}) {
      const ImageDifference d =
          compare(render(m, tf, c, 96, method, Backend::opengl), render(m, tf, c, 96, method, Backend::software));
      // Mesa snaps vertices to 1/256 pixel and interpolates in float: edge pixels differ slightly.
      EXPECT_LT(d.max_abs, 5e-3) << name_of(method) << " mesh " << kind;
      EXPECT_LT(d.rmse, 1e-4) << name_of(method) << " mesh " << kind;
    }
  }
}

TEST(GLBackend, DitheringKeepsFaintLayers) {
  // 60 layers of cells seen straight down, each with opacity ~4e-4: below half an 8-bit step, so
  // undithered 8-bit blending rounds every layer away; dithered, the layers add up on average.
  Mesh m = make_box(4, 4, 60, glm::dvec3(-1), glm::dvec3(1), true);
  set_field(m, "s", [](const glm::dvec3&) { return 0.0; });
  const TransferFunction tf = test::constant_tf(0.025, {1, 1, 1});
  Camera c;
  c.eye = {0, 0, 5};
  c.height = 1.5;  // the slab fills the image
  const Image f = render(m, tf, c, 64, ProjectionMethod::pt_table, Backend::opengl);
  const Image plain = render(m, tf, c, 64, ProjectionMethod::pt_table, Backend::opengl_8bit);
  const Image dithered = render(m, tf, c, 64, ProjectionMethod::pt_table, Backend::opengl_8bit_dithered);
  const double want = -std::expm1(-0.025 * 2.0);
  EXPECT_NEAR(mean_alpha(f), want, 1e-4);
  EXPECT_LT(mean_alpha(plain), 0.25 * want);  // lost to rounding
  EXPECT_NEAR(mean_alpha(dithered), want, 0.1 * want);
}

namespace {

Image slices(const Mesh& m, const TransferFunction& tf, const Camera& c, int size, int n, Backend backend) {
  RenderSettings s;
  s.mode = RenderMode::slicing;
  s.slicing.slices = n, s.slicing.integral = SliceIntegral::sampled, s.slicing.backend = backend;
  return cellproj::render(Volume(m.view()), field_of(m, "s"), tf, s, c, {size, size});
}

}  // namespace

// Slicing through OpenGL: each polygon drawn with its corners' colour and the opacity of one
// spacing, C(s), 1 - exp(-kappa(s) l). Where that is every pixel's light (constant optics, an
// orthographic view along the planes of a box whose faces lie on them, so that no slab is cut by
// the boundary, which the software back end measures per pixel and OpenGL cannot) the float
// target is the software image.
TEST(GLBackend, SlicesOnTheFloatTargetMatchSoftware) {
  Mesh m = make_box(3, 3, 4, glm::dvec3(-1), glm::dvec3(1), true);
  set_field(m, "s", [](const glm::dvec3& x) { return x.x; });
  const Camera c = test::looking_down(2.5);
  const TransferFunction tf = test::constant_tf(1.3, {0.9, 0.6, 0.3});
  const Image gl = slices(m, tf, c, 96, 64, Backend::opengl), sw = slices(m, tf, c, 96, 64, Backend::software);
  const ImageDifference d = compare(gl, sw);
  EXPECT_LT(d.max_abs, 1e-5);
  EXPECT_GT(mean_alpha(sw), 0.3);
  RenderSettings pre;
  pre.mode = RenderMode::slicing, pre.slicing.backend = Backend::opengl;
  EXPECT_THROW(make_renderer(pre), InputError) << "preintegrated slabs are software only";
}

// 240 slices through a slab seen straight down, each of opacity ~2e-4 (below half an 8-bit step):
// plain 8-bit blending loses them, dithered they add up on average.
TEST(GLBackend, DitheringKeepsFaintSlices) {
  Mesh m = make_box(4, 4, 4, glm::dvec3(-1), glm::dvec3(1), true);
  set_field(m, "s", [](const glm::dvec3&) { return 0.0; });
  const TransferFunction tf = test::constant_tf(0.025, {1, 1, 1});
  Camera c;
  c.eye = {0, 0, 5};
  c.height = 1.5;
  const double want = -std::expm1(-0.025 * 2.0);
  EXPECT_NEAR(mean_alpha(slices(m, tf, c, 64, 240, Backend::opengl)), want, 1e-4);
  EXPECT_LT(mean_alpha(slices(m, tf, c, 64, 240, Backend::opengl_8bit)), 0.25 * want);
  EXPECT_NEAR(mean_alpha(slices(m, tf, c, 64, 240, Backend::opengl_8bit_dithered)), want, 0.1 * want);
}
