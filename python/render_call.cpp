#include "python/render_call.hpp"

#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include <tbb/task_arena.h>

#include "base/error.hpp"
#include "mesh/clip.hpp"
#include "mesh/field_choice.hpp"
#include "scene/camera_json.hpp"
#include "scene/prepare.hpp"
#include "scene/quick_scene.hpp"
#include "scene/report_json.hpp"
#include "scene/transfer_function_json.hpp"
#include "view/figure.hpp"

namespace cellproj::python {

std::string python_words(const std::string& message) { return spell_settings(message, "", "=", '_'); }

std::string keywords_doc() {
  std::string doc = "\n\nRender settings (keywords; the command line's options of the same names):\n";
  for (const SettingRow& row : render_settings()) {
    std::string name = row.name;
    std::replace(name.begin(), name.end(), '-', '_');
    doc += "  " + name + "=: " + python_words(setting_help(row)) + "\n";
  }
  return doc;
}

namespace {

// A camera move's value as its text: numbers, a point (x, y, z), True for a switch.
std::string move_text(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return "";
  if (py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)) {
    std::string text;
    for (const auto& x : value) text += (text.empty() ? "" : ",") + std::string(py::str(x));
    return text;
  }
  return py::str(value);
}

// A mesh clipped by planes (mesh/clip.hpp, the CLI's --clip), owning its arrays, with the chosen
// field (and its opacity field) carried to the cut points: what a clipped picture renders, its
// colours and framing still the whole mesh's.
struct ClippedVolume {
  Mesh mesh;
  std::unique_ptr<Volume> volume;
  Field field;
};
ClippedVolume clipped(const NumpyMesh& numpy, const Field& f, const std::vector<std::vector<double>>& planes) {
  const std::vector<ClipPlane> clip = clip_planes(planes);
  const MeshView& v = numpy.view();
  Mesh whole;
  whole.source = v.source;
  whole.points = numpy.point_coordinates();
  whole.connectivity.assign(v.connectivity, v.connectivity + v.offsets[v.n_cells]);
  whole.offsets.assign(v.offsets, v.offsets + v.n_cells + 1);
  whole.types.assign(v.types, v.types + v.n_cells);
  whole.fields.push_back({f.name, std::vector<double>(f.values, f.values + f.size), "the field rendered"});
  if (f.opacity && f.opacity_name != f.name)
    whole.fields.push_back({f.opacity_name, std::vector<double>(f.opacity, f.opacity + f.size), "its opacity field"});
  ClippedVolume out{clip_mesh_kept(whole, clip, v.source), nullptr, {}};
  out.volume = std::make_unique<Volume>(out.mesh.view(), VolumeOptions{/*trusted: the mesh was validated*/ true});
  out.field = field_of(out.mesh, f.name, f.opacity ? f.opacity_name : "");
  return out;
}

// The call's field of `mesh` (its opacity field too).
Field call_field(const NumpyMesh& mesh, const RenderCall& call) {
  Field f = chosen_field(mesh, call.field, call.log, call.log_floor);
  if (!call.opacity_field.empty()) {  // the extinction's own field, never on a log scale
    const Field o = mesh.field(call.opacity_field);
    f.opacity = o.values, f.opacity_name = o.name;
  }
  return f;
}

// threads= as a worker count (0: all cores), checked as the CLI's --threads before TBB sees it.
int take_threads(py::dict& d) {
  if (!d.contains("threads")) return worker_threads(0);
  const py::object t = d["threads"];
  PyDict_DelItemString(d.ptr(), "threads");
  return threads_of(t);
}

template <class T>
void take(py::dict& d, const char* key, T& out) {
  if (!d.contains(key)) return;
  out = d[key].cast<T>();
  PyDict_DelItemString(d.ptr(), key);
}

}  // namespace

std::vector<ClipPlane> clip_planes(const std::vector<std::vector<double>>& planes) {
  std::vector<ClipPlane> clip;
  for (const std::vector<double>& p : planes) {
    if (p.size() != 6)
      throw InputError("setting 'clip': expected planes of 6 numbers (x, y, z, nx, ny, nz), got " +
                       std::to_string(p.size()));
    clip.push_back({{p[0], p[1], p[2]}, {p[3], p[4], p[5]}});
    check(clip.back());
  }
  return clip;
}

bool is_camera_move(const std::string& name) {
  for (const CameraMoveRow& row : camera_moves())
    if (name == row.name) return true;
  return false;
}

void add_camera_moves(const py::dict& kwargs, CameraMoves& moves) {
  for (const auto& [key, value] : kwargs) {
    const std::string name = py::str(key);
    if (!is_camera_move(name) || (py::isinstance<py::bool_>(value) && !value.cast<bool>())) continue;
    set_camera_move(moves, name, move_text(value));
  }
}

RenderOptions options_from(const std::string& method, const py::dict& kwargs) {
  RenderOptions o;
  if (!method.empty()) set_option(o, "method", method);
  for (const auto& [key, value] : kwargs) {
    if (is_camera_move(py::str(key))) continue;                                 // add_camera_moves'
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {  // a repeatable option: iso=[...]
      for (const auto& item : value) set_option(o, py::str(key), py::str(item));
    } else {
      set_option(o, py::str(key), py::str(value));
    }
  }
  return o;
}

int threads_of(const py::handle& threads) {
  const auto refuse = [&](const char* expected) {
    return InputError(std::string("setting 'threads': expected ") + expected + ", 0 (all cores) to " +
                      std::to_string(kMaxThreads) + ", got " + std::string(py::repr(threads)));
  };
  if (py::isinstance<py::bool_>(threads)) throw refuse("an integer");
  const py::object index = py::reinterpret_steal<py::object>(PyNumber_Index(threads.ptr()));  // numpy ints too
  if (!index) {
    PyErr_Clear();
    throw refuse("an integer");
  }
  int overflow = 0;
  const long long n = PyLong_AsLongLongAndOverflow(index.ptr(), &overflow);
  if (overflow) throw refuse("a thread count");
  return worker_threads(n);
}

ImageSize size_from(const std::pair<int, int>& size) {
  if (size.first < 1 || size.second < 1 || size.first > 16384 || size.second > 16384)
    throw InputError("size: expected (width, height) in [1, 16384], got (" + std::to_string(size.first) + ", " +
                     std::to_string(size.second) + ")");
  return {size.first, size.second};
}

Image render_frame(const Renderer& renderer, const Volume& volume, const Field& field, const TransferFunction& tf,
                   const Camera& camera, ImageSize size, int threads, RenderReport* report) {
  py::gil_scoped_release release;
  tbb::task_arena arena(threads);
  return arena.execute([&] { return renderer.render(volume, field, tf, camera, size, report); });
}

Field chosen_field(const NumpyMesh& mesh, const std::string& spec, bool log, std::optional<double> floor) {
  if (floor && !log) throw InputError("setting 'log-floor' is the floor of a log scale: give setting 'log' too");
  return mesh.field(log ? log_spec(spec, floor) : spec);
}

TransferFunction default_tf(const NumpyMesh& mesh, const Field& f, const QuickLook& look) {
  const OpacityInput field{mesh.view(), f.values, log_scale_name(f.name)};
  const OpacityInput opacity{mesh.view(), f.opacity};
  const FieldTransferFunction q = quick_transfer_function(look, field, f.opacity ? &opacity : nullptr);
  return transfer_function_from_json(q.json, "python", "", q.lo, q.hi, field.log, !f.opacity);
}

RenderCall render_call(const py::kwargs& kwargs) {
  RenderCall c;
  py::dict d(kwargs);  // a copy: the keys taken here leave the settings and moves
  take(d, "tf", c.tf), take(d, "camera", c.camera), take(d, "size", c.size), take(d, "field", c.field);
  take(d, "method", c.method), c.threads = take_threads(d), take(d, "log", c.log), take(d, "log_floor", c.log_floor);
  take(d, "cmap", c.cmap), take(d, "clim", c.clim), take(d, "opacity", c.opacity), take(d, "depth", c.depth);
  take(d, "view", c.view), take(d, "opacity_field", c.opacity_field), take(d, "clip", c.clip);
  c.rest = d;
  return c;
}

FramePlan plan_frame(const NumpyMesh& look, const RenderCall& call) {
  const RenderOptions options = options_from(call.method, call.rest);
  const RenderSettings settings = settings_from(options);
  std::unique_ptr<Renderer> renderer = make_renderer(settings);
  refuse_unused(settings, options.given);
  const ImageSize size = size_from(call.size);
  const Field field = call_field(look, call);
  const bool log = log_scale_name(field.name);  // asked for, or a time series' frames played so
  refuse_iso_on_log_scale(settings, log);
  if (call.camera && !call.view.empty()) throw InputError("give camera= or view=, not both");
  Camera camera;
  if (call.camera) {
    camera = *call.camera;
  } else {
    const auto [lo, hi] = bounds(look.view());
    camera = view_camera(call.view, lo, hi, double(size.width) / size.height);
  }
  QuickLook q;  // the CLI's look of a mesh: its colour map, opacity, depth and range
  if (!call.cmap.empty()) q.colormap = call.cmap;
  if (!call.opacity.empty()) q.opacity = call.opacity;
  q.depth = call.depth, q.range = call.clim;
  if (call.tf && (!call.cmap.empty() || !call.opacity.empty() || call.depth != 0.0 || call.clim))
    throw InputError("give tf= or the look keywords (cmap=, opacity=, depth=, clim=), not both");
  const TransferFunction tf = call.tf ? *call.tf : default_tf(look, field, q);
  CameraMoves moves;
  add_camera_moves(call.rest, moves);
  // The legend, as the CLI's: over legend_range, the field's name (on a log scale, the field's
  // own), in the field's units.
  const auto [field_lo, field_hi] = std::minmax_element(field.values, field.values + field.size);
  auto [lo, hi] = legend_range(tf, *field_lo, *field_hi);
  if (log) lo = std::pow(10.0, lo), hi = std::pow(10.0, hi);
  Legend legend{tf, lo, hi, log ? log_scale_scalar(field.name) : field.name, log, false, ""};
  return {settings, std::move(renderer), size, field, tf, camera, moved(camera, moves), std::move(legend)};
}

std::string frame_stats(const RenderReport& report, const FramePlan& plan, std::int64_t cells) {
  nlohmann::json stats = report_json(report);
  stats.update({{"method", plan.renderer->name()},
                {"field", plan.field.name},
                {"cells", cells},
                {"width", plan.size.width},
                {"height", plan.size.height},
                {"render_seconds", report.seconds},
                {"prepare_seconds", report.prepare_seconds}});
  if (plan.field.opacity) stats["opacity_field"] = plan.field.opacity_name;
  return stats.dump();
}

std::pair<Image, std::string> render_planned(const NumpyMesh& mesh, const FramePlan& plan, const RenderCall& call) {
  const Field f = call_field(mesh, call);
  RenderReport report;
  std::optional<ClippedVolume> cut;  // colours and framing are the look's, as the CLI's
  if (!call.clip.empty()) cut = clipped(mesh, f, call.clip);
  Image image = render_frame(*plan.renderer, cut ? *cut->volume : mesh.volume(), cut ? cut->field : f, plan.tf,
                             plan.camera, plan.size, call.threads, &report);
  return {std::move(image), frame_stats(report, plan, mesh.view().n_cells)};
}

}  // namespace cellproj::python
