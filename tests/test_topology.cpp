#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>
#include <glm/geometric.hpp>

#include "mesh/geometry.hpp"
#include "mesh/split_topology.hpp"
#include "mesh/topology.hpp"
#include "test_util.hpp"

using namespace cellproj;

TEST(Topology, BoxFacesAndConvexity) {
  const Mesh m = make_box(3, 4, 5, glm::dvec3(0), glm::dvec3(1), false);
  const FaceTopology t = build_topology(m.view());
  EXPECT_EQ(static_cast<std::int64_t>(t.boundary.size()), 2 * (3 * 4 + 4 * 5 + 3 * 5));
  EXPECT_EQ(t.shared_faces, 2 * 4 * 5 + 3 * 3 * 5 + 3 * 4 * 4);
  EXPECT_EQ(t.nonplanar_faces, 0);
  EXPECT_TRUE(boundary_convexity(m.view(), t).convex);
  // Neighbours are symmetric.
  for (std::int64_t c = 0; c < m.n_cells(); ++c)
    for (std::int64_t f = t.face_offsets[c]; f < t.face_offsets[c + 1]; ++f)
      if (t.neighbor[f] >= 0) {
        const std::int64_t n = t.neighbor[f];
        bool back = false;
        for (std::int64_t g = t.face_offsets[n]; g < t.face_offsets[n + 1]; ++g) back |= t.neighbor[g] == c;
        EXPECT_TRUE(back);
      }
}

TEST(Topology, SwirlIsNotConvexAndHasWarpedFaces) {
  const Mesh m = generate("swirl", 4);
  const FaceTopology t = build_topology(m.view());
  const HullReport h = boundary_convexity(m.view(), t);
  EXPECT_FALSE(h.convex);
  EXPECT_GT(h.boundary_faces_off_hull, 0);
  EXPECT_GT(t.nonplanar_faces, 0);
  EXPECT_GT(t.max_relative_nonplanarity, 1e-3);
}

TEST(Topology, FaceSharedByThreeCellsIsNonManifold) {
  Mesh m;
  for (glm::dvec3 p : {glm::dvec3(0, 0, 0), {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {1, 1, 1}}) m.add_point(p);
  m.add_cell(CellType::Tetra, {0, 1, 2, 3});
  m.add_cell(CellType::Tetra, {0, 2, 1, 4});
  m.add_cell(CellType::Tetra, {0, 1, 2, 5});  // overlaps the first
  const FaceTopology t = build_topology(m.view());
  EXPECT_EQ(t.nonmanifold_faces, 1);
  EXPECT_EQ(t.neighbor[t.face_offsets[0] + 3], kNonManifold);
}

TEST(Topology, QuadMatchesOnlyAQuad) {
  // A hexahedron next to a pyramid (shared quad) and a tetrahedron on a split half of it (no match).
  Mesh m;
  for (int k = 0; k < 2; ++k)
    for (glm::dvec3 p : {glm::dvec3(0, 0, 0), {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}) m.add_point(p + glm::dvec3(0, 0, k));
  m.add_point({0.5, 0.5, 2});
  m.add_cell(CellType::Hexahedron, {0, 1, 2, 3, 4, 5, 6, 7});
  m.add_cell(CellType::Pyramid, {4, 5, 6, 7, 8});
  const FaceTopology t = build_topology(m.view());
  EXPECT_EQ(t.shared_faces, 1);
  EXPECT_EQ(static_cast<std::int64_t>(t.boundary.size()), 5 + 4);
}

// The split mesh's topology patched from the mesh's equals the one built from scratch, for random
// sets of split cells on meshes of hexahedra, wedges, pyramids and tetrahedra (whose faces meet
// whole quads, split quads and other tetrahedra).
TEST(Topology, SplitTopologyEqualsBuildingIt) {
  std::mt19937 rng(9);
  for (const std::string kind : {"mixed", "swirl", "box", "swirl-tets", "seamed mixed", "seamed swirl"}) {
    const bool seamed = kind.rfind("seamed ", 0) == 0;
    const Mesh m = seamed ? test::with_seam(generate(kind.substr(7), 4), 0.0) : generate(kind, 4);
    const FaceTopology base = build_topology(m.view());
    for (int share : {0, 5, 30, 100}) {
      std::vector<char> which(static_cast<std::size_t>(m.n_cells()), 0);
      std::uniform_int_distribution<int> pct(0, 99);
      for (auto& w : which) w = pct(rng) < share;
      const SplitMesh split = split_cells(m.view(), which);
      const FaceTopology want = build_topology(split.view), got = split_topology(m.view(), base, split);
      EXPECT_EQ(got.face_offsets, want.face_offsets) << kind << " " << share;
      EXPECT_EQ(got.neighbor, want.neighbor) << kind << " " << share;
      EXPECT_EQ(got.boundary, want.boundary) << kind << " " << share;
      auto sorted = [](std::vector<std::array<std::int64_t, 3>> v) { return std::sort(v.begin(), v.end()), v; };
      EXPECT_EQ(sorted(got.split_faces), sorted(want.split_faces)) << kind << " " << share;
      EXPECT_EQ(got.shared_faces, want.shared_faces) << kind << " " << share;
      EXPECT_EQ(got.nonmanifold_faces, want.nonmanifold_faces);
      EXPECT_EQ(got.seam_faces, want.seam_faces) << kind << " " << share;
      if (seamed) EXPECT_GT(got.seam_faces, 0) << kind << " " << share;
      if (share > 0 && kind != "swirl-tets") EXPECT_GT(split.cells_split, 0);
    }
  }
}

// A mesh whose own tetrahedra already meet whole quads (here: a mesh split once, taken as the
// input): its quads matched to two triangles stay so, or become pairs of triangles when split.
TEST(Topology, SplitTopologyOfAMeshWithSplitQuads) {
  std::mt19937 rng(4);
  std::uniform_int_distribution<int> pct(0, 99);
  for (const char* kind : {"mixed", "swirl", "box"}) {
    const Mesh m = generate(kind, 4);
    std::vector<char> once(static_cast<std::size_t>(m.n_cells()), 0);
    for (auto& w : once) w = pct(rng) < 40;
    const SplitMesh input = split_cells(m.view(), once);
    const FaceTopology base = build_topology(input.view);
    ASSERT_GT(base.split_faces.size(), 0u) << kind;
    for (int share : {10, 50}) {
      std::vector<char> which(static_cast<std::size_t>(input.view.n_cells), 0);
      for (auto& w : which) w = pct(rng) < share;
      const SplitMesh split = split_cells(input.view, which);
      const FaceTopology want = build_topology(split.view), got = split_topology(input.view, base, split);
      EXPECT_EQ(got.neighbor, want.neighbor) << kind << " " << share;
      EXPECT_EQ(got.boundary, want.boundary) << kind << " " << share;
      auto sorted = [](std::vector<std::array<std::int64_t, 3>> v) { return std::sort(v.begin(), v.end()), v; };
      EXPECT_EQ(sorted(got.split_faces), sorted(want.split_faces)) << kind << " " << share;
      EXPECT_EQ(got.shared_faces, want.shared_faces) << kind << " " << share;
    }
  }
}

// Two blocks with their interface points repeated: the seam's faces are matched by position, so
// the topology is the one of the mesh stored with each point once (the same cells across the same
// faces, quads across split quads included) and the boundary is convex again.
TEST(Topology, SeamOfRepeatedPointsIsGlued) {
  for (const char* kind : {"box", "mixed", "swirl"}) {
    const Mesh m = generate(kind, 4), seamed = test::with_seam(m, 0.0);
    const FaceTopology want = build_topology(m.view()), got = build_topology(seamed.view());
    EXPECT_EQ(want.seam_faces, 0) << kind;
    EXPECT_GT(got.seam_faces, 0) << kind;
    EXPECT_EQ(got.neighbor, want.neighbor) << kind;
    EXPECT_EQ(got.boundary, want.boundary) << kind;
    EXPECT_EQ(got.shared_faces, want.shared_faces) << kind;
    auto sorted = [](std::vector<std::array<std::int64_t, 3>> v) { return std::sort(v.begin(), v.end()), v; };
    EXPECT_EQ(sorted(got.split_faces), sorted(want.split_faces)) << kind;
    EXPECT_EQ(boundary_convexity(seamed.view(), got).convex, boundary_convexity(m.view(), want).convex) << kind;
    // The cells beyond the seam split into tetrahedra: each seam quad is glued to two triangles.
    std::vector<char> beyond(static_cast<std::size_t>(m.n_cells()), 0);
    for (std::int64_t c = 0; c < m.n_cells(); ++c) beyond[c] = seamed.connectivity[seamed.offsets[c]] >= m.n_points();
    const SplitMesh split = split_cells(m.view(), beyond), split_seamed = split_cells(seamed.view(), beyond);
    const FaceTopology want_split = build_topology(split.view), got_split = build_topology(split_seamed.view);
    EXPECT_EQ(got_split.neighbor, want_split.neighbor) << kind;
    EXPECT_EQ(sorted(got_split.split_faces), sorted(want_split.split_faces)) << kind;
    // A glued pair lists 2 faces, a quad glued to its two triangles 3: some of the latter.
    EXPECT_GT(got_split.seam.size(), 2 * static_cast<std::size_t>(got_split.seam_faces)) << kind;
  }
  const FaceTopology box = build_topology(test::with_seam(generate("box", 4), 0.0).view());
  EXPECT_EQ(box.seam_faces, 4 * 4);  // the interface x = 0 of a 4 x 4 x 4 box
}

// Faces at one place are glued only when their cells lie on opposite sides and no third face is
// there: coincident faces of overlapping cells stay boundary faces.
TEST(Topology, CoincidentFacesOfOverlappingCellsAreNotGlued) {
  const glm::dvec3 tri[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  auto mesh_with = [&](std::initializer_list<double> apex_z) {
    Mesh m;
    for (const double z : apex_z) {  // each tetrahedron on its own copy of the triangle
      const std::int64_t a = m.add_point(tri[0]), b = m.add_point(tri[1]), c = m.add_point(tri[2]);
      const std::int64_t d = m.add_point({0.2, 0.2, z});
      m.add_cell(CellType::Tetra, z > 0 ? std::initializer_list<std::int64_t>{a, b, c, d}
                                        : std::initializer_list<std::int64_t>{a, c, b, d});
    }
    return m;
  };
  EXPECT_EQ(build_topology(mesh_with({1.0, -1.0}).view()).seam_faces, 1);
  EXPECT_EQ(build_topology(mesh_with({1.0, 0.5}).view()).seam_faces, 0);         // same side: overlapping
  EXPECT_EQ(build_topology(mesh_with({1.0, -1.0, -0.5}).view()).seam_faces, 0);  // three faces at one place
  // Solver arrays handed over unvalidated: a NaN point is never at the same place as another.
  Mesh nan = mesh_with({1.0, -1.0});
  nan.points[0] = nan.points[12] = std::nan("");
  EXPECT_EQ(build_topology(nan.view()).seam_faces, 0);
}

// build_topology's bucketed matching against a plain map from face keys to cell faces, on meshes
// of every cell type with some cells repeated (faces shared by three or four cells), run with 4
// threads: the same neighbours, counts, first non-manifold cell and quad warps.
TEST(Topology, MatchesAMapOfFaceKeys) {
  for (const std::string kind : {"mixed", "swirl", "box", "swirl-tets"}) {
    Mesh m = generate(kind, 5);
    const std::int64_t n = m.n_cells();
    for (std::int64_t c = n / 7; c < n; c += n / 5) {  // repeated cells: their faces are non-manifold
      const std::vector<std::int64_t> ids(m.view().cell(c), m.view().cell(c) + m.view().cell_size(c));
      m.add_cell(m.view().type(c), ids.data());
    }
    const MeshView v = m.view();
    FaceTopology t;
    tbb::task_arena(4).execute([&] { t = build_topology(v); });

    std::map<FaceKey, std::vector<std::pair<std::int64_t, std::int64_t>>> faces;  // key -> (cell face, cell)
    for (std::int64_t c = 0; c < v.n_cells; ++c)
      for (int f = 0; f < cell_def(v.type(c)).faces; ++f) {
        const FaceDef& d = cell_def(v.type(c)).face[f];
        std::int64_t ids[4];
        for (int k = 0; k < d.size; ++k) ids[k] = v.cell(c)[d.v[k]];
        faces[face_key_of(ids, d.size)].push_back({t.face_offsets[c] + f, c});
      }
    std::int64_t shared = 0, nonmanifold = 0, first_nonmanifold = -1, nonplanar = 0;
    double max_warp = 0, max_relative = 0;
    for (const auto& [key, list] : faces) {
      for (std::size_t i = 0; i < list.size(); ++i) {
        const std::int64_t expected = list.size() == 1   ? kBoundary
                                      : list.size() == 2 ? list[1 - i].second
                                                         : kNonManifold;
        if (t.neighbor[list[i].first] != kSplitFace) EXPECT_EQ(t.neighbor[list[i].first], expected) << kind;
      }
      shared += list.size() == 2;
      if (list.size() > 2 && nonmanifold++ == 0) first_nonmanifold = list[0].second;
      if (key[3] != std::numeric_limits<std::int64_t>::max()) {
        const std::int64_t c = list[0].second;
        const FaceDef& d = cell_def(v.type(c)).face[list[0].first - t.face_offsets[c]];
        glm::dvec3 q[4];
        for (int k = 0; k < 4; ++k) q[k] = v.point(v.cell(c)[d.v[k]]);
        const double warp = quad_warp(q[0], q[1], q[2], q[3]);
        const double diag = 0.5 * (glm::length(q[2] - q[0]) + glm::length(q[3] - q[1]));
        max_warp = std::max(max_warp, warp), max_relative = std::max(max_relative, diag > 0 ? warp / diag : 0.0);
        nonplanar += diag > 0 && warp / diag > kNonPlanarRelative;
      }
    }
    EXPECT_GT(nonmanifold, 0) << kind;
    EXPECT_EQ(t.shared_faces, shared + static_cast<std::int64_t>(t.split_faces.size())) << kind;
    EXPECT_EQ(t.nonmanifold_faces, nonmanifold) << kind;
    EXPECT_EQ(t.first_nonmanifold_cell, first_nonmanifold) << kind;
    EXPECT_EQ(t.nonplanar_faces, nonplanar) << kind;
    EXPECT_EQ(t.max_nonplanarity, max_warp) << kind;
    EXPECT_EQ(t.max_relative_nonplanarity, max_relative) << kind;
  }
}
