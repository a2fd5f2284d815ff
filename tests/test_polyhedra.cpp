// Whole-cell projection of hexahedra, wedges and pyramids (image-plane subdivision) and the
// view-dependent splitting of problem cells, against the exact renderer and the order oracle.
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

#include "grid/face_split.hpp"
#include "grid/read_mesh.hpp"
#include "grid/split_topology.hpp"
#include "grid/tetrahedralize.hpp"
#include "parallel/projection_renderer.hpp"
#include "projection/projected_cell.hpp"
#include "view/screen.hpp"
#include "raycast/order_oracle.hpp"
#include "raycast/reference_renderer.hpp"
#include "scene/names.hpp"
#include "test_util.hpp"
#include "visibility/split_sorter.hpp"

using namespace cellproj;

namespace {

// A deterministic jitter in [-1, 1]^3 per grid point.
glm::dvec3 jitter(const glm::dvec3& u) {
  auto h = [](double x) { const double s = std::sin(x) * 43758.5453; return 2.0 * (s - std::floor(s)) - 1.0; };
  return {h(12.9898 * u.x + 78.233 * u.y + 37.719 * u.z), h(39.3468 * u.x + 11.135 * u.y + 83.155 * u.z),
          h(73.156 * u.x + 52.235 * u.y + 9.151 * u.z)};
}

// A twisted, jittered curvilinear grid of n^3 hexahedra: strongly warped faces, a non-convex boundary.
Mesh warped_hexahedra(int n) {
  const double cell = 2.0 / n;
  Mesh m = make_curvilinear(n, n, n, [cell](const glm::dvec3& u) {
    const double a = 1.2 * (u.z - 0.5);
    const glm::dvec3 p(2 * u.x - 1, 2 * u.y - 1, 2 * u.z - 1);
    return glm::dvec3(std::cos(a) * p.x - std::sin(a) * p.y, std::sin(a) * p.x + std::cos(a) * p.y, p.z) +
           0.15 * cell * jitter(u);
  }, false);
  return m;
}

Mesh twisted_mixed(int n) {
  return make_mixed(n, n, n, [](const glm::dvec3& u) {
    const double a = 1.0 * (u.z - 0.5);
    const glm::dvec3 p(2 * u.x - 1, 2 * u.y - 1, 2 * u.z - 1);
    return glm::dvec3(std::cos(a) * p.x - std::sin(a) * p.y, std::sin(a) * p.x + std::cos(a) * p.y, p.z + 0.1 * p.x * p.y);
  });
}

void affine_field(Mesh& m) {
  set_field(m, "s", [](const glm::dvec3& x) { return 0.35 * x.x - 0.25 * x.y + 0.3 * x.z + 0.4; });
}

TransferFunction tf() {  // breakpoints inside cells, a wide range of extinction
  return TransferFunction({{-0.3, {0.1, 0.2, 0.9}}, {0.4, {0.9, 0.9, 0.2}}, {1.1, {1, 0.2, 0.1}}},
                          {{-0.3, 0.3}, {0.2, 3.0}, {0.5, 0.6}, {1.1, 4.0}});
}

std::vector<Camera> views(int n) { return test::sphere_views(n, 6.0, 4.5, 3.6, 45); }

using test::perspective;

Image project(const Mesh& m, const std::string& field, const Camera& c, int size, Tetrahedralize mode,
              ProjectionStats* st = nullptr) {
  return test::project(m, field, tf(), c, size, test::with_method(ProjectionMethod::pt_breakpoints), mode, st);
}

}  // namespace

TEST(Polyhedra, ACubeIsOneHexagonOfPolygonsAndExact) {
  // One cube seen obliquely: three faces in front, three behind, every pixel's segment exact.
  Mesh m = make_box(1, 1, 1, glm::dvec3(-1), glm::dvec3(1), false);
  affine_field(m);
  for (const Camera& c : views(3)) {
    ProjectionStats st;
    const Image img = project(m, "s", c, 64, Tetrahedralize::problem, &st);
    EXPECT_EQ(st.counters.polyhedra, 1);
    EXPECT_EQ(st.tets, 0);
    EXPECT_GE(st.counters.polygons, 3);
    const Image ref = test::exact(m, "s", tf(), c, 64, 64, CellInterpolation::isoparametric);
    EXPECT_LT(compare(img, ref).max_abs, 2e-5);
  }
}

TEST(Polyhedra, WarpedGridsMatchExactAndSplitOnlyProblemCells) {
  for (int kind = 0; kind < 2; ++kind) {
    Mesh m = kind == 0 ? warped_hexahedra(6) : twisted_mixed(4);
    affine_field(m);
    std::int64_t problem_views = 0;
    for (const Camera& c : views(4)) {
      ProjectionStats st;
      const Image img = project(m, "s", c, 72, Tetrahedralize::problem, &st);
      const Image ref = test::exact(m, "s", tf(), c, 72, 72, CellInterpolation::canonical_tets);
      // A pixel centre on an edge seen edge-on may differ by a few 1e-4 (as with every cell split: the
      // tracer and the coverage rule break the tie differently); everywhere else float precision.
      const ImageDifference d = compare(img, ref);
      EXPECT_LT(d.max_abs, 1e-3) << "mesh " << kind << " eye " << c.eye.x << " " << c.eye.y << " " << c.eye.z;
      EXPECT_LT(d.rmse, 2e-5) << "mesh " << kind << " eye " << c.eye.x << " " << c.eye.y << " " << c.eye.z;
      EXPECT_EQ(st.cells_split, st.problem_cells + st.cycle_splits);
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
  for (const Camera& c : views(4)) {
    ProjectionStats st;
    const Image none = project(m, "s", c, 72, Tetrahedralize::none, &st);
    if (st.problem_cells == 0) continue;
    const Image ref = test::exact(m, "s", tf(), c, 72, 72, CellInterpolation::canonical_tets);
    worst_none = std::max(worst_none, compare(none, ref).max_abs);
    worst_problem = std::max(worst_problem, compare(project(m, "s", c, 72, Tetrahedralize::problem), ref).max_abs);
  }
  EXPECT_GT(worst_none, 20 * worst_problem);
}

// Both exact sorts on meshes whose warped hexahedra stay whole where they do not fold: pairwise
// tests occlusion on the cells' surface triangles (a warped quad's two), not on one plane a face.
TEST(Polyhedra, SplittingSorterHasNoOrderViolations) {
  for (int kind = 0; kind < 2; ++kind) {
    Mesh m = kind == 0 ? warped_hexahedra(5) : twisted_mixed(4);
    const SplittingSorter sorter(m.view(), Tetrahedralize::problem);
    for (const SortMethod method : {SortMethod::mpvo_abuffer, SortMethod::pairwise})
      for (const Camera& c : views(4)) {
        const ViewOrder v = sorter.sort(method, {c, 64, 64});
        const MeshView& cells = v.mesh->cells;
        ASSERT_EQ(static_cast<std::int64_t>(v.sorted.order.size()), cells.n_cells);
        const CellRayTracer tracer(cells);
        const OrderCheck k = check_order(tracer, cells.n_cells, v.sorted.order, c, 64, 64);
        EXPECT_EQ(k.violations, 0) << "mesh " << kind << ", " << name_of(method) << ", " << v.problem_cells << " problem cells";
        EXPECT_EQ(k.missing_cells + k.repeated_cells, 0);
      }
  }
}

// Two blocks with their interface points repeated render as the mesh stored with each point
// once: the seam is glued (grid/seams.cpp), so the order, the problem cells split and the picture
// are the same, whether the sort is auto or asked for.
TEST(Polyhedra, SeamedMeshRendersAsIfStoredWhole) {
  Mesh whole = twisted_mixed(4);
  affine_field(whole);
  Mesh seamed = test::with_seam(whole, 0.0);
  for (const Camera& c : views(2)) {
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
  const Camera c = views(2).back();
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
  EXPECT_LT(compare(img, test::exact(m, "affine", tf(), c, 96, 96, CellInterpolation::canonical_tets)).max_abs,
            5e-5);
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
    for (const Camera& c : views(2)) {
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
        EXPECT_EQ(std::memcmp(general.data(), fast.data(), general.size() * sizeof(ProjectedTriangle)), 0) << "cell " << cell;
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

namespace {

// Problem cells by their definition, one view at a time and every triangle pair (doubles; the
// library tests exactly): a contour edge between two of the cell's triangles (quads split by the
// lowest-id diagonal) that folds inward, or a vertex not in front of the eye. -1: a determinant
// too near zero for doubles to tell.
int problem_by_definition(const MeshView& mesh, const RecentredPoints& pts, const Viewpoint& view, std::int64_t c) {
  if (mesh.type(c) == CellType::Tetra) return 0;
  const CellDef& def = cell_def(mesh.type(c));
  const std::int64_t* ids = mesh.cell(c);
  if (view.perspective)
    for (int k = 0; k < def.vertices; ++k)
      if (!(glm::dot(pts(ids[k]) - view.eye, view.dir) > 0.0)) return 1;
  std::int64_t surface[kMaxSurfaceTriangles][3];
  std::vector<std::array<std::int64_t, 3>> tri;
  for (int t = 0, n = surface_triangles(mesh, c, surface); t < n; ++t) tri.push_back({surface[t][0], surface[t][1], surface[t][2]});
  bool unsure = false;
  // The sign of (b - a) x (c - a) . w, or 0 when it is within rounding of zero.
  auto sign = [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& w) {
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double s = glm::dot(n, w), scale = glm::length(n) * glm::length(w);
    if (std::abs(s) <= 1e-9 * scale) unsure = true;
    return s > 0 ? 1 : -1;
  };
  auto facing = [&](const std::array<std::int64_t, 3>& t) {
    const glm::dvec3 a = pts(t[0]), b = pts(t[1]), c2 = pts(t[2]);
    return sign(a, b, c2, view.perspective ? view.eye - a : -view.dir);
  };
  bool problem = false;
  for (std::size_t t = 0; t < tri.size(); ++t)
    for (std::size_t u = t + 1; u < tri.size(); ++u)
      for (int e = 0; e < 3; ++e)
        for (int g = 0; g < 3; ++g)
          if (tri[t][e] == tri[u][(g + 1) % 3] && tri[t][(e + 1) % 3] == tri[u][g] && facing(tri[t]) * facing(tri[u]) < 0) {
            const glm::dvec3 a = pts(tri[t][0]), b = pts(tri[t][1]), c2 = pts(tri[t][2]);
            problem = problem || sign(a, b, c2, pts(tri[u][(g + 2) % 3]) - a) > 0;  // beyond the outward side
          }
  return unsure ? -1 : problem;
}

}  // namespace

// The folds found once per mesh give, in every view, the problem cells of the definition.
TEST(Polyhedra, FoldsFoundOnceGiveEachViewsProblemCells) {
  for (const Mesh& m : {warped_hexahedra(6), twisted_mixed(6)}) {
    const auto pts = std::make_shared<const RecentredPoints>(recentre(m.view()));
    const CellFolds folds(m.view(), pts);
    EXPECT_GT(folds.folds(), 0);
    std::int64_t problems = 0, unsure = 0;
    for (const Camera& cam : views(6)) {
      const Viewpoint v = viewpoint(cam, pts->centre);
      std::int64_t count = 0;
      const std::vector<char> got = folds.problem_cells(v, &count);
      for (std::int64_t cell = 0; cell < m.n_cells(); ++cell) {
        const int want = problem_by_definition(m.view(), *pts, v, cell);
        if (want < 0) ++unsure;
        else EXPECT_EQ(got[cell], want) << "cell " << cell;
      }
      EXPECT_EQ(count, std::count(got.begin(), got.end(), char(1)));
      problems += count;
    }
    EXPECT_GT(problems, 0);
    EXPECT_LT(unsure, m.n_cells());  // over 12 views: rarely too close to call in doubles
  }
}

// A split mesh's sorter that copies the face planes of the cells left whole from the unsplit
// mesh's sorter sorts exactly as one that computes them all.
TEST(Polyhedra, SplitSorterCopyingWholeCellsPlanesSortsTheSame) {
  for (int kind = 0; kind < 2; ++kind) {
    const Mesh m = kind == 0 ? warped_hexahedra(5) : twisted_mixed(4);
    const auto pts = std::make_shared<const RecentredPoints>(recentre(m.view()));
    const FaceTopology topo = build_topology(m.view());
    const VisibilitySorter whole(m.view(), topo, boundary_convexity(m.view(), topo), pts);
    std::vector<char> which(static_cast<std::size_t>(m.n_cells()), 0);
    for (std::size_t c = 0; c < which.size(); c += 3) which[c] = 1;
    const SplitMesh split = split_cells(m.view(), which);
    const FaceTopology st = build_topology(split.view);
    const HullReport hull = boundary_convexity(split.view, st);
    const VisibilitySorter fresh(split.view, st, hull, pts), copied(split.view, st, hull, pts, &whole, &split.parent);
    for (const Camera& c : views(3))
      for (const SortMethod method : {SortMethod::mpvo, SortMethod::mpvo_abuffer}) {
        const SortResult a = fresh.sort(method, {c, 64, 64}), b = copied.sort(method, {c, 64, 64});
        EXPECT_EQ(a.order, b.order) << kind;
        EXPECT_EQ(a.stats.face_relations, b.stats.face_relations);
        EXPECT_EQ(a.stats.gap_relations, b.stats.gap_relations);
      }
  }
}

// A hexahedron collapsed to a wedge (two vertex ids repeated, as some files store wedges): its
// zero-area triangles make no fold, and a warped neighbour's folds are still found.
TEST(Polyhedra, FoldsOfACollapsedHexahedron) {
  Mesh m = warped_hexahedra(2);
  const auto* ids = m.view().cell(0);
  std::vector<std::int64_t> collapsed(ids, ids + 8);
  collapsed[7] = collapsed[4], collapsed[6] = collapsed[5];  // the top face's edge 4-5 doubled
  m.add_cell(CellType::Hexahedron, collapsed.data());
  set_field(m, "s", [](const glm::dvec3&) { return 0.0; });
  const auto pts = std::make_shared<const RecentredPoints>(recentre(m.view()));
  const CellFolds folds(m.view(), pts);
  EXPECT_GT(folds.folds(), 0);
  for (const Camera& cam : views(3)) {
    const std::vector<char> problem = folds.problem_cells(viewpoint(cam, pts->centre));
    EXPECT_EQ(problem.size(), static_cast<std::size_t>(m.n_cells()));
  }
  // Split with the cells around it, its topology is patched as it is built.
  std::vector<char> which(static_cast<std::size_t>(m.n_cells()), 1);
  which[1] = 0;
  const SplitMesh split = split_cells(m.view(), which);
  const FaceTopology base = build_topology(m.view()), want = build_topology(split.view);
  const FaceTopology got = split_topology(m.view(), base, split);
  EXPECT_EQ(got.neighbor, want.neighbor);
  EXPECT_EQ(got.boundary, want.boundary);
}
