// Whole-cell projection of hexahedra, wedges and pyramids (image-plane subdivision) and the
// view-dependent splitting of problem cells, against the exact renderer. The folds that make a
// problem cell: test_folds.cpp; sorting split meshes: test_split_sorting.cpp.
// For a field affine in space every interpolation agrees (canonical tetrahedra, isoparametric,
// linear along each ray segment), so there the projection must equal `exact` to float precision:
// any wrong polygon, thick vertex, missed or doubled pixel, or wrong order shows.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "frame/projection_renderer.hpp"
#include "io/read_mesh.hpp"
#include "mesh/face_split.hpp"
#include "mesh/split_topology.hpp"
#include "mesh/tetrahedralize.hpp"
#include "projection/projected_cell.hpp"
#include "raycast/order_oracle.hpp"
#include "raycast/reference_renderer.hpp"
#include "render/names.hpp"
#include "test_util.hpp"
#include "view/screen.hpp"
#include "visibility/split_sorter.hpp"

using namespace cellproj;

namespace {

using test::twisted_mixed;
using test::warped_hexahedra;

void affine_field(Mesh& m) {
  set_field(m, "s", [](const glm::dvec3& x) { return 0.35 * x.x - 0.25 * x.y + 0.3 * x.z + 0.4; });
}

TransferFunction tf() {  // breakpoints inside cells, a wide range of extinction
  return TransferFunction({{-0.3, {0.1, 0.2, 0.9}}, {0.4, {0.9, 0.9, 0.2}}, {1.1, {1, 0.2, 0.1}}},
                          {{-0.3, 0.3}, {0.2, 3.0}, {0.5, 0.6}, {1.1, 4.0}});
}

using test::perspective;

Image project(const Mesh& m, const std::string& field, const Camera& c, int size, Tetrahedralize mode,
              ProjectionStats* st = nullptr) {
  return test::project(m, field, tf(), c, size, test::with_method(ProjectionMethod::pt_breakpoints), mode, st);
}

}  // namespace

TEST(Polyhedra, ACubeIsOneHexagonOfPolygonsAndExact) {
  // One cube seen obliquely: three faces in front, three behind. pt-breakpoints draws them as two
  // layers, every pixel's segment exact and every front pixel meeting its back; the Gouraud
  // methods subdivide the hexagon into front ∩ back polygons.
  Mesh m = make_box(1, 1, 1, glm::dvec3(-1), glm::dvec3(1), false);
  affine_field(m);
  for (const Camera& c : test::views_of_unit_mesh(3)) {
    ProjectionStats st;
    const Image img = project(m, "s", c, 64, Tetrahedralize::problem, &st);
    EXPECT_EQ(st.counters.polyhedra, 1);
    EXPECT_EQ(st.counters.layered, 1);
    EXPECT_EQ(st.counters.unmatched, 0);
    EXPECT_EQ(st.tets, 0);
    const Image ref = test::exact(m, "s", tf(), c, 64, 64, CellInterpolation::isoparametric);
    EXPECT_LT(compare(img, ref).max_abs, 2e-5);
    // At 64² the cube's image box is over kLayersUpToPixels: `automatic` subdivides it too.
    for (WholeCells whole : {WholeCells::automatic, WholeCells::polygons}) {
      ProjectionStats linear;
      ProjectionOptions o = test::with_method(ProjectionMethod::pt_linear);
      o.whole_cells = whole;
      test::project(m, "s", tf(), c, 64, o, Tetrahedralize::problem, &linear);
      EXPECT_GE(linear.counters.polygons, 3);
      EXPECT_EQ(linear.counters.layered, 0);
    }
  }
}

// pt-linear and pt-table on a whole cell by its layers: each pixel is a thick vertex (MWSC section
// 2), its segment's length and end scalars from the cell's front and back faces. On a cube with an
// affine field that is exactly opacity 1 - exp(-l (kappa(s_front) + kappa(s_back)) / 2) and the mean
// of the ends' colours at every pixel, here against each pixel's ray clipped to the cube. The
// polygons of the image-plane subdivision interpolate those values instead, and differ.
TEST(Polyhedra, LayersGiveEachPixelItsOwnThickVertex) {
  Mesh m = make_box(1, 1, 1, glm::dvec3(-1), glm::dvec3(1), false);
  affine_field(m);
  const auto s = [](const glm::dvec3& x) { return 0.35 * x.x - 0.25 * x.y + 0.3 * x.z + 0.4; };
  const TransferFunction linear_tf({{-1, {0.1, 0.3, 0.9}}, {2, {1, 0.6, 0.2}}}, {{-1, 0.2}, {2, 2.5}});
  const int size = 48;
  for (const TransferFunction& f : {tf(), linear_tf})  // breakpoints inside the cell, and none
    for (const Camera& c : {test::view_from({2.2, 1.3, 3.1}, Projection::Orthographic),
                            test::perspective({2.6, -1.9, 2.3}, {0, 0, 0}, 70)}) {
      const PixelRays rays(c, size, size);
      double worst[2] = {0, 0}, subdivision = 0;
      for (ProjectionMethod method : {ProjectionMethod::pt_linear, ProjectionMethod::pt_table}) {
        ProjectionOptions o = test::with_method(method);
        o.whole_cells = WholeCells::layers;
        ProjectionStats st;
        const Image img = test::project(m, "s", f, c, size, o, Tetrahedralize::problem, &st);
        EXPECT_EQ(st.counters.layered, 1);
        EXPECT_EQ(st.counters.polygons, 0);
        o.whole_cells = WholeCells::polygons;
        const Image polygons = test::project(m, "s", f, c, size, o);
        for (int j = 0; j < size; ++j)
          for (int i = 0; i < size; ++i) {
            const Ray r = rays.ray(i + 0.5, j + 0.5);
            double t0 = 0, t1 = std::numeric_limits<double>::infinity();  // the ray in the cube (slabs)
            for (int a = 0; a < 3; ++a) {
              const double u = (-1 - r.origin[a]) / r.dir[a], v = (1 - r.origin[a]) / r.dir[a];
              t0 = std::max(t0, std::min(u, v)), t1 = std::min(t1, std::max(u, v));
            }
            float want[4] = {0, 0, 0, 0};
            if (t1 > t0) {
              const double sf = s(r.origin + t0 * r.dir), sb = s(r.origin + t1 * r.dir);
              const double alpha = -std::expm1(-(t1 - t0) * 0.5 * (f.extinction(sf) + f.extinction(sb)));
              const glm::dvec3 rgb = 0.5 * (f.color(sf) + f.color(sb)) * alpha;
              want[0] = float(rgb.r), want[1] = float(rgb.g), want[2] = float(rgb.b), want[3] = float(alpha);
            }
            const std::size_t at = 4 * (static_cast<std::size_t>(j) * size + i);
            for (int k = 0; k < 4; ++k) {
              const int m_index = method == ProjectionMethod::pt_table;
              worst[m_index] = std::max(worst[m_index], double(std::abs(img.rgba[at + k] - want[k])));
              if (method == ProjectionMethod::pt_linear)
                subdivision = std::max(subdivision, double(std::abs(polygons.rgba[at + k] - want[k])));
            }
          }
      }
      EXPECT_LT(worst[0], 1e-6) << "pt-linear";
      // pt-table's table, bilinear on 256² nodes over kappa in [0, 4] and l in [0, 2√3]: up to
      // (Δκ² l² + Δl² κ²) / 8 ≈ 4e-4 for 1 - exp(-κ l).
      EXPECT_LT(worst[1], 5e-4) << "pt-table";
      EXPECT_GT(subdivision, 1e-3) << "the subdivision's polygons interpolate, and this view must show it";
    }
}

// The OpenGL back ends draw whole cells as polygons only: asking them for layers is refused before a
// frame, from the library as from the command line.
TEST(Polyhedra, OpenGLRefusesWholeCellsByLayers) {
  ProjectionOptions o = test::with_method(ProjectionMethod::pt_linear);
  o.backend = Backend::opengl;
  for (WholeCells whole : {WholeCells::automatic, WholeCells::polygons}) {
    o.whole_cells = whole;
    EXPECT_NO_THROW(check_options(o));
  }
  o.whole_cells = WholeCells::layers;
  EXPECT_THROW(check_options(o), InputError);
  o.backend = Backend::software;
  EXPECT_NO_THROW(check_options(o));
}

TEST(Polyhedra, WarpedGridsMatchExactAndSplitOnlyProblemCells) {
  for (int kind = 0; kind < 2; ++kind) {
    Mesh m = kind == 0 ? warped_hexahedra(6) : twisted_mixed(4);
    affine_field(m);
    std::int64_t problem_views = 0;
    for (const Camera& c : test::views_of_unit_mesh(4)) {
      ProjectionStats st;
      const Image img = project(m, "s", c, 72, Tetrahedralize::problem, &st);
      const Image ref = test::exact(m, "s", tf(), c, 72, 72, CellInterpolation::canonical_tets);
      // A pixel centre on an edge seen edge-on may differ by a few 1e-4 (as with every cell split: the
      // tracer and the coverage rule break the tie differently); everywhere else float precision.
      const ImageDifference d = compare(img, ref);
      EXPECT_LT(d.max_abs, 1e-3) << "mesh " << kind << " eye " << c.eye.x << " " << c.eye.y << " " << c.eye.z;
      EXPECT_LT(d.rmse, 2e-5) << "mesh " << kind << " eye " << c.eye.x << " " << c.eye.y << " " << c.eye.z;
      EXPECT_EQ(st.cells_split, st.problem_cells + st.cycle_splits);
      EXPECT_EQ(st.counters.unmatched, 0);           // the front and back layers cover the same centres
      EXPECT_LT(st.problem_cells, m.n_cells() / 2);  // a heavily warped grid: up to a third in perspective
      EXPECT_TRUE(st.sort.cycles.empty());
      problem_views += st.problem_cells > 0;
    }
    EXPECT_GT(problem_views, 0) << "the test meshes must have folded faces in some view";
  }
}

TEST(Polyhedra, WholeCellsWhereFacesFoldAreWrong) {
  // --tetrahedralize none projects problem cells whole: the error the split removes.
  Mesh m = warped_hexahedra(6);
  affine_field(m);
  double worst_none = 0, worst_problem = 0;
  for (const Camera& c : test::views_of_unit_mesh(4)) {
    ProjectionStats st;
    const Image none = project(m, "s", c, 72, Tetrahedralize::none, &st);
    if (st.problem_cells == 0) continue;
    const Image ref = test::exact(m, "s", tf(), c, 72, 72, CellInterpolation::canonical_tets);
    worst_none = std::max(worst_none, compare(none, ref).max_abs);
    worst_problem = std::max(worst_problem, compare(project(m, "s", c, 72, Tetrahedralize::problem), ref).max_abs);
  }
  EXPECT_GT(worst_none, 20 * worst_problem);
}

// Two blocks with their interface points repeated render as the mesh stored with each point
// once: the seam is glued (mesh/seams.cpp), so the order, the problem cells split and the picture
// are the same, whether the sort is auto or asked for.
TEST(Polyhedra, SeamedMeshRendersAsIfStoredWhole) {
  Mesh whole = twisted_mixed(4);
  affine_field(whole);
  Mesh seamed = test::with_seam(whole, 0.0);
  for (const Camera& c : test::views_of_unit_mesh(2)) {
    ProjectionStats a, b;
    const Image wi = project(whole, "s", c, 64, Tetrahedralize::problem, &a);
    const Image si = project(seamed, "s", c, 64, Tetrahedralize::problem, &b);
    EXPECT_EQ(si.rgba, wi.rgba);
    EXPECT_EQ(b.sort.gap_relations, a.sort.gap_relations);
    EXPECT_EQ(b.cells_split, a.cells_split);
  }
}

TEST(Polyhedra, OneAndManyThreadsGiveTheSameBits) {
  Mesh m = twisted_mixed(4);
  affine_field(m);
  const ProjectionRenderer r(m.view());
  const double* s = test::field_values(m, "s");
  const Camera c = test::views_of_unit_mesh(2).back();
  ProjectionOptions o;
  o.batch_cells = 16;
  Image one, many;
  tbb::task_arena(1).execute([&] { one = r.render(s, tf(), c, 80, 80, o); });
  tbb::task_arena(4).execute([&] { many = r.render(s, tf(), c, 80, 80, o); });
  EXPECT_EQ(one.rgba, many.rgba);
}

TEST(Polyhedra, ExodusHexahedraMatchExact) {
  // disk_out_ref.ex2 (Exodus II, 7,472 hexahedra, non-convex, warped faces) under an affine field:
  // equal to exact. Under its own Temp field, whole cells are at least as close to the
  // isoparametric field as the canonical tetrahedra are.
  const std::string path = test::shared_data("exodus_disk_out_ref/disk_out_ref.ex2");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path;
  Mesh m = read_mesh(path);
  const Camera c = perspective({24, -30, 14}, {0, 0, 0}, 40);
  set_field(m, "affine", [](const glm::dvec3& x) { return 0.03 * x.x - 0.02 * x.y + 0.04 * x.z + 0.4; });
  const Image img = project(m, "affine", c, 96, Tetrahedralize::problem);
  EXPECT_LT(compare(img, test::exact(m, "affine", tf(), c, 96, 96, CellInterpolation::canonical_tets)).max_abs, 5e-5);
  const TransferFunction temp({{293, {0.1, 0.2, 0.9}}, {600, {0.9, 0.9, 0.2}}, {913, {1, 0.2, 0.1}}},
                              {{293, 0.02}, {500, 0.3}, {913, 0.1}});
  const Image iso = test::exact(m, "Temp", temp, c, 96, 96, CellInterpolation::isoparametric);
  const double whole = compare(test::project(m, "Temp", temp, c, 96, {}, Tetrahedralize::problem), iso).rmse;
  const double tets = compare(test::project(m, "Temp", temp, c, 96, {}, Tetrahedralize::all), iso).rmse;
  EXPECT_LE(whole, 1.05 * tets);
  EXPECT_LT(whole, 0.02);
}

TEST(Polyhedra, LookedUpSubdivisionsGiveTheGeneralPathsBits) {
  // The fast path reuses the subdivision of an earlier cell with the same projection topology:
  // triangle for triangle, bit for bit what the general path makes. On a structured grid most
  // cells are looked up.
  for (int kind = 0; kind < 2; ++kind) {
    Mesh m = kind == 0 ? warped_hexahedra(6) : generate("swirl", 6);
    affine_field(m);
    const MeshView mesh = m.view();
    const RecentredPoints pts = recentre(mesh);
    for (const Camera& c : test::views_of_unit_mesh(2)) {
      const PixelRays rays(recentred(c, pts.centre), 200, 200);
      const ScreenPoints screen = project_points(pts, test::field_values(m, "s"), rays);
      SubdivisionCache cache;
      std::int64_t cells = 0;
      for (std::int64_t cell = 0; cell < mesh.n_cells; ++cell) {
        ScreenVertex v[8];
        for (int k = 0; k < 8; ++k) v[k] = screen.v[static_cast<std::size_t>(mesh.cell(cell)[k])];
        if (rays.perspective() && std::any_of(v, v + 8, [](const ScreenVertex& x) { return !(x.z > 0); })) continue;
        std::vector<ProjectedTriangle> general, fast;
        project_cell(v, mesh.cell(cell), mesh.type(cell), rays.perspective(), 1, general);
        project_cell(v, mesh.cell(cell), mesh.type(cell), rays.perspective(), 1, fast, &cache);
        ASSERT_EQ(general.size(), fast.size()) << "cell " << cell;
        EXPECT_EQ(std::memcmp(general.data(), fast.data(), general.size() * sizeof(ProjectedTriangle)), 0)
            << "cell " << cell;
        ++cells;
      }
      EXPECT_EQ(cache.hits + cache.misses, cells);
      if (kind == 1) EXPECT_GT(cache.hits, cells / 2) << "a structured grid repeats its projection topologies";
    }
  }
}

TEST(Polyhedra, CameraInsideAWarpedGridRayCastsTheSplitCellsAroundTheEye) {
  // Cells reaching behind the eye are problem cells: split, and their tetrahedra ray cast.
  Mesh m = warped_hexahedra(5);
  affine_field(m);
  const Camera c = perspective({0.05, -0.1, 0.02}, {0.6, 0.9, 0.3}, 70);
  ProjectionStats st;
  const Image img = project(m, "s", c, 64, Tetrahedralize::problem, &st);
  EXPECT_GT(st.counters.behind_eye, 0);
  EXPECT_GT(st.cells_split, 0);
  const Image ref = test::exact(m, "s", tf(), c, 64, 64, CellInterpolation::canonical_tets);
  const ImageDifference d = compare(img, ref);
  EXPECT_LT(d.rmse, 2e-5);
  EXPECT_LT(d.max_abs, 1e-3);
}
