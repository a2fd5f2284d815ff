// The plan of a projection frame (frame/frame_plan.hpp): every decision the conductor runs on,
// asked without rendering.
#include <gtest/gtest.h>

#include "frame/frame_plan.hpp"

using namespace cellproj;

namespace {
int asked = 0;
bool acyclic() { return ++asked, true; }
bool cyclic() { return ++asked, false; }
}  // namespace

TEST(FramePlan, TheDefaultsDrawByTilesAndCountSmallCellsAfter) {
  asked = 0;
  const FramePlan p = plan_frame({}, Tetrahedralize::problem, 1024, 2, acyclic);
  EXPECT_TRUE(p.software);
  EXPECT_TRUE(p.by_tiles);
  EXPECT_TRUE(p.count_small_after);
  EXPECT_EQ(p.small_cells, SmallCells::draw);
  EXPECT_FALSE(p.tile_orders);         // automatic: not below 4 threads...
  EXPECT_EQ(asked, 0);                 // ...and the costly acyclicity check is not asked
  EXPECT_FALSE(p.passes_beside_sort);  // problem cells split per view: the passes wait for the split
  EXPECT_EQ(p.tile_rows, 64);          // 1024 / (4 * 2) = 128, at most 64
}

TEST(FramePlan, TileOrdersAutomaticallyFromFourThreadsOnAnAcyclicMesh) {
  asked = 0;
  EXPECT_TRUE(plan_frame({}, Tetrahedralize::all, 1024, 4, acyclic).tile_orders);
  EXPECT_FALSE(plan_frame({}, Tetrahedralize::all, 1024, 4, cyclic).tile_orders);
  EXPECT_EQ(asked, 2);
  ProjectionOptions on;
  on.tile_orders = TileOrders::on;
  EXPECT_TRUE(plan_frame(on, Tetrahedralize::all, 1024, 1, cyclic).tile_orders);  // forced
  on.compositing = Compositing::stream;
  EXPECT_FALSE(plan_frame(on, Tetrahedralize::all, 1024, 1, acyclic).tile_orders);  // no tiles
  EXPECT_TRUE(plan_frame(on, Tetrahedralize::all, 1024, 1, acyclic).passes_beside_sort);
}

TEST(FramePlan, SplatsTakeTheStreamAndAreCountedBeforeDrawing) {
  ProjectionOptions o;
  o.splat.small_cells = SmallCells::splat;
  const FramePlan p = plan_frame(o, Tetrahedralize::none, 600, 2, acyclic);
  EXPECT_FALSE(p.by_tiles);
  EXPECT_FALSE(p.count_small_after);
  EXPECT_EQ(p.splat_threshold, kDefaultPixelThreshold);
  o.splat.small_cells = SmallCells::draw;
  o.splat.threshold = 4;  // a threshold above one pixel centre is read before drawing
  EXPECT_FALSE(plan_frame(o, Tetrahedralize::none, 600, 2, acyclic).count_small_after);
  o.tile_rows = 10;
  EXPECT_EQ(plan_frame(o, Tetrahedralize::none, 600, 2, acyclic).tile_rows, 10);
}
