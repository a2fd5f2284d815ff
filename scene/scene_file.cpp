#include "scene/scene_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/error.hpp"
#include "base/file_status.hpp"
#include "io/read_mesh.hpp"
#include "render/settings_table.hpp"

namespace fs = std::filesystem;

namespace cellproj {
namespace {

void only_keys(const nlohmann::json& j, const std::string& at, std::initializer_list<const char*> known) {
  for (const auto& [k, v] : j.items()) {
    bool ok = false;
    std::string list;
    for (const char* name : known) {
      ok |= k == name;
      list += (list.empty() ? "" : ", ") + std::string(name);
    }
    if (!ok) throw InputError(at + ": unknown key '" + k + "' (known: " + list + ")");
  }
}

// Calls f(object, at) for each element of the list j[key] (none when absent), each an object
// holding only `keys`; `form` says what an element looks like, for messages.
template <class F>
void each_object(const nlohmann::json& j, const char* key, const std::string& path, const std::string& form,
                 std::initializer_list<const char*> keys, F&& f) {
  if (!j.contains(key)) return;
  const auto& list = j[key];
  if (!list.is_array()) throw InputError(path + ": " + key + ": expected a list of " + form);
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string at = path + ": " + key + "[" + std::to_string(k) + "]";
    if (!list[k].is_object()) throw InputError(at + ": expected " + form);
    only_keys(list[k], at, keys);
    f(list[k], at);
  }
}

std::string text(const nlohmann::json& v, const std::string& at) {
  if (!v.is_string()) throw InputError(at + ": expected a string, got " + v.dump());
  return v.get<std::string>();
}

int positive_int(const nlohmann::json& v, const std::string& at, int max, int min = 1) {
  if (!v.is_number_integer() || v.get<long long>() < min || v.get<long long>() > max)
    throw InputError(at + ": expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " +
                     v.dump());
  return v.get<int>();
}

}  // namespace

namespace {

// Sets each of `defaults` that `options` was not given, as a default (not the user's word).
void set_defaults(const std::vector<std::pair<std::string, std::string>>& defaults, RenderOptions& options) {
  for (const auto& [name, value] : defaults)
    if (!option_given(options, name)) {
      set_option(options, name, value);
      const std::string canonical = find_setting(name)->name;  // set_option knew it
      options.given.erase(std::find(options.given.begin(), options.given.end(), canonical));
    }
}

}  // namespace

std::vector<std::string> apply_scene_options(const Scene& scene, RenderOptions& options) {
  std::vector<std::string> warnings;
  set_defaults(scene.render_options, options);
  const std::string method = option_text(options, "method");
  set_defaults(method == "layers"  ? scene.layer_options
               : method == "exact" ? scene.iso_options
                                   : std::vector<std::pair<std::string, std::string>>{},
               options);
  const bool has_iso =
      std::any_of(scene.iso_options.begin(), scene.iso_options.end(), [](const auto& o) { return o.first == "iso"; });
  if (has_iso && method != "exact")
    warnings.push_back(where(scene.source, "its iso-surfaces are drawn by setting 'method' exact; setting 'method' " +
                                               method + " draws the volume alone"));
  // A scene's render setting the method does not read is left out, and said (the command line's
  // method may differ from the scene's).
  try {
    const RenderSettings settings = settings_from(options);
    for (const auto& [name, value] : scene.render_options)
      if (!find_setting(name)->reads(settings))
        warnings.push_back(
            where(scene.source, "render." + name + " does not apply to setting 'method' " + method + ": left out"));
  } catch (const InputError&) {  // the front end reports the settings' error where it reads them
  }
  return warnings;
}

ClipPlane parse_clip_plane(const std::string& text) {
  const std::vector<double> v = parse_number_list("clip", text);
  if (v.size() != 6)
    throw InputError("setting 'clip': expected x,y,z,nx,ny,nz (a point and the normal), got '" + text + "'");
  ClipPlane p{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
  check(p);
  return p;
}

void parse_size(const std::string& t, int& w, int& h) {
  const auto x = t.find('x');
  try {
    std::size_t a = 0, b = 0;
    if (x == std::string::npos) throw std::invalid_argument("no x");
    w = std::stoi(t.substr(0, x), &a);
    h = std::stoi(t.substr(x + 1), &b);
    if (a != x || b != t.size() - x - 1 || w < 1 || h < 1 || w > 16384 || h > 16384)
      throw std::invalid_argument("range");
  } catch (const std::exception&) {
    throw InputError("setting 'size': expected WxH with W and H in [1, 16384], e.g. 512x512; got '" + t + "'");
  }
}

glm::dvec3 parse_color(const std::string& t, const std::string& what) {
  if (t == "black") return glm::dvec3(0.0);
  if (t == "white") return glm::dvec3(1.0);
  glm::dvec3 c(0.0);
  if (t.size() == 7 && t[0] == '#' && t.find_first_not_of("0123456789abcdefABCDEF", 1) == std::string::npos) {
    for (int k = 0; k < 3; ++k) c[k] = std::stoi(t.substr(1 + 2 * k, 2), nullptr, 16) / 255.0;
    return c;
  }
  std::size_t at = 0;
  for (int k = 0; k < 3; ++k) {
    const std::size_t end = k < 2 ? t.find(',', at) : t.size();
    std::size_t used = 0;
    bool ok = end != std::string::npos && end > at;
    try {
      if (ok) c[k] = std::stod(t.substr(at, end - at), &used);
    } catch (const std::exception&) {
      ok = false;
    }
    if (!ok || used != end - at || !(c[k] >= 0 && c[k] <= 1))
      throw InputError(what + ": expected R,G,B with each in [0, 1], #rrggbb, black or white; got '" + t + "'");
    at = end + 1;
  }
  return c;
}

Scene load_scene(const std::string& path) {
  if (path_is_folder(path)) throw InputError(where(path, "is a folder, not a scene file"));
  std::ifstream in(path);
  if (!in)
    throw InputError(where(path, path_exists(path)
                                     ? "cannot read the scene file (" + std::string(std::strerror(errno)) + ")"
                                     : "no such scene file"));
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range: a number beyond a double
    // The parser's words without its own tag ("[json.exception.parse_error.101] "); a mesh given
    // where a scene was expected said so.
    const std::string what = e.what(),
                      said = what.substr(what.find("] ") == std::string::npos ? 0 : what.find("] ") + 2);
    bool mesh = false;
    try {
      mesh = !format_for(path).empty();
    } catch (const InputError&) {
    }
    throw InputError(
        where(path, mesh ? "is a mesh file, not a scene (a JSON file, docs/scene.md): render the mesh itself"
                         : "not valid JSON (a scene file, docs/scene.md): " + said));
  }
  return scene_from_json(j, path, fs::path(path).parent_path().string());
}

namespace {

// A JSON number as option text, every digit kept; a list of them comma-separated.
std::string number_text(const nlohmann::json& v, const std::string& at) {
  if (!v.is_number()) throw InputError(at + ": expected a number, got " + v.dump());
  std::ostringstream out;
  out.precision(17);
  out << v.get<double>();
  return out.str();
}
std::string numbers_text(const nlohmann::json& v, const std::string& at) {
  if (!v.is_array() || v.empty()) throw InputError(at + ": expected a list of numbers, got " + v.dump());
  std::string list;
  for (const auto& x : v) list += (list.empty() ? "" : ",") + number_text(x, at);
  return list;
}

// Render options from a scene, checked now by their parser for `method`, so that a bad value
// names the scene ("scene.json: layers: setting 'layer': ...").
void check_options(const std::vector<std::pair<std::string, std::string>>& o, const std::string& method, bool needs_iso,
                   const std::string& at) {
  RenderOptions check;
  set_option(check, "method", method);
  if (needs_iso) set_option(check, "iso", "0");
  try {
    for (const auto& [name, value] : o) set_option(check, name, value);
    settings_from(check);
  } catch (const InputError& e) {
    throw InputError(at + ": " + e.what());
  }
}

// {"iso": 0.5, "color": [1, 0, 0], "layer": [1, 2], "weights": [2, 1], "silhouettes": "both",
// "silhouette_epsilon": 0.2} as the settings iso 0.5:1,0,0, layer 1,2 ...
std::vector<std::pair<std::string, std::string>> layer_options_from_json(const nlohmann::json& l,
                                                                         const std::string& at) {
  if (!l.is_object()) throw InputError(at + ": expected an object");
  only_keys(l, at, {"iso", "color", "layer", "weights", "silhouettes", "silhouette_epsilon"});
  const auto number = [&](const nlohmann::json& v, const std::string& key) { return number_text(v, at + "." + key); };
  const auto numbers = [&](const nlohmann::json& v, const std::string& key) { return numbers_text(v, at + "." + key); };
  std::vector<std::pair<std::string, std::string>> o;
  if (l.contains("iso")) {
    std::string iso = number(l["iso"], "iso");
    if (l.contains("color")) iso += ":" + numbers(l["color"], "color");
    o.emplace_back("iso", iso);
  } else if (l.contains("color")) {
    throw InputError(at + ".color: goes with \"iso\"");
  }
  if (l.contains("layer"))
    o.emplace_back("layer", l["layer"].is_number() ? number(l["layer"], "layer") : numbers(l["layer"], "layer"));
  if (l.contains("weights")) o.emplace_back("layer-weights", numbers(l["weights"], "weights"));
  if (l.contains("silhouettes")) o.emplace_back("silhouettes", text(l["silhouettes"], at + ".silhouettes"));
  if (l.contains("silhouette_epsilon"))
    o.emplace_back("silhouette-epsilon", number(l["silhouette_epsilon"], "silhouette_epsilon"));
  check_options(o, "layers", !l.contains("iso"), at);
  return o;
}

// The scene's iso-surfaces: "iso": [{"value": V, "color": [r, g, b], "opacity": A}, ...] with
// "iso_mode", "iso_opacity" and "volume" (true or false), as the settings iso V:R,G,B,A ..., iso-mode ...
std::vector<std::pair<std::string, std::string>> iso_options_from_json(const nlohmann::json& j,
                                                                       const std::string& path) {
  std::vector<std::pair<std::string, std::string>> o;
  each_object(j, "iso", path, "{\"value\": V, \"color\": [r, g, b], \"opacity\": A}", {"value", "color", "opacity"},
              [&](const nlohmann::json& s, const std::string& at) {
                if (!s.contains("value")) throw InputError(at + ": missing \"value\"");
                std::string iso = number_text(s["value"], at + ".value");
                if (s.contains("color") || s.contains("opacity")) {
                  if (!s.contains("color")) throw InputError(at + ".opacity: goes with \"color\"");
                  iso += ":" + numbers_text(s["color"], at + ".color");
                  if (s.contains("opacity")) iso += "," + number_text(s["opacity"], at + ".opacity");
                }
                o.emplace_back("iso", iso);
              });
  if (j.contains("iso_mode")) o.emplace_back("iso-mode", text(j["iso_mode"], path + ": iso_mode"));
  if (j.contains("iso_opacity")) o.emplace_back("iso-opacity", text(j["iso_opacity"], path + ": iso_opacity"));
  if (j.contains("volume")) {
    if (!j["volume"].is_boolean())
      throw InputError(path + ": volume: expected true or false, got " + j["volume"].dump());
    o.emplace_back("volume", j["volume"].get<bool>() ? "on" : "off");
  }
  check_options(o, "exact", false, path);
  return o;
}

// "reader": {"format": ..., "q_file": ..., "zone": ..., "time_step": ...}
ReadOptions reader_from_json(const nlohmann::json& r, const std::string& at, const std::string& base_dir) {
  ReadOptions o;
  if (!r.is_object()) throw InputError(at + ": expected an object");
  only_keys(r, at, {"format", "q_file", "zone", "time_step", "cell_data"});
  if (r.contains("format")) o.format = text(r["format"], at + ".format");
  if (r.contains("q_file")) {
    fs::path q = text(r["q_file"], at + ".q_file");
    o.q_file = q.is_relative() ? (fs::path(base_dir) / q).string() : q.string();
  }
  if (r.contains("zone")) o.zone = text(r["zone"], at + ".zone");
  if (r.contains("time_step")) o.time_step = positive_int(r["time_step"], at + ".time_step", 1 << 30, 0);
  if (r.contains("cell_data")) {
    try {
      o.cell_data = cell_data_from_name(text(r["cell_data"], at + ".cell_data"));
    } catch (const InputError& e) {
      throw InputError(at + ".cell_data: " + e.what());
    }
  }
  return o;
}

std::string resolved(const nlohmann::json& v, const std::string& at, const std::string& base_dir) {
  const fs::path p = text(v, at);
  return p.is_relative() ? (fs::path(base_dir) / p).lexically_normal().string() : p.string();
}

// {"method": "pt-table", "table_size": 64, "cull_transparent": false}: render settings by their
// names in the table (render/settings_table.hpp), each checked now so that a bad one names the
// scene. Iso-surfaces and layers have blocks of their own.
std::vector<std::pair<std::string, std::string>> render_options_from_json(const nlohmann::json& r,
                                                                          const std::string& at) {
  if (!r.is_object()) throw InputError(at + ": expected an object of render settings, e.g. {\"method\": \"exact\"}");
  std::vector<std::pair<std::string, std::string>> out;
  RenderOptions check;
  for (const auto& [key, v] : r.items()) {
    const std::string here = at + "." + key;
    const SettingRow* row = find_setting(key);
    if (row && row->repeatable) throw InputError(here + ": give iso-surfaces in the scene's \"iso\" list");
    if (!v.is_string() && !v.is_boolean() && !v.is_number())
      throw InputError(here + ": expected a string, number or boolean, got " + v.dump());
    const std::string value = v.is_string()    ? v.get<std::string>()
                              : v.is_boolean() ? std::string(v.get<bool>() ? "on" : "off")
                                               : number_text(v, here);
    try {
      set_option(check, key, value);
    } catch (const InputError& e) {
      throw InputError(here + ": " + e.what());
    }
    out.emplace_back(key, value);
  }
  return out;
}

// One entry of "volumes": {"mesh", "reader", "field", "transfer_function", "iso", "volume"}.
SceneVolume volume_from_json(const nlohmann::json& v, const std::string& at, const std::string& base_dir) {
  SceneVolume out;
  if (!v.contains("mesh")) throw InputError(at + ": missing \"mesh\" (the mesh file)");
  out.mesh = resolved(v["mesh"], at + ".mesh", base_dir);
  if (v.contains("reader")) out.reader = reader_from_json(v["reader"], at + ".reader", base_dir);
  if (v.contains("field")) out.field = text(v["field"], at + ".field");
  if (!v.contains("transfer_function")) throw InputError(at + ": missing \"transfer_function\"");
  out.transfer_function = v["transfer_function"];
  // Its iso-surfaces and "volume" by the parser of the top-level ones (and of the settings iso and volume).
  RenderOptions o;
  set_option(o, "method", "exact");
  for (const auto& [name, value] : iso_options_from_json(v, at)) set_option(o, name, value);
  const IsoOptions iso = settings_from(o).iso;
  out.iso = iso.surfaces;
  out.volume = iso.volume;
  return out;
}

}  // namespace

Scene scene_from_json(const nlohmann::json& j, const std::string& path, const std::string& base_dir) {
  if (!j.is_object()) throw InputError(where(path, "a scene is a JSON object"));
  only_keys(
      j, path,
      {"mesh", "reader", "field", "log", "log_floor", "opacity_field", "transfer_function", "camera", "camera_moves",
       "image", "render", "layers", "clip", "iso", "iso_mode", "iso_opacity", "volume", "volumes"});
  Scene s;
  s.source = path;
  s.base_dir = base_dir;
  if (j.contains("volumes")) {
    for (const char* key : {"mesh", "reader", "field", "transfer_function", "iso", "volume", "layers"})
      if (j.contains(key))
        throw InputError(path + ": " + key + ": with a \"volumes\" list, give it inside each volume" +
                         (std::string(key) == "layers" ? " (setting 'method' layers draws one mesh)" : ""));
    each_object(j, "volumes", path, "{\"mesh\": ..., \"transfer_function\": ...}",
                {"mesh", "reader", "field", "transfer_function", "iso", "volume"},
                [&](const nlohmann::json& v, const std::string& at) {
                  s.volumes.push_back(volume_from_json(v, at, s.base_dir));
                });
    if (s.volumes.empty()) throw InputError(path + ": volumes: the list is empty");
    const SceneVolume& first = s.volumes.front();
    s.mesh = first.mesh, s.reader = first.reader, s.field = first.field, s.transfer_function = first.transfer_function;
    if (s.volumes.size() == 1) {  // one volume: the ordinary scene
      for (const IsoSurface& iso : first.iso) {
        char text[160];
        if (iso.color_given)
          std::snprintf(text, sizeof text, "%.17g:%.17g,%.17g,%.17g,%.17g", iso.value, iso.color.r, iso.color.g,
                        iso.color.b, iso.opacity);
        else
          std::snprintf(text, sizeof text, "%.17g", iso.value);
        s.iso_options.emplace_back("iso", text);
      }
      if (!first.volume) s.iso_options.emplace_back("volume", "off");
      s.volumes.clear();
    }
  }
  if (!j.contains("mesh") && s.mesh.empty()) throw InputError(where(path, "missing \"mesh\" (the mesh file)"));
  if (j.contains("mesh")) s.mesh = resolved(j["mesh"], path + ": mesh", s.base_dir);
  if (j.contains("reader")) s.reader = reader_from_json(j["reader"], path + ": reader", s.base_dir);
  if (j.contains("field")) s.field = text(j["field"], path + ": field");
  if (j.contains("opacity_field")) {
    if (!s.volumes.empty()) throw InputError(path + ": opacity_field: one mesh's, not with a \"volumes\" list");
    s.opacity_field = text(j["opacity_field"], path + ": opacity_field");
  }
  if (j.contains("log")) {
    if (!j["log"].is_boolean()) throw InputError(path + ": log: expected true or false, got " + j["log"].dump());
    s.log_scale = j["log"].get<bool>();
  }
  if (j.contains("log_floor")) {
    const nlohmann::json& f = j["log_floor"];
    if (!f.is_number() || !(f.get<double>() > 0))
      throw InputError(path + ": log_floor: expected a positive number, got " + f.dump());
    s.log_floor = f.get<double>();
  }
  if (!j.contains("transfer_function") && s.transfer_function.is_null())
    throw InputError(where(path, "missing \"transfer_function\""));
  if (j.contains("transfer_function")) s.transfer_function = j["transfer_function"];
  if (j.contains("camera")) s.camera = camera_from_json(j["camera"], path);
  if (j.contains("camera_moves")) s.camera_moves = camera_moves_from_json(j["camera_moves"], path + ": camera_moves");
  each_object(j, "clip", path, "{\"point\": [x, y, z], \"normal\": [x, y, z]}", {"point", "normal"},
              [&](const nlohmann::json& p, const std::string& at) {
                ClipPlane plane;
                for (const auto& [key, v] : {std::pair{"point", &plane.point}, std::pair{"normal", &plane.normal}}) {
                  if (!p.contains(key)) throw InputError(at + ": missing \"" + key + "\"");
                  *v = vec3(p[key], at + "." + key);
                }
                try {
                  check(plane);
                } catch (const InputError& e) {
                  throw InputError(at + ": " + e.what());
                }
                s.clip.push_back(plane);
              });
  if (j.contains("render")) s.render_options = render_options_from_json(j["render"], path + ": render");
  if (j.contains("layers")) s.layer_options = layer_options_from_json(j["layers"], path + ": layers");
  for (auto& o : iso_options_from_json(j, path)) s.iso_options.push_back(std::move(o));
  if (j.contains("image")) {
    const auto& im = j["image"];
    const std::string at = path + ": image";
    if (!im.is_object()) throw InputError(at + ": expected an object");
    only_keys(im, at, {"width", "height", "background"});
    if (im.contains("width")) s.width = positive_int(im["width"], at + ".width", 16384);
    if (im.contains("height")) s.height = positive_int(im["height"], at + ".height", 16384);
    if (im.contains("background") && im["background"] == "none") {
      s.transparent = true;  // PNGs with straight alpha
    } else if (im.contains("background")) {
      const auto& b = im["background"];
      if (!b.is_array() || b.size() != 3)
        throw InputError(at + ".background: expected [r, g, b] or \"none\", got " + b.dump());
      for (int k = 0; k < 3; ++k) {
        if (!b[k].is_number() || b[k].get<double>() < 0 || b[k].get<double>() > 1)
          throw InputError(at + ".background: components must be numbers in [0, 1], got " + b.dump());
        s.background[k] = b[k].get<double>();
      }
    }
  }
  return s;
}

}  // namespace cellproj
