#include "scene/render_options.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "base/error.hpp"
#include "scene/names.hpp"
#include "scene/scene_file.hpp"

namespace cellproj {
namespace {

// A switch option's text, "on" or "off", as a bool.
bool on_off(const std::string& name, const std::string& text) {
  if (text != "on" && text != "off") throw InputError("--" + name + ": expected on or off, got '" + text + "'");
  return text == "on";
}

// The text of one option as a value of its type, the whole text used.
template <class T>
T number_of(const std::string& name, const std::string& text) {
  std::size_t used = 0;
  T value{};
  try {
    if constexpr (std::is_same_v<T, int>)
      value = std::stoi(text, &used);
    else
      value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size())
    throw InputError("--" + name + ": expected " + (std::is_same_v<T, int> ? "an integer" : "a number") + ", got '" +
                     text + "'");
  return value;
}

template <class F>
auto named(const char* option, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    throw InputError(std::string("--") + option + ": " + e.what());
  }
}

// "1,2,3" or "0.5,0.25": the comma-separated numbers of option `name`.
template <class T>
std::vector<T> list_of(const std::string& name, const std::string& text) {
  std::vector<T> values;
  for (std::size_t at = 0; at <= text.size();) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    values.push_back(number_of<T>(name, text.substr(at, comma - at)));
    at = comma + 1;
  }
  return values;
}

// "V", "V:R,G,B" or "V:R,G,B,A": an iso-surface (A its head-on opacity, default 1).
IsoSurface iso_surface(const std::string& text) {
  IsoSurface s;
  const std::size_t colon = text.find(':');
  s.value = number_of<double>("iso", text.substr(0, colon));
  s.color_given = colon != std::string::npos;
  if (!s.color_given) return s;
  const std::vector<double> c = list_of<double>("iso", text.substr(colon + 1));
  if (c.size() != 3 && c.size() != 4)
    throw InputError("--iso: '" + text + "': give V, V:R,G,B or V:R,G,B,A (colour and opacity in [0, 1])");
  s.color = {c[0], c[1], c[2]};
  if (c.size() == 4) s.opacity = c[3];
  IsoOptions check_one;
  check_one.surfaces = {s};
  check(check_one);
  return s;
}

// --iso V or V:R,G,B (the layers' colour), --layer, --layer-weights, --silhouettes.
LayerOptions layer_options(const RenderOptions& o, bool layers_mode) {
  LayerOptions l;
  if (layers_mode && o.iso.size() != 1)
    throw InputError(o.iso.empty() ? "--method layers needs --iso V, the iso-value whose crossings it draws"
                                   : "--method layers draws the crossings of one iso-value: give --iso once");
  if (!o.iso.empty()) {
    const IsoSurface s = iso_surface(o.iso.front());
    if (layers_mode && s.opacity != 1.0) throw InputError("--iso: layers are opaque: give V or V:R,G,B");
    l.iso = s.value;
    if (s.color_given) l.color = s.color;
  }
  l.layers = list_of<int>("layer", o.layer);
  if (!o.layer_weights.empty()) l.weights = list_of<double>("layer-weights", o.layer_weights);
  l.silhouettes = named("silhouettes", [&] { return parse_silhouettes(o.silhouettes); });
  l.silhouette_epsilon = o.silhouette_epsilon;
  check(l);
  return l;
}

// --iso (repeatable), --volume, --iso-mode, --iso-opacity: iso-surfaces with the volume.
IsoOptions iso_options(const RenderOptions& o) {
  IsoOptions i;
  for (const std::string& text : o.iso) i.surfaces.push_back(iso_surface(text));
  i.volume = on_off("volume", o.volume);
  i.mode = named("iso-mode", [&] { return parse_iso_mode(o.iso_mode); });
  i.opacity = named("iso-opacity", [&] { return parse_iso_opacity(o.iso_opacity); });
  return i;
}

}  // namespace

std::vector<int> parse_int_list(const std::string& name, const std::string& text) { return list_of<int>(name, text); }
std::vector<double> parse_number_list(const std::string& name, const std::string& text) {
  return list_of<double>(name, text);
}

RenderSettings settings_from(const RenderOptions& o) {
  RenderSettings s;
  named("method", [&] { parse_render_method(o.method, s); });
  s.projection.sort = named("sort", [&] { return parse_sort_method(o.sort); });
  s.projection.gaps = named("gaps", [&] { return parse_gap_method(o.gaps); });
  s.projection.backend = named("backend", [&] { return parse_backend(o.backend); });
  s.tetrahedralize = named("tetrahedralize", [&] { return parse_tetrahedralize(o.tetrahedralize); });
  s.interpolation = named("interpolation", [&] { return parse_cell_interpolation(o.interpolation); });
  s.slicing.axis = named("slice-axis", [&] { return parse_slice_axis(o.slice_axis); });
  s.slicing.integral = named("slice-integral", [&] { return parse_slice_integral(o.slice_integral); });
  s.projection.splat.small_cells = named("small-cells", [&] { return parse_small_cells(o.small_cells); });
  if (o.table_size < 2 || o.table_size > 8192)
    throw InputError("--table-size: expected an integer in [2, 8192], got " + std::to_string(o.table_size));
  s.projection.table_size = o.table_size;
  s.slicing.table_size = o.table_size;
  s.slicing.slices = o.slices;
  s.slicing.backend = s.projection.backend;
  // NaN stands for "the method's default": given by name, it is a mistake.
  if (std::isnan(o.splat_threshold) && std::find(o.given.begin(), o.given.end(), "splat-threshold") != o.given.end())
    throw InputError("--splat-threshold must be a finite number >= 0, not nan");
  s.projection.splat.threshold = o.splat_threshold;
  s.projection.splat.prefilter = o.splat_prefilter;
  s.slicing.splat = s.projection.splat;
  s.layers = layer_options(o, s.mode == RenderMode::layers);
  s.iso = iso_options(o);
  s.projection.cull_transparent = on_off("cull-transparent", o.cull_transparent);
  if (o.compositing != "tiles" && o.compositing != "stream")
    throw InputError("--compositing: expected tiles or stream, got '" + o.compositing + "'");
  s.projection.compositing = o.compositing == "tiles" ? Compositing::tiles : Compositing::stream;
  if (o.tile_rows < 0 || o.tile_rows > 65536)
    throw InputError("--tile-rows: expected an integer in [0, 65536] (0: automatic), got " + std::to_string(o.tile_rows));
  s.projection.tile_rows = o.tile_rows;
  s.projection.early_termination = on_off("early-termination", o.early_termination);
  if (o.tile_orders != "auto" && o.tile_orders != "on" && o.tile_orders != "off")
    throw InputError("--tile-orders: expected auto, on or off, got '" + o.tile_orders + "'");
  s.projection.tile_orders = o.tile_orders == "auto" ? TileOrders::automatic
                             : o.tile_orders == "on" ? TileOrders::on
                                                     : TileOrders::off;
  if (o.whole_cells != "auto" && o.whole_cells != "layers" && o.whole_cells != "polygons")
    throw InputError("--whole-cells: expected auto, layers or polygons, got '" + o.whole_cells + "'");
  s.projection.whole_cells = o.whole_cells == "auto"     ? WholeCells::automatic
                             : o.whole_cells == "layers" ? WholeCells::layers
                                                         : WholeCells::polygons;
  return s;
}

std::vector<std::string> render_option_names() {
  return {"method",         "sort",        "gaps",       "backend", "tetrahedralize",  "interpolation",  "slice-axis",
          "slice-integral", "small-cells", "table-size", "slices",  "splat-threshold", "splat-prefilter",
          "iso",            "layer",       "layer-weights", "silhouettes", "silhouette-epsilon", "volume", "iso-mode",
          "iso-opacity",    "cull-transparent", "compositing", "tile-rows", "early-termination",
          "whole-cells",    "tile-orders"};
}

void set_option(RenderOptions& o, const std::string& given_name, const std::string& value) {
  std::string name = given_name;
  std::replace(name.begin(), name.end(), '_', '-');
  std::string* text = name == "method"              ? &o.method
                      : name == "sort"              ? &o.sort
                      : name == "gaps"              ? &o.gaps
                      : name == "backend"           ? &o.backend
                      : name == "tetrahedralize"    ? &o.tetrahedralize
                      : name == "interpolation"     ? &o.interpolation
                      : name == "slice-axis"        ? &o.slice_axis
                      : name == "slice-integral"    ? &o.slice_integral
                      : name == "small-cells"       ? &o.small_cells
                      : name == "layer"             ? &o.layer
                      : name == "layer-weights"     ? &o.layer_weights
                      : name == "silhouettes"       ? &o.silhouettes
                      : name == "volume"            ? &o.volume
                      : name == "iso-mode"          ? &o.iso_mode
                      : name == "iso-opacity"       ? &o.iso_opacity
                      : name == "cull-transparent"  ? &o.cull_transparent
                      : name == "compositing"       ? &o.compositing
                      : name == "early-termination" ? &o.early_termination
                      : name == "whole-cells"       ? &o.whole_cells
                      : name == "tile-orders"       ? &o.tile_orders
                                                    : nullptr;
  if (text)
    *text = value;
  else if (name == "iso")
    o.iso.push_back(value);
  else if (name == "table-size")
    o.table_size = number_of<int>(name, value);
  else if (name == "slices")
    o.slices = number_of<int>(name, value);
  else if (name == "tile-rows")
    o.tile_rows = number_of<int>(name, value);
  else if (name == "splat-threshold")
    o.splat_threshold = number_of<double>(name, value);
  else if (name == "splat-prefilter")
    o.splat_prefilter = number_of<double>(name, value);
  else if (name == "silhouette-epsilon")
    o.silhouette_epsilon = number_of<double>(name, value);
  else {
    std::string list;
    for (const auto& n : render_option_names()) list += (list.empty() ? "" : ", ") + n;
    throw InputError("unknown render option '" + given_name + "' (known: " + list + ")");
  }
  if (std::find(o.given.begin(), o.given.end(), name) == o.given.end()) o.given.push_back(name);
}

void refuse_unused(const Renderer& renderer, const std::vector<std::string>& given) {
  const std::vector<std::string> used = renderer.settings_used();
  std::string list;
  for (const auto& u : used) list += (list.empty() ? "" : ", --") + u;
  for (const auto& g : given)
    if (std::find(used.begin(), used.end(), g) == used.end())
      throw InputError("--" + g + " does not apply to --method " + renderer.name() + ", which reads --" + list);
}

}  // namespace cellproj
