#include "scene/transfer_function_json.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "optics/colormaps.hpp"

namespace cellproj {
namespace {

double number(const nlohmann::json& v, const std::string& where_) {
  if (!v.is_number()) throw InputError(where_ + ": expected a number, got " + v.dump());
  return v.get<double>();
}

std::vector<ColorPoint> color_points(const nlohmann::json& arr, const std::string& key) {
  if (!arr.is_array()) throw InputError(key + ": expected an array of [s, r, g, b]");
  std::vector<ColorPoint> out;
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const std::string at = key + "[" + std::to_string(i) + "]";
    if (!arr[i].is_array() || arr[i].size() != 4)
      throw InputError(at + ": expected [s, r, g, b], got " + arr[i].dump());
    out.push_back({number(arr[i][0], at), {number(arr[i][1], at), number(arr[i][2], at), number(arr[i][3], at)}});
  }
  return out;
}

// A ParaView preset: [{"Name": ..., "RGBPoints": [x, r, g, b, ...]}, ...] (or one such object).
std::vector<ColorPoint> paraview_preset(const nlohmann::json& spec, const std::string& key, const std::string& base_dir,
                                        double lo, double hi) {
  if (!spec.is_object() || !(spec.contains("file") || spec.contains("name")))
    throw InputError(key + ": expected {\"name\": ...} (a built-in map) or {\"file\": ..., \"name\": ...}");
  for (const auto& [k, v] : spec.items())
    if (k != "file" && k != "name" && k != "range") throw InputError(key + ": unknown key '" + k + "'");
  if (spec.contains("range")) {
    const auto& r = spec["range"];
    if (!r.is_array() || r.size() != 2) throw InputError(key + ".range: expected [s0, s1]");
    lo = number(r[0], key + ".range");
    hi = number(r[1], key + ".range");
  }
  if (!spec.contains("file")) {
    if (!spec["name"].is_string()) throw InputError(key + ".name: expected a string, got " + spec["name"].dump());
    try {
      return colormap(spec["name"].get<std::string>(), lo, hi);
    } catch (const InputError& e) {
      throw InputError(key + ".name: " + e.what());
    }
  }
  if (!spec["file"].is_string()) throw InputError(key + ".file: expected a string, got " + spec["file"].dump());
  std::filesystem::path file = spec["file"].get<std::string>();
  if (file.is_relative()) file = std::filesystem::path(base_dir) / file;
  std::ifstream in(file);
  if (!in) throw InputError(key + ": cannot open preset file " + file.string());
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string() + ": not valid JSON (" + e.what() + ")");
  }
  if (doc.is_object()) doc = nlohmann::json::array({doc});
  if (spec.contains("name") && !spec["name"].is_string())
    throw InputError(key + ".name: expected a string, got " + spec["name"].dump());
  const std::string name = spec.value("name", "");
  const nlohmann::json* map = nullptr;
  std::string names;
  for (const auto& m : doc) {
    if (!m.is_object() || !m.contains("RGBPoints")) continue;
    const std::string n = m.value("Name", "");
    names += (names.empty() ? "" : ", ") + n;
    if (!map && (name.empty() || n == name)) map = &m;
  }
  if (!map)
    throw InputError(file.string() + ": no colour map " + (name.empty() ? "with RGBPoints" : "named '" + name + "'") +
                     "; the maps are: " + (names.empty() ? "(none)" : names));
  const auto& pts = (*map)["RGBPoints"];
  if (!pts.is_array() || pts.size() < 4 || pts.size() % 4)
    throw InputError(file.string() + ": RGBPoints must hold x, r, g, b quadruples");
  const std::string at = file.string() + ": RGBPoints";
  const double x0 = number(pts[0], at), x1 = number(pts[pts.size() - 4], at);
  std::vector<ColorPoint> out;
  for (std::size_t i = 0; i < pts.size(); i += 4) {
    const double x = number(pts[i], at);
    const double s = x1 > x0 ? lo + (x - x0) / (x1 - x0) * (hi - lo) : lo;
    out.push_back({s, {number(pts[i + 1], at), number(pts[i + 2], at), number(pts[i + 3], at)}});
  }
  return out;
}

}  // namespace

namespace {

// s placed on a log axis: its log10 (InputError at `at` unless s > 0).
double on_log_axis(double s, const std::string& at) {
  if (!(s > 0))
    throw InputError(at + ": " + std::to_string(s) + " has no place on a log scale (values must be above 0)");
  return std::log10(s);
}

}  // namespace

TransferFunction transfer_function_from_json(const nlohmann::json& j, const std::string& source,
                                             const std::string& base_dir, double field_min, double field_max,
                                             bool log_axis, bool extinction_on_log_axis) {
  const std::string key = source + ": transfer_function";
  if (!j.is_object()) throw InputError(key + ": expected an object with \"color\" and \"extinction\"");
  for (const auto& [k, v] : j.items())
    if (k != "color" && k != "color_preset" && k != "extinction")
      throw InputError(key + ": unknown key '" + k + "' (known: color, color_preset, extinction)");
  if (j.contains("color") == j.contains("color_preset"))
    throw InputError(key + ": give exactly one of \"color\" and \"color_preset\"");
  if (!j.contains("extinction")) throw InputError(key + ": missing \"extinction\"");
  // On a log axis a preset is spread evenly over the log of its range, explicit points placed at their logs.
  if (log_axis) field_min = on_log_axis(field_min, key), field_max = on_log_axis(field_max, key);
  std::vector<ColorPoint> color;
  if (j.contains("color")) {
    color = color_points(j["color"], key + ".color");
    if (log_axis)
      for (std::size_t i = 0; i < color.size(); ++i)
        color[i].s = on_log_axis(color[i].s, key + ".color[" + std::to_string(i) + "]");
  } else {
    nlohmann::json preset = j["color_preset"];
    if (log_axis && preset.is_object() && preset.contains("range") && preset["range"].is_array())
      for (std::size_t i = 0; i < preset["range"].size(); ++i)
        preset["range"][i] = on_log_axis(number(preset["range"][i], key + ".color_preset.range"),
                                         key + ".color_preset.range[" + std::to_string(i) + "]");
    color = paraview_preset(preset, key + ".color_preset", base_dir, field_min, field_max);
  }
  const auto& e = j["extinction"];
  if (!e.is_array()) throw InputError(key + ".extinction: expected an array of [s, kappa]");
  std::vector<ExtinctionPoint> ext;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const std::string at = key + ".extinction[" + std::to_string(i) + "]";
    if (!e[i].is_array() || e[i].size() != 2) throw InputError(at + ": expected [s, kappa], got " + e[i].dump());
    const double at_s = number(e[i][0], at);
    ext.push_back({log_axis && extinction_on_log_axis ? on_log_axis(at_s, at) : at_s, number(e[i][1], at)});
  }
  return TransferFunction(std::move(color), std::move(ext), key);
}

}  // namespace cellproj
