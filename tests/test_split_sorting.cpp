// Sorting meshes whose problem cells are split per view (visibility/split_sorter): no order
// violation against the ray-traced oracle, and the split sorter's shortcuts sort as a fresh one.
#include <algorithm>
#include <cmath>
#include <memory>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "mesh/generate.hpp"
#include "mesh/split_topology.hpp"
#include "mesh/topology.hpp"
#include "raycast/order_oracle.hpp"
#include "render/names.hpp"
#include "test_util.hpp"
#include "visibility/split_sorter.hpp"

using namespace cellproj;

using test::twisted_mixed;
using test::warped_hexahedra;

// Both exact sorts on meshes whose warped hexahedra stay whole where they do not fold: pairwise
// tests occlusion on the cells' surface triangles (a warped quad's two), not on one plane a face.
TEST(SplitSorting, SplittingSorterHasNoOrderViolations) {
  for (int kind = 0; kind < 2; ++kind) {
    Mesh m = kind == 0 ? warped_hexahedra(5) : twisted_mixed(4);
    const SplittingSorter sorter(m.view(), Tetrahedralize::problem);
    for (const SortMethod method : {SortMethod::mpvo_abuffer, SortMethod::pairwise})
      for (const Camera& c : test::views_of_unit_mesh(4)) {
        const ViewOrder v = sorter.sort(method, {c, 64, 64});
        const MeshView& cells = v.mesh->cells;
        ASSERT_EQ(static_cast<std::int64_t>(v.sorted.order.size()), cells.n_cells);
        const CellRayTracer tracer(cells);
        const OrderCheck k = check_order(tracer, cells.n_cells, v.sorted.order, c, 64, 64);
        EXPECT_EQ(k.violations, 0) << "mesh " << kind << ", " << name_of(method) << ", " << v.problem_cells
                                   << " problem cells";
        EXPECT_EQ(k.missing_cells + k.repeated_cells, 0);
      }
  }
}

// A split mesh's sorter that copies the face planes of the cells left whole from the unsplit
// mesh's sorter sorts exactly as one that computes them all.
TEST(SplitSorting, SplitSorterCopyingWholeCellsPlanesSortsTheSame) {
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
    for (const Camera& c : test::views_of_unit_mesh(3))
      for (const SortMethod method : {SortMethod::mpvo, SortMethod::mpvo_abuffer}) {
        const SortResult a = fresh.sort(method, {c, 64, 64}), b = copied.sort(method, {c, 64, 64});
        EXPECT_EQ(a.order, b.order) << kind;
        EXPECT_EQ(a.stats.face_relations, b.stats.face_relations);
        EXPECT_EQ(a.stats.gap_relations, b.stats.gap_relations);
      }
  }
}

// The face relations are found in parallel chunks of faces and of cells (visibility/mpvo.cpp): on
// meshes of several chunks (tetrahedra alone; hexahedra, wedges and pyramids split where they
// fold, with split quads beside whole cells) one thread and four give the same order, and it has
// no violation.
TEST(SplitSorting, FaceRelationsInParallelSortAsOnOneThread) {
  for (int kind = 0; kind < 2; ++kind) {
    const Mesh m = kind == 0 ? generate("box-tets", 16) : twisted_mixed(18);
    const SplittingSorter sorter(m.view(), kind == 0 ? Tetrahedralize::none : Tetrahedralize::problem);
    for (const Camera& c : test::views_of_unit_mesh(3)) {
      ViewOrder one, four;
      tbb::task_arena(1).execute([&] { one = sorter.sort(SortMethod::mpvo, {c, 64, 64}); });
      tbb::task_arena(4).execute([&] { four = sorter.sort(SortMethod::mpvo, {c, 64, 64}); });
      ASSERT_GT(one.mesh->cells.n_cells, 8192 * 2) << "several chunks of cells";
      EXPECT_EQ(one.sorted.order, four.sorted.order) << kind;
      EXPECT_EQ(one.sorted.stats.face_relations, four.sorted.stats.face_relations);
      const CellRayTracer tracer(one.mesh->cells);
      const OrderCheck k = check_order(tracer, one.mesh->cells.n_cells, one.sorted.order, c, 64, 64);
      EXPECT_EQ(k.violations, 0) << kind << ", " << one.problem_cells << " problem cells";
    }
  }
}
