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

#include <tbb/task_arena.h>
#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "io/read_mesh.hpp"
#include "io/series_files.hpp"
#include "mesh/clip.hpp"
#include "optics/colormaps.hpp"
#include "python/numpy_mesh.hpp"
#include "python/pictures.hpp"
#include "python/render_call.hpp"
#include "python/series.hpp"
#include "render/playback.hpp"
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
using namespace cellproj::python;

namespace {

// A mesh's connectivity or offsets as a read-only int64 array over the volume's own, kept alive by `self`.
py::array ids_array(py::object self, const std::int64_t* MeshView::*ids) {
  const MeshView& v = self.cast<const NumpyMesh&>().view();
  const py::ssize_t n = ids == &MeshView::offsets ? v.n_cells + 1 : v.offsets[v.n_cells];
  return read_only(py::array(py::dtype::of<std::int64_t>(), {n}, {py::ssize_t(sizeof(std::int64_t))}, v.*ids, self));
}

glm::dvec3 vec(const std::vector<double>& v, const char* what) {
  if (v.size() != 3) throw InputError(std::string(what) + ": expected 3 numbers");
  return {v[0], v[1], v[2]};
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
  input_error.attr("__doc__") = "Bad input: a file, an array, a keyword or a value, named with what is wrong";
  static py::exception<ResourceError> resource_error(m, "ResourceError", PyExc_RuntimeError);
  resource_error.attr("__doc__") = "Not enough of a resource: memory, or a back end this build does not have";
  // A valid request not drawn yet: an InputError, and Python's NotImplementedError.
  static py::exception<UnsupportedError> unsupported_error(
      m, "UnsupportedError", py::make_tuple(input_error, py::handle(PyExc_NotImplementedError)));
  unsupported_error.attr("__doc__") = "A valid request this version does not draw yet";
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
      .def_property_readonly(
          "n_points", [](const NumpyMesh& s) { return s.view().n_points; }, "How many points")
      .def_property_readonly(
          "n_cells", [](const NumpyMesh& s) { return s.view().n_cells; }, "How many cells")
      .def_property_readonly(
          "fields",
          [](const NumpyMesh& s) {
            py::dict d;
            for (const FieldShape& f : s.field_shapes()) d[py::str(f.name)] = f.components;
            return d;
          },
          "The fields, name -> components per point (1 for a scalar); field='V:x', 'V_X', 'V:magnitude' or "
          "'S:von_mises' picks a scalar of a vector or tensor, 'V' alone its magnitude")
      .def_property_readonly(
          "points",
          [](const NumpyMesh& s) {
            std::vector<double> xyz = s.point_coordinates();
            py::array_t<double> out({py::ssize_t(xyz.size() / 3), py::ssize_t(3)});
            std::copy(xyz.begin(), xyz.end(), out.mutable_data());
            return out;
          },
          "The points, (N, 3) float64: a copy")
      .def_property_readonly(
          "connectivity", [](py::object self) { return ids_array(self, &MeshView::connectivity); },
          "The cells' point ids, int64, read-only, no copy (inverted cells as re-oriented)")
      .def_property_readonly(
          "offsets", [](py::object self) { return ids_array(self, &MeshView::offsets); },
          "Where each cell's ids start in connectivity (n_cells + 1 entries), int64, read-only, no copy")
      .def_property_readonly(
          "types",
          [](py::object self) {
            const MeshView& v = self.cast<const NumpyMesh&>().view();
            return read_only(py::array(py::dtype::of<std::uint8_t>(), {v.n_cells}, {1}, v.types, self));
          },
          "The cells' VTK type codes, uint8, read-only, no copy")
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
      .def("add_field", &NumpyMesh::add_field, py::arg("name"), py::arg("values"),
           "Adds (or replaces) a field: values (N,) or (N, k) for k components, one row per point, read in place "
           "when float64 and contiguous")
      .def(
          "update",
          [](NumpyMesh& mesh, std::optional<py::array> field, std::optional<py::array> points,
             const std::string& name) {
            if (points) mesh.set_points(*points);
            if (field) mesh.add_field(mesh.stored_name(name), *field);
          },
          py::kw_only(), py::arg("field") = py::none(), py::arg("points") = py::none(), py::arg("name") = "",
          "A solver's next step, its arrays taken in place (float64, contiguous: no copy): field= the values of "
          "field `name` ('' the only one; 'V:x' names V), (N,) or (N, k) as stored; the preparation is kept. "
          "points= (N, 3): the same cells over moved points, validated; the preparation is made again on the next "
          "render (connectivity and types are kept)")
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
      .def(
          "color",
          [](const TransferFunction& tf, double s) {
            const glm::dvec3 c = tf.color(s);
            return py::make_tuple(c.r, c.g, c.b);
          },
          py::arg("s"), "The colour (r, g, b) at field value s")
      .def("extinction", &TransferFunction::extinction, py::arg("s"),
           "The extinction coefficient at field value s (per unit length)");
  m.def("colormaps", &colormap_list, "The built-in colour maps, by ParaView's names");

  bind_pictures(m);
  bind_series(m);

  py::class_<Camera>(m, "Camera", "A camera: where the eye is, what it looks at, and how it projects")
      .def(py::init(&make_camera), py::arg("eye"), py::arg("target"), py::arg("up") = std::vector<double>{0, 0, 1},
           py::arg("projection") = "perspective", py::arg("fov_y") = 30.0, py::arg("height") = 2.0,
           "eye, target and up as (x, y, z); projection 'perspective' (fov_y: the vertical field of view in "
           "degrees) or 'orthographic' (height: the view's height in the mesh's units)")
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
      .def_property_readonly(
          "eye", [](const Camera& c) { return py::make_tuple(c.eye.x, c.eye.y, c.eye.z); }, "The eye's position")
      .def_property_readonly(
          "target", [](const Camera& c) { return py::make_tuple(c.target.x, c.target.y, c.target.z); },
          "The point looked at")
      .def_property_readonly(
          "up", [](const Camera& c) { return py::make_tuple(c.up.x, c.up.y, c.up.z); }, "The up direction");

  m.def(
      "_render",
      [](const NumpyMesh& mesh, const NumpyMesh* look, const py::kwargs& kwargs) {
        const RenderCall call = render_call(kwargs);
        const FramePlan plan = plan_frame(look ? *look : mesh, call);
        auto [image, stats] = render_planned(mesh, plan, call);
        return py::make_tuple(to_numpy(std::move(image)), stats, plan.legend, plan.tf, plan.view);
      },
      py::arg("mesh"), py::arg("look") = py::none(),
      "cellproj.render's door: the image, its --stats as JSON, its legend, and the transfer function and camera "
      "(before the moves) it was drawn with; colours and framing are look's, else the mesh's");
  m.def("_keywords_doc", &keywords_doc);

  m.def(
      "render_scene",
      [](const std::string& path, std::optional<std::pair<int, int>> size, const std::string& field,
         const std::string& view, const std::string& method, const py::object& threads_arg, std::optional<double> time,
         bool log, std::optional<double> log_floor, const py::kwargs& kwargs) {
        const int threads = threads_of(threads_arg);
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
          tbb::task_arena arena(threads);
          Image image =
              arena.execute([&] { return render_volumes(volumes.entries(), settings, volumes.camera(), image_size); });
          py::gil_scoped_acquire acquire;
          return to_numpy(std::move(image));
        }
        // A time series (the scene's mesh a .pvd, a pattern, or an Exodus file given a time): the
        // field at `time`, interpolated between key frames, as `cellproj render --time`.
        if (time || is_series_path(scene.mesh)) {
          py::gil_scoped_release release;
          TimeSeries series = list_series(scene.mesh, scene.reader);
          const std::vector<double> times{time ? *time : series.frames.front().time};
          locate(series, times[0]);
          SeriesPlayer player(std::move(series), scene_field(scene), key_frame_reader(scene.reader));
          const PreparedScene prepared = prepare_scene(scene, first_key_frame(player, scene));
          // One frame played as the CLI plays it (clipped with the scene's planes).
          Playback playback(player, player.frame_at(times[0]), times, false, scene.clip);
          tbb::task_arena arena(threads);
          Image image =
              arena.execute([&] { return playback.render_next(*renderer, prepared.tf, prepared.camera, image_size); });
          py::gil_scoped_acquire acquire;
          return to_numpy(std::move(image));
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
