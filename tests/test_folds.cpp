// The folds of warped quadrilateral faces (mesh/face_split, MWSC section 4): found once per mesh,
// they give in every view the cells a ray may cross more than twice, by their definition.
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "mesh/face_split.hpp"
#include "mesh/split_topology.hpp"
#include "mesh/topology.hpp"
#include "test_util.hpp"
#include "visibility/split_sorter.hpp"

using namespace cellproj;

using test::twisted_mixed;
using test::warped_hexahedra;

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
  for (int t = 0, n = surface_triangles(mesh, c, surface); t < n; ++t)
    tri.push_back({surface[t][0], surface[t][1], surface[t][2]});
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
          if (tri[t][e] == tri[u][(g + 1) % 3] && tri[t][(e + 1) % 3] == tri[u][g] &&
              facing(tri[t]) * facing(tri[u]) < 0) {
            const glm::dvec3 a = pts(tri[t][0]), b = pts(tri[t][1]), c2 = pts(tri[t][2]);
            problem = problem || sign(a, b, c2, pts(tri[u][(g + 2) % 3]) - a) > 0;  // beyond the outward side
          }
  return unsure ? -1 : problem;
}

}  // namespace

// The folds found once per mesh give, in every view, the problem cells of the definition.
TEST(Folds, FoundOnceGiveEachViewsProblemCells) {
  for (const Mesh& m : {warped_hexahedra(6), twisted_mixed(6)}) {
    const auto pts = std::make_shared<const RecentredPoints>(recentre(m.view()));
    const CellFolds folds(m.view(), pts);
    EXPECT_GT(folds.folds(), 0);
    std::int64_t problems = 0, unsure = 0;
    for (const Camera& cam : test::views_of_unit_mesh(6)) {
      const Viewpoint v = viewpoint(cam, pts->centre);
      std::int64_t count = 0;
      const std::vector<char> got = folds.problem_cells(v, &count);
      for (std::int64_t cell = 0; cell < m.n_cells(); ++cell) {
        const int want = problem_by_definition(m.view(), *pts, v, cell);
        if (want < 0)
          ++unsure;
        else
          EXPECT_EQ(got[cell], want) << "cell " << cell;
      }
      EXPECT_EQ(count, std::count(got.begin(), got.end(), char(1)));
      problems += count;
    }
    EXPECT_GT(problems, 0);
    EXPECT_LT(unsure, m.n_cells());  // over 12 views: rarely too close to call in doubles
  }
}

// A hexahedron collapsed to a wedge (two vertex ids repeated, as some files store wedges): its
// zero-area triangles make no fold, and a warped neighbour's folds are still found.
TEST(Folds, OfACollapsedHexahedron) {
  Mesh m = warped_hexahedra(2);
  const auto* ids = m.view().cell(0);
  std::vector<std::int64_t> collapsed(ids, ids + 8);
  collapsed[7] = collapsed[4], collapsed[6] = collapsed[5];  // the top face's edge 4-5 doubled
  m.add_cell(CellType::Hexahedron, collapsed.data());
  set_field(m, "s", [](const glm::dvec3&) { return 0.0; });
  const auto pts = std::make_shared<const RecentredPoints>(recentre(m.view()));
  const CellFolds folds(m.view(), pts);
  EXPECT_GT(folds.folds(), 0);
  for (const Camera& cam : test::views_of_unit_mesh(3)) {
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
