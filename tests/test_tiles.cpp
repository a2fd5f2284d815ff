// Compositing by image tiles (composite/tiled_compositor.hpp) against the ordered stream: the same
// bits and the same counts for any tile height and thread count, on tetrahedra and whole cells, with
// the eye outside, inside (cells ray cast from it) and an orthographic eye plane through the mesh;
// and frame after frame at 1024², no new memory (the framebuffer's block reused).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "base/huge_pages.hpp"
#include "composite/tiled_compositor.hpp"
#include "frame/projection_renderer.hpp"
#include "mesh/generate.hpp"
#include "mesh/validate.hpp"
#include "projection/method.hpp"
#include "render/names.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

TransferFunction tiles_tf() {
  return TransferFunction({{-1, {0.1, 0.2, 0.9}}, {0.0, {0.9, 0.9, 0.2}}, {1, {1, 1, 1}}},
                          {{-1, 0.4}, {-0.3, 3.0}, {0.2, 0.5}, {1, 2.0}});
}

void expect_same_counts(const ProjectionStats& a, const ProjectionStats& b, const std::string& what) {
  const ProjectionCounters &x = a.counters, &y = b.counters;
  EXPECT_EQ(x.tets, y.tets) << what;
  EXPECT_EQ(x.class1, y.class1) << what;
  EXPECT_EQ(x.class2, y.class2) << what;
  EXPECT_EQ(x.empty, y.empty) << what;
  EXPECT_EQ(x.behind_eye, y.behind_eye) << what;
  EXPECT_EQ(x.polyhedra, y.polyhedra) << what;
  EXPECT_EQ(x.polygons, y.polygons) << what;
  EXPECT_EQ(x.layered, y.layered) << what;
  EXPECT_EQ(x.unmatched, y.unmatched) << what;
  EXPECT_EQ(x.breakpoint_cells, y.breakpoint_cells) << what;
  EXPECT_EQ(x.fragments, y.fragments) << what;
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// This process's resident memory in bytes (Linux), or -1.
std::int64_t resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  long long size = 0, resident = 0;
  if (!(statm >> size >> resident)) return -1;
  return resident * sysconf(_SC_PAGESIZE);
}

}  // namespace

TEST(FrameMemory, FramesAfterTheFirstTakeNoNewMemory) {
  if (kAddressSanitizer)
    GTEST_SKIP() << "AddressSanitizer's allocator holds freed blocks in quarantine: no reuse to measure";
  // The command line's allocator settings, under which the framebuffer's aligned_alloc left a
  // 16 MB hole a frame at 1024² that the next frame's could not reuse (base/huge_pages.hpp).
  keep_frame_arrays_in_heap();
  const Mesh m = generate("box-tets", 12);  // bench/run's tets-10k
  const ProjectionRenderer r(m.view());
  const TransferFunction tf = tiles_tf();
  const Camera cam = test::view_from({3.6, -4.6, 3.0}, Projection::Perspective);
  const auto frame = [&] {
    Image image = r.render(test::field_values(m), tf, cam, 1024, 1024, test::with_method(ProjectionMethod::pt_linear));
    EXPECT_GT(*std::max_element(image.rgba.begin(), image.rgba.end()), 0.0f);
    return image;
  };
  const Image first = frame();  // kept, as the command line keeps the frame it writes after timing
  for (int f = 0; f < 2; ++f) frame();
  const std::int64_t before = resident_bytes();
  if (before < 0) GTEST_SKIP() << "no /proc/self/statm";
  for (int f = 0; f < 8; ++f) frame();
  EXPECT_LT(resident_bytes() - before, std::int64_t{4} << 20) << "8 frames of a 16 MB framebuffer";
}

TEST(Tiles, TheSameBitsAndCountsAsTheStreamForAnyTileHeightAndThreads) {
  const TransferFunction tf = tiles_tf();
  for (bool tetrahedra : {true, false}) {
    const Mesh m = test::wavy_grid(5, tetrahedra);
    const ProjectionRenderer r(m.view(), tetrahedra ? Tetrahedralize::problem : Tetrahedralize::none);
    const double* s = test::field_values(m, "s");
    const Camera cams[3] = {test::view_from({0.5, -3, 2}, Projection::Perspective),
                            test::inside_wavy_grid(Projection::Perspective),
                            test::inside_wavy_grid(Projection::Orthographic)};
    for (int v = 0; v < 3; ++v)
      for (ProjectionMethod method :
           {ProjectionMethod::pt_linear, ProjectionMethod::pt_table, ProjectionMethod::pt_breakpoints}) {
        if (!tetrahedra && v > 0) continue;  // whole cells reaching behind the eye are not drawn
        ProjectionOptions o;
        o.method = method;
        o.compositing = Compositing::stream;
        ProjectionStats st_stream;
        Image stream;
        tbb::task_arena(1).execute([&] { stream = r.render(s, tf, cams[v], 90, 70, o, &st_stream); });
        EXPECT_GT(st_stream.counters.fragments, 1000);
        if (v > 0 && tetrahedra) EXPECT_GT(st_stream.counters.behind_eye, 0);
        if (!tetrahedra && method == ProjectionMethod::pt_breakpoints) EXPECT_GT(st_stream.counters.layered, 0);
        o.compositing = Compositing::tiles;
        for (int rows : {0, 1, 7, 64})
          for (int threads : {1, 3}) {
            o.tile_rows = rows;
            ProjectionStats st;
            Image tiles;
            tbb::task_arena(threads).execute([&] { tiles = r.render(s, tf, cams[v], 90, 70, o, &st); });
            const std::string what = std::string(tetrahedra ? "tets" : "hexes") + " view " + std::to_string(v) + " " +
                                     name_of(method) + " rows " + std::to_string(rows) + " threads " +
                                     std::to_string(threads);
            EXPECT_EQ(stream.rgba, tiles.rgba) << what;
            expect_same_counts(st_stream, st, what);
            EXPECT_GT(st.tiles, 0) << what;
            EXPECT_GE(st.tile_visits, st.cells) << what;  // every cell met at least once
          }
      }
  }
}

// pt-linear's tiles draw a tetrahedron of any size as one fan (its image box may exceed
// kFanUpToPixels: no buffer), the stream draws one that large by its triangles: the same bits and
// counts on a mesh of 48 tetrahedra each a few thousand pixels wide, in perspective and orthographic.
TEST(Tiles, LargeTetrahedraByTheFanAsByTheirTriangles) {
  const TransferFunction tf = tiles_tf();
  const Mesh m = generate("box-tets", 2);
  const ProjectionRenderer r(m.view());
  for (Projection projection : {Projection::Perspective, Projection::Orthographic}) {
    const Camera cam = test::view_from({2.6, -3.1, 2.2}, projection);
    ProjectionOptions o = test::with_method(ProjectionMethod::pt_linear);
    o.compositing = Compositing::stream;
    ProjectionStats st_stream, st_tiles;
    const Image stream = r.render(test::field_values(m), tf, cam, 256, 256, o, &st_stream);
    o.compositing = Compositing::tiles;
    const Image tiles = r.render(test::field_values(m), tf, cam, 256, 256, o, &st_tiles);
    EXPECT_GT(st_stream.counters.fragments / 48, 4 * kFanUpToPixels);  // mean image box well above it
    EXPECT_EQ(stream.rgba, tiles.rgba);
    expect_same_counts(st_stream, st_tiles, projection == Projection::Perspective ? "perspective" : "orthographic");
  }
}

// Each tile ordering its own cells (frame/tile_orders.hpp) gives the same bits as one order of
// every cell, on convex Delaunay meshes of tetrahedra (a box; random points, irregular; a grid
// graded towards one face: big cells behind small ones), where no view makes a cycle, in perspective and
// orthographic, with the eye outside and inside, for two tile heights and thread counts; front to
// back with transparent cells (not drawn, kept in the relations). A mesh whose boundary
// is not convex keeps the global order. `auto` takes the tiles' orders on these meshes from 4 threads.
TEST(Tiles, EachTileOrderingItsOwnCellsGivesTheSamePicture) {
  const test::TempDir dir;
  // Extinction 0 below -0.2: the cells there are culled from drawing.
  const TransferFunction base_tf = tiles_tf();
  const TransferFunction clear_below({{-1, {0.1, 0.2, 0.9}}, {0.0, {0.9, 0.9, 0.2}}, {1, {1, 1, 1}}},
                                     {{-1, 0.0}, {-0.2, 0.0}, {0.1, 3.0}, {1, 1.5}});
  std::vector<Camera> cams = test::views_of_unit_mesh(2);
  Camera inside = test::view_from({0.1, 0.2, 0.05}, Projection::Perspective);
  inside.target = {1.0, 0.3, -0.2}, inside.fov_y = 70;
  cams.push_back(inside);
  const Mesh meshes[3] = {generate("box-tets", 5), test::delaunay_cube(dir, 400, 11), generate("graded-tets", 4)};
  for (int k = 0; k < 3; ++k) {
    const Mesh& m = meshes[k];
    const ProjectionRenderer r(m.view());
    ASSERT_TRUE(r.convex_boundary()) << k;
    {
      ProjectionStats st;
      tbb::task_arena(kTileOrdersFromThreads).execute([&] {
        r.render(test::field_values(m), tiles_tf(), cams[0], 32, 32, test::with_method(ProjectionMethod::pt_linear),
                 &st);
      });
      EXPECT_TRUE(st.tile_orders) << "auto on an acyclic mesh, mesh " << k;
    }
    const double* s = test::field_values(m);
    for (std::size_t v = 0; v < cams.size(); ++v)
      for (ProjectionMethod method : {ProjectionMethod::pt_linear, ProjectionMethod::pt_breakpoints})
        for (int variant = 0; variant < 2; ++variant) {  // back to front; front to back with culled cells
          const bool front_to_back = variant == 1;
          const TransferFunction& tf = front_to_back ? clear_below : base_tf;
          ProjectionOptions o = test::with_method(method);
          o.early_termination = front_to_back;
          o.tile_orders = TileOrders::off;
          ProjectionStats st_global;
          const Image global = r.render(s, tf, cams[v], 72, 60, o, &st_global);
          EXPECT_FALSE(st_global.tile_orders);
          EXPECT_GT(st_global.counters.fragments, 500);
          o.tile_orders = TileOrders::on;
          for (int run = 0; run < 2; ++run) {  // default tiles on 1 thread; 5-row tiles on 3
            const int rows = run == 0 ? 0 : 5, threads = run == 0 ? 1 : 3;
            o.tile_rows = rows;
            ProjectionStats st;
            Image tiles;
            tbb::task_arena(threads).execute([&] { tiles = r.render(s, tf, cams[v], 72, 60, o, &st); });
            const std::string what = "mesh " + std::to_string(k) + " view " + std::to_string(v) + " " +
                                     name_of(method) + " rows " + std::to_string(rows) + " threads " +
                                     std::to_string(threads) + (front_to_back ? " front to back" : "");
            EXPECT_TRUE(st.tile_orders) << what;
            EXPECT_EQ(global.rgba, tiles.rgba) << what;
            expect_same_counts(st_global, st, what);
            EXPECT_EQ(st_global.culled_transparent, st.culled_transparent) << what;
          }
        }
  }
  const Mesh wavy = test::wavy_grid(4, true);  // its sides bulge in and out
  const ProjectionRenderer r(wavy.view());
  ProjectionOptions o = test::with_method(ProjectionMethod::pt_linear);
  o.tile_orders = TileOrders::on;
  ProjectionStats st;
  r.render(test::field_values(wavy, "s"), tiles_tf(), cams[0], 40, 40, o, &st);
  EXPECT_FALSE(r.convex_boundary());
  EXPECT_FALSE(st.tile_orders);
  EXPECT_EQ(st.sort.method, SortMethod::mpvo_abuffer);
}

// A tile whose relations hold a visibility cycle hands the frame back to the sort of the whole
// mesh, which breaks it. The canonical tetrahedra of a box of hexahedra whose inner corners are
// moved (valid cells, a convex boundary) are not Delaunay, and MPVO meets cycles within a tile in
// more than 5 of these 20 views. `auto` never takes the tiles' orders on such a mesh.
TEST(Tiles, ATileWithAVisibilityCycleFallsBackToTheWholeOrder) {
  Mesh m = make_curvilinear(
      7, 7, 7,
      [](const glm::dvec3& u) {
        glm::dvec3 p = 2.0 * u - 1.0;
        const auto inside = [](double t) { return t > 1e-9 && t < 1 - 1e-9; };
        if (inside(u.x) && inside(u.y) && inside(u.z)) p += 0.1 * test::jitter(u);
        return p;
      },
      false);
  set_field(m, "s", [](const glm::dvec3& x) { return std::sin(2 * x.x) * std::cos(1.5 * x.y) + 0.4 * x.z; });
  const ValidationReport valid = validate(m.view());
  ASSERT_EQ(valid.inverted_cells + valid.degenerate_cells, 0);
  const ProjectionRenderer r(m.view(), Tetrahedralize::all);
  ASSERT_TRUE(r.convex_boundary());
  int fell_back = 0;
  for (const Camera& cam : test::sphere_views(10, 6.0, 4.5, 3.6, 45)) {
    ProjectionOptions o = test::with_method(ProjectionMethod::pt_linear);
    ProjectionStats global, tiles, automatic;
    tbb::task_arena(kTileOrdersFromThreads).execute([&] {
      r.render(test::field_values(m, "s"), tiles_tf(), cam, 48, 48, o, &automatic);
    });
    EXPECT_FALSE(automatic.tile_orders);
    o.tile_orders = TileOrders::off;
    const Image a = r.render(test::field_values(m, "s"), tiles_tf(), cam, 48, 48, o, &global);
    o.tile_orders = TileOrders::on;
    const Image b = r.render(test::field_values(m, "s"), tiles_tf(), cam, 48, 48, o, &tiles);
    if (tiles.tile_orders) continue;
    ++fell_back;
    EXPECT_FALSE(global.sort.cycles.empty());
    EXPECT_EQ(tiles.sort.cycles.size(), global.sort.cycles.size());
    EXPECT_EQ(a.rgba, b.rgba);
  }
  EXPECT_GT(fell_back, 5);
}

TEST(Tiles, BinsKeepTheOrderAndMeetEveryItemOnce) {
  // Items reaching rows [k, k + 3) of a 10-row image (clamped), tiles of 4 rows; item 5 covers no row.
  const auto rows_of = [](std::size_t k) {
    return k == 5 ? RowRange{7, 7} : RowRange{static_cast<int>(k), std::min(10, static_cast<int>(k) + 3)};
  };
  const TileBins bins = bin_to_tiles(10, 10, 4, rows_of);
  ASSERT_EQ(bins.first.size(), 4u);  // 3 tiles: rows 0-3, 4-7, 8-9
  const std::vector<std::size_t> tile0(bins.items.begin() + bins.first[0], bins.items.begin() + bins.first[1]);
  const std::vector<std::size_t> tile1(bins.items.begin() + bins.first[1], bins.items.begin() + bins.first[2]);
  const std::vector<std::size_t> tile2(bins.items.begin() + bins.first[2], bins.items.begin() + bins.first[3]);
  EXPECT_EQ(tile0, (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_EQ(tile1, (std::vector<std::size_t>{2, 3, 4, 5, 6, 7}));  // item 5 once, in its first row's tile
  EXPECT_EQ(tile2, (std::vector<std::size_t>{6, 7, 8, 9}));
}

TEST(Tiles, TileHeightIsAboutFourTilesPerThreadWithin16To64Rows) {
  EXPECT_EQ(tile_rows(1024, 2), 64);
  EXPECT_EQ(tile_rows(1024, 8), 32);
  EXPECT_EQ(tile_rows(1024, 64), 16);
  EXPECT_EQ(tile_rows(256, 2), 32);
  EXPECT_EQ(tile_rows(100, 4), 16);
}
