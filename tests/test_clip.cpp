// Clipping planes (issue 19): a mesh clipped by planes renders as the same volume built directly
// on the kept region, through vertices, faces and cells alike, with no crack, for the exact
// renderer and cell projection.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "mesh/clip.hpp"
#include "mesh/generate.hpp"
#include "mesh/geometry.hpp"
#include "mesh/tetrahedralize.hpp"
#include "mesh/topology.hpp"
#include "mesh/validate.hpp"
#include "tests/test_util.hpp"

namespace cellproj {
namespace {

// A field linear in x, y, z: exactly what the tetrahedra of any split carry.
double linear(const glm::dvec3& x) { return 0.5 + 0.3 * x.x - 0.2 * x.y + 0.25 * x.z; }

Mesh box(int nx, int ny, int nz, glm::dvec3 lo, glm::dvec3 hi, bool tets) {
  Mesh m = make_box(nx, ny, nz, lo, hi, tets);
  set_field(m, "f", linear);
  return m;
}

const TransferFunction& tf() {
  static const TransferFunction t({{0.0, {0.2, 0.4, 1.0}}, {1.0, {1.0, 0.6, 0.2}}}, {{0.0, 1.0}, {1.0, 5.0}});
  return t;
}

// The exact picture of `clipped` against that of the kept region meshed directly, from a corner.
void expect_same_volume(const Mesh& clipped, const Mesh& direct, const std::string& what) {
  const Camera camera = test::view_from({2.5, -3.0, 2.0}, Projection::Perspective);
  const Image a = test::exact(clipped, "f", tf(), camera, 48, 48);
  const Image b = test::exact(direct, "f", tf(), camera, 48, 48);
  const ImageDifference d = compare(a, b);
  EXPECT_LT(d.max_abs, 1e-6) << what;
  EXPECT_GT(*std::max_element(b.rgba.begin(), b.rgba.end()), 0.2f) << what;
}

TEST(Clip, APlaneThroughCellsKeepsExactlyTheVolumeOnItsSide) {
  // z = 0.3 cuts through the cells of a 4^3 box of [-1, 1]^3 (hexahedra and tetrahedra): the kept
  // part is the box [-1, 1]^2 x [-1, 0.3], whose linear field any mesh of it carries exactly.
  for (bool tets : {false, true}) {
    ClipReport r;
    const Mesh m = clip_mesh(box(4, 4, 4, glm::dvec3(-1), glm::dvec3(1), tets), {{{0, 0, 0.3}, {0, 0, 1}}}, &r);
    EXPECT_GT(r.cut, 0);
    EXPECT_GT(r.dropped, 0);
    EXPECT_GT(r.kept_whole, 0);
    EXPECT_EQ(validate(m.view()).inverted_cells, 0);
    expect_same_volume(m, box(3, 3, 3, glm::dvec3(-1), {1, 1, 0.3}, true), tets ? "tetrahedra" : "hexahedra");
  }
}

TEST(Clip, PlanesThroughVerticesFacesAndOnADiagonalLeaveNoCrack) {
  // x = 0 runs through vertices and faces of the grid; a tilted plane through the diagonal of
  // faces; two planes at once. The clipped mesh is conforming: its boundary is the kept convex
  // region's, no face inside it is left unmatched.
  const Mesh whole = box(4, 4, 4, glm::dvec3(-1), glm::dvec3(1), false);
  const Mesh half = clip_mesh(whole, {{{0, 0, 0}, {1, 0, 0}}});
  expect_same_volume(half, box(2, 4, 4, glm::dvec3(-1), {0, 1, 1}, true), "x = 0, through vertices and faces");
  const Mesh wedge = clip_mesh(whole, {{{0, 0, 0}, {1, 1, 0}}, {{0, 0, 0.45}, {0, 0, 1}}});
  const FaceTopology topo = build_topology(wedge.view());
  EXPECT_EQ(topo.nonmanifold_faces, 0);
  EXPECT_TRUE(boundary_convexity(wedge.view(), topo).convex) << "a crack would leave boundary faces inside";
  // The kept region x + y <= 0, z <= 0.45 of the box has 1/2 of the box's base over 1.45 of its height.
  double volume = 0.0;
  const MeshView v = wedge.view();
  for (std::int64_t c = 0; c < v.n_cells; ++c) {
    Tet t[kMaxTetsPerCell];
    const int n = canonical_tetrahedra(v, c, t);
    for (int k = 0; k < n; ++k)
      volume += std::abs(tet_volume6(v.point(t[k][0]), v.point(t[k][1]), v.point(t[k][2]), v.point(t[k][3]))) / 6;
  }
  EXPECT_NEAR(volume, 2.0 * 1.45, 1e-12);
}

TEST(Clip, ProjectionDrawsTheClippedMeshAsExactDoes) {
  const Mesh m = clip_mesh(generate("swirl-tets", 5), {{{0.1, 0.0, 0.0}, {1, 0.3, 0.2}}});
  const Camera camera = test::view_from({1.6, -2.6, 2.2}, Projection::Perspective);
  const TransferFunction t({{0.0, {0.2, 0.4, 1.0}}, {1.0, {1.0, 0.6, 0.2}}}, {{0.0, 1.0}, {1.0, 8.0}});
  const Image p = test::project(m, "", t, camera, 48);
  const Image e = test::exact(m, "", t, camera, 48, 48);
  EXPECT_LT(compare(p, e).max_abs, 1e-5);
}

TEST(Clip, TheWeightsMapAFieldOntoTheClippedPointsAsClippingItDoes) {
  // A field carried through clip_mesh and the same field mapped by the weights agree; a point kept
  // has itself as its one source.
  Mesh m = test::twisted_mixed(4);
  PointField& f = m.add_field("f", "test");
  for (std::int64_t p = 0; p < m.n_points(); ++p) f.values[p] = std::cos(3 * m.view().point(p).x) + p % 7;
  for (int planes = 1; planes <= 3; ++planes) {
    const std::vector<ClipPlane> all = {
        {{0.1, 0, 0}, {1, 0.3, 0}}, {{0, 0, 0.2}, {0.2, 0, 1}}, {{0, -0.4, 0}, {0, -1, 0.5}}};
    const std::vector<ClipPlane> use(all.begin(), all.begin() + planes);
    ClipWeights w;
    const Mesh c = clip_mesh(m, use, nullptr, &w);
    ASSERT_EQ(w.size(), c.n_points());
    const std::vector<double> mapped = w.apply(m.field("f").values);
    double worst = 0.0;
    for (std::int64_t p = 0; p < c.n_points(); ++p)
      worst = std::max(worst, std::abs(mapped[p] - c.field("f").values[p]));
    EXPECT_LT(worst, 1e-12) << planes << " planes";
    int single = 0;
    for (std::int64_t p = 0; p < w.size(); ++p)
      single += w.start[p + 1] - w.start[p] == 1 && w.weight[w.start[p]] == 1.0;
    EXPECT_GT(single, 0);
  }
}

TEST(Clip, ABadPlaneIsRefused) {
  EXPECT_THROW(clip_mesh(generate("box", 2), {{{0, 0, 0}, {0, 0, 0}}}), InputError);
  EXPECT_THROW(clip_mesh(generate("box", 2), {{{0, NAN, 0}, {0, 0, 1}}}), InputError);
  EXPECT_EQ(clip_mesh(generate("box", 2), {{{0, 0, -5}, {0, 0, 1}}}).n_cells(), 0) << "nothing on the kept side";
}

}  // namespace
}  // namespace cellproj
