// Cells with extinction 0 over their scalar range are left out of cell projection (issue 21,
// culling work that cannot show): the same bits for every method, small cells splatted too.
#include <gtest/gtest.h>

#include "frame/projection_renderer.hpp"
#include "mesh/generate.hpp"
#include "tests/test_util.hpp"

namespace cellproj {
namespace {

TEST(Culling, TransparentOverARangeIsExactlyWhereTheExtinctionIsZero) {
  const TransferFunction tf({{0.0, {1, 1, 1}}}, {{0.3, 0.0}, {0.5, 0.0}, {0.5, 3.0}, {1.0, 6.0}});
  EXPECT_TRUE(tf.has_transparent_range());
  EXPECT_TRUE(tf.transparent_over(-1.0, 0.45));  // clamped below 0.3: zero
  EXPECT_FALSE(tf.transparent_over(0.45, 0.5));  // the step's right side, 3, at 0.5
  EXPECT_FALSE(tf.transparent_over(0.6, 0.2));   // either order
  const TransferFunction hump({{0.0, {1, 1, 1}}}, {{0.2, 0.0}, {0.4, 1.0}, {0.6, 0.0}});
  EXPECT_FALSE(hump.transparent_over(0.1, 0.7)) << "zero at both ends, not between";
  EXPECT_TRUE(hump.transparent_over(0.6, 0.9));
  EXPECT_FALSE(test::constant_tf(0.5, {1, 1, 1}).has_transparent_range());
}

TEST(Culling, LeavingOutTransparentCellsGivesTheSameBitsForEveryMethod) {
  const Mesh m = generate("mixed", 8);  // 1 - |x|^2/3 + 0.3 xyz: the outer cells below 0.55 are clear
  const TransferFunction tf({{0.0, {0.2, 0.4, 1.0}}, {1.0, {1.0, 0.7, 0.2}}}, {{0.55, 0.0}, {0.55, 2.0}, {1.0, 9.0}});
  const Camera camera = test::view_from({2.0, -3.0, 2.5}, Projection::Perspective);
  for (ProjectionMethod method : {ProjectionMethod::pt_linear, ProjectionMethod::pt_table,
                                  ProjectionMethod::pt_analytic, ProjectionMethod::pt_breakpoints}) {
    for (SmallCells small : {SmallCells::draw, SmallCells::splat}) {
      ProjectionOptions on = test::with_method(method), off = on;
      on.splat.small_cells = off.splat.small_cells = small;
      on.splat.threshold = off.splat.threshold = 6;
      off.cull_transparent = false;
      ProjectionStats st_on, st_off;
      const Image a = test::project(m, "", tf, camera, 64, on, Tetrahedralize::problem, &st_on);
      const Image b = test::project(m, "", tf, camera, 64, off, Tetrahedralize::problem, &st_off);
      EXPECT_EQ(a.rgba, b.rgba) << name_of(method) << " small cells " << int(small);
      EXPECT_GT(st_on.culled_transparent, 100);  // 191 of the 1893 cells projected
      EXPECT_EQ(st_off.culled_transparent, 0);
      EXPECT_GT(*std::max_element(a.rgba.begin(), a.rgba.end()), 0.1f);
    }
  }
}

}  // namespace
}  // namespace cellproj
