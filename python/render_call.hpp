#pragma once
// What cellproj.render was asked, and the plan of its picture: the renderer, the field, the
// transfer function and the camera, made as `cellproj render MESH` makes them. Shared by a mesh's
// one picture and a time series' frames. Internal to the module.
#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mesh/clip.hpp"
#include "python/numpy_mesh.hpp"
#include "python/pictures.hpp"
#include "render/renderer.hpp"
#include "render/settings_table.hpp"
#include "scene/quick_scene.hpp"
#include "view/camera.hpp"
#include "view/camera_moves.hpp"

namespace cellproj::python {

namespace py = pybind11;

// A library message as Python says it: setting 'table-size' as the keyword table_size=.
std::string python_words(const std::string& message);

// cellproj.render's keywords (python/cellproj/__init__.py hands them over by name): the look and
// the view; the rest are render settings and camera moves.
struct RenderCall {
  std::optional<TransferFunction> tf;
  std::optional<Camera> camera;
  std::pair<int, int> size{512, 512};
  std::string field, method = "pt-breakpoints";
  int threads = 1;  // workers: threads_of(threads=)
  bool log = false;
  std::optional<double> log_floor;
  std::string cmap;
  std::optional<std::pair<double, double>> clim;
  std::string opacity;
  double depth = 0.0;
  std::string view, opacity_field;
  std::vector<std::vector<double>> clip;
  py::dict rest;  // render settings (method=, sort=, table_size=, ...) and camera moves (azimuth=, ...)
};
RenderCall render_call(const py::kwargs& kwargs);

// clip= as planes (6 numbers each: x, y, z, nx, ny, nz), checked.
std::vector<ClipPlane> clip_planes(const std::vector<std::vector<double>>& planes);

// The plan of a picture whose colours and framing are those of `look`'s field and bounds.
struct FramePlan {
  RenderSettings settings;
  std::unique_ptr<Renderer> renderer;
  ImageSize size;
  Field field;  // look's
  TransferFunction tf;
  Camera view;    // the camera before the call's moves
  Camera camera;  // moved
  Legend legend;
};
FramePlan plan_frame(const NumpyMesh& look, const RenderCall& call);

// The field `spec` of `mesh`, on a log scale when asked (mesh/field_choice.hpp).
Field chosen_field(const NumpyMesh& mesh, const std::string& spec, bool log, std::optional<double> floor);

// The transfer function `cellproj render MESH` gives the field (scene/quick_scene.hpp): over its
// range in the field's units, placed on a log axis when the field is on a log scale; the
// extinction over the opacity field's values when it has one of its own.
TransferFunction default_tf(const NumpyMesh& mesh, const Field& f, const QuickLook& look);

// Renders on `threads` workers (threads_of's count) without the GIL.
Image render_frame(const Renderer& renderer, const Volume& volume, const Field& field, const TransferFunction& tf,
                   const Camera& camera, ImageSize size, int threads, RenderReport* report = nullptr);

// One picture of `mesh`'s field (the same choice as plan.field's, on `mesh`), clipped by the
// call's planes; its --stats as JSON.
std::pair<Image, std::string> render_planned(const NumpyMesh& mesh, const FramePlan& plan, const RenderCall& call);

// The --stats of a frame, as the CLI's keys.
std::string frame_stats(const RenderReport& report, const FramePlan& plan, std::int64_t cells);

// The render settings as keywords, for docstrings: one line each, from the settings table.
std::string keywords_doc();

// The camera moves among the keywords (azimuth=30, zoom=2, ...), added to `moves`; False skips a switch.
void add_camera_moves(const py::dict& kwargs, CameraMoves& moves);
bool is_camera_move(const std::string& name);

// `method` empty: not given (a scene's, or the default).
RenderOptions options_from(const std::string& method, const py::dict& kwargs);

ImageSize size_from(const std::pair<int, int>& size);

// threads= (an int: 0 all cores, up to kMaxThreads) as a worker count; InputError for anything else.
int threads_of(const py::handle& threads);

}  // namespace cellproj::python
