// Time series (issue 20): .pvd collections, numbered files and Exodus time steps as key frames,
// the field (and moving points) interpolated between two key frames, only two held, and playback
// with a background thread giving the same bits as a single-step file of the interpolated field.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <netcdf.h>

#include "base/error.hpp"
#include "io/series_files.hpp"
#include "io/write_mesh.hpp"
#include "mesh/generate.hpp"
#include "render/playback.hpp"
#include "scene/camera_json.hpp"
#include "tests/test_util.hpp"

namespace cellproj {
namespace {

// Key frame k of a series on one box of tetrahedra: the field sin(x + 2y - z + k).
Mesh step(int k, double move = 0.0) {
  Mesh m = make_box(4, 3, 3, {-1, -1, -1}, {1, 1, 1}, true);
  set_field(m, "f", [k](const glm::dvec3& x) { return std::sin(x.x + 2 * x.y - x.z + k); });
  for (std::size_t i = 0; i < m.points.size(); i += 3) m.points[i] *= 1.0 + move * k;
  return m;
}

void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& sets) {
  std::ofstream f(path);
  f << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [t, file] : sets) f << "  <DataSet timestep=\"" << t << "\" part=\"0\" file=\"" << file << "\"/>\n";
  f << "</Collection>\n</VTKFile>\n";
}

void expect_refused(const std::function<void()>& f, const std::string& says) {
  try {
    f();
    ADD_FAILURE() << "accepted; expected: " << says;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
  }
}

TEST(TimeSeries, ListsCollectionsAndNumberedFilesInTimeOrder) {
  test::TempDir dir;
  for (int k : {0, 1, 10}) {
    char name[32];
    std::snprintf(name, sizeof name, "m_%04d.vtu", k);
    write_vtu(step(k), dir.file(name));
  }
  write_vtu(step(3), dir.file("m_3.vtu"));  // not what %04d prints: not of the series
  write_pvd(dir.file("s.pvd"), {{2.5, "m_0010.vtu"}, {0.0, "m_0000.vtu"}, {1.0, "m_0001.vtu"}});
  const TimeSeries pvd = list_series(dir.file("s.pvd"), {});
  ASSERT_EQ(pvd.frames.size(), 3u);
  EXPECT_EQ(pvd.frames[0].time, 0.0);
  EXPECT_EQ(pvd.frames[2].time, 2.5);
  EXPECT_EQ(pvd.frames[2].path, dir.file("m_0010.vtu"));
  const TimeSeries numbered = list_series(dir.file("m_%04d.vtu"), {});
  ASSERT_EQ(numbered.frames.size(), 3u);
  EXPECT_EQ(numbered.frames[1].time, 1.0);
  EXPECT_EQ(numbered.frames[2].time, 10.0);
  EXPECT_TRUE(is_series_path(dir.file("s.pvd")));
  EXPECT_TRUE(is_series_path(dir.file("m_%04d.vtu")));
  EXPECT_FALSE(is_series_path(dir.file("m_0000.vtu")));

  const SeriesPosition at = locate(pvd, 0.25);
  EXPECT_EQ(at.before, 0u);
  EXPECT_EQ(at.after, 1u);
  EXPECT_DOUBLE_EQ(at.weight, 0.25);
  const SeriesPosition key = locate(pvd, 1.0);
  EXPECT_EQ(key.before, 1u);
  EXPECT_EQ(key.after, 1u);
  expect_refused([&] { locate(pvd, 2.6); }, "outside the series' times [0.000000, 2.500000]");
}

TEST(TimeSeries, BadCollectionsAreRefusedNamingTheFile) {
  test::TempDir dir;
  write_vtu(step(0), dir.file("a.vtu"));
  std::ofstream(dir.file("junk.pvd")) << "not xml at all <";
  expect_refused([&] { list_series(dir.file("junk.pvd"), {}); }, "junk.pvd");
  std::ofstream(dir.file("nofile.pvd")) << "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"0\"/>"
                                           "</Collection></VTKFile>";
  expect_refused([&] { list_series(dir.file("nofile.pvd"), {}); }, "DataSet 0 has no file attribute");
  write_pvd(dir.file("twice.pvd"), {{1.0, "a.vtu"}, {1.0, "a.vtu"}});
  expect_refused([&] { list_series(dir.file("twice.pvd"), {}); }, "two key frames at time 1");
  std::ofstream(dir.file("empty.pvd")) << "<VTKFile type=\"Collection\"><Collection/></VTKFile>";
  expect_refused([&] { list_series(dir.file("empty.pvd"), {}); }, "names no key frame");
  expect_refused([&] { list_series(dir.file("none_%03d.vtu"), {}); }, "names no key frame");
  expect_refused([&] { list_series(dir.file("a.vtu"), {}); }, "not a time series");
  write_pvd(dir.file("gone.pvd"), {{0.0, "a.vtu"}, {1.0, "gone.vtu"}});
  SeriesPlayer player(list_series(dir.file("gone.pvd"), {}), "f", key_frame_reader({}));
  expect_refused([&] { player.frame_at(0.5); }, "gone.vtu");
  write_vtu(make_box(2, 2, 2, {-1, -1, -1}, {1, 1, 1}, true), dir.file("other.vtu"));
  write_pvd(dir.file("cells.pvd"), {{0.0, "a.vtu"}, {1.0, "other.vtu"}});
  SeriesPlayer differ(list_series(dir.file("cells.pvd"), {}), "f", key_frame_reader({}));
  expect_refused([&] { differ.frame_at(0.5); }, "its cells differ from the first key frame's");
}

TEST(TimeSeries, TheFieldIsTheLinearMixOfTheTwoKeyFramesAroundTAndOnlyTwoAreRead) {
  test::TempDir dir;
  std::vector<std::pair<double, std::string>> sets;
  for (int k = 0; k < 4; ++k) {
    write_vtu(step(k), dir.file("s" + std::to_string(k) + ".vtu"));
    sets.push_back({0.5 * k, "s" + std::to_string(k) + ".vtu"});
  }
  write_pvd(dir.file("s.pvd"), sets);
  SeriesPlayer player(list_series(dir.file("s.pvd"), {}), "", key_frame_reader({}));
  int frames = 0;
  const double* shared = nullptr;
  for (double t = 0.0; t <= 1.5; t += 0.125, ++frames) {
    const SeriesFrame f = player.frame_at(t);
    const SeriesPosition p = locate(player.series(), t);
    const std::vector<double> a = step(static_cast<int>(p.before)).fields[0].values,
                              b = step(static_cast<int>(p.after)).fields[0].values;
    ASSERT_EQ(f.field.size(), a.size());
    for (std::size_t i = 0; i < a.size(); ++i)
      ASSERT_EQ(f.field[i], p.before == p.after ? a[i] : (1.0 - p.weight) * a[i] + p.weight * b[i]) << "t " << t;
    if (!shared) shared = f.points->data();
    EXPECT_EQ(f.points->data(), shared) << "the points do not move: every frame shares the first key frame's";
  }
  EXPECT_EQ(frames, 13);
  EXPECT_EQ(player.key_frames_read(), 4) << "a playback forwards reads each key frame once";
  EXPECT_FALSE(player.points_move());
  EXPECT_EQ(player.field_name(), "f");
  EXPECT_EQ(player.cells().n_cells(), step(0).n_cells());
}

TEST(TimeSeries, MovingPointsAreDetectedAndInterpolated) {
  test::TempDir dir;
  write_vtu(step(0, 0.5), dir.file("a.vtu"));
  write_vtu(step(1, 0.5), dir.file("b.vtu"));
  write_pvd(dir.file("m.pvd"), {{0.0, "a.vtu"}, {2.0, "b.vtu"}});
  SeriesPlayer player(list_series(dir.file("m.pvd"), {}), "f", key_frame_reader({}));
  const SeriesFrame f = player.frame_at(0.5);
  EXPECT_TRUE(player.points_move());
  const std::vector<double> a = step(0, 0.5).points, b = step(1, 0.5).points;
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ((*f.points)[i], 0.75 * a[i] + 0.25 * b[i]);
}

// A second time step appended to an Exodus file VTK wrote with one: time_whole[1] and the nodal
// variable's second record (netCDF's record dimension grows).
void append_exodus_step(const std::string& path, double time, const std::vector<double>& values) {
  int id = 0, var = 0, nvars = 0;
  ASSERT_EQ(nc_open(path.c_str(), NC_WRITE, &id), NC_NOERR);
  const std::size_t one = 1, start[2] = {1, 0}, count[2] = {1, values.size()};
  ASSERT_EQ(nc_inq_varid(id, "time_whole", &var), NC_NOERR);
  ASSERT_EQ(nc_put_vara_double(id, var, &one, &one, &time), NC_NOERR);
  nc_inq_nvars(id, &nvars);
  int written = 0;
  for (int v = 0; v < nvars; ++v) {
    char name[NC_MAX_NAME + 1];
    nc_inq_varname(id, v, name);
    if (std::string(name).rfind("vals_nod_var", 0) == 0)
      written += nc_put_vara_double(id, v, start, count, values.data()) == NC_NOERR;
  }
  ASSERT_GE(written, 1) << "no nodal variable in " << path;
  nc_close(id);
}

TEST(TimeSeries, AnExodusFilesTimeStepsAreItsKeyFrames) {
  test::TempDir dir;
  const std::string path = dir.file("t.exo");
  write_exodus(step(0), path);
  append_exodus_step(path, 4.0, step(1).fields[0].values);
  const TimeSeries s = list_series(path, {});
  ASSERT_EQ(s.frames.size(), 2u);
  EXPECT_EQ(s.frames[1].time, 4.0);
  EXPECT_EQ(s.frames[1].time_step, 1);
  SeriesPlayer player(s, "f", key_frame_reader({}));
  const SeriesFrame f = player.frame_at(1.0);
  const Mesh m0 = read_mesh(path), m1 = read_mesh(path, [] {
                                     ReadOptions o;
                                     o.time_step = 1;
                                     return o;
                                   }());
  const auto& a = m0.field("f").values;
  const auto& b = m1.field("f").values;
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(f.field[i], 0.75 * a[i] + 0.25 * b[i]);
  EXPECT_NE(a, b);
}

TEST(TimeSeries, PlaybackEqualsRenderingASingleStepFileOfTheInterpolatedField) {
  // Each frame of a played series, with and without the background thread, is bit for bit the
  // picture of a file holding that frame's interpolated field alone.
  test::TempDir dir;
  write_vtu(step(0), dir.file("a.vtu"));
  write_vtu(step(1), dir.file("b.vtu"));
  write_vtu(step(2), dir.file("c.vtu"));
  write_pvd(dir.file("s.pvd"), {{0.0, "a.vtu"}, {1.0, "b.vtu"}, {3.0, "c.vtu"}});
  const std::vector<double> times = {0.0, 0.3, 1.0, 2.2};
  const TransferFunction tf({{-1.0, {0.1, 0.3, 0.9}}, {1.0, {1.0, 0.8, 0.2}}}, {{-1.0, 0.2}, {1.0, 4.0}});
  const auto renderer = make_renderer(RenderSettings{});
  const auto camera = [](int f) { return orbit(test::view_from({2, -3, 4}, Projection::Perspective), 10.0 * f); };
  for (bool prefetch : {true, false}) {
    SeriesPlayer player(list_series(dir.file("s.pvd"), {}), "f", key_frame_reader({}));
    std::vector<Image> played(times.size());
    const PlaybackStats st =
        play_series(player, player.frame_at(times[0]), times, prefetch, *renderer, tf, camera, {48, 40},
                    [&](int f, Image&& img, const RenderReport&) { played[f] = std::move(img); });
    EXPECT_EQ(st.volumes, 1) << "the points do not move: one volume for the whole playback";
    for (std::size_t f = 0; f < times.size(); ++f) {
      const SeriesPosition p = locate(player.series(), times[f]);
      Mesh single = step(0);
      const auto a = step(static_cast<int>(p.before)).fields[0].values,
                 b = step(static_cast<int>(p.after)).fields[0].values;
      for (std::size_t i = 0; i < a.size(); ++i)
        single.fields[0].values[i] = p.before == p.after ? a[i] : (1.0 - p.weight) * a[i] + p.weight * b[i];
      write_vtu(single, dir.file("single.vtu"));
      const Mesh back = read_mesh(dir.file("single.vtu"));
      const Image expect =
          render(Volume(back.view()), field_of(back, "f"), tf, RenderSettings{}, camera(static_cast<int>(f)), {48, 40});
      EXPECT_EQ(played[f].rgba, expect.rgba) << "frame " << f << " prefetch " << prefetch;
    }
  }
}

TEST(TimeSeries, AClippedPlaybackEqualsEachFrameClippedOnItsOwn) {
  // With clipping planes, the cells are clipped once (the points do not move) and each frame's
  // field mapped onto them; with moving points every frame is clipped. Either way each frame is the
  // picture of that frame's whole mesh clipped, to the rounding of the field's mix.
  test::TempDir dir;
  const std::vector<ClipPlane> planes = {{{0.1, 0.0, 0.0}, {1.0, 0.4, 0.0}}, {{0.0, 0.0, -0.3}, {0.0, 0.2, -1.0}}};
  const TransferFunction tf({{-1.0, {0.1, 0.3, 0.9}}, {1.0, {1.0, 0.8, 0.2}}}, {{-1.0, 0.2}, {1.0, 4.0}});
  const auto renderer = make_renderer(RenderSettings{});
  const auto camera = [](int f) { return orbit(test::view_from({2, -3, 4}, Projection::Perspective), 10.0 * f); };
  for (double move : {0.0, 0.1}) {
    write_vtu(step(0, move), dir.file("a.vtu"));
    write_vtu(step(1, move), dir.file("b.vtu"));
    write_pvd(dir.file("s.pvd"), {{0.0, "a.vtu"}, {1.0, "b.vtu"}});
    const std::vector<double> times = {0.0, 0.4, 1.0};
    SeriesPlayer player(list_series(dir.file("s.pvd"), {}), "f", key_frame_reader({}));
    std::vector<Image> played(times.size());
    ClipReport report;
    const PlaybackStats st = play_series(
        player, player.frame_at(times[0]), times, true, *renderer, tf, camera, {40, 32},
        [&](int f, Image&& img, const RenderReport&) { played[f] = std::move(img); }, {}, planes, &report);
    EXPECT_EQ(st.volumes, move == 0.0 ? 1 : 3) << move;
    EXPECT_GT(report.cut, 0);
    for (std::size_t f = 0; f < times.size(); ++f) {
      SeriesPlayer one(list_series(dir.file("s.pvd"), {}), "f", key_frame_reader({}));
      const SeriesFrame frame = one.frame_at(times[f]);
      Mesh whole = one.cells();
      whole.points = *frame.points;
      whole.fields.push_back({"f", frame.field, "frame"});
      const Mesh clipped = clip_mesh(whole, planes);
      const Image expect = render(Volume(clipped.view()), field_of(clipped, "f"), tf, RenderSettings{},
                                  camera(static_cast<int>(f)), {40, 32});
      EXPECT_LT(compare(played[f], expect).max_abs, 1e-6) << "frame " << f << " move " << move;
    }
  }
}

}  // namespace
}  // namespace cellproj
