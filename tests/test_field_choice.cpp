// Fields as solvers write them: a vector or tensor kept whole by the readers, one scalar of it
// chosen by every spelling a user brings (NAME:x, ParaView's NAME_X, the magnitude, the von Mises
// stress), the same picture whichever door the field came in by.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"
#include "mesh/field_choice.hpp"
#include "mesh/generate.hpp"
#include "render/field_set.hpp"
#include "render/renderer.hpp"
#include "scene/prepare.hpp"
#include "scene/quick_scene.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

// A 3^3 box of tetrahedra with a scalar, a vector, a symmetric and a full tensor per point.
Mesh fields_box() {
  Mesh m = make_box(3, 3, 3, glm::dvec3(-1), glm::dvec3(1), true);
  set_field(m, "p", [](const glm::dvec3& x) { return x.x + 2 * x.y; });
  m.add_field("V", "test", 3);
  m.add_field("S", "test", 6);
  m.add_field("T", "test", 9);
  for (std::int64_t p = 0; p < m.n_points(); ++p)
    for (int k = 0; k < 9; ++k) {
      const double value = 0.1 * (k + 1) + m.points[3 * p + k % 3];
      if (k < 3) m.fields[1].values[3 * p + k] = value;
      if (k < 6) m.fields[2].values[6 * p + k] = value;
      m.fields[3].values[9 * p + k] = value;
    }
  return m;
}

}  // namespace

TEST(FieldChoice, EverySpellingOfAComponentChoosesIt) {
  const Mesh m = fields_box();
  for (const char* spec : {"V:x", "V:X", "V_X", "V_x", "V:0"}) {
    const FieldChoice c = choose_field(m, spec);
    EXPECT_EQ(c.field, "V") << spec;
    EXPECT_EQ(c.component, 0) << spec;
    EXPECT_EQ(c.name, "V:x") << spec;
  }
  EXPECT_EQ(choose_field(m, "V_Z").component, 2);
  EXPECT_EQ(choose_field(m, "V:magnitude").component, FieldChoice::kMagnitude);
  EXPECT_EQ(choose_field(m, "V_Magnitude").component, FieldChoice::kMagnitude);
  EXPECT_EQ(choose_field(m, "S:yz").component, 4);  // VTK's order XX YY ZZ XY YZ XZ
  EXPECT_EQ(choose_field(m, "T:yz").component, 5);  // row by row
  EXPECT_EQ(choose_field(m, "S_VonMises").component, FieldChoice::kVonMises);
  EXPECT_EQ(choose_field(m, "p").component, FieldChoice::kWhole);
  // A vector alone is its magnitude, and says so.
  const FieldChoice whole = choose_field(m, "V");
  EXPECT_EQ(whole.component, FieldChoice::kMagnitude);
  EXPECT_NE(whole.note.find("V has 3 components: showing its magnitude"), std::string::npos) << whole.note;
}

TEST(FieldChoice, WhatIsNotAFieldIsRefusedNamingWhatIs) {
  const Mesh m = fields_box();
  EXPECT_NE(test::input_error([&] { choose_field(m, "V:w"); }).find("V has 3 components; pick x, y, z, magnitude"),
            std::string::npos);
  EXPECT_NE(test::input_error([&] { choose_field(m, "V:3"); }).find("or 0..2"), std::string::npos);
  EXPECT_NE(test::input_error([&] { choose_field(m, "V:von_mises"); }).find("V has 3 components"), std::string::npos);
  EXPECT_NE(test::input_error([&] { choose_field(m, "p:x"); }).find("p is a scalar"), std::string::npos);
  EXPECT_NE(test::input_error([&] { choose_field(m, "q"); }).find("the fields are: p, V (3 components), S (6"),
            std::string::npos);
  EXPECT_NE(test::input_error([&] { choose_field(m, ""); }).find("several fields"), std::string::npos);
}

TEST(FieldChoice, ScalarsOfAVectorAndATensor) {
  const double v[] = {3, 4, 12};
  EXPECT_EQ(scalar_values(v, 1, 3, 1)[0], 4);
  EXPECT_DOUBLE_EQ(scalar_values(v, 1, 3, FieldChoice::kMagnitude)[0], 13);
  // Von Mises: sqrt of half the squared principal differences plus three times the shears squared.
  const double uniaxial[] = {5, 0, 0, 0, 0, 0}, shear[] = {0, 0, 0, 2, 0, 0};
  EXPECT_DOUBLE_EQ(scalar_values(uniaxial, 1, 6, FieldChoice::kVonMises)[0], 5);
  EXPECT_DOUBLE_EQ(scalar_values(shear, 1, 6, FieldChoice::kVonMises)[0], 2 * std::sqrt(3.0));
  const double full[] = {1, 2, 3, 2, 4, 5, 3, 5, 6}, six[] = {1, 4, 6, 2, 5, 3};  // the same symmetric tensor
  EXPECT_DOUBLE_EQ(scalar_values(full, 1, 9, FieldChoice::kVonMises)[0],
                   scalar_values(six, 1, 6, FieldChoice::kVonMises)[0]);
}

TEST(FieldChoice, AChosenScalarIsMadeOnceAndKeptInTheMesh) {
  Mesh m = fields_box();
  const std::size_t before = m.fields.size();
  const PointField& y = select_field(m, "V_Y");
  EXPECT_EQ(y.name, "V:y");
  EXPECT_EQ(y.values.size(), static_cast<std::size_t>(m.n_points()));
  for (std::int64_t p = 0; p < m.n_points(); ++p) ASSERT_EQ(y.values[p], m.field("V").values[3 * p + 1]);
  select_field(m, "V:y");
  EXPECT_EQ(m.fields.size(), before + 1);
}

TEST(FieldChoice, AFieldSetOverCallerArraysChoosesAsTheMeshDoes) {
  const Mesh m = fields_box();
  const Volume volume(m.view());
  FieldSet set;
  set.add(volume, m);
  const Field x = set.scalar("V_X", "arrays");
  EXPECT_EQ(x.name, "V:x");
  EXPECT_EQ(scalar_values(m.field("V"), 0), std::vector<double>(x.values, x.values + x.size));
  EXPECT_EQ(set.scalar("V:x", "arrays").values, x.values);  // made once
  const std::vector<double> bad(static_cast<std::size_t>(m.n_points() * 3 - 1), 0.0);
  EXPECT_NE(test::input_error([&] {
              set.set(volume, "W", bad.data(), static_cast<std::int64_t>(bad.size()), 3);
            }).find("values for " + std::to_string(m.n_points()) + " points of 3 components"),
            std::string::npos);
}

// The x component read from a .vtu, a CGNS and an Exodus file renders as that component written
// out as a scalar field of its own: bit for bit.
TEST(FieldChoice, AComponentRendersAsTheSameValuesWrittenAsAScalar) {
  if (!std::filesystem::exists(test::shared_data(""))) GTEST_SKIP() << "no ../shared/data beside this clone";
  const test::TempDir dir;
  struct File {
    const char* path;
    const char* spec;
  };
  for (const File f : {File{"cgns_static_mixer/static_mixer.vtu", "Velocity_X"},
                       File{"cgns_static_mixer/StaticMixer.cgns.gz", "Velocity:x"},
                       File{"exodus_disk_out_ref/disk_out_ref.ex2", "V:x"}}) {
    SCOPED_TRACE(f.path);
    LoadedMesh loaded = load_mesh(test::shared_data(f.path));
    const PointField x = select_field(loaded.mesh, f.spec);
    Mesh scalar = loaded.mesh;
    scalar.fields = {{"x", x.values, "written", 1}};
    write_vtu(scalar, dir.file("x.vtu"));
    const LoadedMesh back = load_mesh(dir.file("x.vtu"));
    ASSERT_EQ(back.mesh.field("x").values, x.values);
    const auto [lo, hi] = bounds(loaded.mesh);
    const Camera camera = frame_box(lo, hi, Projection::Orthographic, {0.6, 0.5, 1.0}, {0, 1, 0}, 1.0);
    const auto [vlo, vhi] = std::minmax_element(x.values.begin(), x.values.end());
    const TransferFunction tf({{*vlo, {0, 0, 1}}, {*vhi, {1, 0, 0}}},
                              {{*vlo, 0.0}, {*vhi, 8.0 / glm::length(hi - lo)}});
    const auto renderer = make_renderer({});
    const Image a = renderer->render(Volume(loaded.mesh.view()), field_of(loaded.mesh, x.name), tf, camera, {64, 64});
    const Image b = renderer->render(Volume(back.mesh.view()), field_of(back.mesh, "x"), tf, camera, {64, 64});
    EXPECT_EQ(a.rgba, b.rgba);
  }
}

// The scene's field and the time series' take the same words: a scene of a vector's component.
TEST(FieldChoice, ASceneRendersAVectorsComponent) {
  if (!std::filesystem::exists(test::shared_data(""))) GTEST_SKIP() << "no ../shared/data beside this clone";
  Scene s;
  s.mesh = test::shared_data("exodus_disk_out_ref/disk_out_ref.ex2");
  s.field = "V_Z";
  s.transfer_function = quick_transfer_function(QuickLook{}, 0.0, 1.0, 1.0);
  const PreparedScene p = prepare_scene(s);
  EXPECT_EQ(p.field, "V:z");
  const std::vector<double> z = scalar_values(p.loaded.mesh.field("V"), 2);
  EXPECT_EQ(p.field_min, *std::min_element(z.begin(), z.end()));
}
