// Cell projection against the exact reference renderer and against invariants: pt-breakpoints
// equals `exact` (canonical tetrahedra) to float precision; uniform slabs render uniform whatever
// the view (no pixel skipped or composited twice); 1 and N threads give the same bits.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "frame/projection_renderer.hpp"
#include "projection/projected_tet.hpp"
#include "raycast/reference_renderer.hpp"
#include "render/names.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

using test::view_from;

Image project(const Mesh& m, const TransferFunction& tf, const Camera& c, int size, ProjectionMethod method,
              ProjectionStats* stats = nullptr, SortMethod sort = SortMethod::automatic) {
  return test::project(m, "", tf, c, size, test::with_method(method, sort), Tetrahedralize::problem, stats);
}

Image exact(const Mesh& m, const TransferFunction& tf, const Camera& c, int size) {
  return test::exact(m, "", tf, c, size, size, CellInterpolation::canonical_tets);
}

// A transfer function with a step, kinks and a wide range of extinction.
TransferFunction hard_tf() {
  return TransferFunction({{-1, {0.1, 0.2, 0.9}}, {0.0, {0.9, 0.9, 0.2}}, {0.0, {1, 0.3, 0.1}}, {1, {1, 1, 1}}},
                          {{-1, 0.2}, {-0.3, 3.0}, {0.2, 0.5}, {0.6, 6.0}, {1, 1.0}});
}

Mesh wavy_tets(int n) {
  Mesh m = make_box(n, n, n, glm::dvec3(-1), glm::dvec3(1), true);
  set_field(m, "s", [](const glm::dvec3& x) { return std::sin(2 * x.x) * std::cos(1.5 * x.y) + 0.4 * x.z; });
  return m;
}

}  // namespace

void expect_thick(const ProjectedTet& p, int hull_size, const ThickVertex& want) {
  ASSERT_EQ(p.hull_size, hull_size);
  const double got[6] = {p.thick.x, p.thick.y, p.thick.zf, p.thick.zb, p.thick.sf, p.thick.sb};
  const double exp[6] = {want.x, want.y, want.zf, want.zb, want.sf, want.sb};
  for (int k = 0; k < 6; ++k) EXPECT_DOUBLE_EQ(got[k], exp[k]) << "component " << k;
}

TEST(ProjectedTet, ClassesFromProjectedFaceSigns) {
  // Vertex 3 straight above the centroid of the base: class 1 with vertex 3 as the thick vertex,
  // its other end on the base (orthographic, looking down z).
  const ScreenVertex up[4] = {{0, 0, 5, 0}, {6, 0, 5, 0}, {0, 6, 5, 0}, {2, 2, 3, 1}};
  expect_thick(project_tet(up, false), 3, {2, 2, 3, 5, 1, 0});
  // Two crossing edges (0-1 at depth 1, 2-3 at depth 4): class 2, thick vertex at their crossing.
  const ScreenVertex cross[4] = {{0, 0, 1, 0}, {4, 4, 1, 2}, {4, 0, 4, 10}, {0, 4, 4, 20}};
  expect_thick(project_tet(cross, false), 4, {2, 2, 1, 4, 1, 15});
  // Degenerate: a vertex exactly on an edge's image, and all four on a line.
  const ScreenVertex on_edge[4] = {{0, 0, 5, 0}, {6, 0, 5, 0}, {0, 6, 5, 0}, {3, 0, 3, 1}};
  EXPECT_EQ(project_tet(on_edge, false).hull_size, 3);
  EXPECT_TRUE(project_tet(on_edge, false).edge_on);  // face 0-1-3 edge-on: drawn triangle by triangle
  EXPECT_FALSE(project_tet(up, false).edge_on || project_tet(cross, false).edge_on);
  const ScreenVertex line[4] = {{0, 0, 5, 0}, {1, 1, 4, 0}, {2, 2, 3, 0}, {3, 3, 2, 1}};
  EXPECT_EQ(project_tet(line, false).hull_size, 0);
}

TEST(ProjectedTet, TurnSignIsTheExactOrientation) {
  // turn_sign's filtered sign against CGAL's exact one (exact_orientation), and its area against
  // area2, bit for bit:
  // random triples, then nearly collinear ones (a third point on the line through two, moved by an
  // ulp or a few), at coordinates from 1e-300 to 1e300 (underflow and huge coordinates).
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int filtered = 0, near_line = 0;
  for (double scale : {1e-300, 1e-160, 1e-3, 1.0, 1e6, 1e150, 1e300})
    for (int t = 0; t < 2000; ++t) {
      const ScreenVertex a{scale * u(rng), scale * u(rng), 1, 0}, b{scale * u(rng), scale * u(rng), 1, 0};
      ScreenVertex c{scale * u(rng), scale * u(rng), 1, 0};
      if (t % 2) {  // on the line a-b to rounding, then nudged by up to 3 ulps
        const double s = u(rng);
        c.x = a.x + s * (b.x - a.x), c.y = a.y + s * (b.y - a.y);
        for (int k = t % 7; k > 3; --k) c.y = std::nextafter(c.y, t % 4 ? 1e308 : -1e308);
        ++near_line;
      }
      double area = 0;
      const int sign = turn_sign(a, b, c, area);
      ASSERT_EQ(sign, exact_orientation(a, b, c)) << "scale " << scale << " triple " << t;
      const double want = area2(a, b, c);
      ASSERT_TRUE(std::memcmp(&area, &want, sizeof area) == 0 || (std::isnan(area) && std::isnan(want)));
      filtered += std::abs(area) > 0;
    }
  EXPECT_GT(near_line, 5000);
  EXPECT_GT(filtered, 7000);
  const ScreenVertex p{0, 0, 1, 0}, q{1, 1, 1, 0}, r{2, 2, 1, 0};  // exactly collinear
  double area = 1;
  EXPECT_EQ(turn_sign(p, q, r, area), 0);
  EXPECT_EQ(area, 0.0);
}

TEST(Projection, BreakpointsEqualExactOrthographicAndPerspective) {
  const Mesh m = wavy_tets(5);
  const TransferFunction tf = hard_tf();
  for (Projection p : {Projection::Orthographic, Projection::Perspective})
    for (const glm::dvec3& eye : {glm::dvec3(0.3, -4, 2.5), glm::dvec3(-3, 1.2, -2)}) {
      const Camera c = view_from(eye, p);
      ProjectionStats st;
      const ImageDifference d =
          compare(project(m, tf, c, 96, ProjectionMethod::pt_breakpoints, &st), exact(m, tf, c, 96));
      EXPECT_LT(d.max_abs, 2e-5) << (p == Projection::Perspective ? "perspective" : "orthographic");
      EXPECT_LT(d.rmse, 2e-6);
      EXPECT_GT(st.counters.breakpoint_cells, 0);
      EXPECT_GT(st.counters.class1, 0);
      EXPECT_GT(st.counters.class2, 0);
    }
}

TEST(Projection, TheLadderOrdersByError) {
  // pt-breakpoints < pt-analytic < pt-table, pt-linear in error against exact (RMSE), on a field
  // that crosses the transfer function's breakpoints.
  const Mesh m = wavy_tets(6);
  const TransferFunction tf = hard_tf();
  const Camera c = view_from({1, -4, 2}, Projection::Perspective);
  const Image ref = exact(m, tf, c, 128);
  auto err = [&](ProjectionMethod method) { return compare(project(m, tf, c, 128, method), ref).rmse; };
  const double breakpoints = err(ProjectionMethod::pt_breakpoints), analytic = err(ProjectionMethod::pt_analytic);
  const double table = err(ProjectionMethod::pt_table), linear = err(ProjectionMethod::pt_linear);
  EXPECT_LT(breakpoints, 1e-6);
  EXPECT_LT(breakpoints * 100, analytic);
  EXPECT_LT(analytic, table);
  EXPECT_LT(analytic, linear);
}

TEST(Projection, AnalyticIsExactForAPiecewiseLinearFieldWithinOnePiece) {
  // No breakpoint inside any cell's range: pt-analytic is pt-breakpoints and both are exact.
  Mesh m = wavy_tets(4);
  const TransferFunction tf({{-5, {1, 0.2, 0}}, {5, {0, 0.4, 1}}}, {{-5, 0.1}, {5, 4.0}});
  const Camera c = view_from({2, -3, 1.5}, Projection::Perspective);
  ProjectionStats st;
  const Image img = project(m, tf, c, 80, ProjectionMethod::pt_analytic, &st);
  EXPECT_EQ(st.counters.breakpoint_cells, 0);
  EXPECT_LT(compare(img, exact(m, tf, c, 80)).max_abs, 2e-5);
}

TEST(Projection, UniformSlabHasNoSeams) {
  // A slab of 6 x 6 x 2 cubes (432 tetrahedra) with constant kappa: every pixel whose ray crosses
  // the whole slab gets exactly 1 - exp(-kappa * thickness): a skipped or doubled fragment would
  // show. Views: straight down (faces edge-on, vertices exactly on pixel centres) and oblique.
  Mesh m = make_box(6, 6, 2, {-1.125, -1.125, -0.25}, {1.125, 1.125, 0.25}, true);
  set_field(m, "s", [](const glm::dvec3&) { return 0.0; });
  const double kappa = 1.3;
  const TransferFunction tf = test::constant_tf(kappa, {0.2, 0.7, 0.4});
  // 36 pixels over 3 units: pixel centres at -1.5 + (i + 0.5) / 12 hit the vertices at multiples of 0.375.
  Camera down = view_from({0, 0, 5}, Projection::Orthographic, 3.0);
  down.up = {0, 1, 0};
  for (ProjectionMethod method : {ProjectionMethod::pt_analytic, ProjectionMethod::pt_breakpoints}) {
    ProjectionStats st;
    const Image img = project(m, tf, down, 36, method, &st);
    // The same pixel-cell pairs as the exact renderer's ray traversal, which counts every cell a
    // centre's ray crosses exactly once, rays along faces and edges included.
    ExactStats es;
    test::exact(m, "s", tf, down, 36, 36, CellInterpolation::canonical_tets, &es);
    EXPECT_EQ(st.counters.fragments, es.segments);
    int inside = 0;
    for (int j = 0; j < 36; ++j)
      for (int i = 0; i < 36; ++i) {
        const double x = -1.5 + (i + 0.5) / 12.0, y = 1.5 - (j + 0.5) / 12.0;
        if (std::abs(x) >= 1.125 || std::abs(y) >= 1.125) continue;  // edge and outside pixels
        ++inside;
        ASSERT_NEAR(img.pixel(i, j)[3], -std::expm1(-kappa * 0.5), 1e-6) << name_of(method) << " " << i << "," << j;
      }
    EXPECT_EQ(inside, 26 * 26);
  }
  // Oblique: against the exact renderer, pixel by pixel.
  const Camera oblique = view_from({1.1, -2.3, 3.7}, Projection::Perspective);
  EXPECT_LT(compare(project(m, tf, oblique, 64, ProjectionMethod::pt_analytic), exact(m, tf, oblique, 64)).max_abs,
            2e-6);
}

TEST(Projection, OneAndManyThreadsGiveTheSameBits) {
  const Mesh m = wavy_tets(6);
  const TransferFunction tf = hard_tf();
  const Camera c = view_from({0.5, -3, 2}, Projection::Perspective);
  for (ProjectionMethod method : {ProjectionMethod::pt_analytic, ProjectionMethod::pt_table})
    for (Compositing compositing : {Compositing::tiles, Compositing::stream}) {
      ProjectionOptions o;
      o.method = method;
      o.compositing = compositing;
      o.batch_cells = 64;  // the stream: many tokens in flight
      const ProjectionRenderer r(m.view());
      const double* s = test::field_values(m, "s");
      Image one, many;
      tbb::task_arena(1).execute([&] { one = r.render(s, tf, c, 100, 100, o); });
      tbb::task_arena(4).execute([&] { many = r.render(s, tf, c, 100, 100, o); });
      ASSERT_EQ(one.rgba.size(), many.rgba.size());
      EXPECT_EQ(one.rgba, many.rgba) << name_of(method);
    }
}

TEST(Projection, HexahedraAreSplitCanonically) {
  // A curvilinear hexahedral grid: projected through its canonical tetrahedra (--tetrahedralize
  // all), it matches the exact renderer in canonical-tets mode.
  Mesh m = test::wavy_grid(4, false);
  set_field(m, "s", [](const glm::dvec3& x) { return x.x * x.y + 0.5 * x.z; });
  const TransferFunction tf = hard_tf();
  const Camera c = view_from({2.5, -2, 1.8}, Projection::Perspective);
  ProjectionStats st;
  const Image img = test::project(m, "s", tf, c, 80, {}, Tetrahedralize::all, &st);
  EXPECT_EQ(st.cells_split, 64);
  EXPECT_EQ(st.tets, 64 * 6);
  EXPECT_LT(compare(img, exact(m, tf, c, 80)).max_abs, 2e-5);
}

TEST(Projection, ConvexLinearSceneModelsNothingExtra) {
  // A convex tetrahedral mesh under a linear transfer function: no cell split, no breakpoint cut,
  // no gap relation (the sort `auto` picks plain MPVO).
  Mesh m = make_box(4, 4, 4, glm::dvec3(-1), glm::dvec3(1), true);
  set_field(m, "s", [](const glm::dvec3& x) { return x.x + x.y; });
  const TransferFunction tf({{-2, {0, 0, 1}}, {2, {1, 0, 0}}}, {{-2, 0.5}, {2, 2.0}});
  ProjectionStats st;
  project(m, tf, view_from({1, -3, 2}, Projection::Perspective), 64, ProjectionMethod::pt_breakpoints, &st);
  EXPECT_EQ(st.cells_split, 0);
  EXPECT_EQ(st.counters.breakpoint_cells, 0);
  EXPECT_EQ(st.sort.gap_relations, 0);
  EXPECT_EQ(st.sort.method, SortMethod::mpvo);
}

TEST(Projection, NonConvexMeshNeedsTheGapRelations) {
  // The swirl ring (non-convex): with mpvo-abuffer the picture equals exact from every view; plain
  // MPVO, blind to the gaps, is visibly wrong from some.
  Mesh m = generate("swirl-tets", 6);
  const TransferFunction tf = hard_tf();
  const auto [lo, hi] = std::minmax_element(m.fields[0].values.begin(), m.fields[0].values.end());
  const double s0 = *lo, s1 = *hi;
  for (double& v : m.fields[0].values) v = 2 * (v - s0) / (s1 - s0) - 1;
  double worst_mpvo = 0.0;
  for (const glm::dvec3& d : sphere_directions(6)) {
    Camera c = view_from(3.5 * d, Projection::Perspective);
    c.fov_y = 50;
    ProjectionStats st;
    const Image ref = exact(m, tf, c, 64);
    EXPECT_LT(compare(project(m, tf, c, 64, ProjectionMethod::pt_breakpoints, &st), ref).max_abs, 2e-5);
    EXPECT_EQ(st.sort.method, SortMethod::mpvo_abuffer);
    const Image plain = project(m, tf, c, 64, ProjectionMethod::pt_breakpoints, nullptr, SortMethod::mpvo);
    worst_mpvo = std::max(worst_mpvo, compare(plain, ref).max_abs);
  }
  EXPECT_GT(worst_mpvo, 1e-2);
}

TEST(Projection, SliversAndTinyCellsStayFinite) {
  // Cells far smaller than a pixel, and a sliver of relative volume 1e-12: no NaN, and the fine
  // mesh's total opacity matches a coarse mesh of the same (linear) field.
  const TransferFunction tf({{0, {1, 0.5, 0}}, {1, {0, 0.5, 1}}}, {{0, 1.0}, {1, 3.0}});
  auto linear = [](const glm::dvec3& x) { return 0.5 + 0.25 * (x.x + x.z); };
  Mesh fine = make_box(24, 24, 24, glm::dvec3(-1), glm::dvec3(1), true);
  Mesh coarse = make_box(2, 2, 2, glm::dvec3(-1), glm::dvec3(1), true);
  set_field(fine, "s", linear);
  set_field(coarse, "s", linear);
  const Camera c = view_from({1.3, -2.1, 1.7}, Projection::Orthographic, 4.0);
  const Image a = project(fine, tf, c, 16, ProjectionMethod::pt_analytic);  // ~ 20 cells per pixel width
  const Image b = project(coarse, tf, c, 16, ProjectionMethod::pt_analytic);
  for (float v : a.rgba) ASSERT_TRUE(std::isfinite(v));
  EXPECT_LT(compare(a, b).max_abs, 2e-5);

  Mesh sliver;
  for (const glm::dvec3& p :
       {glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0.3, 0.3, 1e-12)})
    sliver.add_point(p);
  sliver.add_cell(CellType::Tetra, {0, 1, 2, 3});
  set_field(sliver, "s", [](const glm::dvec3& x) { return x.x; });
  for (const glm::dvec3& eye : {glm::dvec3(0.2, 0.1, 3), glm::dvec3(3, 0.2, 0.0), glm::dvec3(1, 1, 1)}) {
    const Image img = project(sliver, tf, view_from(eye, Projection::Perspective), 32, ProjectionMethod::pt_analytic);
    for (float v : img.rgba) ASSERT_TRUE(std::isfinite(v));
    for (std::size_t k = 3; k < img.rgba.size(); k += 4) ASSERT_LT(img.rgba[k], 1e-6);  // thickness <= 1e-12
  }
}

TEST(Projection, HugeCoordinateOffsetChangesNothing) {
  // Cells of size 1e-3 at 1e6 from the origin render as they do at the origin (points recentred).
  // Extinction per unit length scaled to the cells' size.
  const TransferFunction tf(hard_tf().color_points(), {{-1, 200}, {-0.3, 3000}, {0.2, 500}, {0.6, 6000}, {1, 1000}});
  auto cube = [](const glm::dvec3& shift) {
    Mesh m = make_box(4, 4, 4, shift - glm::dvec3(2e-3), shift + glm::dvec3(2e-3), true);
    set_field(m, "s", [&](const glm::dvec3& x) { return std::sin(1e3 * (x.x - shift.x)) + 500 * (x.z - shift.z); });
    return m;
  };
  const glm::dvec3 far(1e6, -1e6, 1e6);
  auto camera = [](const glm::dvec3& target) {
    Camera c;
    c.projection = Projection::Perspective;
    c.eye = target + glm::dvec3(5e-3, -7e-3, 6e-3);
    c.target = target;
    c.up = {0, 0, 1};
    c.fov_y = 45;
    return c;
  };
  const Image near_img = project(cube(glm::dvec3(0)), tf, camera(glm::dvec3(0)), 64, ProjectionMethod::pt_breakpoints);
  const Image far_img = project(cube(far), tf, camera(far), 64, ProjectionMethod::pt_breakpoints);
  double total = 0;
  for (std::size_t k = 3; k < near_img.rgba.size(); k += 4) total += near_img.rgba[k];
  EXPECT_GT(total, 100.0);  // the picture is not empty
  EXPECT_LT(compare(near_img, far_img).max_abs, 1e-4);
}

TEST(Projection, StepAndSteepTransferFunctionsStayExact) {
  // Extinction jumping from 0 to 800 over 1e-6 of the scalar, and a colour step: pt-breakpoints
  // still equals exact; the sliver of the field between the two control points is cut, not smeared.
  const Mesh m = wavy_tets(5);
  const TransferFunction tf({{-2, {0.1, 0.1, 1}}, {0.1, {0.1, 0.1, 1}}, {0.1, {1, 0.5, 0}}, {2, {1, 1, 0}}},
                            {{-2, 0.0}, {0.3, 0.0}, {0.300001, 800.0}, {0.5, 800.0}, {0.5, 0.2}, {2, 0.2}});
  for (Projection p : {Projection::Orthographic, Projection::Perspective}) {
    const Camera c = view_from({1.2, -3.1, 2.4}, p);
    const Image img = project(m, tf, c, 80, ProjectionMethod::pt_breakpoints);
    for (float v : img.rgba) ASSERT_TRUE(std::isfinite(v));
    EXPECT_LT(compare(img, exact(m, tf, c, 80)).max_abs, 2e-5);
  }
}

TEST(Projection, CameraInsideTheMeshRayCastsTheCellsAroundTheEye) {
  // The eye inside the mesh: the cells reaching behind it are ray cast from the eye, the rest
  // projected; together they equal the exact renderer.
  const Mesh m = wavy_tets(6);
  const TransferFunction tf = hard_tf();
  const Camera c = test::inside_wavy_grid(Projection::Perspective);
  ProjectionStats st;
  const Image img = project(m, tf, c, 72, ProjectionMethod::pt_breakpoints, &st);
  EXPECT_GT(st.counters.behind_eye, 0);
  EXPECT_LT(compare(img, exact(m, tf, c, 72)).max_abs, 2e-5);
}

TEST(Projection, HugeCellsAreCompositedDirectlyInOrder) {
  // At 1200^2 each of these 48 tetrahedra covers more than 1M pixels of bounding box, so the
  // stream's compositor draws them itself instead of buffering their fragments: still exact, still
  // the same bits from any number of threads, and as the tiles draw them.
  Mesh m = make_box(2, 2, 2, glm::dvec3(-1), glm::dvec3(1), true);
  set_field(m, "s", [](const glm::dvec3& x) { return 0.5 * x.x + 0.3 * x.y * x.y - 0.2 * x.z; });
  const TransferFunction tf = hard_tf();
  const Camera c = view_from({0.9, -1.7, 1.2}, Projection::Perspective);  // close: the box fills the image
  ProjectionOptions o;
  o.method = ProjectionMethod::pt_breakpoints;
  o.compositing = Compositing::stream;
  const ProjectionRenderer r(m.view());
  const double* s = test::field_values(m, "s");
  Image one, many, tiles;
  ProjectionStats st;
  tbb::task_arena(1).execute([&] { one = r.render(s, tf, c, 1200, 1200, o, &st); });
  tbb::task_arena(3).execute([&] { many = r.render(s, tf, c, 1200, 1200, o); });
  o.compositing = Compositing::tiles;
  tbb::task_arena(3).execute([&] { tiles = r.render(s, tf, c, 1200, 1200, o); });
  EXPECT_GT(st.counters.direct_cells, 0);
  EXPECT_LT(st.counters.direct_cells, st.tets);  // and the others buffered, interleaved in order
  EXPECT_EQ(one.rgba, many.rgba);
  EXPECT_EQ(one.rgba, tiles.rgba);
  EXPECT_LT(compare(one, exact(m, tf, c, 1200)).max_abs, 2e-5);
}
