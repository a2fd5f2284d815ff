// MIP, MinIP and the mean along each ray against their closed forms (issue 20).
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/generate.hpp"
#include "raycast/ray_reduction.hpp"
#include "tests/test_util.hpp"

namespace cellproj {
namespace {

// Orthographic rays straight down -z through the box [-1, 1]^3, at pixel centres of [-0.9, 0.9]^2.
Camera down() { return test::looking_down(1.8); }

TEST(RayReduction, IsExactForALinearFieldOnTetrahedraAndHexahedra) {
  for (bool tets : {true, false}) {
    const Mesh m = make_box(5, 4, 3, {-1, -1, -1}, {1, 1, 1}, tets);
    std::vector<double> f(m.n_points());
    for (std::int64_t p = 0; p < m.n_points(); ++p)
      f[p] = m.points[3 * p] + 2 * m.points[3 * p + 1] + 3 * m.points[3 * p + 2];
    const CellRayTracer tracer(m.view());
    const int n = 9;
    for (RayReduction r : {RayReduction::maximum, RayReduction::minimum, RayReduction::average}) {
      const std::vector<double> v = reduce_ray_values(tracer, f.data(), down(), n, n, r);
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const double x = -0.9 + 1.8 * (i + 0.5) / n, y = 0.9 - 1.8 * (j + 0.5) / n;  // row 0 at the top
          const double z = r == RayReduction::maximum ? 1.0 : r == RayReduction::minimum ? -1.0 : 0.0;
          ASSERT_NEAR(v[j * n + i], x + 2 * y + 3 * z, 1e-9) << "tets " << tets << " reduction " << int(r);
        }
    }
  }
}

TEST(RayReduction, FindsTheMaximumOfARadialFieldWhereTheRayPassesClosest) {
  // f = -|p|: along a vertical ray at (x, y) the maximum is -sqrt(x^2 + y^2), at z = 0. The
  // piecewise-linear field is within O(h) of it at the cone's tip, O(h^2) elsewhere.
  const Mesh m = make_box(16, 16, 16, {-1, -1, -1}, {1, 1, 1}, true);
  std::vector<double> f(m.n_points());
  for (std::int64_t p = 0; p < m.n_points(); ++p)
    f[p] = -std::sqrt(m.points[3 * p] * m.points[3 * p] + m.points[3 * p + 1] * m.points[3 * p + 1] +
                      m.points[3 * p + 2] * m.points[3 * p + 2]);
  const CellRayTracer tracer(m.view());
  const int n = 12;
  const std::vector<double> v = reduce_ray_values(tracer, f.data(), down(), n, n, RayReduction::maximum);
  double worst = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -0.9 + 1.8 * (i + 0.5) / n, y = 0.9 - 1.8 * (j + 0.5) / n;
      worst = std::max(worst, std::abs(v[j * n + i] + std::hypot(x, y)));
    }
  EXPECT_LT(worst, 0.3 * 0.125);  // h = 1/8; measured 0.029 (0.23 h), beside the tip
  EXPECT_GT(worst, 0.0);          // it is an interpolant, not the analytic field
}

TEST(RayReduction, ShowsTheValueThroughTheColourMapOpaqueAndLeavesMissesEmpty) {
  const Mesh m = make_box(2, 2, 2, {-0.5, -0.5, -1}, {0.5, 0.5, 1}, true);
  std::vector<double> f(m.n_points());
  for (std::int64_t p = 0; p < m.n_points(); ++p) f[p] = m.points[3 * p + 2] + 1.0;  // 0 to 2 along z
  const CellRayTracer tracer(m.view());
  const TransferFunction tf({{0, {0, 0, 0}}, {2, {1, 0.5, 0}}}, {{0, 0.0}});
  const Image img = reduce_rays(tracer, f.data(), tf, down(), 8, 8, RayReduction::maximum);
  const float* centre = img.pixel(4, 4);
  EXPECT_FLOAT_EQ(centre[0], 1.0f);  // the maximum, 2, at the top: tf.color(2)
  EXPECT_FLOAT_EQ(centre[1], 0.5f);
  EXPECT_FLOAT_EQ(centre[3], 1.0f);
  EXPECT_EQ(img.pixel(0, 0)[3], 0.0f);  // outside the box's 1 x 1 footprint
}

}  // namespace
}  // namespace cellproj
