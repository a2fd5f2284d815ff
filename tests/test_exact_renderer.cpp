// The exact reference renderer against analytic answers.
#include <cmath>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "raycast/reference_renderer.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

using test::looking_down;

Image render(const Mesh& m, const TransferFunction& tf, const Camera& c, int w, int h) {
  return test::exact(m, "", tf, c, w, h);
}

}  // namespace

TEST(ExactRenderer, ConstantCube) {
  Mesh m = make_box(2, 2, 2, glm::dvec3(-1), glm::dvec3(1), false);  // hexahedra
  set_field(m, "s", [](const glm::dvec3&) { return 0.0; });
  const glm::dvec3 C{0.2, 0.6, 0.9};
  const Image img = render(m, test::constant_tf(0.7, C), looking_down(4.0), 16, 16);
  const double A = 1 - std::exp(-0.7 * 2.0);
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) {
      const bool inside = i >= 4 && i < 12 && j >= 4 && j < 12;  // centres at +-0.125 ... +-0.875
      const float* p = img.pixel(i, j);
      ASSERT_NEAR(p[3], inside ? A : 0.0, 1e-6) << i << "," << j;
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(p[k], inside ? C[k] * A : 0.0, 1e-6);
    }
}

TEST(ExactRenderer, LinearKappaAndColourAlongTheRay) {
  Mesh m = make_box(3, 3, 5, glm::dvec3(-1), glm::dvec3(1), true);
  set_field(m, "s", [](const glm::dvec3& x) { return x.z; });  // linear: exact in every tetrahedron
  const TransferFunction tf({{-1, {1, 0, 0}}, {1, {0, 0, 1}}}, {{-1, 0.5}, {1, 3.0}});
  const Image img = render(m, tf, looking_down(4.0), 16, 16);
  // The ray enters at z = 1 (kappa 3, blue) and leaves at z = -1 (kappa 0.5, red).
  const double depth = 2.0 * (3.0 + 0.5) / 2;
  const glm::dvec3 light = test::simpson_light(
      2.0, [](double t) { return 3.0 - 1.25 * t; }, [](double t) { return glm::dvec3(t / 2, 0, 1 - t / 2); });
  for (int j = 4; j < 12; ++j)
    for (int i = 4; i < 12; ++i) {
      const float* p = img.pixel(i, j);
      ASSERT_NEAR(p[3], 1 - std::exp(-depth), 1e-6);
      ASSERT_NEAR(p[0], light.r, 1e-6);
      ASSERT_NEAR(p[2], light.b, 1e-6);
    }
}

TEST(ExactRenderer, TwoCubesWithAGapAddNothingInTheGap) {
  Mesh a = make_box(2, 2, 2, {-1, -1, 0.5}, {1, 1, 1.5}, true);
  set_field(a, "s", [](const glm::dvec3&) { return 0.0; });
  Mesh b = make_box(2, 2, 2, {-1, -1, -1.5}, {1, 1, -0.5}, false);
  set_field(b, "s", [](const glm::dvec3&) { return 1.0; });
  test::append(a, b);
  // Red below s = 0.5, blue above: a colour step.
  const TransferFunction tf({{0.5, {1, 0, 0}}, {0.5, {0, 0, 1}}}, {{0, 0.8}});
  const Image img = render(a, tf, looking_down(4.0), 16, 16);
  const double A = 1 - std::exp(-0.8);
  const float* p = img.pixel(8, 8);
  EXPECT_NEAR(p[0], A, 1e-6);                   // the red front cube
  EXPECT_NEAR(p[2], (1 - A) * A, 1e-6);         // the blue back cube seen through it
  EXPECT_NEAR(p[3], 1 - std::exp(-1.6), 1e-6);  // the gap absorbs nothing
}

TEST(ExactRenderer, TransferFunctionBreakpointsInsideACell) {
  Mesh m = make_box(1, 1, 1, glm::dvec3(-1), glm::dvec3(1), false);  // one hexahedron
  set_field(m, "s", [](const glm::dvec3& x) { return x.z; });
  // A tent of kappa peaking at s = 0.3, and a colour breakpoint at s = -0.2.
  const TransferFunction tf({{-0.2, {1, 1, 1}}, {1, {0, 1, 0}}}, {{-1, 0.0}, {0.3, 4.0}, {1, 0.0}});
  const Image img = render(m, tf, looking_down(4.0), 8, 8);
  auto kappa = [](double t) {
    const double z = 1 - t;
    return z > 0.3 ? 4 * (1 - z) / 0.7 : 4 * (z + 1) / 1.3;
  };
  auto colour = [](double t) {
    const double z = 1 - t;
    return z < -0.2 ? glm::dvec3(1) : glm::dvec3((1 - z) / 1.2, 1, (1 - z) / 1.2);
  };
  const glm::dvec3 light = test::simpson_light(2.0, kappa, colour);
  const float* p = img.pixel(4, 4);
  EXPECT_NEAR(p[3], 1 - std::exp(-4.0), 1e-6);  // area of the tent: 2 * 4 / 2
  EXPECT_NEAR(p[0], light.r, 1e-6);
  EXPECT_NEAR(p[1], light.g, 1e-6);
}

TEST(ExactRenderer, PixelCentreConvention) {
  // Pixels are one unit square; centres at x = i - 3.5, y = 3.5 - j.
  Mesh m = make_box(1, 1, 1, {0.4, -0.6, -1}, {1.6, 0.6, 1}, true);
  set_field(m, "s", [](const glm::dvec3&) { return 0.0; });
  const Image img = render(m, test::constant_tf(1.0, {1, 1, 1}), looking_down(8.0), 8, 8);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const bool covered = (i == 4 || i == 5) && (j == 3 || j == 4);
      EXPECT_EQ(img.pixel(i, j)[3] > 0, covered) << i << "," << j;
    }
}

TEST(ExactRenderer, PerspectiveFromFarAwayMatchesOrthographic) {
  Mesh m = make_box(3, 3, 3, glm::dvec3(-1), glm::dvec3(1), true);
  set_field(m, "s", [](const glm::dvec3& x) { return x.x + x.y * 0.5 + x.z; });
  const TransferFunction tf({{-3, {1, 0, 0}}, {3, {0, 1, 1}}}, {{-3, 0.2}, {3, 2.0}});
  Camera ortho = looking_down(4.0);
  ortho.eye = {0, 0, 1e4};
  Camera persp = ortho;
  persp.projection = Projection::Perspective;
  persp.fov_y = 2 * std::atan(2.0 / 1e4) * 180 / M_PI;  // 4 units tall at the target
  const auto d = compare(render(m, tf, ortho, 32, 32), render(m, tf, persp, 32, 32));
  EXPECT_LT(d.max_abs, 2e-4);  // rays diverge by ~1e-4 across the mesh
}

TEST(ExactRenderer, OneAndTwoThreadsGiveTheSameImage) {
  const Mesh m = generate("swirl", 6);
  const TransferFunction tf({{0, {0, 0, 1}}, {1, {1, 1, 0}}}, {{0, 0.5}, {1, 8}});
  const Camera c = frame_box(glm::dvec3(-1), glm::dvec3(1), Projection::Perspective, {1, 1, 1}, {0, 0, 1}, 1.0);
  Image one, two;
  tbb::task_arena(1).execute([&] { one = render(m, tf, c, 64, 64); });
  tbb::task_arena(2).execute([&] { two = render(m, tf, c, 64, 64); });
  EXPECT_EQ(one.rgba, two.rgba);
}

TEST(ExactRenderer, HugeCoordinateOffsetChangesNothing) {
  auto scene = [](glm::dvec3 offset) {
    Mesh m = make_box(10, 10, 10, offset - glm::dvec3(5e-3), offset + glm::dvec3(5e-3), true);  // cells of 1e-3
    set_field(m, "s", [&](const glm::dvec3& x) { return (x.x - offset.x) * 100; });
    Camera c = looking_down(0.02);
    c.eye += offset;
    c.target += offset;
    const TransferFunction tf({{-0.5, {1, 0, 0}}, {0.5, {0, 0, 1}}}, {{-0.5, 50}, {0.5, 200}});
    return render(m, tf, c, 24, 24);
  };
  const Image near = scene(glm::dvec3(0)), far = scene(glm::dvec3(1e6));
  EXPECT_GT(near.pixel(12, 12)[3], 0.5);
  EXPECT_LT(compare(near, far).max_abs, 1e-5);
}

TEST(ExactRenderer, ZeroVolumeCellsAddNothing) {
  Mesh m = make_box(1, 1, 1, glm::dvec3(-1), glm::dvec3(1), true);
  set_field(m, "s", [](const glm::dvec3&) { return 0.0; });
  const std::int64_t a = m.add_point({0, 0, 0}), b = m.add_point({0.5, 0, 0}), c = m.add_point({0, 0.5, 0}),
                     d = m.add_point({0.5, 0.5, 0});  // a flat tetrahedron inside
  m.fields[0].values.resize(static_cast<std::size_t>(m.n_points()), 0.0);
  m.add_cell(CellType::Tetra, {a, b, c, d});
  const ExactRenderer r(m.view());
  EXPECT_EQ(r.tracer().dropped_degenerate(), 1);
  const Image img = r.render(test::field_values(m, "s"), test::constant_tf(1.0, {1, 1, 1}), looking_down(4.0), 8, 8);
  EXPECT_NEAR(img.pixel(4, 4)[3], 1 - std::exp(-2.0), 1e-6);
}

TEST(ExactRenderer, RaysAlongEdgesAndInFacesCountEachCellOnce) {
  // Pixel centres exactly on the vertex columns of a tetrahedral slab: every ray runs along edges
  // and inside faces (vertical faces and the canonical split's diagonals), seen edge-on.
  Mesh m = make_box(8, 8, 2, {-1, -1, -0.5}, {1, 1, 0.5}, true);
  set_field(m, "s", [](const glm::dvec3&) { return 0.0; });
  const Image img = render(m, test::constant_tf(1.3, {1, 1, 1}), looking_down(2.25), 9, 9);
  for (int j = 1; j < 8; ++j)
    for (int i = 1; i < 8; ++i) ASSERT_NEAR(img.pixel(i, j)[3], 1 - std::exp(-1.3), 1e-6) << i << "," << j;
}
