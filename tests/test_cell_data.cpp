// Cell data as a finite-volume solver writes it, drawn constant over each cell (each cell its own
// points, its faces seams matched by position): exact in every method, the jump at a shared face
// kept; or averaged to the points.
#include <cmath>

#include <gtest/gtest.h>

#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"
#include "mesh/cell_data.hpp"
#include "mesh/generate.hpp"
#include "mesh/geometry.hpp"
#include "raycast/iso_layers.hpp"
#include "render/renderer.hpp"
#include "render/settings_table.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

// The unit tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1) with one cell value.
Mesh unit_tet(double value) {
  Mesh m;
  m.source = "one tetrahedron";
  for (const glm::dvec3& p : {glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)})
    m.add_point(p);
  m.add_cell(CellType::Tetra, {0, 1, 2, 3});
  m.cell_fields.push_back({"c", {value}, "cell data", 1});
  return m;
}

Image render_with(const std::string& method, const Mesh& m, const TransferFunction& tf, const Camera& camera,
                  int size) {
  RenderOptions o;
  set_option(o, "method", method);
  if (method == "slicing") set_option(o, "slices", "1024");
  return make_renderer(settings_from(o))->render(Volume(m.view()), field_of(m, "c"), tf, camera, {size, size});
}

}  // namespace

// Orthographic from +z down onto the tetrahedron: at (x, y) the ray crosses the cell from z = 0 to
// the face x + y + z = 1, a chord of L = 1 - x - y, and alpha = 1 - exp(-kappa L) (MWSC: constant
// extinction over the segment) in every method.
TEST(CellData, AConstantCellIsTheExponentialOfItsChordInEveryMethod) {
  Mesh m = unit_tet(0.7);
  apply_cell_data(m, CellData::cells);
  const double kappa = 2.5;
  const TransferFunction tf({{0.0, {0.2, 0.6, 1.0}}, {1.0, {1.0, 0.4, 0.1}}}, {{0.0, 0.0}, {1.0, kappa / 0.7}});
  const int size = 64;
  const Camera camera = test::looking_down(1.0, {0.5, 0.5, 0.5});
  struct Bound {
    const char* method;
    double tolerance;
  };
  for (const Bound b : {Bound{"pt-breakpoints", 1e-5}, Bound{"pt-analytic", 1e-5}, Bound{"pt-table", 2e-3},
                        Bound{"exact", 1e-5}, Bound{"slicing", 3e-3}}) {
    SCOPED_TRACE(b.method);
    const Image img = render_with(b.method, m, tf, camera, size);
    for (const auto [i, j] : {std::pair{10, 50}, std::pair{20, 45}, std::pair{12, 40}}) {
      const double x = (i + 0.5) / size, y = 1.0 - (j + 0.5) / size;  // row 0 at the top
      ASSERT_LT(x + y, 1.0);
      const double alpha = 1.0 - std::exp(-kappa * (1.0 - x - y));
      EXPECT_NEAR(img.rgba[(static_cast<std::size_t>(j) * size + i) * 4 + 3], alpha, b.tolerance) << i << "," << j;
    }
  }
}

// Two cells side by side, seen from above: each pixel shows its own cell's colour, unblended up to
// the shared face (the jump a solver's cells have), where averaging to the points blends them.
TEST(CellData, TwoCellsShowTheJumpAtTheirSharedFace) {
  Mesh m = make_box(2, 1, 1, glm::dvec3(0), glm::dvec3(2, 1, 1), false);  // two hexahedra, shared face x = 1
  m.cell_fields.push_back({"c", {0.0, 1.0}, "cell data", 1});
  Mesh averaged = m;
  apply_cell_data(m, CellData::cells);
  apply_cell_data(averaged, CellData::points);
  EXPECT_EQ(m.n_points(), 16);  // each hexahedron its 8 corners
  const TransferFunction tf({{0.0, {0.0, 0.0, 1.0}}, {1.0, {1.0, 0.0, 0.0}}}, {{0.0, 1.0}, {1.0, 1.0}});
  const Camera camera = test::looking_down(1.0, {1.0, 0.5, 0.5});  // x from 0.5 to 1.5 across the image
  const int size = 64;
  const Image cells = render_with("exact", m, tf, camera, size);
  const Image points =
      make_renderer({})->render(Volume(averaged.view()), field_of(averaged, "c"), tf, camera, {size, size});
  const auto red = [&](const Image& img, int i) {  // un-premultiplied red at column i, middle row
    const std::size_t at = (static_cast<std::size_t>(size / 2) * size + i) * 4;
    return img.rgba[at] / img.rgba[at + 3];
  };
  EXPECT_NEAR(red(cells, size / 2 - 1), 0.0, 1e-5);  // the last column left of x = 1: the blue cell alone
  EXPECT_NEAR(red(cells, size / 2), 1.0, 1e-5);      // the first right of it: the red cell alone
  EXPECT_GT(red(points, size / 2 - 1), 0.3);         // averaged: a blend on both sides
  EXPECT_LT(red(points, size / 2), 0.7);
}

// pt-breakpoints equals the exact renderer to 1e-6 with cell data, as with point data: the field is
// constant over each cell, and the cells' faces between them are seams the sort orders across.
TEST(CellData, BreakpointsEqualTheExactRendererWithCellData) {
  Mesh m = make_box(6, 6, 6, glm::dvec3(-1), glm::dvec3(1), true);
  const MeshView view = m.view();
  std::vector<double> values;
  for (std::int64_t c = 0; c < m.n_cells(); ++c) {
    const glm::dvec3 x = cell_centroid(view, c);
    values.push_back(0.5 + 0.5 * std::sin(3 * x.x) * std::cos(2 * x.y + x.z));
  }
  m.cell_fields.push_back({"c", values, "cell data", 1});
  apply_cell_data(m, CellData::cells);
  const TransferFunction tf({{0.0, {0.1, 0.2, 0.9}}, {0.5, {0.9, 0.9, 0.2}}, {1.0, {1, 0.2, 0.1}}},
                            {{0.0, 0.3}, {0.4, 3.0}, {1.0, 1.0}});
  const Camera camera = test::view_from({2.5, -2, 1.8}, Projection::Perspective);
  const Image e = render_with("exact", m, tf, camera, 48), b = render_with("pt-breakpoints", m, tf, camera, 48);
  double worst = 0, alpha = 0;
  for (std::size_t i = 0; i < e.rgba.size(); ++i) worst = std::max(worst, double(std::abs(e.rgba[i] - b.rgba[i])));
  for (std::size_t i = 3; i < e.rgba.size(); i += 4) alpha += e.rgba[i];
  EXPECT_LT(worst, 1e-6);
  EXPECT_GT(alpha / (e.rgba.size() / 4), 0.2);
}

// A file's cell data read either way; the default draws the cells, and info's mode keeps them as read.
TEST(CellData, AFilesCellDataIsReadEitherWay) {
  const test::TempDir dir;
  Mesh m = make_box(3, 3, 3, glm::dvec3(0), glm::dvec3(1), true);
  set_field(m, "p", [](const glm::dvec3& x) { return x.x; });
  std::vector<double> c(static_cast<std::size_t>(m.n_cells()));
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = double(i);
  m.cell_fields.push_back({"p", c, "cell data", 1});  // the same name as a point field: read back as p_cell
  write_vtu(m, dir.file("m.vtu"));
  ReadOptions keep;
  keep.cell_data.reset();
  const LoadedMesh raw = load_mesh(dir.file("m.vtu"), keep);
  ASSERT_EQ(raw.mesh.cell_fields.size(), 1u);
  EXPECT_EQ(raw.mesh.cell_fields[0].name, "p_cell");
  EXPECT_EQ(raw.mesh.cell_fields[0].values, c);
  const LoadedMesh cells = load_mesh(dir.file("m.vtu"));
  EXPECT_EQ(cells.mesh.n_points(), 4 * m.n_cells());
  EXPECT_EQ(cells.mesh.field("p_cell").values[cells.mesh.connectivity[4 * 5 + 2]], 5.0);  // cell 5's third corner
  ReadOptions points;
  points.cell_data = CellData::points;
  const LoadedMesh averaged = load_mesh(dir.file("m.vtu"), points);
  EXPECT_EQ(averaged.mesh.n_points(), m.n_points());
  EXPECT_TRUE(averaged.mesh.find_field("p_cell"));
}

// Cell data crosses an iso-value only where one cell meets the next: its iso-surface is the faces
// between cells whose values straddle it (a staircase, as the solver's cells are), found by the
// layers and the exact renderer's surfaces and shaded by the face's normal, not drawn flat.
TEST(CellData, AnIsoValueBetweenTwoCellsIsTheirSharedFaceShadedByItsNormal) {
  Mesh m = make_box(2, 1, 1, glm::dvec3(0), glm::dvec3(2, 1, 1), false);  // two hexahedra, shared face x = 1
  m.cell_fields.push_back({"c", {0.0, 1.0}, "cell data", 1});
  apply_cell_data(m, CellData::cells);
  const Camera camera = test::perspective({3.5, -2.2, 2.4}, {1.0, 0.5, 0.5}, 40);
  const int n = 48;
  const CellRayTracer tracer(m.view());
  const double* values = test::field_values(m, "c");
  const LayerDepths d = layer_depths(tracer, values, 0.5, iso_tolerance(0.5, 0.0, 1.0), camera, n, n, 1);
  LayerOptions o;
  o.iso = 0.5, o.layers = {1};
  const glm::dvec3 base(0.9, 0.6, 0.3);
  const Image img = render_layers(tracer, values, m.n_points(), test::constant_tf(1.0, base), camera, n, n, o);
  int on_face = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::size_t p = static_cast<std::size_t>(j) * n + i;
      const Ray ray = PixelRays(camera, n, n).ray(i + 0.5, j + 0.5);
      // Where the ray meets the plane x = 1 inside the face, it crosses 0.5 once, there.
      const double t = (1.0 - ray.origin.x) / ray.dir.x;
      const glm::dvec3 hit = ray.origin + t * ray.dir;
      const bool inside = hit.y > 0.02 && hit.y < 0.98 && hit.z > 0.02 && hit.z < 0.98;
      const bool outside = hit.y < -0.02 || hit.y > 1.02 || hit.z < -0.02 || hit.z > 1.02;
      if (!inside && !outside) continue;  // near the face's edges: either
      ASSERT_EQ(d.count[p], inside ? 1 : 0) << i << "," << j;
      if (!inside) continue;
      ++on_face;
      EXPECT_NEAR(d.t[p], t, 1e-9 * (1.0 + t));
      const glm::dvec3 expect = shade_layer(base, {1.0, 0.0, 0.0}, ray.dir);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(img.pixel(i, j)[c], expect[c], 1e-6) << i << "," << j;
    }
  EXPECT_GT(on_face, 100);
}
