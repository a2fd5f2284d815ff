// Cells renumbered for locality (mesh/cell_order.hpp): a structured numbering is judged local and
// left alone, a shuffled one renumbered along a Morton curve; the renumbering keeps every cell,
// is the same on any thread count, and the renderer draws a shuffled mesh bit for bit as the
// mesh numbered in order (points keep their numbers, and every ray meets the same cells in the same
// order); so do the exact ray caster (and the methods on its traversal) and slicing.
#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include "mesh/cell_order.hpp"
#include "mesh/generate.hpp"
#include "render/renderer.hpp"
#include "render/volume.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

// m with its cells in a random order (a fixed seed); points and fields unchanged.
Mesh shuffled(const Mesh& m, unsigned seed = 7) {
  const MeshView v = m.view();
  std::vector<std::int64_t> order(static_cast<std::size_t>(v.n_cells));
  std::iota(order.begin(), order.end(), std::int64_t(0));
  std::shuffle(order.begin(), order.end(), std::mt19937(seed));
  Mesh out = m;
  out.connectivity.clear(), out.offsets = {0}, out.types.clear();
  for (const std::int64_t c : order) out.add_cell(v.type(c), v.cell(c));
  return out;
}

// Each cell as its sorted vertex ids and type, the list sorted: the cells whatever their numbers.
std::vector<std::array<std::int64_t, 9>> cell_set(const MeshView& v) {
  std::vector<std::array<std::int64_t, 9>> cells;
  for (std::int64_t c = 0; c < v.n_cells; ++c) {
    std::array<std::int64_t, 9> key;
    key.fill(-1);
    std::copy_n(v.cell(c), v.cell_size(c), key.begin());
    std::sort(key.begin(), key.begin() + v.cell_size(c));
    key[8] = v.types[c];
    cells.push_back(key);
  }
  std::sort(cells.begin(), cells.end());
  return cells;
}

// m with the field "s" in [0.1, 0.9].
Mesh with_field(Mesh m) {
  set_field(m, "s", [](const glm::dvec3& x) { return 0.5 + 0.4 * std::sin(2 * x.x + x.y) * std::cos(1.5 * x.z); });
  return m;
}
Mesh box_tets(int n) { return with_field(make_box(n, n, n, {-1, -1, -1}, {1, 1, 1}, true)); }
Mesh mixed(int n) { return with_field(test::twisted_mixed(n)); }

TransferFunction order_tf() {
  return TransferFunction({{0.0, {0.1, 0.3, 0.9}}, {0.5, {0.9, 0.8, 0.3}}, {1.0, {1, 0.3, 0.1}}},
                          {{0.0, 0.5}, {0.4, 2.0}, {0.7, 6.0}, {1.0, 3.0}});
}

}  // namespace

TEST(CellOrder, StructuredNumberingIsLocalAndAShuffledOneIsNot) {
  const Mesh m = box_tets(16);  // 24,576 tetrahedra
  const double ordered = numbering_spread(m.view()), scattered = numbering_spread(shuffled(m).view());
  EXPECT_LT(ordered, 2.0);
  // A random numbering's consecutive cells lie about half the box apart: some 0.5 N^(1/3) cell
  // radii for N cells (14.5 here).
  EXPECT_GT(scattered, 1.5 * kLocalSpread);
  EXPECT_EQ(numbering_spread(make_box(1, 1, 1, {0, 0, 0}, {1, 1, 1}, false).view()), 0.0);  // one cell
}

TEST(CellOrder, MortonOrderIsAPermutationAndTheSameOnAnyThreadCount) {
  const Mesh m = shuffled(box_tets(12));
  std::vector<std::int64_t> one, two;
  tbb::task_arena(1).execute([&] { one = morton_cell_order(m.view()); });
  tbb::task_arena(2).execute([&] { two = morton_cell_order(m.view()); });
  EXPECT_EQ(one, two);
  std::vector<std::int64_t> sorted = one, all(sorted.size());
  std::sort(sorted.begin(), sorted.end());
  std::iota(all.begin(), all.end(), std::int64_t(0));
  EXPECT_EQ(sorted, all);
  // Consecutive cells of the curve lie close: near a structured numbering's spread, not the shuffle's.
  Mesh along = m;
  along.connectivity.clear(), along.offsets = {0}, along.types.clear();
  for (const std::int64_t c : one) along.add_cell(m.view().type(c), m.view().cell(c));
  EXPECT_LT(numbering_spread(along.view()), 2.0);
}

TEST(CellOrder, LocalCellsRenumbersOnlyAScatteredMeshAndKeepsEveryCell) {
  const Mesh ordered = mixed(14);  // hexahedra, wedges, pyramids and tetrahedra
  const LocalCells kept(ordered.view());
  EXPECT_FALSE(kept.renumbered());
  EXPECT_EQ(kept.view().connectivity, ordered.view().connectivity);  // the caller's arrays, no copy

  const Mesh scattered = shuffled(ordered);
  LocalCells local(scattered.view());
  ASSERT_TRUE(local.renumbered()) << "spread " << local.spread();
  EXPECT_GT(local.spread(), kLocalSpread);
  EXPECT_EQ(local.view().n_cells, scattered.view().n_cells);
  EXPECT_EQ(local.view().offsets[local.view().n_cells], scattered.view().offsets[scattered.view().n_cells]);
  EXPECT_EQ(cell_set(local.view()), cell_set(scattered.view()));  // the same cells, vertex order and type kept
  EXPECT_LT(numbering_spread(local.view()), 2.0);
  const LocalCells moved(std::move(local));  // the arrays move in place: the view stays good
  EXPECT_TRUE(moved.renumbered());
  EXPECT_EQ(cell_set(moved.view()), cell_set(scattered.view()));
}

TEST(CellOrder, APointOfNoPlaceStillGivesAnOrder) {
  // A trusted mesh's NaN point (validation refuses it otherwise): its cells get some key, every cell is ordered once.
  Mesh m = shuffled(box_tets(12));
  m.points[3 * 5] = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::int64_t> order = morton_cell_order(m.view()), all(order.size());
  std::sort(order.begin(), order.end());
  std::iota(all.begin(), all.end(), std::int64_t(0));
  EXPECT_EQ(order, all);
}

TEST(CellOrder, AShuffledMeshRendersTheSamePictureBitForBit) {
  const Mesh m = box_tets(16), s = shuffled(m);
  const TransferFunction tf = order_tf();
  const Camera cameras[] = {test::perspective({3.2, -2.5, 2.1}, {0, 0, 0}, 40), test::looking_down(2.6)};
  for (const Camera& camera : cameras)
    for (const ProjectionMethod method : {ProjectionMethod::pt_linear, ProjectionMethod::pt_breakpoints}) {
      ProjectionStats as_given, renumbered;
      const Image a =
          test::project(m, "s", tf, camera, 96, test::with_method(method), Tetrahedralize::problem, &as_given);
      const Image b =
          test::project(s, "s", tf, camera, 96, test::with_method(method), Tetrahedralize::problem, &renumbered);
      EXPECT_FALSE(as_given.cells_renumbered);
      EXPECT_TRUE(renumbered.cells_renumbered);
      EXPECT_EQ(a.rgba, b.rgba) << name_of(method);
      EXPECT_EQ(as_given.counters.fragments, renumbered.counters.fragments);
      EXPECT_GT(*std::max_element(a.rgba.begin(), a.rgba.end()), 0.1f);
    }
}

TEST(CellOrder, AShuffledMixedMeshRendersTheSamePicture) {
  // Whole hexahedra, wedges and pyramids, some split into tetrahedra for the view (their diagonals
  // from the lowest-numbered vertex: the points keep their numbers), on a twisted, non-convex
  // boundary (the A-buffer's gaps): renumbered, the same bits as the mesh numbered in order.
  const Mesh m = mixed(14);
  const TransferFunction tf = order_tf();
  const Camera camera = test::perspective({3.4, -2.2, 2.4}, {0, 0, 0}, 45);
  const ProjectionOptions options = test::with_method(ProjectionMethod::pt_breakpoints, SortMethod::mpvo_abuffer);
  ProjectionStats stats;
  const Image renumbered = test::project(shuffled(m), "", tf, camera, 64, options, Tetrahedralize::problem, &stats);
  EXPECT_TRUE(stats.cells_renumbered);
  EXPECT_GT(stats.problem_cells, 0);
  EXPECT_GT(stats.sort.gap_relations, 0);  // a relation across the boundary's gap
  EXPECT_EQ(renumbered.rgba, test::project(m, "", tf, camera, 64, options).rgba);
}

TEST(CellOrder, TheRayCasterAndSlicingDrawAShuffledMeshTheSameToo) {
  // Tetrahedra, and whole cells (the isoparametric field's per-cell data must follow the tracer's
  // numbering: a mismatch would be a wrong picture, not an error).
  for (const Mesh& m : {box_tets(16), mixed(14)}) {
    const Mesh s = shuffled(m);
    const Volume ordered(m.view()), scattered(s.view());
    const TransferFunction tf = order_tf();
    const Camera camera = test::perspective({3.2, -2.5, 2.1}, {0, 0, 0}, 40);
    RenderSettings exact, mip, slicing;
    exact.mode = RenderMode::exact, mip.mode = RenderMode::reduction, slicing.mode = RenderMode::slicing;
    slicing.slicing.slices = 64;
    for (const RenderSettings& settings : {exact, mip, slicing}) {
      RenderReport as_given, renumbered;
      const Image a = render(ordered, field_of(m, "s"), tf, settings, camera, {64, 64}, &as_given);
      const Image b = render(scattered, field_of(s, "s"), tf, settings, camera, {64, 64}, &renumbered);
      EXPECT_EQ(a.rgba, b.rgba) << static_cast<int>(settings.mode);
      const auto renumbered_flag = [](const RenderReport& r) {
        for (const auto& [name, value] : r.values)
          if (name == "cells_renumbered") return std::get<std::int64_t>(value);
        return std::int64_t{-1};
      };
      EXPECT_EQ(renumbered_flag(as_given), 0);
      EXPECT_EQ(renumbered_flag(renumbered), 1);
    }
  }
}
