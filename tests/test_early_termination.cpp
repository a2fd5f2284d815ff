// Early ray termination (--early-termination on): tiles composited front to back, pixels closed
// within 1e-6 of opaque, cells behind closed pixels left out. The picture against back to front,
// the same bits for any thread count and tile height, and the options it cannot go with.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "base/error.hpp"
#include "composite/opaque_mask.hpp"
#include "frame/projection_renderer.hpp"
#include "render/names.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

// Colour ramps over s in [-1.4, 1.4]; `kappa` scales the extinction (40: every ray through the
// mesh is opaque long before it leaves; 1: none is).
TransferFunction ramp(double kappa) {
  return TransferFunction({{-1.4, {0.1, 0.2, 0.9}}, {0.0, {0.9, 0.9, 0.2}}, {1.4, {1, 0.4, 0.1}}},
                          {{-1.4, 0.5 * kappa}, {0.0, 2.0 * kappa}, {1.4, 1.0 * kappa}});
}

}  // namespace

TEST(EarlyTermination, TheMaskTellsWhetherEveryPixelOfABoxIsOpaque) {
  OpaqueMask m(130, 3);
  for (int i = 60; i <= 70; ++i) m.set(i, 1);  // across the first word boundary
  EXPECT_TRUE(m.all(60, 70, 1, 1));
  EXPECT_TRUE(m.all(63, 64, 1, 1));
  EXPECT_FALSE(m.all(59, 70, 1, 1));
  EXPECT_FALSE(m.all(60, 71, 1, 1));
  EXPECT_FALSE(m.all(60, 70, 0, 1));
  EXPECT_TRUE(m.all(5, 4, 0, 2));            // an empty box
  for (int i = 0; i < 40; ++i) m.set(i, 0);  // row 0: enough opaque pixels, none in the box
  EXPECT_FALSE(m.all(60, 70, 0, 0));
  EXPECT_TRUE(m.all(0, 39, 0, 0));
  m.set(129, 2);
  EXPECT_TRUE(m.opaque(129, 2));
  EXPECT_FALSE(m.opaque(128, 2));
  EXPECT_TRUE(m.all(129, 129, 2, 2));
}

TEST(EarlyTermination, WithinTwoMillionthsOfBackToFrontAndTheSameBitsForAnyThreadsAndTiles) {
  for (bool tetrahedra : {true, false})
    for (double kappa : {40.0, 1.0}) {
      const TransferFunction tf = ramp(kappa);
      const Mesh m = test::wavy_grid(6, tetrahedra);
      const ProjectionRenderer r(m.view(), tetrahedra ? Tetrahedralize::problem : Tetrahedralize::none);
      const double* s = test::field_values(m, "s");
      const Camera cams[2] = {test::view_from({0.5, -3, 2}, Projection::Perspective),
                              test::inside_wavy_grid(Projection::Perspective)};
      for (int v = 0; v < (tetrahedra ? 2 : 1); ++v)
        for (ProjectionMethod method :
             {ProjectionMethod::pt_linear, ProjectionMethod::pt_table, ProjectionMethod::pt_breakpoints}) {
          const std::string what = std::string(tetrahedra ? "tets" : "hexes") + " kappa " + std::to_string(kappa) +
                                   " view " + std::to_string(v) + " " + name_of(method);
          ProjectionOptions o;
          o.method = method;
          ProjectionStats back_st;
          const Image back = r.render(s, tf, cams[v], 96, 72, o, &back_st);
          o.early_termination = true;
          ProjectionStats st;
          Image front;
          tbb::task_arena(1).execute([&] { front = r.render(s, tf, cams[v], 96, 72, o, &st); });
          // Rounding in another order, and at most 1e-6 of light behind a closed pixel.
          EXPECT_LE(compare(back, front).max_abs, 2e-6) << what;
          EXPECT_EQ(st.counters.fragments + st.counters.hidden_fragments > 0, true) << what;
          if (kappa > 1) {
            EXPECT_GT(st.counters.hidden_cells, 0) << what;  // cells wholly behind closed pixels
            EXPECT_LT(st.counters.fragments, back_st.counters.fragments) << what;
          } else {
            EXPECT_EQ(st.counters.hidden_cells + st.counters.hidden_fragments, 0) << what;  // nothing closes
            EXPECT_EQ(st.counters.fragments, back_st.counters.fragments) << what;
          }
          std::int64_t hidden_in_7_rows = -1;  // the cells left out depend on the tiles, not on the threads
          for (int rows : {0, 7})
            for (int threads : {1, 3}) {
              o.tile_rows = rows;
              ProjectionStats st_n;
              Image again;
              tbb::task_arena(threads).execute([&] { again = r.render(s, tf, cams[v], 96, 72, o, &st_n); });
              // A cell is left out of a tile only where each of its pixels would drop its fragment.
              EXPECT_EQ(front.rgba, again.rgba) << what << " rows " << rows << " threads " << threads;
              if (rows == 7 && threads == 1) hidden_in_7_rows = st_n.counters.hidden_cells;
              if (rows == 7 && threads > 1) EXPECT_EQ(st_n.counters.hidden_cells, hidden_in_7_rows) << what;
            }
        }
    }
}

TEST(EarlyTermination, NeedsTilesTheSoftwareBackEndAndNoSplats) {
  ProjectionOptions o;
  o.early_termination = true;
  EXPECT_NO_THROW(check_options(o));
  o.compositing = Compositing::stream;
  EXPECT_THROW(check_options(o), InputError);
  o.compositing = Compositing::tiles;
  o.splat.small_cells = SmallCells::splat;
  EXPECT_THROW(check_options(o), InputError);
}
