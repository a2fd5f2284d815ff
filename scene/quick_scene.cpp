#include "scene/quick_scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "mesh/field_choice.hpp"
#include "optics/auto_opacity.hpp"
#include "optics/colormaps.hpp"
#include "scene/camera_json.hpp"
#include "scene/prepare.hpp"

namespace cellproj {
namespace {

struct NamedView {
  const char* name;
  glm::dvec3 from, up;  // towards the eye, and the camera's up
};

// ParaView's view buttons: "+x" looks along +x (the eye on the -x side), z up; "+z" and "-z", y up.
const NamedView kViews[] = {
    {"+x", {-1, 0, 0}, {0, 0, 1}}, {"-x", {1, 0, 0}, {0, 0, 1}},  {"+y", {0, -1, 0}, {0, 0, 1}},
    {"-y", {0, 1, 0}, {0, 0, 1}},  {"+z", {0, 0, -1}, {0, 1, 0}}, {"-z", {0, 0, 1}, {0, 1, 0}},
    {"iso", {1, 1, 1}, {0, 0, 1}},
};

// `auto`'s extinction over the field's values (on a log scale, their logs; the points returned in
// the field's units): found before (a partition index's), or from the mesh; a given depth fixes
// the largest.
nlohmann::json auto_points(const QuickLook& look, const OpacityInput& in, double diagonal) {
  std::vector<ExtinctionPoint> points;
  if (in.known) {
    points = *in.known;
  } else if (in.mesh.n_cells > 0) {
    points = auto_extinction(in.mesh, in.field, kDefaultFrom, kDefaultUp);
  } else {
    throw InputError("setting 'opacity': auto looks at the cells, and " + in.mesh.source +
                     " has none here (a partition index keeps auto's extinction for its fields as they are, not on "
                     "a log scale); give another opacity");
  }
  if (look.depth > 0) {  // the shape kept, the largest extinction given
    double top = 0;
    for (const ExtinctionPoint& p : points) top = std::max(top, p.kappa);
    for (ExtinctionPoint& p : points) p.kappa *= top > 0 ? look.depth / (diagonal > 0 ? diagonal : 1.0) / top : 0.0;
  }
  nlohmann::json out = nlohmann::json::array();
  for (const ExtinctionPoint& p : points) out.push_back({in.log ? std::pow(10.0, p.s) : p.s, p.kappa});
  return out;
}

// [[s, kappa], ...] for look.opacity over [lo, hi], kappa such that kappa * diagonal is the depth.
nlohmann::json extinction(const QuickLook& look, double lo, double hi, double diagonal, const OpacityInput* input) {
  if (look.depth < 0 || !std::isfinite(look.depth))
    throw InputError("setting 'depth': expected a positive optical depth, got " + std::to_string(look.depth));
  if (look.opacity == "auto") {
    if (!input) throw InternalError("opacity auto needs the mesh and its field");
    return auto_points(look, *input, diagonal);
  }
  const double per_length = 1.0 / (diagonal > 0 ? diagonal : 1.0),
               k = (look.depth > 0 ? look.depth : 20.0) * per_length;
  if (const std::vector<ExtinctionPoint> shape = opacity_shape(look.opacity, lo, hi); !shape.empty()) {
    nlohmann::json points = nlohmann::json::array();
    for (const ExtinctionPoint& p : shape) points.push_back({p.s, p.kappa * k});
    return points;
  }
  nlohmann::json points = nlohmann::json::array();
  std::size_t at = 0;
  const std::string& t = look.opacity;
  while (at < t.size()) {
    const std::size_t comma = std::min(t.find(',', at), t.size());
    const std::string item = t.substr(at, comma - at);
    const std::size_t eq = item.find('=');
    try {
      std::size_t a = 0, b = 0;
      if (eq == std::string::npos) throw std::invalid_argument("no =");
      const double s = std::stod(item.substr(0, eq), &a), depth = std::stod(item.substr(eq + 1), &b);
      if (a != eq || b != item.size() - eq - 1 || !std::isfinite(s) || !(depth >= 0) || !std::isfinite(depth))
        throw std::invalid_argument("bad");
      points.push_back({s, depth * per_length});
    } catch (const std::exception&) {
      throw InputError("setting 'opacity': expected " + opacity_names() +
                       " or S=DEPTH,S=DEPTH,... (DEPTH >= 0), got '" + item + "' in '" + t + "'");
    }
    at = comma + 1;
  }
  if (points.empty()) throw InputError("setting 'opacity': empty; give " + opacity_names() + " or S=DEPTH,S=DEPTH,...");
  return points;
}

// The colour map of `look` over [lo, hi], as the scene's "color_preset".
nlohmann::json color_preset(const QuickLook& look, double lo, double hi) {
  try {
    colormap(look.colormap, lo, hi);
  } catch (const InputError& e) {
    throw InputError(std::string("setting 'colormap': ") + e.what());
  }
  return {{"name", look.colormap}, {"range", {lo, hi}}};
}

}  // namespace

nlohmann::json quick_transfer_function(const QuickLook& look, double lo, double hi, double diagonal,
                                       const OpacityInput* input) {
  return {{"color_preset", color_preset(look, lo, hi)}, {"extinction", extinction(look, lo, hi, diagonal, input)}};
}

FieldTransferFunction quick_transfer_function(const QuickLook& look, const OpacityInput& field,
                                              const OpacityInput* opacity) {
  const auto range = [](const OpacityInput& in) {
    const auto [lo_at, hi_at] = std::minmax_element(in.field, in.field + in.mesh.n_points);
    return in.log ? std::pair{std::pow(10.0, *lo_at), std::pow(10.0, *hi_at)} : std::pair{*lo_at, *hi_at};
  };
  auto [lo, hi] = range(field);
  if (look.range) {
    std::tie(lo, hi) = *look.range;
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi) || (field.log && !(lo > 0)))
      throw InputError("setting 'range': expected LO,HI with LO < HI" +
                       std::string(field.log ? ", above 0 on a log scale" : "") + ", got " + std::to_string(lo) + "," +
                       std::to_string(hi));
  }
  const auto [blo, bhi] = bounds(field.mesh);
  const double diagonal = glm::length(bhi - blo);
  if (!opacity) return {quick_transfer_function(look, lo, hi, diagonal, &field), lo, hi};
  const auto [olo, ohi] = range(*opacity);  // the extinction over the opacity field's own range
  return {{{"color_preset", color_preset(look, lo, hi)}, {"extinction", extinction(look, olo, ohi, diagonal, opacity)}},
          lo,
          hi};
}

std::string view_names() {
  std::string list;
  for (const NamedView& v : kViews) list += (list.empty() ? "" : ", ") + std::string(v.name);
  return list;
}

Camera view_camera(const std::string& view, const glm::dvec3& lo, const glm::dvec3& hi, double aspect) {
  if (!(aspect > 0.0) || !std::isfinite(aspect))
    throw InputError("aspect: expected a finite width / height above 0, got " + std::to_string(aspect));
  if (view.empty()) return frame_box(lo, hi, Projection::Orthographic, kDefaultFrom, kDefaultUp, aspect);
  for (const NamedView& v : kViews)
    if (view == v.name) return frame_box(lo, hi, Projection::Orthographic, v.from, v.up, aspect);
  throw InputError("setting 'view': unknown view '" + view + "' (known: " + view_names() + ")");
}

nlohmann::json quick_scene(LoadedMesh& loaded, const std::string& mesh_path, const ReadOptions& reader,
                           const QuickLook& look, const std::string& scene_dir,
                           const std::vector<ExtinctionPoint>* known_auto) {
  if (look.log_floor && !look.log)
    throw InputError("setting 'log-floor' is the floor of a log scale: give setting 'log' too");
  // The field as the user spelt it (a vector alone, its magnitude, is said so when the scene is prepared).
  const std::string field = look.field.empty() ? choose_field(loaded.mesh, "").field : look.field;
  // The extinction's own field first: selecting a field may add one to the mesh's list.
  const std::string opacity_field =
      look.opacity_field.empty() ? ""
                                 : select_field(loaded.mesh, choose_field(loaded.mesh, look.opacity_field).name).name;
  const FieldChoice choice = choose_field(loaded.mesh, look.log ? log_spec(look.field, look.log_floor) : look.field);
  const PointField& f = select_field(loaded.mesh, choice.name);
  check_finite(mesh_path, f);
  // The transfer function in the field's units (on a log scale placed at their logs when prepared);
  // a log asked for, or the name of a series' played log.
  const OpacityInput color{loaded.mesh.view(), f.values.data(), log_scale_name(f.name), known_auto};
  std::optional<OpacityInput> opacity;
  if (!opacity_field.empty()) {
    const PointField& o = loaded.mesh.field(opacity_field);
    check_finite(mesh_path, o);
    opacity = OpacityInput{loaded.mesh.view(), o.values.data()};
  }
  const auto [blo, bhi] = bounds(loaded.mesh);
  const Camera camera = view_camera(look.view, blo, bhi, double(look.width) / look.height);
  namespace fs = std::filesystem;
  std::string mesh = fs::absolute(mesh_path).lexically_normal().string();
  if (!scene_dir.empty()) {  // relative when the scene sits next to the mesh or near it, so the two can move together
    const std::string relative = fs::absolute(mesh_path).lexically_relative(fs::absolute(scene_dir)).string();
    if (!relative.empty() && relative.rfind("../..", 0) != 0) mesh = relative;
  }
  nlohmann::json scene = {
      {"mesh", mesh},
      {"field", field},
      {"transfer_function", quick_transfer_function(look, color, opacity ? &*opacity : nullptr).json},
      {"camera", camera_to_json(camera)},
      {"image", {{"width", look.width}, {"height", look.height}}}};
  if (look.log) scene["log"] = true;
  if (look.log_floor) scene["log_floor"] = *look.log_floor;
  if (!opacity_field.empty()) scene["opacity_field"] = look.opacity_field;
  nlohmann::json r = nlohmann::json::object();
  if (!reader.format.empty()) r["format"] = reader.format;
  if (!reader.q_file.empty()) r["q_file"] = fs::absolute(reader.q_file).lexically_normal().string();
  if (!reader.zone.empty()) r["zone"] = reader.zone;
  if (reader.time_step != 0) r["time_step"] = reader.time_step;
  if (reader.cell_data && *reader.cell_data != CellData::cells) r["cell_data"] = cell_data_name(*reader.cell_data);
  if (!r.empty()) scene["reader"] = r;
  return scene;
}

}  // namespace cellproj
