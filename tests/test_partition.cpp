// Bricks for distributed rendering (issue 18): the k-d tree, the cells clipped to their bricks,
// the brick order from any camera, and a frame of bricks composited in that order against the
// whole mesh's picture (the MPI ranks are tested by tests/mpi_render.sh).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>

#include "composite/fragment.hpp"
#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"
#include "mesh/generate.hpp"
#include "mesh/geometry.hpp"
#include "mesh/tetrahedralize.hpp"
#include "mesh/validate.hpp"
#include "partition/brick_order.hpp"
#include "partition/kd_partition.hpp"
#include "raycast/cell_ray_tracer.hpp"
#include "raycast/order_oracle.hpp"
#include "tests/test_util.hpp"
#include "visibility/split_sorter.hpp"

namespace cellproj {
namespace {

// The volume of the canonical tetrahedra (what every renderer draws).
double volume(const Mesh& m) {
  const MeshView v = m.view();
  double sum = 0.0;
  Tet tets[kMaxTetsPerCell];
  for (std::int64_t c = 0; c < v.n_cells; ++c) {
    const int n = canonical_tetrahedra(v, c, tets);
    for (int t = 0; t < n; ++t)
      sum +=
          std::abs(tet_volume6(v.point(tets[t][0]), v.point(tets[t][1]), v.point(tets[t][2]), v.point(tets[t][3]))) / 6;
  }
  return sum;
}

std::vector<Mesh> bricks_of(const Mesh& m, const KdTree& tree) {
  const auto cells = cells_of_bricks(m.view(), tree);
  std::vector<Mesh> out;
  for (int b = 0; b < tree.bricks(); ++b) out.push_back(extract_brick(m, tree, b, cells[b]));
  return out;
}

TEST(Partition, BricksHoldTheWholeVolumeEachInsideItsBox) {
  for (const char* kind : {"box-tets", "swirl", "mixed", "graded"}) {
    const Mesh m = generate(kind, 6);
    for (int n : {1, 2, 3, 5, 8}) {
      const KdTree tree = build_kd_tree(m.view(), cell_costs(m.view()), n);
      ASSERT_EQ(tree.bricks(), n);
      double sum = 0.0;
      const std::vector<Mesh> bricks = bricks_of(m, tree);
      for (int b = 0; b < n; ++b) {
        const Mesh& brick = bricks[b];
        sum += volume(brick);
        EXPECT_EQ(validate(brick.view()).inverted_cells, 0) << kind;
        const KdBox& box = tree.nodes[tree.leaf_of[b]].box;
        const double eps = 1e-12 * glm::length(tree.nodes[0].box.hi - tree.nodes[0].box.lo);
        for (std::int64_t p = 0; p < brick.n_points(); ++p)
          for (int k = 0; k < 3; ++k) {
            EXPECT_GE(brick.view().point(p)[k], box.lo[k] - eps) << kind << " brick " << b;
            EXPECT_LE(brick.view().point(p)[k], box.hi[k] + eps) << kind << " brick " << b;
          }
      }
      EXPECT_NEAR(sum, volume(m), 1e-12 * volume(m)) << kind << ", " << n << " bricks";
    }
  }
}

const TransferFunction& tf() {
  static const TransferFunction t({{0.0, {0.2, 0.4, 1.0}}, {1.0, {1.0, 0.6, 0.2}}}, {{0.0, 0.5}, {1.0, 4.0}});
  return t;
}

// The bricks' pictures "over" each other in the tree's order from the camera.
template <class Render>
Image composite_bricks(const std::vector<Mesh>& bricks, const KdTree& tree, const Camera& camera, Render render) {
  Image out;
  for (int b : back_to_front(tree, camera)) {
    if (bricks[b].n_cells() == 0) continue;
    const Image img = render(bricks[b]);
    if (out.rgba.empty()) out = Image(img.width, img.height);
    for (std::size_t k = 0; k < out.rgba.size(); k += 4) over(&out.rgba[k], &img.rgba[k]);
  }
  return out;
}

TEST(Partition, BricksCompositedInTreeOrderGiveTheWholePicture) {
  // The exact renderer on the canonical tetrahedra: a cut cell's pieces carry its field exactly.
  for (const char* kind : {"swirl", "mixed", "box-tets"}) {
    const Mesh m = generate(kind, 5);
    const std::string field = m.fields.front().name;
    const KdTree tree = build_kd_tree(m.view(), cell_costs(m.view()), 5);
    const std::vector<Mesh> bricks = bricks_of(m, tree);
    for (const Camera& camera : test::views_of_unit_mesh(4)) {
      const auto render = [&](const Mesh& mesh) {
        return test::exact(mesh, field, tf(), camera, 40, 40, CellInterpolation::canonical_tets);
      };
      const ImageDifference d = compare(render(m), composite_bricks(bricks, tree, camera, render));
      EXPECT_LT(d.max_abs, 1e-6) << kind;
    }
  }
}

// Where the ray o + t d enters the box (t >= 0), or infinity when it misses it.
double entry(const KdBox& b, const glm::dvec3& o, const glm::dvec3& d) {
  double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      if (o[k] < b.lo[k] || o[k] > b.hi[k]) return t1;
      continue;
    }
    double a = (b.lo[k] - o[k]) / d[k], c = (b.hi[k] - o[k]) / d[k];
    if (a > c) std::swap(a, c);
    t0 = std::max(t0, a), t1 = std::min(t1, c);
  }
  return t0 < t1 ? t0 : std::numeric_limits<double>::infinity();
}

TEST(Partition, BrickOrderIsBackToFrontAlongEveryRay) {
  // The oracle: along random rays of random cameras (eyes inside and outside the bricks, both
  // projections), the bricks a ray passes through must come in the order farthest first.
  const Mesh m = generate("graded-tets", 6);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n : {2, 3, 7, 16}) {
    const KdTree tree = build_kd_tree(m.view(), cell_costs(m.view()), n);
    int checked = 0;
    for (int v = 0; v < 40; ++v) {
      const bool persp = v % 2 == 0;
      const glm::dvec3 eye = v % 4 < 2 ? glm::dvec3(u(rng), u(rng), u(rng)) * 0.9  // inside some brick
                                       : glm::dvec3(u(rng), u(rng), u(rng)) * 4.0 + glm::dvec3(0, 0, 3);
      const glm::dvec3 target(u(rng) * 0.5, u(rng) * 0.5, u(rng) * 0.5);
      const Camera camera{persp ? Projection::Perspective : Projection::Orthographic, eye, target, {0.3, 1, 0.2}};
      const std::vector<int> order = back_to_front(tree, camera);
      ASSERT_EQ(static_cast<int>(order.size()), n);
      std::vector<int> position(n);
      for (int k = 0; k < n; ++k) position[order[k]] = k;
      for (int r = 0; r < 50; ++r) {
        const glm::dvec3 d = glm::normalize(persp ? glm::dvec3(u(rng), u(rng), u(rng)) : target - eye);
        const glm::dvec3 o =
            persp ? eye : eye + glm::dvec3(u(rng), u(rng), u(rng)) * 0.8;  // orthographic: parallel rays
        std::vector<std::pair<double, int>> hits;
        for (int b = 0; b < n; ++b)
          if (const double t = entry(tree.nodes[tree.leaf_of[b]].box, o, d); std::isfinite(t)) hits.push_back({t, b});
        std::sort(hits.begin(), hits.end());
        for (std::size_t k = 1; k < hits.size(); ++k, ++checked)
          EXPECT_GT(position[hits[k - 1].second], position[hits[k].second]) << n << " bricks, view " << v;
      }
    }
    EXPECT_GT(checked, 100);
  }
}

TEST(Partition, RanksGetContiguousSubtreesBalancedByCost) {
  const Mesh m = generate("graded-tets", 8);  // cells graded in size: a cell count split is not a cost split
  const KdTree tree = build_kd_tree(m.view(), cell_costs(m.view()), 8);
  double lo = 1e300, hi = 0;
  for (int b = 0; b < 8; ++b)
    lo = std::min(lo, tree.nodes[tree.leaf_of[b]].cost), hi = std::max(hi, tree.nodes[tree.leaf_of[b]].cost);
  EXPECT_LT(hi / lo, 1.2);  // the split is by centroid: a cell's whole cost goes to one side
  for (int ranks : {1, 2, 3, 4, 8, 11}) {
    const std::vector<int> roots = rank_subtrees(tree, ranks);
    ASSERT_EQ(static_cast<int>(roots.size()), ranks);
    std::vector<int> all;
    for (int r : roots)
      if (r >= 0)
        for (int b : bricks_under(tree, r)) all.push_back(b);
    std::vector<int> expected(8);
    std::iota(expected.begin(), expected.end(), 0);
    EXPECT_EQ(all, expected) << ranks << " ranks: every brick once, left to right";
    EXPECT_EQ(std::count(roots.begin(), roots.end(), -1), std::max(0, ranks - 8));
  }
  EXPECT_EQ(bricks_under(tree, rank_subtrees(tree, 4)[1]).size(), 2u);  // 8 bricks over 4 ranks: 2 each
}

TEST(Partition, TheSortInsideEachBrickHasNoOrderViolation) {
  // Bricks of a non-convex curvilinear grid are non-convex (cut by the planes as well): the
  // renderer's sort (gap relations, problem cells split per view) must still order each brick's
  // cells exactly (the oracle), as on the whole mesh.
  for (const Mesh& m : {test::warped_hexahedra(6), generate("swirl", 6)}) {
    for (const Mesh& brick : bricks_of(m, build_kd_tree(m.view(), cell_costs(m.view()), 4))) {
      const SplittingSorter sorter(brick.view(), Tetrahedralize::problem);
      for (const Camera& camera : test::views_of_unit_mesh(4)) {
        const ViewOrder v = sorter.sort(SortMethod::mpvo_abuffer, {camera, 64, 64});
        const CellRayTracer tracer(v.mesh->cells);
        const OrderCheck k = check_order(tracer, v.mesh->cells.n_cells, v.sorted.order, camera, 64, 64);
        EXPECT_EQ(k.violations, 0) << brick.source;
        EXPECT_EQ(k.missing_cells + k.repeated_cells, 0);
        EXPECT_GT(k.pixels_covered, 0);
      }
    }
  }
}

TEST(Partition, BricksWrittenAndReadBackAreTheSame) {
  const Mesh m = generate("swirl", 5);
  const KdTree tree = build_kd_tree(m.view(), cell_costs(m.view()), 2);
  const std::vector<Mesh> bricks = bricks_of(m, tree);
  test::TempDir dir;
  for (int b = 0; b < 2; ++b) {
    write_vtu(bricks[b], dir.file("b.vtu"));
    const Mesh back = load_mesh(dir.file("b.vtu")).mesh;
    EXPECT_EQ(back.points, bricks[b].points);
    EXPECT_EQ(back.connectivity, bricks[b].connectivity);
    EXPECT_EQ(back.fields.at(0).values, bricks[b].fields.at(0).values);
  }
}

}  // namespace
}  // namespace cellproj
