// Isoparametric cells in the exact renderer: shape functions, Newton inversion, analytic integrals.
#include <cmath>

#include <gtest/gtest.h>

#include "mesh/validate.hpp"
#include "raycast/reference_renderer.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

Camera down_on_unit_square() { return test::looking_down(1.0, {0.5, 0.5, 0}); }  // x to the right, y up

}  // namespace

TEST(ShapeFunctions, PartitionOfUnityAndDerivatives) {
  for (CellType type : {CellType::Hexahedron, CellType::Wedge, CellType::Pyramid}) {
    const glm::dvec3 xi{0.21, 0.33, 0.45};
    double w[8], wp[8], wm[8];
    glm::dvec3 dw[8];
    const int n = shape_functions(type, xi, w, dw);
    double sum = 0.0;
    for (int k = 0; k < n; ++k) sum += w[k];
    EXPECT_NEAR(sum, 1.0, 1e-15) << cell_name(type);
    for (int axis = 0; axis < 3; ++axis) {  // central differences, exact for these polynomials
      glm::dvec3 h(0.0);
      h[axis] = 1e-4;
      shape_functions(type, xi + h, wp);
      shape_functions(type, xi - h, wm);
      for (int k = 0; k < n; ++k) EXPECT_NEAR(dw[k][axis], (wp[k] - wm[k]) / 2e-4, 1e-9) << cell_name(type) << k;
    }
  }
}

TEST(IsoparametricField, NewtonFindsTheNaturalCoordinatesOfAWarpedHexahedron) {
  Mesh m = make_curvilinear(
      1, 1, 1,
      [](const glm::dvec3& u) {
        return glm::dvec3(u.x + 0.3 * u.y * u.z, u.y + 0.2 * u.x * u.z, u.z * (1 + 0.25 * u.x * u.y));
      },
      false);
  set_field(m, "s", [](const glm::dvec3& x) { return x.x; });
  const MeshView v = m.view();
  std::vector<double> sxi(8);  // a field equal to the natural coordinate r at the vertices
  for (int k = 0; k < 8; ++k) sxi[v.cell(0)[k]] = (k == 1 || k == 2 || k == 5 || k == 6) ? 1.0 : 0.0;
  const std::vector<double> xyz(m.points);
  const IsoparametricField field(v, xyz.data());
  const glm::dvec3 target{0.3, 0.7, 0.6};
  double w[8];
  shape_functions(CellType::Hexahedron, target, w);
  glm::dvec3 p(0.0);
  for (int k = 0; k < 8; ++k) p += w[k] * v.point(v.cell(0)[k]);
  glm::dvec3 xi = field.centre_guess(0);
  double s = -1;
  ASSERT_TRUE(field.value(sxi.data(), 0, p, xi, s));
  EXPECT_NEAR(xi.x, target.x, 1e-12);
  EXPECT_NEAR(xi.y, target.y, 1e-12);
  EXPECT_NEAR(xi.z, target.z, 1e-12);
  EXPECT_NEAR(s, target.x, 1e-12);
}

// s = x y z is trilinear, so isoparametric hexahedra hold it exactly: a ray down z at (x, y) with
// kappa = 3 s has optical depth 3 x y / 2. The canonical tetrahedra cannot hold it.
TEST(ExactRendererIsoparametric, TrilinearFieldInHexahedraMatchesTheClosedForm) {
  Mesh m = make_box(2, 2, 2, glm::dvec3(0), glm::dvec3(1), false);
  set_field(m, "s", [](const glm::dvec3& x) { return x.x * x.y * x.z; });
  const glm::dvec3 C{0.9, 0.5, 0.1};
  const TransferFunction tf({{0.0, C}}, {{0.0, 0.0}, {1.0, 3.0}});
  const Image iso = test::exact(m, "s", tf, down_on_unit_square(), 8, 8);
  const Image tets = test::exact(m, "s", tf, down_on_unit_square(), 8, 8, CellInterpolation::canonical_tets);
  double largest_tet_difference = 0.0;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const double x = (i + 0.5) / 8, y = 1 - (j + 0.5) / 8;
      const double A = 1 - std::exp(-1.5 * x * y);
      const float* p = iso.pixel(i, j);
      ASSERT_NEAR(p[3], A, 1e-6) << i << "," << j;
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(p[k], C[k] * A, 1e-6);
      largest_tet_difference = std::max(largest_tet_difference, std::abs(tets.pixel(i, j)[3] - A));
    }
  EXPECT_GT(largest_tet_difference, 1e-3);  // the mode matters
}

// A field linear in space is reproduced exactly by every isoparametric cell, however warped, and
// by the canonical tetrahedra: on a twisted mixed mesh both modes must agree.
TEST(ExactRendererIsoparametric, LinearFieldOnATwistedMixedMeshAgreesWithTheTetrahedra) {
  Mesh m = generate("mixed", 4);
  EXPECT_EQ(validate(m.view()).inverted.size(), 0u);
  set_field(m, "s", [](const glm::dvec3& x) { return 0.5 + 0.2 * x.x - 0.15 * x.y + 0.1 * x.z; });
  const TransferFunction tf({{0.0, {1, 0, 0}}, {0.5, {0, 1, 0}}, {1.0, {0, 0, 1}}},
                            {{0.0, 0.2}, {0.6, 2.0}, {1.0, 0.5}});
  Camera c;
  c.projection = Projection::Perspective;
  c.eye = {2.5, -3.0, 2.0};
  c.up = {0, 0, 1};
  c.fov_y = 40;
  ExactStats st;
  const Image iso = test::exact(m, "s", tf, c, 48, 48, CellInterpolation::isoparametric, &st);
  const Image tets = test::exact(m, "s", tf, c, 48, 48, CellInterpolation::canonical_tets);
  EXPECT_EQ(st.newton_failures, 0);
  const ImageDifference d = compare(iso, tets);
  EXPECT_LT(d.max_abs, 1e-6);
  double covered = 0.0;
  for (int j = 0; j < 48; ++j)
    for (int i = 0; i < 48; ++i) covered += iso.pixel(i, j)[3] > 0.05;
  EXPECT_GT(covered, 300);  // the mesh is in the picture
}
