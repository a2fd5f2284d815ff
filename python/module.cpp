// The Python module `cellproj` (docs/python.md): numpy meshes, readers, transfer functions,
// cameras, and rendering to a float32 (H, W, 4) array with the GIL released. Front end only: every
// choice is made by the same library calls the command line makes, so the pictures are the same.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include <nlohmann/json.hpp>

#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "io/read_mesh.hpp"
#include "io/series_files.hpp"
#include "mesh/clip.hpp"
#include "optics/colormaps.hpp"
#include "python/numpy_mesh.hpp"
#include "python/pictures.hpp"
#include "render/renderer.hpp"
#include "render/settings_table.hpp"
#include "scene/camera_json.hpp"
#include "scene/prepare.hpp"
#include "scene/quick_scene.hpp"
#include "scene/report_json.hpp"
#include "scene/scene_file.hpp"
#include "scene/transfer_function_json.hpp"
#include "scene/volume_scene.hpp"
#include "view/figure.hpp"

namespace py = pybind11;
using namespace cellproj;
using cellproj::python::from_numpy;
using cellproj::python::Legend;
using cellproj::python::NumpyMesh;
using cellproj::python::to_numpy;

namespace {

// A library message as Python says it: setting 'table-size' as the keyword table_size=.
std::string python_words(const std::string& message) { return spell_settings(message, "", "=", '_'); }

// The keyword arguments as render options (method=, sort=, table_size=, ...).
// The render settings as keywords, for docstrings: one line each, from the settings table.
std::string keywords_doc() {
  std::string doc = "\n\nRender settings (keywords; the command line's options of the same names):\n";
  for (const SettingRow& row : render_settings()) {
    std::string name = row.name;
    std::replace(name.begin(), name.end(), '-', '_');
    doc += "  " + name + "=: " + python_words(setting_help(row)) + "\n";
  }
  return doc;
}

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

bool is_camera_move(const std::string& name) {
  for (const CameraMoveRow& row : camera_moves())
    if (name == row.name) return true;
  return false;
}

// The camera moves among the keywords (azimuth=30, zoom=2, ...), added to `moves`; False skips a switch.
void add_camera_moves(const py::kwargs& kwargs, CameraMoves& moves) {
  for (const auto& [key, value] : kwargs) {
    const std::string name = py::str(key);
    if (!is_camera_move(name) || (py::isinstance<py::bool_>(value) && !value.cast<bool>())) continue;
    set_camera_move(moves, name, move_text(value));
  }
}

// `method` empty: not given (a scene's, or the default).
RenderOptions options_from(const std::string& method, const py::kwargs& kwargs) {
  RenderOptions o;
  if (!method.empty()) set_option(o, "method", method);
  for (const auto& [key, value] : kwargs) {
    if (is_camera_move(py::str(key))) continue;                                 // camera_moves_from's
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {  // a repeatable option: iso=[...]
      for (const auto& item : value) set_option(o, py::str(key), py::str(item));
    } else {
      set_option(o, py::str(key), py::str(value));
    }
  }
  return o;
}

ImageSize size_from(const std::pair<int, int>& size) {
  if (size.first < 1 || size.second < 1 || size.first > 16384 || size.second > 16384)
    throw InputError("size: expected (width, height) in [1, 16384], got (" + std::to_string(size.first) + ", " +
                     std::to_string(size.second) + ")");
  return {size.first, size.second};
}

// Renders on `threads` workers (0: all cores) without the GIL.
Image render_frame(const Renderer& renderer, const Volume& volume, const Field& field, const TransferFunction& tf,
                   const Camera& camera, ImageSize size, int threads, RenderReport* report = nullptr) {
  py::gil_scoped_release release;
  tbb::task_arena arena(threads > 0 ? threads : tbb::info::default_concurrency());
  return arena.execute([&] { return renderer.render(volume, field, tf, camera, size, report); });
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
  std::vector<ClipPlane> clip;
  for (const std::vector<double>& p : planes) {
    if (p.size() != 6)
      throw InputError("setting 'clip': expected planes of 6 numbers (x, y, z, nx, ny, nz), got " +
                       std::to_string(p.size()));
    clip.push_back({{p[0], p[1], p[2]}, {p[3], p[4], p[5]}});
    check(clip.back());
  }
  const MeshView& v = numpy.view();
  Mesh whole;
  whole.source = v.source;
  for (std::int64_t q = 0; q < v.n_points; ++q)
    for (int k = 0; k < 3; ++k) whole.points.push_back(v.point(q)[k]);
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

glm::dvec3 vec(const std::vector<double>& v, const char* what) {
  if (v.size() != 3) throw InputError(std::string(what) + ": expected 3 numbers");
  return {v[0], v[1], v[2]};
}

// The transfer function `cellproj render MESH` gives the field (scene/quick_scene.hpp): over its
// range in the field's units, placed on a log axis when the field is on a log scale; the
// extinction over the opacity field's values when it has one of its own.
TransferFunction default_tf(const NumpyMesh& mesh, const Field& f, const QuickLook& look) {
  const OpacityInput field{mesh.view(), f.values, log_scale_name(f.name)};
  const OpacityInput opacity{mesh.view(), f.opacity};
  const FieldTransferFunction q = quick_transfer_function(look, field, f.opacity ? &opacity : nullptr);
  return transfer_function_from_json(q.json, "python", "", q.lo, q.hi, field.log, !f.opacity);
}

// The field `spec` of `mesh`, on a log scale when asked (mesh/field_choice.hpp).
Field chosen_field(const NumpyMesh& mesh, const std::string& spec, bool log, std::optional<double> floor) {
  if (floor && !log) throw InputError("setting 'log-floor' is the floor of a log scale: give setting 'log' too");
  return mesh.field(log ? log_spec(spec, floor) : spec);
}

Camera make_camera(const std::vector<double>& eye, const std::vector<double>& target, const std::vector<double>& up,
                   const std::string& projection, double fov_y, double height) {
  Camera c;
  if (projection == "perspective")
    c.projection = Projection::Perspective;
  else if (projection == "orthographic")
    c.projection = Projection::Orthographic;
  else
    throw InputError("projection: expected 'perspective' or 'orthographic', got '" + projection + "'");
  c.eye = vec(eye, "eye");
  c.target = vec(target, "target");
  c.up = vec(up, "up");
  c.fov_y = fov_y;
  c.height = height;
  check_camera(c, "cellproj.Camera");
  return c;
}

}  // namespace

PYBIND11_MODULE(_cellproj, m) {
  static const std::string render_doc =
      "Renders to a premultiplied float32 (H, W, 4) array; size=(width, height); field='T', or of a vector 'V:x', "
      "'V_X', 'V:magnitude', 'S:von_mises'; log=True: the field on a log scale (log10 at the points, interpolated; "
      "log_floor=F counts values below F as F), the default transfer function over the log of its range." +
      keywords_doc();
  static const std::string render_scene_doc =
      "Renders a scene file as `cellproj render SCENE` does (the same array as its --npy); time=T for a time series, "
      "as --time T; method and the other settings default to the scene's \"render\" block, else as the CLI's "
      "(pt-breakpoints, or exact for a scene of several volumes)." +
      keywords_doc();
  m.doc() = "cellproj: direct volume rendering of unstructured and curvilinear grids (docs/python.md)";
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<ResourceError> resource_error(m, "ResourceError", PyExc_RuntimeError);
  // A valid request not drawn yet: an InputError, and Python's NotImplementedError.
  static py::exception<UnsupportedError> unsupported_error(
      m, "UnsupportedError", py::make_tuple(input_error, py::handle(PyExc_NotImplementedError)));
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const UnsupportedError& e) {
      unsupported_error(python_words(e.what()).c_str());
    } catch (const InputError& e) {
      input_error(python_words(e.what()).c_str());
    } catch (const ResourceError& e) {
      resource_error(python_words(e.what()).c_str());
    }
  });

  py::class_<NumpyMesh>(m, "Mesh", "A mesh over numpy arrays (VTK's layout), validated and committed once")
      .def(py::init([](py::array points, py::array connectivity, py::array offsets, py::array types, py::object scalars,
                       std::string name) {
             return std::make_unique<NumpyMesh>(points, connectivity, offsets, types, scalars, name);
           }),
           py::arg("points"), py::arg("connectivity"), py::arg("offsets"), py::arg("types"),
           py::arg("scalars") = py::none(), py::arg("name") = "numpy arrays",
           "points (N, 3) float64/float32; connectivity, offsets (n_cells + 1) int64/int32; types uint8 VTK "
           "codes; scalars: one array (N,) or a dict name -> array")
      .def_property_readonly("n_points", [](const NumpyMesh& s) { return s.view().n_points; })
      .def_property_readonly("n_cells", [](const NumpyMesh& s) { return s.view().n_cells; })
      .def_property_readonly(
          "fields",
          [](const NumpyMesh& s) {
            py::dict d;
            for (const FieldShape& f : s.field_shapes()) d[py::str(f.name)] = f.components;
            return d;
          },
          "The fields, name -> components per point (1 for a scalar); field='V:x', 'V_X', 'V:magnitude' or "
          "'S:von_mises' picks a scalar of a vector or tensor, 'V' alone its magnitude")
      .def_property_readonly("copies", &NumpyMesh::copies, "What was copied of the caller's arrays, and why")
      .def_property_readonly("bounds",
                             [](const NumpyMesh& s) {
                               const auto [lo, hi] = bounds(s.view());
                               return py::make_tuple(py::make_tuple(lo.x, lo.y, lo.z),
                                                     py::make_tuple(hi.x, hi.y, hi.z));
                             })
      .def(
          "field",
          [](py::object self, const std::string& name) {
            return self.cast<const NumpyMesh&>().field_array(name, self);
          },
          py::arg("name") = "",
          "A field's values, read-only, without a copy: (N,) or (N, k) as stored, or the (N,) scalar a choice "
          "such as 'V:x' makes")
      .def("add_field", &NumpyMesh::add_field, py::arg("name"), py::arg("values"))
      .def("__repr__", [](const NumpyMesh& s) {
        return "<cellproj.Mesh " + s.view().source + ": " + std::to_string(s.view().n_cells) + " cells, " +
               std::to_string(s.view().n_points) + " points>";
      });

  m.def(
      "_mesh_with_cell_data",
      [](py::array points, py::array connectivity, py::array offsets, py::array types, const py::dict& point_fields,
         const py::dict& cell_fields, const std::string& cell_data, const std::string& name) {
        return std::make_unique<NumpyMesh>(python::mesh_with_cell_data(
            points, connectivity, offsets, types, point_fields, cell_fields, cell_data_from_name(cell_data), name));
      },
      "from_vtk's and from_meshio's door for data with cell fields (a copy, validated as cellproj.read validates)");

  m.def(
      "_load_vtk",
      [](std::uintptr_t address, const std::string& source, const std::string& cell_data) {
        ReadOptions o;
        o.cell_data = cell_data_from_name(cell_data);
        auto* data = reinterpret_cast<vtkDataObject*>(address);  // a live object of the caller's, in this VTK
        return std::make_unique<NumpyMesh>(std::make_shared<const Mesh>(load_vtk_object(data, source, o).mesh));
      },
      "from_vtk's door: the VTK object at `address` (its __this__) assembled as read() assembles a file's");
  m.def("_vtk_version", &vtk_library_version);

  m.def(
      "read",
      [](const std::string& path, const std::string& format, const std::string& q_file, const std::string& zone,
         int time_step, const std::string& cell_data) {
        ReadOptions o;
        o.cell_data = cell_data_from_name(cell_data);
        o.format = format;
        o.q_file = q_file;
        o.zone = zone;
        o.time_step = time_step;
        auto mesh = [&] {
          py::gil_scoped_release release;
          return std::make_shared<const Mesh>(load_mesh(path, o).mesh);
        }();
        return std::make_unique<NumpyMesh>(std::move(mesh));
      },
      py::arg("path"), py::arg("format") = "", py::arg("q_file") = "", py::arg("zone") = "", py::arg("time_step") = 0,
      py::arg("cell_data") = "cells",
      "Reads and validates a mesh file (any format `cellproj info` reads); cell_data='cells' draws cell data constant "
      "over each cell (each cell its own points), 'points' averages it to the points");

  py::class_<TransferFunction>(m, "TransferFunction",
                               "Colour and extinction as piecewise-linear functions of the field")
      .def(
          py::init([](std::vector<std::array<double, 2>> extinction,
                      std::optional<std::vector<std::array<double, 4>>> color, std::optional<std::string> colormap_name,
                      std::optional<std::pair<double, double>> range, bool log) {
            if (color.has_value() == colormap_name.has_value())
              throw InputError("TransferFunction: give exactly one of color=[(s, r, g, b), ...] and colormap=NAME");
            if (colormap_name && !range) throw InputError("TransferFunction: colormap= needs range=(lo, hi)");
            // As a scene's transfer function (docs/scene.md), so that log= places the points as a scene's "log".
            nlohmann::json j = {{"extinction", extinction}};
            if (color) j["color"] = *color;
            if (colormap_name) j["color_preset"] = {{"name", *colormap_name}, {"range", {range->first, range->second}}};
            return transfer_function_from_json(j, "TransferFunction", "", 1.0, 1.0, log);
          }),
          py::kw_only(), py::arg("extinction"), py::arg("color") = py::none(), py::arg("colormap") = py::none(),
          py::arg("range") = py::none(), py::arg("log") = false,
          "extinction=[(s, kappa), ...] and color=[(s, r, g, b), ...] or colormap=NAME with range=(lo, hi); "
          "log=True places the points (in the field's units) on a log scale, for render(..., log=True)")
      .def_static(
          "default",
          [](const NumpyMesh& mesh, const std::string& field, const std::string& colormap_name,
             const std::string& opacity, double depth, bool log, std::optional<double> log_floor) {
            QuickLook look;
            look.colormap = colormap_name;
            look.opacity = opacity;
            look.depth = depth;
            return default_tf(mesh, chosen_field(mesh, field, log, log_floor), look);
          },
          py::arg("mesh"), py::arg("field") = "", py::arg("colormap") = QuickLook{}.colormap,
          py::arg("opacity") = QuickLook{}.opacity, py::arg("depth") = QuickLook{}.depth, py::arg("log") = false,
          py::arg("log_floor") = py::none(),
          "The transfer function `cellproj render MESH` uses: a colour map over the field's range and the "
          "extinction opacity= names: auto (faint at the field's background value, scaled so the mesh is neither "
          "an opaque slab nor a haze), ramp, reverse, flat, sigmoid, geometric or 'S=DEPTH,...'; depth= fixes the "
          "largest optical depth across the mesh's diagonal (0: auto's, or 20)")
      .def("color",
           [](const TransferFunction& tf, double s) {
             const glm::dvec3 c = tf.color(s);
             return py::make_tuple(c.r, c.g, c.b);
           })
      .def("extinction", &TransferFunction::extinction);
  m.def("colormaps", &colormap_list, "The built-in colour maps, by ParaView's names");

  cellproj::python::bind_pictures(m);

  py::class_<Camera>(m, "Camera")
      .def(py::init(&make_camera), py::arg("eye"), py::arg("target"), py::arg("up") = std::vector<double>{0, 0, 1},
           py::arg("projection") = "perspective", py::arg("fov_y") = 30.0, py::arg("height") = 2.0)
      .def_static(
          "framing",
          [](const NumpyMesh& mesh, const std::string& view, double aspect) {
            const auto [lo, hi] = bounds(mesh.view());
            return view_camera(view, lo, hi, aspect);
          },
          py::arg("mesh"), py::arg("view") = "", py::arg("aspect") = 1.0,
          "An orthographic camera framing the mesh from a named view (+x, -x, +y, -y, +z, -z, iso; '' the default)")
      .def(
          "orbit", [](const Camera& c, double degrees) { return orbit(c, degrees); }, py::arg("degrees"),
          "The camera turned about its up axis through the target")
      .def(
          "moved",
          [](const Camera& c, const py::kwargs& moves) {
            CameraMoves m;
            add_camera_moves(moves, m);
            for (const auto& [key, value] : moves)
              if (!is_camera_move(py::str(key))) set_camera_move(m, py::str(key), "");  // names the unknown one
            return moved(c, m);
          },
          "The camera moved as ParaView moves it: moved(azimuth=30, elevation=20, roll=0, zoom=2, dolly=1.5, "
          "focus=(x, y, z), perspective=40 or True, parallel=True); angles in degrees")
      .def_property_readonly("eye", [](const Camera& c) { return py::make_tuple(c.eye.x, c.eye.y, c.eye.z); })
      .def_property_readonly("target",
                             [](const Camera& c) { return py::make_tuple(c.target.x, c.target.y, c.target.z); })
      .def_property_readonly("up", [](const Camera& c) { return py::make_tuple(c.up.x, c.up.y, c.up.z); });

  m.def(
      "_render",
      [](const NumpyMesh& mesh, std::optional<TransferFunction> tf, std::optional<Camera> camera,
         std::pair<int, int> size, const std::string& field, const std::string& method, int threads, bool log,
         std::optional<double> log_floor, const std::string& cmap, std::optional<std::pair<double, double>> clim,
         const std::string& opacity, double depth, const std::string& view, const std::string& opacity_field,
         const std::vector<std::vector<double>>& clip, const py::kwargs& kwargs) {
        const RenderOptions options = options_from(method, kwargs);
        const RenderSettings settings = settings_from(options);
        const std::unique_ptr<Renderer> renderer = make_renderer(settings);
        refuse_unused(settings, options.given);
        const ImageSize image_size = size_from(size);
        Field f = chosen_field(mesh, field, log, log_floor);
        if (!opacity_field.empty()) {  // the extinction's own field, never on a log scale
          const Field o = mesh.field(opacity_field);
          f.opacity = o.values, f.opacity_name = o.name;
        }
        refuse_iso_on_log_scale(settings, log);
        const double aspect = double(image_size.width) / image_size.height;
        if (camera && !view.empty()) throw InputError("give camera= or view=, not both");
        if (!camera) {
          const auto [lo, hi] = bounds(mesh.view());
          camera = view_camera(view, lo, hi, aspect);
        }
        QuickLook look;  // the CLI's look of a mesh: its colour map, opacity, depth and range
        if (!cmap.empty()) look.colormap = cmap;
        if (!opacity.empty()) look.opacity = opacity;
        look.depth = depth, look.range = clim;
        if (tf && (!cmap.empty() || !opacity.empty() || depth != 0.0 || clim))
          throw InputError("give tf= or the look keywords (cmap=, opacity=, depth=, clim=), not both");
        if (!tf) tf = default_tf(mesh, f, look);
        CameraMoves moves;
        add_camera_moves(kwargs, moves);
        camera = moved(*camera, moves);
        RenderReport report;
        std::optional<ClippedVolume> cut;  // colours and framing above are the whole mesh's, as the CLI's
        if (!clip.empty()) cut = clipped(mesh, f, clip);
        Image image = render_frame(*renderer, cut ? *cut->volume : mesh.volume(), cut ? cut->field : f, *tf, *camera,
                                   image_size, threads, &report);
        nlohmann::json stats = report_json(report);
        stats.update({{"method", renderer->name()},
                      {"field", f.name},
                      {"cells", mesh.view().n_cells},
                      {"width", image_size.width},
                      {"height", image_size.height}});
        if (f.opacity) stats["opacity_field"] = f.opacity_name;
        // The legend of the picture, as the CLI's: over legend_range, the field's name (on a log scale,
        // the field's own), in the field's units.
        const auto [field_lo, field_hi] = std::minmax_element(f.values, f.values + f.size);
        auto [lo, hi] = legend_range(*tf, *field_lo, *field_hi);
        if (log) lo = std::pow(10.0, lo), hi = std::pow(10.0, hi);
        const Legend legend{*tf, lo, hi, log ? log_scale_scalar(f.name) : f.name, log, false, ""};
        return py::make_tuple(to_numpy(std::move(image)), stats.dump(), legend);
      },
      py::arg("mesh"), py::arg("tf") = py::none(), py::arg("camera") = py::none(),
      py::arg("size") = std::pair<int, int>{512, 512}, py::arg("field") = "", py::arg("method") = "pt-breakpoints",
      py::arg("threads") = 0, py::arg("log") = false, py::arg("log_floor") = py::none(), py::arg("cmap") = "",
      py::arg("clim") = py::none(), py::arg("opacity") = "", py::arg("depth") = 0.0, py::arg("view") = "",
      py::arg("opacity_field") = "", py::arg("clip") = std::vector<std::vector<double>>{},
      "cellproj.render's door: the image, its --stats as JSON and its legend");
  m.def("_keywords_doc", &keywords_doc);

  m.def(
      "render_scene",
      [](const std::string& path, std::optional<std::pair<int, int>> size, const std::string& field,
         const std::string& view, const std::string& method, int threads, std::optional<double> time, bool log,
         std::optional<double> log_floor, const py::kwargs& kwargs) {
        Scene scene = load_scene(path);
        // Several volumes are drawn by the exact renderer, its default there (render/volume_set.hpp).
        RenderOptions options = options_from(method, kwargs);
        if (scene.volumes.size() > 1 && !option_given(options, "method")) {  // the exact renderer's scene
          set_option(options, "method", "exact");
          options.given.pop_back();  // a default, not the caller's word
        }
        for (const std::string& w : apply_scene_options(scene, options))
          PyErr_WarnEx(PyExc_UserWarning, python_words(w).c_str(), 1);
        const std::unique_ptr<Renderer> renderer = make_renderer(settings_from(options));
        refuse_unused(settings_from(options), options.given);
        if (size) std::tie(scene.width, scene.height) = std::tie(size->first, size->second);
        const ImageSize image_size = size_from({scene.width, scene.height});
        if (!field.empty()) scene.field = field;
        if (log) scene.log_scale = true;
        if (log_floor) scene.log_floor = log_floor;
        refuse_iso_on_log_scale(settings_from(options), scene.log_scale);
        if (!view.empty()) {
          scene.camera.reset(), scene.camera_moves = {};
          scene.view = view;
        }
        add_camera_moves(kwargs, scene.camera_moves);  // after the scene's own, as the CLI's
        if (scene.volumes.size() > 1) {                // as `cellproj render` of such a scene
          if (!field.empty())
            throw InputError(path + " has several volumes: give each volume's \"field\" in the scene");
          if (time) throw InputError(path + " has several volumes: time series take one mesh");
          const bool volume_given = option_given(options, "volume");
          const RenderSettings settings = settings_from(options);
          py::gil_scoped_release release;
          const VolumeScene volumes(
              scene, [](const SceneVolume& v) { return load_mesh(v.mesh, v.reader); },
              volume_given ? std::optional<bool>(settings.iso.volume) : std::nullopt);
          tbb::task_arena arena(threads > 0 ? threads : tbb::info::default_concurrency());
          Image image =
              arena.execute([&] { return render_volumes(volumes.entries(), settings, volumes.camera(), image_size); });
          py::gil_scoped_acquire acquire;
          return to_numpy(std::move(image));
        }
        // A time series (the scene's mesh a .pvd, a pattern, or an Exodus file given a time): the
        // field at `time`, interpolated between key frames, as `cellproj render --time`.
        if (time || is_series_path(scene.mesh)) {
          struct Played {
            std::unique_ptr<SeriesPlayer> player;
            PreparedScene prepared;
            SeriesFrame frame;
          };
          const Played p = [&] {
            py::gil_scoped_release release;
            TimeSeries series = list_series(scene.mesh, scene.reader);
            const double t = time ? *time : series.frames.front().time;
            locate(series, t);
            auto player =
                std::make_unique<SeriesPlayer>(std::move(series), scene_field(scene), key_frame_reader(scene.reader));
            LoadedMesh first = first_key_frame(*player, scene);
            PreparedScene prepared = prepare_scene(scene, std::move(first));
            SeriesFrame frame = player->frame_at(t);
            return Played{std::move(player), std::move(prepared), std::move(frame)};
          }();
          if (!scene.clip.empty()) {  // the frame clipped, as the CLI's playback clips it
            Mesh whole = p.player->cells();
            whole.points = *p.frame.points;
            whole.fields.push_back({p.player->field_name(), p.frame.field, "a time series' frame"});
            const Mesh mesh = clip_mesh_kept(whole, scene.clip, path);
            const Volume volume(mesh.view(), {/*trusted: key frames are validated*/ !p.player->points_move()});
            return to_numpy(render_frame(*renderer, volume, field_of(mesh, p.player->field_name()), p.prepared.tf,
                                         p.prepared.camera, image_size, threads));
          }
          const Volume volume(p.player->view(p.frame),
                              {/*trusted: key frames are validated*/ !p.player->points_move()});
          const Field f{p.frame.field.data(), static_cast<std::int64_t>(p.frame.field.size()), p.player->field_name(),
                        nullptr, ""};
          return to_numpy(render_frame(*renderer, volume, f, p.prepared.tf, p.prepared.camera, image_size, threads));
        }
        PreparedScene prepared = [&] {
          py::gil_scoped_release release;
          return prepare_scene(scene);
        }();
        // Clipped after preparing, as the CLI does: colours and framing are the whole mesh's.
        const Mesh mesh = scene.clip.empty() ? std::move(prepared.loaded.mesh)
                                             : clip_mesh_kept(prepared.loaded.mesh, scene.clip, path);
        const Volume volume(mesh.view(), {/*trusted: load_mesh validated it*/ true});
        return to_numpy(render_frame(*renderer, volume, field_of(mesh, prepared.field, prepared.opacity_field),
                                     prepared.tf, prepared.camera, image_size, threads));
      },
      py::arg("path"), py::arg("size") = py::none(), py::arg("field") = "", py::arg("view") = "",
      py::arg("method") = "", py::arg("threads") = 0, py::arg("time") = py::none(), py::arg("log") = false,
      py::arg("log_floor") = py::none(), render_scene_doc.c_str());
}
