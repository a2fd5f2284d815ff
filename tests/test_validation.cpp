#include <cmath>
#include <map>
#include <random>
#include <tuple>

#include <gtest/gtest.h>

#include "base/error.hpp"
#include "mesh/geometry.hpp"
#include "mesh/overlaps.hpp"
#include "mesh/tetrahedralize.hpp"
#include "mesh/topology.hpp"
#include "mesh/validate.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

Mesh unit_tet() {
  Mesh m;
  m.source = "t.vtu";
  for (glm::dvec3 p : {glm::dvec3(0, 0, 0), {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}) m.add_point(p);
  m.add_cell(CellType::Tetra, {0, 1, 2, 3});
  m.add_field("s", "test").values = {0, 1, 2, 3};
  return m;
}

std::string error_of(const MeshView& v) {
  try {
    validate(v);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Validation, ErrorsNameTheFileAndTheElement) {
  Mesh m = unit_tet();
  m.connectivity[2] = 7;
  EXPECT_NE(error_of(m.view()).find("t.vtu: cell 0 (tetra) refers to point 7, out of range [0, 4)"), std::string::npos);
  m = unit_tet();
  m.points[4] = NAN;
  EXPECT_NE(error_of(m.view()).find("point 1 has a non-finite coordinate (y"), std::string::npos);
  m = unit_tet();
  m.fields[0].values[2] = INFINITY;
  try {
    check_finite(m.source, m.fields[0]);
    ADD_FAILURE() << "a non-finite field value passed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("t.vtu: field 's' is not finite at point 2"), std::string::npos) << e.what();
  }
  m = unit_tet();
  m.types[0] = 24;  // quadratic tetra
  EXPECT_NE(error_of(m.view()).find("quadratic_tetra (24): 1 cells (first: cell 0)"), std::string::npos);
  try {
    m.field("pressure");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no point field named 'pressure'; the fields are: s"), std::string::npos);
  }
}

TEST(Validation, InvertedDegenerateAndDuplicateAreCounted) {
  Mesh m = unit_tet();
  m.add_point({0, 0, 0});  // a duplicate of point 0
  m.add_point({2, 0, 0});
  m.add_point({0, 2, 0});
  m.add_point({3, 0, 0});
  m.fields[0].values.resize(8, 0.0);
  m.add_cell(CellType::Tetra, {5, 4, 6, 0 + 3});  // inverted
  m.add_cell(CellType::Tetra, {4, 5, 7, 6});      // flat: all in z = 0
  const auto r = validate(m.view());
  EXPECT_EQ(r.inverted_cells, 1);
  EXPECT_EQ(r.first_inverted, 1);
  EXPECT_EQ(r.degenerate_cells, 1);
  EXPECT_EQ(r.duplicate_points, 1);
  EXPECT_EQ(r.first_duplicate, 4);
  EXPECT_EQ(reorient_inverted(m, r), 1);
  EXPECT_GT(cell_signed_volume(m.view(), 1), 0);
}

TEST(Validation, EveryCellTypeReorientsToPositiveVolume) {
  // A hexahedron, wedge and pyramid mirrored (z -> -z) have negative volume until re-oriented.
  Mesh m;
  for (int k = 0; k < 2; ++k)
    for (glm::dvec3 p : {glm::dvec3(0, 0, 0), {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}) m.add_point(p + glm::dvec3(0, 0, -k));
  m.add_point({0.5, 0.5, -1});
  m.add_cell(CellType::Hexahedron, {0, 1, 2, 3, 4, 5, 6, 7});
  m.add_cell(CellType::Wedge, {0, 3, 1, 4, 7, 5});
  m.add_cell(CellType::Pyramid, {0, 1, 2, 3, 8});
  const auto r = validate(m.view());
  EXPECT_EQ(r.inverted_cells, 3);
  reorient_inverted(m, r);
  for (int c = 0; c < 3; ++c) EXPECT_GT(cell_signed_volume(m.view(), c), 0) << c;
  EXPECT_NEAR(cell_signed_volume(m.view(), 0), 1.0, 1e-12);
  EXPECT_NEAR(cell_signed_volume(m.view(), 1), 0.5, 1e-12);
  EXPECT_NEAR(cell_signed_volume(m.view(), 2), 1.0 / 3, 1e-12);
}

TEST(Tetrahedralize, CanonicalSplitConservesVolumeAndConforms) {
  auto warp = [](const glm::dvec3& u) {
    return glm::dvec3(u.x + 0.2 * u.y * u.z, u.y + 0.15 * u.x * u.x, u.z + 0.1 * std::sin(3 * u.x));
  };
  const Mesh hex = make_curvilinear(2, 2, 2, warp, false);
  const Mesh tets = make_curvilinear(2, 2, 2, warp, true);
  EXPECT_EQ(tets.n_cells(), 6 * hex.n_cells());
  const auto rt = validate(tets.view());
  EXPECT_EQ(rt.inverted_cells, 0);
  EXPECT_EQ(rt.degenerate_cells, 0);
  // Conforming: every interior triangle is shared by exactly two tetrahedra, no hanging faces.
  const FaceTopology t = build_topology(tets.view());
  EXPECT_EQ(t.nonmanifold_faces, 0);
  EXPECT_EQ(static_cast<std::int64_t>(t.boundary.size()), 6 * 4 * 2);  // 6 sides x 4 quads x 2 triangles
  double vt = 0;
  for (double v : rt.volumes) vt += v;
  double vh = 0;  // hexahedra with their faces split the same way have the same volume
  for (std::int64_t c = 0; c < hex.n_cells(); ++c) {
    Tet out[kMaxTetsPerCell];
    const int n = canonical_tetrahedra(hex.view(), c, out);
    for (int k = 0; k < n; ++k)
      vh += tet_volume6(hex.view().point(out[k][0]), hex.view().point(out[k][1]), hex.view().point(out[k][2]),
                        hex.view().point(out[k][3])) /
            6;
  }
  EXPECT_NEAR(vt, vh, 1e-12);
}

// Cells whose interiors overlap are found; cells that only touch (at a face, an edge, a vertex, or
// across a gap thinner than rounding) are not.
TEST(Overlaps, OverlappingCellsAreFoundTouchingOnesAreNot) {
  for (const char* kind : {"box-tets", "box", "mixed", "swirl"}) {
    const OverlapReport r = overlapping_cells(generate(kind, 4).view());
    EXPECT_EQ(r.cell_pairs, 0) << kind;
    EXPECT_GT(r.candidates, 0) << kind;  // neighbours' boxes meet: the test did run
  }
  Mesh m = generate("box", 3);          // 27 hexahedra over [-1, 1]^3
  test::append(m, generate("box", 1));  // one hexahedron over all of them
  const OverlapReport all = overlapping_cells(m.view());
  EXPECT_EQ(all.cell_pairs, 27);
  EXPECT_EQ(all.first_a, 0);
  EXPECT_EQ(all.first_b, 27);
  // Two tetrahedra on the triangle z = 0, one above and one below it, each moved by `lift`.
  auto pair_with = [](double lift) {
    Mesh t;
    const std::int64_t a = t.add_point({0, 0, 0}), b = t.add_point({1, 0, 0}), c = t.add_point({0, 1, 0});
    const std::int64_t up = t.add_point({0.2, 0.2, 1});
    t.add_cell(CellType::Tetra, {a, b, c, up});
    const std::int64_t a2 = t.add_point({0, 0, lift}), b2 = t.add_point({1, 0, lift}), c2 = t.add_point({0, 1, lift});
    const std::int64_t down = t.add_point({0.3, 0.3, lift - 1});
    t.add_cell(CellType::Tetra, {a2, c2, b2, down});
    return overlapping_cells(t.view()).cell_pairs;
  };
  EXPECT_EQ(pair_with(0.0), 0);    // sharing a face's place
  EXPECT_EQ(pair_with(-0.1), 0);   // apart
  EXPECT_EQ(pair_with(1e-12), 0);  // into each other by 1e-12 of their size: a contact
  EXPECT_EQ(pair_with(1e-3), 1);   // into each other
  EXPECT_EQ(pair_with(0.5), 1);
}

// Duplicate points found by hashing their coordinates equal those of a map keyed by coordinates:
// groups of two and three, -0 with +0, and points that differ in one bit of one coordinate.
TEST(Validation, DuplicatePointsMatchAMapOfCoordinates) {
  Mesh m = generate("box", 12);
  std::mt19937 rng(5);
  std::uniform_int_distribution<std::int64_t> any(0, m.n_points() - 1);
  for (int k = 0; k < 300; ++k) m.add_point(m.view().point(any(rng)));  // a copy of some point
  m.add_point({0.0, -0.0, 1.0}), m.add_point({-0.0, 0.0, 1.0});
  const glm::dvec3 x = m.view().point(3);
  m.add_point({std::nextafter(x.x, 10.0), x.y, x.z});  // one bit apart: not a duplicate
  m.fields[0].values.resize(static_cast<std::size_t>(m.n_points()), 0.0);
  const ValidationReport r = validate(m.view());

  std::map<std::tuple<double, double, double>, std::int64_t> first;  // coordinates -> lowest id
  std::int64_t duplicates = 0, first_duplicate = -1;
  for (std::int64_t p = 0; p < m.n_points(); ++p) {
    const glm::dvec3 q = m.view().point(p);
    if (!first.emplace(std::make_tuple(q.x, q.y, q.z), p).second) {
      ++duplicates;
      if (first_duplicate < 0) first_duplicate = p;
    }
  }
  EXPECT_GE(duplicates, 250);
  EXPECT_EQ(r.duplicate_points, duplicates);
  EXPECT_EQ(r.first_duplicate, first_duplicate);
}
