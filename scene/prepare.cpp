#include "scene/prepare.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <limits>

#include "base/error.hpp"
#include "mesh/field_choice.hpp"
#include "mesh/geometry.hpp"
#include "mesh/validate.hpp"
#include "scene/quick_scene.hpp"
#include "scene/transfer_function_json.hpp"

namespace cellproj {

std::pair<glm::dvec3, glm::dvec3> bounds(const MeshView& m) { return point_bounds(m); }

std::pair<glm::dvec3, glm::dvec3> bounds(const Mesh& m) { return bounds(m.view()); }

ColorBar color_bar(const TransferFunction& tf, double lo, double hi, bool log, const std::string& title,
                   const glm::dvec3& background) {
  ColorBar bar;
  bar.lo = lo, bar.hi = hi, bar.log = log, bar.title = title;
  bar.text = text_color_for(background);
  constexpr int kSamples = 256;
  for (int k = 0; k < kSamples; ++k)
    bar.colors.push_back(glm::clamp(tf.color(lo + (k + 0.5) / kSamples * (hi - lo)), 0.0, 1.0));
  return bar;
}

std::pair<double, double> legend_range(const TransferFunction& tf, double field_lo, double field_hi) {
  const std::vector<ColorPoint>& c = tf.color_points();
  if (c.size() >= 2 && c.front().s < c.back().s) return {c.front().s, c.back().s};
  return {field_lo, field_hi};
}

ColorBar color_bar(const PreparedScene& p, const glm::dvec3& background) {
  const auto [lo, hi] = legend_range(p.tf, p.field_min, p.field_max);
  return color_bar(p.tf, lo, hi, p.log_scale, p.scalar.empty() ? p.field : p.scalar, background);
}

void refuse_iso_on_log_scale(const RenderSettings& s, bool log_scale) {
  if (log_scale && (!s.iso.surfaces.empty() || s.mode == RenderMode::layers))
    throw UnsupportedError(
        "setting 'iso' does not go with setting 'log' yet: its values would be read as logs of the field");
}

ColorBar color_bar(const PreparedScene& p, const RenderSettings& s, const glm::dvec3& background,
                   const LegendText& text) {
  ColorBar bar = color_bar(p, background);
  bar.title = legend_title(text.title.empty() ? bar.title : text.title, text.unit);
  const auto mark = [&](double value, const std::optional<glm::dvec3>& color) {
    bar.marks.push_back({value, glm::clamp(color ? *color : p.tf.color(value), 0.0, 1.0)});
  };
  if (s.mode == RenderMode::reduction) {  // the colour map of one value per ray
    const char* which[] = {"maximum", "minimum", "mean"};
    bar.title += std::string(" (") + which[static_cast<int>(s.reduction)] + " along each ray)";
  } else if (s.mode == RenderMode::layers) {  // one colour, shaded: the iso-value's
    mark(s.layers.iso, s.layers.color);
    bar.gradient = false;
  } else if (s.mode == RenderMode::exact) {  // the surfaces' colours, over the volume's when drawn
    for (const IsoSurface& iso : s.iso.surfaces)
      mark(iso.value, iso.color_given ? std::optional<glm::dvec3>(iso.color) : std::nullopt);
    bar.gradient = s.iso.volume || s.iso.surfaces.empty();
  }
  return bar;
}

namespace {

// What of the box [lo, hi] the camera sees, as a warning ("" when some of it is in view and none
// of it behind an orthographic eye): a blank picture should not come without a word.
std::string view_warning(const Camera& camera, const glm::dvec3& lo, const glm::dvec3& hi, int width, int height) {
  const PixelRays rays(camera, width, height);
  int behind = 0, left = 0, right = 0, above = 0, below = 0;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 p{k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z};
    double x = 0, y = 0, z = 0;
    rays.project(p, x, y, z);
    if (z <= 0) {
      ++behind;
      continue;
    }
    left += x < 0;
    right += x > width;
    above += y < 0;
    below += y > height;
  }
  if (behind == 8) return "nothing of the mesh is in view: it lies wholly behind the camera (the picture is empty)";
  if (behind == 0 && (left == 8 || right == 8 || above == 8 || below == 8))
    return "nothing of the mesh is in view: its bounding box lies outside the camera's field of view (the picture is "
           "empty)";
  if (behind > 0 && !rays.perspective())
    return "part of the mesh lies behind the orthographic camera's eye plane and is not drawn; move the eye back "
           "along the view direction to see it all";
  return "";
}

}  // namespace

std::string scene_field(const Scene& s) { return s.log_scale ? log_spec(s.field, s.log_floor) : s.field; }

LoadedMesh first_key_frame(SeriesPlayer& player, Scene& scene) {
  if (!scene.opacity_field.empty())
    throw UnsupportedError(
        where(scene.source, "setting 'opacity-field' draws one mesh's two fields, not a time series' yet"));
  const SeriesFrame frame = player.frame_at(player.series().frames.front().time);
  scene.field = player.field_name(), scene.log_scale = false, scene.log_floor.reset();  // its log is in the name
  LoadedMesh loaded;
  loaded.mesh.source = player.series().source;
  loaded.mesh.points = *frame.points;
  loaded.mesh.fields.push_back({player.field_name(), frame.field, "a time series' key frame"});
  loaded.report = player.first_report();
  return loaded;
}

namespace {

// The scene's camera with its moves made, an error naming the scene.
Camera moved_camera(const Scene& s, const Camera& base) {
  try {
    return moved(base, s.camera_moves);
  } catch (const InputError& e) {
    throw InputError(where(s.source, e.what()));
  }
}

}  // namespace

PreparedVolumes prepare_volumes(const Scene& s, const std::function<LoadedMesh(const SceneVolume&)>& read) {
  std::vector<LoadedMesh> loaded;
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const SceneVolume& v : s.volumes) {
    loaded.push_back(read(v));
    const auto [blo, bhi] = bounds(loaded.back().mesh);
    lo = glm::min(lo, blo), hi = glm::max(hi, bhi);
  }
  PreparedVolumes out;
  const Camera base = s.camera ? *s.camera : view_camera(s.view, lo, hi, double(s.width) / s.height);
  check_camera(base, where(s.source, "the camera framing the volumes' bounds"));
  out.camera = moved_camera(s, base), out.turn_axis = base.up;
  for (std::size_t k = 0; k < s.volumes.size(); ++k) {
    const SceneVolume& v = s.volumes[k];
    Scene one = s;  // the volume as a scene of its own, seen by the common camera
    one.volumes.clear();
    one.mesh = v.mesh, one.reader = v.reader, one.field = v.field, one.transfer_function = v.transfer_function;
    one.camera = out.camera, one.camera_moves = {};
    one.source = s.source + ": volumes[" + std::to_string(k) + "]";
    out.volumes.push_back(prepare_scene(one, std::move(loaded[k])));
    for (std::string& w : out.volumes.back().warnings) out.warnings.push_back(std::move(w));
    out.volumes.back().warnings.clear();
  }
  return out;
}

PreparedScene prepare_scene(const Scene& s) { return prepare_scene(s, load_mesh(s.mesh, s.reader)); }

PreparedScene prepare_scene(const Scene& s, LoadedMesh loaded) {
  if (s.log_floor && !s.log_scale)
    throw InputError(where(s.source, "setting 'log-floor' is the floor of a log scale: give setting 'log' too"));
  const FieldChoice choice = choose_field(loaded.mesh, scene_field(s));
  const std::string note = choice.note;
  const PointField& f = select_field(loaded.mesh, choice.name);
  const std::string field = f.name;
  const bool log_scale = log_scale_name(field);  // asked for, or a series' key frames played so
  check_finite(s.mesh, f);
  const auto [lo_at, hi_at] = std::minmax_element(f.values.begin(), f.values.end());
  const double lo = *lo_at, hi = *hi_at;
  std::string opacity_field;  // the extinction's own field, never on a log scale
  if (!s.opacity_field.empty()) {
    const PointField& o = select_field(loaded.mesh, choose_field(loaded.mesh, s.opacity_field).name);
    check_finite(s.mesh, o);
    opacity_field = o.name;
  }
  const bool opacity_log = opacity_field.empty();
  // A colour preset is stretched over the field's range unless the scene gives one (in the field's
  // units: on a log scale the range is 10^lo to 10^hi).
  TransferFunction tf = log_scale
                            ? transfer_function_from_json(s.transfer_function, s.source, s.base_dir, std::pow(10.0, lo),
                                                          std::pow(10.0, hi), true, opacity_log)
                            : transfer_function_from_json(s.transfer_function, s.source, s.base_dir, lo, hi);
  const std::string scalar = log_scale ? log_scale_scalar(field) : field;
  PreparedScene p{std::move(loaded), field, lo, hi, log_scale, scalar, std::move(tf), Camera{}, {}, {}, opacity_field};
  const auto [blo, bhi] = bounds(p.loaded.mesh);
  const Camera base = s.camera ? *s.camera : view_camera(s.view, blo, bhi, double(s.width) / s.height);
  check_camera(base, where(s.source, "the camera framing " + s.mesh + "'s bounds"));
  p.camera = moved_camera(s, base), p.turn_axis = base.up;
  p.warnings = p.loaded.report.warnings(s.mesh);
  if (!note.empty()) p.warnings.push_back(s.mesh + ": " + note);
  if (const std::string w = view_warning(p.camera, blo, bhi, s.width, s.height); !w.empty())
    p.warnings.push_back(where(s.source, w));
  for (const auto& n : p.loaded.mesh.notes) p.warnings.push_back(s.mesh + ": " + n);
  if (p.field_min == p.field_max)
    p.warnings.push_back(s.mesh + ": field '" + field + "' is constant (" + std::to_string(p.field_min) + ")");
  return p;
}

}  // namespace cellproj
