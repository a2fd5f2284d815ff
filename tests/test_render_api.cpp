// The façade (render/): a Volume committed once from a solver's arrays as they are, a Field per
// call, one Renderer interface over projection and the exact integrator, errors before a frame.
#include <cmath>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "base/error.hpp"
#include "frame/gl_frame.hpp"
#include "mesh/generate.hpp"
#include "render/renderer.hpp"
#include "render/settings_table.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

// A 4^3 box of tetrahedra on coordinates a float holds exactly, with two fields.
Mesh box() {
  Mesh m = make_box(4, 4, 4, glm::dvec3(-1), glm::dvec3(1), true);
  set_field(m, "a", [](const glm::dvec3& x) { return 0.4 * x.x - 0.3 * x.y + 0.5; });
  set_field(m, "b", [](const glm::dvec3& x) { return 0.5 + 0.4 * x.z * x.x; });
  return m;
}

TransferFunction tf() {
  return TransferFunction({{0.0, {0.1, 0.2, 0.9}}, {0.5, {0.9, 0.9, 0.2}}, {1.0, {1, 0.2, 0.1}}},
                          {{0.0, 0.5}, {0.4, 3.0}, {1.0, 1.0}});
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

const Camera kView = test::view_from({2.5, -2, 1.8}, Projection::Perspective);

}  // namespace

TEST(RenderApi, ANewFieldRendersWithoutPreparingAgain) {
  const Mesh m = box();
  const Volume volume(m.view());
  EXPECT_EQ(volume.preparations(), 0);
  const auto renderer = make_renderer({});
  RenderReport first, second;
  const Image a = renderer->render(volume, field_of(m, "a"), tf(), kView, {64, 64}, &first);
  EXPECT_EQ(volume.preparations(), 1);
  EXPECT_GT(first.prepare_seconds, 0.0);
  const Image b = renderer->render(volume, field_of(m, "b"), tf(),
                                   test::view_from({-2, 1, 2}, Projection::Orthographic), {64, 64}, &second);
  EXPECT_EQ(volume.preparations(), 1) << "a new time step, view and field must not rebuild topology, hull or sorter";
  EXPECT_EQ(second.prepare_seconds, 0.0);
  ASSERT_EQ(volume.copies().size(), 1u);  // the caller's arrays are read in place; the preparation says what it copied
  EXPECT_NE(volume.copies()[0].find("points recentred"), std::string::npos);
  EXPECT_NE(a.rgba, b.rgba);
  // The façade's picture is the stage's, bit for bit.
  EXPECT_EQ(a.rgba, test::project(m, "a", tf(), kView, 64).rgba);
}

TEST(RenderApi, MovedPointsGiveTheFreshVolumesPictureAndABadMoveLeavesTheVolumeAsItWas) {
  // A deforming mesh: the same cells over new points render as a volume committed over them, with
  // the preparation made again; a move that folds a cell is re-oriented, one with a NaN refused.
  const Mesh m = box();
  Mesh bent = m;
  for (std::size_t i = 0; i < bent.points.size(); i += 3)
    bent.points[i] += 0.25 * bent.points[i + 2] * bent.points[i + 2];  // x += z^2 / 4
  Volume volume(m.view());
  const auto renderer = make_renderer({});
  const Image before = renderer->render(volume, field_of(m, "a"), tf(), kView, {48, 48});
  volume.set_points(PointArray(bent.points.data()), bent.n_points());
  RenderReport moved;
  const Image after = renderer->render(volume, field_of(m, "a"), tf(), kView, {48, 48}, &moved);
  EXPECT_EQ(volume.preparations(), 2) << "the points moved: the preparation is made again";
  EXPECT_GT(moved.prepare_seconds, 0.0);
  EXPECT_EQ(after.rgba, renderer->render(Volume(bent.view()), field_of(m, "a"), tf(), kView, {48, 48}).rgba);
  EXPECT_NE(after.rgba, before.rgba);

  Mesh mirrored = m;  // every cell inverted: re-oriented in a copy, the picture the mirror's
  for (std::size_t i = 0; i < mirrored.points.size(); i += 3) mirrored.points[i] = -mirrored.points[i];
  volume.set_points(PointArray(mirrored.points.data()), mirrored.n_points());
  EXPECT_EQ(volume.validation().inverted_cells, m.n_cells());
  Mesh fixed = mirrored;
  reorient_inverted(fixed, validate(fixed.view()));
  EXPECT_EQ(renderer->render(volume, field_of(m, "a"), tf(), kView, {48, 48}).rgba,
            renderer->render(Volume(fixed.view()), field_of(m, "a"), tf(), kView, {48, 48}).rgba);

  Mesh bad = bent;
  bad.points[7] = std::nan("");
  EXPECT_NE(error_of([&] { volume.set_points(PointArray(bad.points.data()), bad.n_points()); }).find("point 2"),
            std::string::npos);
  EXPECT_NE(error_of([&] { volume.set_points(PointArray(bent.points.data()), bent.n_points() - 1); }).find("expected"),
            std::string::npos);
  EXPECT_EQ(volume.validation().inverted_cells, m.n_cells()) << "a refused move changes nothing";
}

TEST(RenderApi, ProjectionAndExactBehindOneInterface) {
  const Mesh m = box();
  const Volume volume(m.view());
  RenderSettings exact;
  exact.mode = RenderMode::exact;
  RenderReport pr, er;
  const Image p = render(volume, field_of(m, "a"), tf(), {}, kView, {48, 48}, &pr);
  const Image e = render(volume, field_of(m, "a"), tf(), exact, kView, {48, 48}, &er);
  EXPECT_LT(compare(p, e).max_abs, 2e-5);  // pt-breakpoints is exact for tetrahedra
  EXPECT_EQ(volume.preparations(), 2);     // one for each renderer
  auto has = [](const RenderReport& r, const std::string& name) {
    for (const auto& [n, v] : r.values)
      if (n == name) return true;
    return false;
  };
  EXPECT_TRUE(has(pr, "fragments"));
  EXPECT_TRUE(has(er, "segments"));
  EXPECT_FALSE(has(er, "fragments"));
  EXPECT_EQ(make_renderer(exact)->name(), "exact");
  EXPECT_EQ(make_renderer({})->name(), "pt-breakpoints");
  // Each renderer estimates its own frame; more pixels need more.
  const VolumeSize size = size_of(m.view());
  EXPECT_GT(make_renderer(exact)->estimate_bytes(size, {1024, 1024}),
            make_renderer(exact)->estimate_bytes(size, {64, 64}));
}

TEST(RenderApi, SolverArraysAsTheyAreGiveTheSamePicture) {
  const Mesh m = box();
  const Field a = field_of(m, "a");
  const Image reference = render(Volume(m.view()), a, tf(), {}, kView, {48, 48});
  // 32-bit ids: widened once, and the volume says so.
  const std::vector<std::int32_t> conn(m.connectivity.begin(), m.connectivity.end()),
      off(m.offsets.begin(), m.offsets.end());
  CellArrays cells{conn.data(), off.data(), m.types.data(), m.n_cells(), true};
  const Volume v32(m.points.data(), m.n_points(), cells, "solver arrays");
  ASSERT_EQ(v32.copies().size(), 1u);
  EXPECT_NE(v32.copies()[0].find("32-bit ids widened"), std::string::npos);
  EXPECT_EQ(render(v32, a, tf(), {}, kView, {48, 48}).rgba, reference.rgba);
  CellArrays short_cells = cells;
  short_cells.connectivity_size = static_cast<std::int64_t>(conn.size()) - 4;
  EXPECT_NE(error_of([&] {
              Volume v(m.points.data(), m.n_points(), short_cells, "short");
            }).find("short: the offsets end at " + std::to_string(conn.size())),
            std::string::npos);
  // Float points (exact here) and a strided array of {x, y, z, temperature} records: read in place.
  const std::vector<float> xyz_f(m.points.begin(), m.points.end());
  CellArrays cells64{m.connectivity.data(), m.offsets.data(), m.types.data(), m.n_cells(), false};
  const Volume vf(xyz_f.data(), m.n_points(), cells64, "float points");
  EXPECT_TRUE(vf.copies().empty());
  EXPECT_EQ(render(vf, a, tf(), {}, kView, {48, 48}).rgba, reference.rgba);
  std::vector<double> records;
  for (std::int64_t p = 0; p < m.n_points(); ++p)
    records.insert(records.end(), {m.points[3 * p], m.points[3 * p + 1], m.points[3 * p + 2], -1.0});
  const Volume vs(PointArray::strided(records.data(), 4 * sizeof(double)), m.n_points(), cells64, "records");
  EXPECT_EQ(render(vs, a, tf(), {}, kView, {48, 48}).rgba, reference.rgba);
}

TEST(RenderApi, AMissingOrBadFieldIsAnError) {
  const Mesh m = box();
  const Volume volume(m.view());
  const auto r = make_renderer({});
  EXPECT_NE(error_of([&] {
              r->render(volume, Field{}, tf(), kView, {8, 8});
            }).find("no field given"),
            std::string::npos);
  std::vector<double> short_field(5, 0.0);
  EXPECT_NE(error_of([&] {
              r->render(volume, {short_field.data(), 5, "t"}, tf(), kView, {8, 8});
            }).find("field 't' has 5 values for " + std::to_string(m.n_points()) + " points"),
            std::string::npos);
  std::vector<double> nan_field(static_cast<std::size_t>(m.n_points()), 0.0);
  nan_field[7] = NAN;
  EXPECT_NE(error_of([&] {
              r->render(volume, {nan_field.data(), m.n_points(), "t"}, tf(), kView, {8, 8});
            }).find("field 't' is not finite at point 7"),
            std::string::npos);
  EXPECT_NE(error_of([&] { field_of(m, "c"); }).find("c"), std::string::npos);
}

TEST(RenderApi, ValidationRunsUnlessTheMeshIsTrusted) {
  Mesh m = box();
  m.connectivity[5] = 100000;
  EXPECT_NE(error_of([&] { Volume v(m.view()); }).find("refers to point 100000"), std::string::npos);
  EXPECT_EQ(error_of([&] { Volume v(m.view(), {true}); }), "");  // the caller vouched for it
}

TEST(RenderApi, InvertedCellsAreReorientedInACopy) {
  const Mesh m = box();
  Mesh flipped = m;
  std::swap(flipped.connectivity[1], flipped.connectivity[2]);  // cell 0 inverted
  const std::vector<std::int64_t> before = flipped.connectivity;
  const Volume volume(flipped.view());
  EXPECT_EQ(volume.validation().inverted_cells, 1);
  EXPECT_EQ(flipped.connectivity, before) << "the caller's arrays are read-only";
  ASSERT_EQ(volume.copies().size(), 1u);
  EXPECT_NE(volume.copies()[0].find("1 inverted cells re-oriented"), std::string::npos);
  EXPECT_EQ(render(volume, field_of(flipped, "a"), tf(), {}, kView, {48, 48}).rgba,
            render(Volume(m.view()), field_of(m, "a"), tf(), {}, kView, {48, 48}).rgba);
}

TEST(RenderApi, SettingsThatDoNotGoTogetherAreRefusedBeforeAFrame) {
  RenderSettings s;
  s.projection.backend = Backend::opengl;
  s.projection.method = ProjectionMethod::pt_breakpoints;
  // A build without OSMesa refuses the OpenGL back ends themselves.
  EXPECT_NE(error_of([&] { make_renderer(s); }).find(opengl_built() ? "not pt-breakpoints" : "were not built"),
            std::string::npos);
  s.projection.backend = Backend::software;
  s.projection.method = ProjectionMethod::pt_table;
  s.projection.table_size = 1;
  EXPECT_NE(error_of([&] { make_renderer(s); }).find("opacity table size 1"), std::string::npos);
}

TEST(RenderApi, EveryMethodIsDecidedByItsTraits) {
  // The closed set: each method's traits are consistent with what it computes.
  for (const MethodTraits& t : kProjectionMethods) {
    EXPECT_EQ(&traits(t.method), &t);
    EXPECT_EQ(t.opacity_table || t.point_optics, t.gouraud) << t.name;  // Gouraud corners come from point optics
    EXPECT_EQ(t.opengl, t.gouraud) << t.name;                           // OpenGL draws Gouraud triangles only
    EXPECT_FALSE(t.gouraud && t.cuts_at_breakpoints) << t.name;
  }
}

TEST(RenderApi, AnOrthographicEyeInsideTheMeshDrawsWhatIsInFrontOfItsPlaneOnly) {
  // The exact renderer's rays start on the eye's plane; projection and slicing must agree with it,
  // tetrahedra (ray cast where they cross the plane) and whole cells (split there) alike.
  const Mesh tets = box();
  const Mesh mixed = [] {
    Mesh m = test::twisted_mixed(3);
    set_field(m, "a", [](const glm::dvec3& x) { return 0.4 * x.x - 0.3 * x.y + 0.5; });
    return m;
  }();
  const Camera inside = test::view_from({0.3, -0.25, 0.2}, Projection::Orthographic);
  const Camera outside = test::view_from({3.0, -2.5, 2.0}, Projection::Orthographic);  // the same direction
  RenderSettings exact, slicing;
  exact.mode = RenderMode::exact, slicing.mode = RenderMode::slicing;
  exact.interpolation = CellInterpolation::canonical_tets;
  for (const Mesh* m : {&tets, &mixed}) {
    const Volume volume(m->view());
    const Image e = render(volume, field_of(*m, "a"), tf(), exact, inside, {48, 48});
    const Image p = render(volume, field_of(*m, "a"), tf(), {}, inside, {48, 48});
    const Image s = render(volume, field_of(*m, "a"), tf(), slicing, inside, {48, 48});
    const Image whole = render(volume, field_of(*m, "a"), tf(), {}, outside, {48, 48});
    EXPECT_LT(compare(p, e).max_abs, 2e-5);  // pt-breakpoints is exact for linear tetrahedra
    // Slicing's error on these meshes at 48x48 (0.039 max, 0.0021 rms when printed) is about its
    // error with the eye outside; bench/ortho_eye_inside.sh measures the difference.
    EXPECT_LT(compare(s, e).max_abs, 0.06);
    EXPECT_LT(compare(s, e).rmse, 0.005);
    EXPECT_GT(compare(whole, e).max_abs, 0.2);  // what lies behind the plane is missing indeed
  }
}

// Anti-aliasing (setting 'ssaa'): for every method the frame drawn n times larger on each side and
// box-filtered down; it brings the picture nearer the anti-aliased exact image where cells are
// thinner than a pixel.
TEST(RenderApi, SupersamplingIsTheLargerFrameBoxFilteredAndNearerTheAntiAliasedImage) {
  Mesh m = make_graded(6, 0.004, true);  // cells from 0.004 of the mesh's side: thinner than a pixel
  set_field(m, "f", [](const glm::dvec3& x) { return x.x + 0.5 * x.y; });
  const Volume volume(m.view());
  const Field f = field_of(m, "f");
  const TransferFunction tf = test::constant_tf(3.0, {1.0, 0.6, 0.2});
  const Camera camera = test::view_from({2.0, -2.6, 1.7}, Projection::Orthographic, 2.4);
  const ImageSize size{40, 32};
  for (const char* method : {"pt-linear", "pt-breakpoints", "exact", "slicing"}) {
    RenderOptions o;
    set_option(o, "method", method);
    const RenderSettings one = settings_from(o);
    set_option(o, "ssaa", "3");
    const RenderSettings three = settings_from(o);
    RenderReport report;
    const Image aa = render(volume, f, tf, three, camera, size, &report);
    EXPECT_EQ(aa.width, size.width);
    const ReportValue* n = report.find("ssaa");
    ASSERT_NE(n, nullptr) << method;
    EXPECT_EQ(std::get<std::int64_t>(*n), 3);
    EXPECT_EQ(aa.rgba, downsample(render(volume, f, tf, one, camera, {120, 96}), 3).rgba) << method;
  }
  RenderSettings exact;
  exact.mode = RenderMode::exact;
  const Image reference = downsample(render(volume, f, tf, exact, camera, {320, 256}), 8);
  RenderSettings aa;
  aa.ssaa = 4;
  const double aliased = compare(render(volume, f, tf, {}, camera, size), reference).rmse;
  const double smoothed = compare(render(volume, f, tf, aa, camera, size), reference).rmse;
  EXPECT_GT(aliased, 2e-3);  // the thin cells alias
  EXPECT_LT(smoothed, 0.5 * aliased) << aliased << " " << smoothed;

  // The tent filter: the larger frame tent-filtered, and nearer the tent-filtered reference too.
  aa.ssaa_filter = SampleFilter::tent;
  EXPECT_EQ(render(volume, f, tf, aa, camera, size).rgba,
            downsample(render(volume, f, tf, {}, camera, {160, 128}), 4, SampleFilter::tent).rgba);
  const Image tent_reference = downsample(render(volume, f, tf, exact, camera, {320, 256}), 8, SampleFilter::tent);
  EXPECT_LT(compare(render(volume, f, tf, aa, camera, size), tent_reference).rmse,
            0.5 * compare(render(volume, f, tf, {}, camera, size), tent_reference).rmse);

  EXPECT_THROW(supersampled_size({8192, 8192}, 16), InputError);  // beyond 65536 pixels a side
  EXPECT_THROW(supersampled_size({64, 64}, 0), InputError);
  RenderSettings too_many;
  too_many.ssaa = kMaxSsaa + 1;
  EXPECT_THROW(make_renderer(too_many), InputError);
}
