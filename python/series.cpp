#include "python/series.hpp"

#include <pybind11/stl.h>

#include <nlohmann/json.hpp>

#include <tbb/task_arena.h>

#include "base/error.hpp"
#include "io/series_files.hpp"
#include "mesh/clip.hpp"
#include "python/numpy_mesh.hpp"
#include "python/render_call.hpp"
#include "render/playback.hpp"
#include "scene/prepare.hpp"

namespace cellproj::python {

Series::Series(const std::string& path, const ReadOptions& reader)
    : listed_(list_series(path, reader)), reader_(reader) {}

std::vector<double> Series::times() const {
  std::vector<double> t;
  for (const KeyFrame& k : listed_.frames) t.push_back(k.time);
  return t;
}

std::unique_ptr<NumpyMesh> Series::key_frame(std::ptrdiff_t i) const {
  const auto n = static_cast<std::ptrdiff_t>(listed_.frames.size());
  if (i < -n || i >= n)
    throw py::index_error(listed_.source + ": key frame " + std::to_string(i) + " of " + std::to_string(n));
  const KeyFrame& k = listed_.frames[static_cast<std::size_t>(i < 0 ? i + n : i)];
  auto mesh = [&] {
    py::gil_scoped_release release;
    return std::make_shared<const Mesh>(key_frame_reader(reader_)(k).mesh);
  }();
  return std::make_unique<NumpyMesh>(std::move(mesh));
}

std::unique_ptr<NumpyMesh> Series::at(double t, const std::string& spec) {
  py::gil_scoped_release release;
  locate(listed_, t);  // in range, before any read
  if (!player_ || spec != spec_) {
    player_ = std::make_unique<SeriesPlayer>(listed_, spec, key_frame_reader(reader_));
    spec_ = spec;
  }
  const SeriesFrame frame = player_->frame_at(t);
  py::gil_scoped_acquire acquire;
  return frame_mesh(*player_, frame);
}

std::unique_ptr<NumpyMesh> frame_mesh(const SeriesPlayer& player, const SeriesFrame& frame) {
  Mesh m = player.cells();
  m.source = player.series().source;
  m.points = *frame.points;
  m.fields.push_back({player.field_name(), frame.field, "a time series' frame"});
  return std::make_unique<NumpyMesh>(std::make_shared<const Mesh>(std::move(m)), !player.points_move());
}

namespace {

// The frames of a series at `times`, rendered in order as the CLI's --animate renders them: colours
// and framing from the first key frame whatever the times, the next frame made in the background.
class SeriesPlayback {
 public:
  SeriesPlayback(const Series& series, const std::vector<double>& times, bool prefetch, const py::kwargs& kwargs)
      : call_(render_call(kwargs)) {
    if (times.empty()) throw InputError(series.listed().source + ": times= lists no frame");
    if (call_.log_floor && !call_.log)
      throw InputError("setting 'log-floor' is the floor of a log scale: give setting 'log' too");
    Scene scene;  // what first_key_frame reads of a scene: the field, its log, the opacity field
    scene.source = series.listed().source;
    scene.field = call_.field, scene.log_scale = call_.log, scene.log_floor = call_.log_floor;
    scene.opacity_field = call_.opacity_field;
    {
      py::gil_scoped_release release;
      for (double t : {times.front(), times.back()}) locate(series.listed(), t);  // in range, before any read
      player_ = std::make_unique<SeriesPlayer>(series.listed(), scene_field(scene), key_frame_reader(series.reader()));
      first_key_frame(*player_, scene);  // refuses an opacity field; the player holds the first key frame
    }
    look_ = frame_mesh(*player_, player_->frame_at(series.listed().frames.front().time));
    call_.field = "", call_.log = false, call_.log_floor.reset();  // the frames' one field, its log in its name
    plan_.emplace(plan_frame(*look_, call_));
    SeriesFrame first = [&] {
      py::gil_scoped_release release;
      return player_->frame_at(times.front());
    }();
    playback_ = std::make_unique<Playback>(*player_, std::move(first), times, prefetch, clip_planes(call_.clip));
  }

  // The next frame: its picture, its --stats (with its time) and its legend.
  py::tuple next() {
    if (playback_->next_frame() >= playback_->frames()) throw py::stop_iteration();
    const double time = playback_->time_of(playback_->next_frame());
    RenderReport report;
    Image image = [&] {
      py::gil_scoped_release release;
      tbb::task_arena arena(call_.threads);
      return arena.execute(
          [&] { return playback_->render_next(*plan_->renderer, plan_->tf, plan_->camera, plan_->size, &report); });
    }();
    nlohmann::json stats = nlohmann::json::parse(frame_stats(report, *plan_, player_->cells().n_cells()));
    stats["time"] = time;
    stats["key_frames_read"] = player_->key_frames_read();
    return py::make_tuple(to_numpy(std::move(image)), stats.dump(), plan_->legend);
  }

 private:
  RenderCall call_;
  std::unique_ptr<SeriesPlayer> player_;
  std::unique_ptr<NumpyMesh> look_;
  std::optional<FramePlan> plan_;       // the first key frame's colours and framing
  std::unique_ptr<Playback> playback_;  // last: it uses the player
};

}  // namespace

void bind_series(py::module_& m) {
  py::class_<Series>(m, "Series",
                     "A time series: a ParaView .pvd collection, numbered files (mesh_%04d.vtu) or an Exodus file's "
                     "time steps, listed without reading a mesh")
      .def(py::init([](const std::string& path, const std::string& cell_data) {
             ReadOptions o;
             o.cell_data = cell_data_from_name(cell_data);
             py::gil_scoped_release release;
             return std::make_unique<Series>(path, o);
           }),
           py::arg("path"), py::arg("cell_data") = "cells",
           "Lists the series at `path` (cellproj.read_series); cell_data as cellproj.read's")
      .def_property_readonly("times", &Series::times, "The key frames' times, increasing")
      .def_property_readonly(
          "source", [](const Series& s) { return s.listed().source; }, "The .pvd, pattern or Exodus file")
      .def_property_readonly(
          "files",
          [](const Series& s) {
            std::vector<std::string> files;
            for (const KeyFrame& k : s.listed().frames) files.push_back(k.path);
            return files;
          },
          "Each key frame's file")
      .def(
          "__len__", [](const Series& s) { return s.listed().frames.size(); }, "How many key frames")
      .def("__getitem__", &Series::key_frame, py::arg("index"), "Key frame `index` read whole, every field")
      .def("at", &Series::at, py::arg("time"), py::arg("field") = "",
           "The mesh at `time`: the field (a scalar choice such as 'V:x') and, when they move, the points "
           "interpolated linearly between the key frames around it")
      .def("__repr__", [](const Series& s) {
        const TimeSeries& l = s.listed();
        return "<cellproj.Series " + l.source + ": " + std::to_string(l.frames.size()) +
               " key frames, t = " + std::to_string(l.frames.front().time) + " .. " +
               std::to_string(l.frames.back().time) + ">";
      });
  py::class_<SeriesPlayback>(m, "_Playback")
      .def(py::init([](const Series& s, const std::vector<double>& times, bool prefetch, const py::kwargs& kwargs) {
        return std::make_unique<SeriesPlayback>(s, times, prefetch, kwargs);
      }))
      .def("__iter__", [](py::object self) { return self; })
      .def("__next__", &SeriesPlayback::next);
  m.def("_animation_times", &animation_times);
  m.def("_is_series_path", &is_series_path);
}

}  // namespace cellproj::python
