// The splats' stencil (MWSC section 6): a splat adds light only where no drawn cell holds the ray
// at its depth; in cell projection the stencil is the exact traversal of the drawn cells along
// each pixel's ray.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "frame/splat_stencil.hpp"
#include "mesh/generate.hpp"
#include "raycast/cell_ray_tracer.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

// A thin round splat (tau = alpha to 1e-4) of variance 4 pixels^2 at (16, 16) in a 32 x 32 image.
Footprint round_splat() {
  Footprint f;
  f.centre = {16.0, 16.0};
  f.covariance = glm::dmat2(4.0);
  f.conic = glm::dmat2(0.25);
  f.peak = 1e-4;
  f.cutoff = 30.0;
  f.color = {1.0, 1.0, 1.0};
  f.visible = true;
  return f;
}

// The optical depth a splat leaves in each pixel, and the pixels inside its cutoff.
struct Drawn {
  std::vector<double> tau = std::vector<double>(32 * 32, 0.0);
  SplatCounters count;  // splat_fragments: pixels drawn; masked_fragments: held
  double sum() const {
    double s = 0.0;
    for (double t : tau) s += t;
    return s;
  }
};
template <class Open>
Drawn draw(const Footprint& f, Open&& open) {
  Drawn d;
  rasterize_splat_open(
      f, 32, 32, open,
      [&](int i, int j, const glm::dvec3&, double alpha) {
        d.tau[static_cast<std::size_t>(j * 32 + i)] = -std::log1p(-alpha);
      },
      d.count);
  return d;
}

}  // namespace

TEST(SplatStencil, AMaskedSplatAddsNothingWhereTheStencilHoldsAndTheSameElsewhere) {
  const Footprint f = round_splat();
  const Drawn all = draw(f, [](int, int) { return true; });
  EXPECT_EQ(all.count.masked_fragments, 0);
  EXPECT_GT(all.count.splat_fragments, 50);
  const Drawn half = draw(f, [](int i, int) { return i >= 16; });
  EXPECT_EQ(half.count.splat_fragments + half.count.masked_fragments, all.count.splat_fragments);
  EXPECT_GT(half.count.masked_fragments, 0);
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i) {
      const std::size_t p = static_cast<std::size_t>(j * 32 + i);
      EXPECT_EQ(half.tau[p], i >= 16 ? all.tau[p] : 0.0) << i << ", " << j;
    }
  EXPECT_NEAR(half.sum() / all.sum(), 0.5, 0.05);  // the right half of a splat centred at 16
  const Drawn none = draw(f, [](int, int) { return false; });
  EXPECT_EQ(none.sum(), 0.0);
  EXPECT_EQ(none.count.splat_fragments, 0);
}

TEST(SplatStencil, ItHoldsTheRayWhereADrawnCellIsAndNowhereElse) {
  // [-1, 1]^3 seen from z = 5, orthographic: the middle pixel's ray is inside from t = 4 to 6.
  const Mesh box = make_box(4, 4, 4, glm::dvec3(-1), glm::dvec3(1), true);
  const MeshView v = box.view();
  const CellRayTracer tracer(v);
  const Camera camera = test::looking_down(3.0);
  const std::vector<PixelBox> first_tile{PixelBox(glm::dvec2(0, 0), glm::dvec2(20, 0), glm::dvec2(0, 20), 32, 32)};
  std::vector<std::uint8_t> drawn(static_cast<std::size_t>(v.n_cells), 1);
  const SplatStencil all(tracer, camera, 32, 32, first_tile, drawn);
  EXPECT_EQ(all.tiles_traced(), 4);  // the box reaches pixel 20: tiles of 16 pixels
  EXPECT_TRUE(all.holds(16, 16, 4.01));
  EXPECT_TRUE(all.holds(16, 16, 5.0));  // across the faces between the cells: merged
  EXPECT_TRUE(all.holds(16, 16, 5.99));
  EXPECT_FALSE(all.holds(16, 16, 3.99));
  EXPECT_FALSE(all.holds(16, 16, 6.01));
  EXPECT_FALSE(all.holds(0, 0, 5.0));  // outside the box: its ray misses the mesh

  // The layer of cells between z = 0 and 0.5 not drawn (small): a gap from t = 4.5 to 5.
  for (std::int64_t c = 0; c < v.n_cells; ++c) {
    double z = 0.0;
    for (int k = 0; k < 4; ++k) z += 0.25 * box.points[3 * static_cast<std::size_t>(v.cell(c)[k]) + 2];
    if (z > 0.0 && z < 0.5) drawn[static_cast<std::size_t>(c)] = 0;
  }
  const SplatStencil gap(tracer, camera, 32, 32, first_tile, drawn);
  EXPECT_TRUE(gap.holds(16, 16, 4.25));
  EXPECT_FALSE(gap.holds(16, 16, 4.75));
  EXPECT_TRUE(gap.holds(16, 16, 5.25));
}
