// The OpenGL back end (OSMesa): the same picture as the software back end on a float target; on
// an 8-bit target faint layers round away, and alpha dithering brings them back on average.
#include <cmath>

#include <gtest/gtest.h>

#include "parallel/projection_renderer.hpp"
#include "scene/names.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

Image render(const Mesh& m, const TransferFunction& tf, const Camera& c, int size, ProjectionMethod method,
             Backend backend) {
  ProjectionOptions o;
  o.method = method;
  o.backend = backend;
  return test::project(m, "s", tf, c, size, o);
}

double mean_alpha(const Image& img) {
  double sum = 0;
  for (std::size_t k = 3; k < img.rgba.size(); k += 4) sum += img.rgba[k];
  return sum / (img.rgba.size() / 4);
}

}  // namespace

TEST(GLBackend, FloatTargetMatchesSoftware) {
  // Tetrahedra, and a twisted mixed mesh whose hexahedra, wedges and pyramids are projected whole.
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
      const ImageDifference d = compare(render(m, tf, c, 96, method, Backend::opengl),
                                        render(m, tf, c, 96, method, Backend::software));
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
