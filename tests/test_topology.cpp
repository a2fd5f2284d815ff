#include <gtest/gtest.h>

#include "grid/topology.hpp"
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
