#include "optics/transfer_function.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "grid/error.hpp"

namespace cellproj {
namespace {

template <class P>
void check_order(const std::vector<P>& pts, const std::string& what) {
  if (pts.empty()) throw InputError(what + ": needs at least one control point");
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!std::isfinite(pts[i].s)) throw InputError(what + "[" + std::to_string(i) + "]: s is not finite");
    if (i > 0 && pts[i].s < pts[i - 1].s)
      throw InputError(what + "[" + std::to_string(i) + "]: s = " + std::to_string(pts[i].s) +
                       " comes after s = " + std::to_string(pts[i - 1].s) + "; control points must be in increasing s");
  }
}

// Index of the segment [i-1, i] whose linear function holds at s (0 or size() when clamped).
template <class P>
std::size_t segment_at(const std::vector<P>& pts, double s) {
  return static_cast<std::size_t>(
      std::upper_bound(pts.begin(), pts.end(), s, [](double v, const P& p) { return v < p.s; }) - pts.begin());
}

template <class P, class V, class Get>
V eval_on_segment(const std::vector<P>& pts, std::size_t i, double s, Get get) {
  if (i == 0) return get(pts.front());
  if (i >= pts.size()) return get(pts.back());
  const P& a = pts[i - 1];
  const P& b = pts[i];
  const double w = (s - a.s) / (b.s - a.s);  // b.s > a.s: a step is never the segment found
  return get(a) + (get(b) - get(a)) * w;
}

}  // namespace

TransferFunction::TransferFunction(std::vector<ColorPoint> color, std::vector<ExtinctionPoint> extinction,
                                   const std::string& source)
    : color_(std::move(color)), extinction_(std::move(extinction)) {
  check_order(color_, source + ": color");
  check_order(extinction_, source + ": extinction");
  for (std::size_t i = 0; i < color_.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!(color_[i].rgb[k] >= 0.0 && color_[i].rgb[k] <= 1.0))
        throw InputError(source + ": color[" + std::to_string(i) + "]: " + "rgb"[k] + " = " +
                         std::to_string(color_[i].rgb[k]) + " is outside [0, 1]");
  for (std::size_t i = 0; i < extinction_.size(); ++i)
    if (!(extinction_[i].kappa >= 0.0) || !std::isfinite(extinction_[i].kappa))
      throw InputError(source + ": extinction[" + std::to_string(i) + "]: kappa = " +
                       std::to_string(extinction_[i].kappa) + " must be finite and >= 0");
  for (const auto& p : color_) breakpoints_.push_back(p.s);
  for (const auto& p : extinction_) breakpoints_.push_back(p.s);
  std::sort(breakpoints_.begin(), breakpoints_.end());
  breakpoints_.erase(std::unique(breakpoints_.begin(), breakpoints_.end()), breakpoints_.end());
}

glm::dvec3 TransferFunction::color(double s) const {
  return eval_on_segment<ColorPoint, glm::dvec3>(color_, segment_at(color_, s), s, [](const ColorPoint& p) { return p.rgb; });
}

double TransferFunction::extinction(double s) const {
  return eval_on_segment<ExtinctionPoint, double>(extinction_, segment_at(extinction_, s), s,
                                                  [](const ExtinctionPoint& p) { return p.kappa; });
}

TransferFunction::Ends TransferFunction::piece(double sa, double sb) const {
  const double mid = 0.5 * (sa + sb);
  const std::size_t ic = segment_at(color_, mid), ik = segment_at(extinction_, mid);
  auto rgb = [](const ColorPoint& p) { return p.rgb; };
  auto kappa = [](const ExtinctionPoint& p) { return p.kappa; };
  return {eval_on_segment<ColorPoint, glm::dvec3>(color_, ic, sa, rgb),
          eval_on_segment<ColorPoint, glm::dvec3>(color_, ic, sb, rgb),
          std::max(0.0, eval_on_segment<ExtinctionPoint, double>(extinction_, ik, sa, kappa)),
          std::max(0.0, eval_on_segment<ExtinctionPoint, double>(extinction_, ik, sb, kappa))};
}

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
    if (!arr[i].is_array() || arr[i].size() != 4) throw InputError(at + ": expected [s, r, g, b], got " + arr[i].dump());
    out.push_back({number(arr[i][0], at), {number(arr[i][1], at), number(arr[i][2], at), number(arr[i][3], at)}});
  }
  return out;
}

// A ParaView preset: [{"Name": ..., "RGBPoints": [x, r, g, b, ...]}, ...] (or one such object).
std::vector<ColorPoint> paraview_preset(const nlohmann::json& spec, const std::string& key, const std::string& base_dir,
                                        double lo, double hi) {
  if (!spec.is_object() || !spec.contains("file")) throw InputError(key + ": expected {\"file\": ..., \"name\": ...}");
  for (const auto& [k, v] : spec.items())
    if (k != "file" && k != "name" && k != "range") throw InputError(key + ": unknown key '" + k + "'");
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
  const std::string name = spec.value("name", "");
  const nlohmann::json* map = nullptr;
  std::string names;
  for (const auto& m : doc) {
    if (!m.is_object() || !m.contains("RGBPoints")) continue;
    const std::string n = m.value("Name", "");
    names += (names.empty() ? "" : ", ") + n;
    if (!map && (name.empty() || n == name)) map = &m;
  }
  if (!map) throw InputError(file.string() + ": no colour map " + (name.empty() ? "with RGBPoints" : "named '" + name + "'") +
                             "; the maps are: " + (names.empty() ? "(none)" : names));
  const auto& pts = (*map)["RGBPoints"];
  if (!pts.is_array() || pts.size() < 4 || pts.size() % 4)
    throw InputError(file.string() + ": RGBPoints must hold x, r, g, b quadruples");
  if (spec.contains("range")) {
    const auto& r = spec["range"];
    if (!r.is_array() || r.size() != 2) throw InputError(key + ".range: expected [s0, s1]");
    lo = number(r[0], key + ".range");
    hi = number(r[1], key + ".range");
  }
  const double x0 = pts[0].get<double>(), x1 = pts[pts.size() - 4].get<double>();
  std::vector<ColorPoint> out;
  for (std::size_t i = 0; i < pts.size(); i += 4) {
    const double x = pts[i].get<double>();
    const double s = x1 > x0 ? lo + (x - x0) / (x1 - x0) * (hi - lo) : lo;
    out.push_back({s, {pts[i + 1].get<double>(), pts[i + 2].get<double>(), pts[i + 3].get<double>()}});
  }
  return out;
}

}  // namespace

TransferFunction transfer_function_from_json(const nlohmann::json& j, const std::string& source,
                                             const std::string& base_dir, double field_min, double field_max) {
  const std::string key = source + ": transfer_function";
  if (!j.is_object()) throw InputError(key + ": expected an object with \"color\" and \"extinction\"");
  for (const auto& [k, v] : j.items())
    if (k != "color" && k != "color_preset" && k != "extinction")
      throw InputError(key + ": unknown key '" + k + "' (known: color, color_preset, extinction)");
  if (j.contains("color") == j.contains("color_preset"))
    throw InputError(key + ": give exactly one of \"color\" and \"color_preset\"");
  if (!j.contains("extinction")) throw InputError(key + ": missing \"extinction\"");
  std::vector<ColorPoint> color = j.contains("color")
                                      ? color_points(j["color"], key + ".color")
                                      : paraview_preset(j["color_preset"], key + ".color_preset", base_dir, field_min, field_max);
  const auto& e = j["extinction"];
  if (!e.is_array()) throw InputError(key + ".extinction: expected an array of [s, kappa]");
  std::vector<ExtinctionPoint> ext;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const std::string at = key + ".extinction[" + std::to_string(i) + "]";
    if (!e[i].is_array() || e[i].size() != 2) throw InputError(at + ": expected [s, kappa], got " + e[i].dump());
    ext.push_back({number(e[i][0], at), number(e[i][1], at)});
  }
  return TransferFunction(std::move(color), std::move(ext), key);
}

}  // namespace cellproj
