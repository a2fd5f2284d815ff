// Fields as solvers write them: a vector or tensor kept whole by the readers, one scalar of it
// chosen by every spelling a user brings (NAME:x, ParaView's NAME_X, the magnitude, the von Mises
// stress), the same picture whichever door the field came in by.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"
#include "mesh/field_choice.hpp"
#include "mesh/generate.hpp"
#include "optics/colormaps.hpp"
#include "render/field_set.hpp"
#include "render/renderer.hpp"
#include "render/settings.hpp"
#include "scene/prepare.hpp"
#include "scene/quick_scene.hpp"
#include "scene/transfer_function_json.hpp"
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
  QuickLook ramp;
  ramp.opacity = "ramp";
  s.transfer_function = quick_transfer_function(ramp, 0.0, 1.0, 1.0);
  const PreparedScene p = prepare_scene(s);
  EXPECT_EQ(p.field, "V:z");
  const std::vector<double> z = scalar_values(p.loaded.mesh.field("V"), 2);
  EXPECT_EQ(p.field_min, *std::min_element(z.begin(), z.end()));
}

// The log scale: log10 of the values at the points, interpolated; the transfer function's points in
// the field's units placed at their logs.
TEST(LogScale, TheFieldIsTheLogOfTheValuesAtThePoints) {
  Mesh m = fields_box();
  set_field(m, "q", [](const glm::dvec3& x) { return std::pow(10.0, 2 * x.x); });
  const PointField& q = m.field("q");
  const std::vector<double> values = q.values;
  const PointField& lq = select_field(m, log_spec("q", {}));
  EXPECT_EQ(lq.name, "log10(q)");
  for (std::size_t p = 0; p < values.size(); ++p) ASSERT_EQ(lq.values[p], std::log10(values[p]));
  // Not above 0: refused with the count and the smallest, or floored.
  const std::string e = test::input_error([&] { select_field(m, log_spec("p", {})); });
  EXPECT_NE(e.find("field 'p' on a log scale: "), std::string::npos) << e;
  EXPECT_NE(e.find("values are not above 0 (the smallest -3"), std::string::npos) << e;
  const PointField& floored = select_field(m, log_spec("p", 0.5));
  EXPECT_EQ(floored.name, "log10(max(p, 0.5))");
  EXPECT_EQ(*std::min_element(floored.values.begin(), floored.values.end()), std::log10(0.5));
  EXPECT_NE(test::input_error([&] { log_spec("p", 0.0); }).find("setting 'log-floor'"), std::string::npos);
  // A vector's component on a log scale, and the name read back.
  EXPECT_EQ(choose_field(m, "log10(V_X)").name, "log10(V:x)");
  EXPECT_EQ(log_scale_scalar("log10(max(V:x, 0.25))"), "V:x");
}

TEST(LogScale, TransferFunctionPointsArePlacedAtTheirLogs) {
  const nlohmann::json j = {{"color_preset", {{"name", "viridis"}}}, {"extinction", {{1.0, 0.0}, {100.0, 2.0}}}};
  const TransferFunction tf = transfer_function_from_json(j, "test", "", 1.0, 100.0, true);
  EXPECT_DOUBLE_EQ(tf.extinction(1.0), 1.0);  // at 10: halfway between 1 and 100 on the log axis
  const std::vector<ColorPoint> map = colormap("viridis", 0.0, 2.0);  // spread evenly over the logs
  EXPECT_EQ(tf.color_points().front().s, 0.0);
  EXPECT_EQ(tf.color_points().back().s, 2.0);
  EXPECT_EQ(tf.color(1.0), TransferFunction(map, {{0, 0}}).color(1.0));
  const nlohmann::json zero = {{"color_preset", {{"name", "viridis"}}}, {"extinction", {{0.0, 0.0}, {100.0, 2.0}}}};
  EXPECT_NE(test::input_error([&] {
              transfer_function_from_json(zero, "test", "", 1.0, 100.0, true);
            }).find("extinction[0]: 0.000000 has no place on a log scale"),
            std::string::npos);
}

// The exact integral holds on a log scale as for any field (the log is what is interpolated):
// pt-breakpoints equals the exact renderer to 1e-6.
TEST(LogScale, BreakpointsEqualTheExactRendererOnALogScale) {
  Mesh m = make_box(5, 5, 5, glm::dvec3(-1), glm::dvec3(1), true);
  set_field(m, "q", [](const glm::dvec3& x) { return std::pow(10.0, 1.5 * x.x + x.y * x.z + 0.5); });
  const PointField& lq = select_field(m, log_spec("q", {}));
  const auto [lo, hi] = std::minmax_element(lq.values.begin(), lq.values.end());
  const nlohmann::json j = {{"color_preset", {{"name", "turbo"}}},
                            {"extinction", {{0.01, 0.2}, {0.5, 3.0}, {3.0, 0.5}, {100.0, 2.5}}}};
  const TransferFunction tf =
      transfer_function_from_json(j, "test", "", std::pow(10.0, *lo), std::pow(10.0, *hi), true);
  const Volume volume(m.view());
  const Field f = field_of(m, lq.name);
  RenderSettings exact;
  exact.mode = RenderMode::exact;
  const Camera camera = test::view_from({2.5, -2, 1.8}, Projection::Perspective);
  const Image e = make_renderer(exact)->render(volume, f, tf, camera, {48, 48});
  const Image b = make_renderer({})->render(volume, f, tf, camera, {48, 48});
  double worst = 0, alpha = 0;
  for (std::size_t i = 0; i < e.rgba.size(); ++i) worst = std::max(worst, double(std::abs(e.rgba[i] - b.rgba[i])));
  for (std::size_t i = 3; i < e.rgba.size(); i += 4) alpha += e.rgba[i];
  EXPECT_LT(worst, 1e-6);
  EXPECT_GT(alpha / (e.rgba.size() / 4), 0.2);  // a picture, not an empty frame
}
