#include "render/settings_table.hpp"

#include <algorithm>
#include <cmath>
#include <regex>
#include <sstream>
#include <type_traits>

#include "base/error.hpp"
#include "base/name_table.hpp"
#include "base/whole_number.hpp"
#include "render/names.hpp"

namespace cellproj {
namespace {

// ---- Reading a setting's text ---------------------------------------------------------------

template <class T>
T number_of(const std::string& text) {
  if (const std::optional<T> v = whole_number<T>(text)) return *v;
  throw InputError(std::string("expected ") + (std::is_same_v<T, int> ? "an integer" : "a number") + ", got '" + text +
                   "'");
}

template <class T>
std::vector<T> list_of(const std::string& text) {
  std::vector<T> values;
  for (std::size_t at = 0; at <= text.size();) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    values.push_back(number_of<T>(text.substr(at, comma - at)));
    at = comma + 1;
  }
  return values;
}

int int_in(const std::string& text, int lo, int hi, const char* note = "") {
  const int v = number_of<int>(text);
  if (v < lo || v > hi)
    throw InputError("expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]" + note +
                     ", got " + std::to_string(v));
  return v;
}

bool on_off(const std::string& text) {
  if (text != "on" && text != "off") throw InputError("expected on or off, got '" + text + "'");
  return text == "on";
}

// A choice of a small closed set, by its names (for settings with no name table of their own).
template <class E, std::size_t N>
E choice(const std::pair<E, const char*> (&table)[N], const std::string& text) {
  for (const auto& [e, n] : table)
    if (text == n) return e;
  std::string list;
  for (std::size_t i = 0; i < N; ++i) list += (i == 0 ? "" : i + 1 == N ? " or " : ", ") + std::string(table[i].second);
  throw InputError("expected " + list + ", got '" + text + "'");
}

// "V", "V:R,G,B" or "V:R,G,B,A": an iso-surface (A its head-on opacity, default 1).
IsoSurface iso_surface(const std::string& text) {
  IsoSurface s;
  const std::size_t colon = text.find(':');
  s.value = number_of<double>(text.substr(0, colon));
  s.color_given = colon != std::string::npos;
  if (!s.color_given) return s;
  const std::vector<double> c = list_of<double>(text.substr(colon + 1));
  if (c.size() != 3 && c.size() != 4)
    throw InputError("'" + text + "': give V, V:R,G,B or V:R,G,B,A (colour and opacity in [0, 1])");
  s.color = {c[0], c[1], c[2]};
  if (c.size() == 4) s.opacity = c[3];
  IsoOptions one;
  one.surfaces = {s};
  check(one);
  return s;
}

// ---- Printing it back -----------------------------------------------------------------------

std::string number_text(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}
template <class T>
std::string list_text(const std::vector<T>& values) {
  std::string out;
  for (const T& v : values) out += (out.empty() ? "" : ",") + number_text(static_cast<double>(v));
  return out;
}
std::string on_off_text(bool on) { return on ? "on" : "off"; }
std::string iso_text(const IsoSurface& s) {
  std::string out = number_text(s.value);
  if (!s.color_given) return out;
  out += ":" + list_text(std::vector<double>{s.color.x, s.color.y, s.color.z});
  return s.opacity == 1.0 ? out : out + "," + number_text(s.opacity);
}

constexpr std::pair<Compositing, const char*> kCompositing[] = {{Compositing::tiles, "tiles"},
                                                                {Compositing::stream, "stream"}};
constexpr std::pair<TileOrders, const char*> kTileOrders[] = {
    {TileOrders::automatic, "auto"}, {TileOrders::on, "on"}, {TileOrders::off, "off"}};
constexpr std::pair<WholeCells, const char*> kWholeCells[] = {
    {WholeCells::automatic, "auto"}, {WholeCells::layers, "layers"}, {WholeCells::polygons, "polygons"}};

// ---- Which renderers read a setting ---------------------------------------------------------

bool always(const RenderSettings&) { return true; }
bool projection(const RenderSettings& s) { return s.mode == RenderMode::projection; }
bool gouraud_projection(const RenderSettings& s) { return projection(s) && traits(s.projection.method).gouraud; }
bool slicing(const RenderSettings& s) { return s.mode == RenderMode::slicing; }
bool projection_or_slicing(const RenderSettings& s) { return projection(s) || slicing(s); }
bool exact(const RenderSettings& s) { return s.mode == RenderMode::exact; }
bool layers(const RenderSettings& s) { return s.mode == RenderMode::layers; }
bool exact_or_layers(const RenderSettings& s) { return exact(s) || layers(s); }

// ---- The table --------------------------------------------------------------------------------

const std::vector<SettingRow> kRows = {
    {"method",
     "Rendering method: pt-breakpoints (exact for the canonical tetrahedra), pt-analytic, pt-table, pt-linear "
     "(fastest), exact (the reference ray integrator), slicing (cells cut on parallel planes, no sort), mip, minip, "
     "average (one value per ray), or layers (the n-th crossings of an iso-value along each ray); docs/methods.md",
     false, always, [](RenderSettings& s, const std::string& t) { parse_render_method(t, s); },
     [](const RenderSettings& s) { return render_method_name(s); }, render_method_names},
    {"iso",
     "Iso-surfaces, repeatable, V:R,G,B,A (A the opacity seen head-on, default 1; without a colour the colour "
     "map's at V): with exact, drawn with the volume; with layers, the one iso-value V or V:R,G,B whose "
     "crossings it draws",
     true, exact_or_layers, [](RenderSettings& s, const std::string& t) { s.iso.surfaces.push_back(iso_surface(t)); },
     [](const RenderSettings& s) {
       std::string out;
       for (const IsoSurface& i : s.iso.surfaces) out += (out.empty() ? "" : " ") + iso_text(i);
       return out;
     },
     [] { return std::string("V, V:R,G,B or V:R,G,B,A"); }},
    {"volume", "exact with iso-surfaces: draw the volume between the surfaces", false, exact,
     [](RenderSettings& s, const std::string& t) { s.iso.volume = on_off(t); },
     [](const RenderSettings& s) { return on_off_text(s.iso.volume); }, [] { return std::string("on, off"); }},
    {"iso-mode",
     "exact with iso-surfaces: ordered (exact order along each ray), blend2 (the volume, then the surfaces over "
     "it in submission order), oit3, oit4 (libMini's order-independent passes)",
     false, exact, [](RenderSettings& s, const std::string& t) { s.iso.mode = parse_iso_mode(t); },
     [](const RenderSettings& s) { return std::string(name_of(s.iso.mode)); }, iso_mode_names},
    {"iso-opacity",
     "exact with iso-surfaces: how a surface's opacity grows with the view's slant (spectrum: a thin layer's "
     "1 - exp(-c d / |cos t|); spectrum-fit: libMini's cosine-power fit)",
     false, exact, [](RenderSettings& s, const std::string& t) { s.iso.opacity = parse_iso_opacity(t); },
     [](const RenderSettings& s) { return std::string(name_of(s.iso.opacity)); }, iso_opacity_names},
    {"layer", "layers: which crossings of the iso-value to draw, 1 the nearest: N, or increasing N1,N2,... blended",
     false, layers, [](RenderSettings& s, const std::string& t) { s.layers.layers = list_of<int>(t); },
     [](const RenderSettings& s) { return list_text(s.layers.layers); },
     [] { return std::string("integers, increasing from 1"); }},
    {"layer-weights",
     "layers: one weight per layer, blended as their weighted mean where the ray reaches them (none given: equal)",
     false, layers, [](RenderSettings& s, const std::string& t) { s.layers.weights = list_of<double>(t); },
     [](const RenderSettings& s) { return list_text(s.layers.weights); }, [] { return std::string("numbers >= 0"); }},
    {"silhouettes",
     "layers: draw where the view grazes a layer (visible: the front layer, black; hidden: the layers behind it "
     "up to the deepest layer drawn, grey)",
     false, layers, [](RenderSettings& s, const std::string& t) { s.layers.silhouettes = parse_silhouettes(t); },
     [](const RenderSettings& s) { return std::string(name_of(s.layers.silhouettes)); }, silhouettes_names},
    {"silhouette-epsilon", "layers: a silhouette where |view . normal| is below this", false, layers,
     [](RenderSettings& s, const std::string& t) { s.layers.silhouette_epsilon = number_of<double>(t); },
     [](const RenderSettings& s) { return number_text(s.layers.silhouette_epsilon); },
     [] { return std::string("a number in (0, 1]"); }},
    {"slices", "slicing: the number of planes (at most 16 per pixel of the image's longer side)", false, slicing,
     [](RenderSettings& s, const std::string& t) { s.slicing.slices = number_of<int>(t); },
     [](const RenderSettings& s) { return std::to_string(s.slicing.slices); },
     [] { return std::string("an integer >= 1"); }},
    {"slice-axis", "slicing: the plane family (auto: the axis-aligned stack closest to the view)", false, slicing,
     [](RenderSettings& s, const std::string& t) { s.slicing.axis = parse_slice_axis(t); },
     [](const RenderSettings& s) { return std::string(name_of(s.slicing.axis)); }, slice_axis_names},
    {"slice-integral",
     "slicing: the light between two planes sampled, or preintegrated (looked up from the scalar at both ends)", false,
     slicing, [](RenderSettings& s, const std::string& t) { s.slicing.integral = parse_slice_integral(t); },
     [](const RenderSettings& s) { return std::string(name_of(s.slicing.integral)); }, slice_integral_names},
    {"small-cells",
     "projection and slicing: what small cells get (splat and skip need the software back end); "
     "docs/methods.md, Splatting",
     false, projection_or_slicing,
     [](RenderSettings& s, const std::string& t) {
       s.projection.splat.small_cells = s.slicing.splat.small_cells = parse_small_cells(t);
     },
     [](const RenderSettings& s) { return std::string(name_of(s.projection.splat.small_cells)); }, small_cells_names},
    {"splat-threshold",
     "Which cells are small: projection, those covering fewer pixel centres (nan: 1, those covering none); "
     "slicing, those of less volume than this times the spacing cubed (nan: 1)",
     false, projection_or_slicing,
     [](RenderSettings& s, const std::string& t) {
       const double v = number_of<double>(t);
       // NaN stands for "the method's default": given by name, it is a mistake.
       if (std::isnan(v)) throw InputError("must be a finite number >= 0, not nan");
       s.projection.splat.threshold = s.slicing.splat.threshold = v;
     },
     [](const RenderSettings& s) { return number_text(s.projection.splat.threshold); },
     [] { return std::string("a number >= 0"); }},
    {"splat-prefilter", "Standard deviation in pixels of the splats' anti-aliasing pre-filter (0.3 to 4)", false,
     projection_or_slicing,
     [](RenderSettings& s, const std::string& t) {
       s.projection.splat.prefilter = s.slicing.splat.prefilter = number_of<double>(t);
     },
     [](const RenderSettings& s) { return number_text(s.projection.splat.prefilter); },
     [] { return std::string("a number"); }},
    {"cull-transparent",
     "projection: leave out the cells whose scalar range has extinction 0 throughout (the same picture, less work)",
     false, projection, [](RenderSettings& s, const std::string& t) { s.projection.cull_transparent = on_off(t); },
     [](const RenderSettings& s) { return on_off_text(s.projection.cull_transparent); },
     [] { return std::string("on, off"); }},
    {"compositing",
     "software projection: tiles (image tiles each drawing the cells that reach it, in order, no fragment stored) "
     "or stream (fragments buffered by batch, blended in order); the same picture",
     false, projection,
     [](RenderSettings& s, const std::string& t) { s.projection.compositing = choice(kCompositing, t); },
     [](const RenderSettings& s) { return std::string(name_in(kCompositing, s.projection.compositing)); },
     [] { return names(kCompositing); }},
    {"early-termination",
     "software projection with tiles: on composites each tile front to back, closing a pixel once within 1e-6 of "
     "opaque and leaving out the cells behind closed pixels (faster on opaque scenes; the picture within 2e-6 of "
     "off, not the same bits)",
     false, projection, [](RenderSettings& s, const std::string& t) { s.projection.early_termination = on_off(t); },
     [](const RenderSettings& s) { return on_off_text(s.projection.early_termination); },
     [] { return std::string("on, off"); }},
    {"tile-orders",
     "software projection with tiles: on has each image tile order its own cells by the face relations among "
     "them where those are the whole order (mpvo on a convex mesh), with no serial sort of the whole mesh before "
     "the tiles; off sorts every cell once; auto: on from 4 threads on a mesh no view makes a cycle in; the same "
     "picture",
     false, projection,
     [](RenderSettings& s, const std::string& t) { s.projection.tile_orders = choice(kTileOrders, t); },
     [](const RenderSettings& s) { return std::string(name_in(kTileOrders, s.projection.tile_orders)); },
     [] { return names(kTileOrders); }},
    {"whole-cells",
     "software pt-linear and pt-table on hexahedra, wedges and pyramids: layers (the thick-vertex formula at every "
     "pixel from the cell's front and back faces), polygons (the image-plane subdivision Gouraud-shaded, as the "
     "OpenGL back ends draw them) or auto (layers for cells whose image box spans at most 256 pixels, polygons "
     "for larger ones)",
     false, gouraud_projection,
     [](RenderSettings& s, const std::string& t) { s.projection.whole_cells = choice(kWholeCells, t); },
     [](const RenderSettings& s) { return std::string(name_in(kWholeCells, s.projection.whole_cells)); },
     [] { return names(kWholeCells); }},
    {"tile-rows", "software projection with tiles: rows per image tile (0: about 4 tiles per thread, 16 to 64 rows)",
     false, projection,
     [](RenderSettings& s, const std::string& t) { s.projection.tile_rows = int_in(t, 0, 65536, " (0: automatic)"); },
     [](const RenderSettings& s) { return std::to_string(s.projection.tile_rows); },
     [] { return std::string("an integer in [0, 65536]"); }},
    {"sort", "Visibility sort for the projection methods", false, projection,
     [](RenderSettings& s, const std::string& t) { s.projection.sort = parse_sort_method(t); },
     [](const RenderSettings& s) { return std::string(name_of(s.projection.sort)); }, sort_method_names},
    {"gaps", "How mpvo-abuffer finds the relations across gaps (as sortbench's)", false, projection,
     [](RenderSettings& s, const std::string& t) { s.projection.gaps = parse_gap_method(t); },
     [](const RenderSettings& s) { return std::string(name_of(s.projection.gaps)); }, gap_method_names},
    {"backend",
     "Where the projection methods and slicing rasterize: software, or for pt-linear, pt-table and slicing's "
     "sampled integral opengl (OSMesa, float target), opengl-8bit, opengl-8bit-dither",
     false, projection_or_slicing,
     [](RenderSettings& s, const std::string& t) { s.projection.backend = s.slicing.backend = parse_backend(t); },
     [](const RenderSettings& s) { return std::string(name_of(s.projection.backend)); }, backend_names},
    {"tetrahedralize",
     "Which cells other than tetrahedra projection and slicing split into tetrahedra: problem (per view, those "
     "with a folded non-planar face), all, or none (every cell whole)",
     false, projection_or_slicing,
     [](RenderSettings& s, const std::string& t) { s.tetrahedralize = parse_tetrahedralize(t); },
     [](const RenderSettings& s) { return std::string(name_of(s.tetrahedralize)); }, tetrahedralize_names},
    {"table-size", "pt-table: nodes per axis of the opacity table; slicing: of the preintegrated table", false,
     projection_or_slicing,
     [](RenderSettings& s, const std::string& t) {
       s.projection.table_size = s.slicing.table_size = int_in(t, 2, 8192);
     },
     [](const RenderSettings& s) { return std::to_string(s.projection.table_size); },
     [] { return std::string("an integer in [2, 8192]"); }},
    {"ssaa",
     "Anti-aliasing: each pixel made of N x N samples (box filter, or tent: ssaa-filter), for every method; the "
     "frame's work and "
     "memory grow N-squared-fold (docs/accuracy.md, Anti-aliasing)",
     false, always, [](RenderSettings& s, const std::string& t) { s.ssaa = int_in(t, 1, kMaxSsaa); },
     [](const RenderSettings& s) { return std::to_string(s.ssaa); },
     [] { return "an integer in [1, " + std::to_string(kMaxSsaa) + "]"; }},
    {"ssaa-filter",
     "With ssaa: box (each pixel the mean of its samples) or tent (the samples within a pixel of its centre "
     "weighted 1 - distance: smoother edges, a touch softer)",
     false, always, [](RenderSettings& s, const std::string& t) { s.ssaa_filter = parse_sample_filter(t); },
     [](const RenderSettings& s) { return std::string(name_of(s.ssaa_filter)); }, sample_filter_names},
    {"interpolation", "exact: the field inside hexahedra, wedges and pyramids", false, exact,
     [](RenderSettings& s, const std::string& t) { s.interpolation = parse_cell_interpolation(t); },
     [](const RenderSettings& s) { return std::string(name_of(s.interpolation)); }, cell_interpolation_names},
};

std::string canonical(std::string name) {
  std::replace(name.begin(), name.end(), '_', '-');
  return name;
}

// Runs f, naming setting `name` in its InputError.
template <class F>
auto named(const std::string& name, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    const std::string word = setting_word(name), what = e.what();
    if (what.rfind(word, 0) == 0) throw;  // named already (a stage's own check)
    throw InputError(word + ": " + what);
  }
}

// What the settings of the layers' mode take from the iso-surfaces: its one iso-value and colour.
void finish_layers(RenderSettings& s) {
  const bool layers_mode = s.mode == RenderMode::layers;
  const std::vector<IsoSurface>& iso = s.iso.surfaces;
  if (layers_mode && iso.size() != 1)
    throw InputError(iso.empty() ? setting_word("method") + " layers needs " + setting_word("iso") +
                                       " V, the iso-value whose crossings it draws"
                                 : setting_word("method") + " layers draws the crossings of one iso-value: give " +
                                       setting_word("iso") + " once");
  if (!iso.empty()) {
    if (layers_mode && iso.front().opacity != 1.0)
      throw InputError(setting_word("iso") + ": layers are opaque: give V or V:R,G,B");
    s.layers.iso = iso.front().value;
    if (iso.front().color_given) s.layers.color = iso.front().color;
  }
  check(s.layers);
}

}  // namespace

const std::vector<SettingRow>& render_settings() { return kRows; }

const SettingRow* find_setting(const std::string& name) {
  const std::string n = canonical(name);
  for (const SettingRow& row : kRows)
    if (n == row.name) return &row;
  return nullptr;
}

std::string setting_word(const std::string& name) { return "setting '" + name + "'"; }

std::string setting_help(const SettingRow& row) {
  std::string help = row.help;
  const std::string fallback = row.print(RenderSettings{});
  help += " (" + row.takes();
  if (!fallback.empty() && fallback != "nan") help += "; default " + fallback;
  return help + ")";
}

std::string spell_settings(const std::string& message, const std::string& before, const std::string& after, char dash) {
  static const std::regex word("setting '([a-z][a-z0-9-]*)'");
  std::string out;
  auto at = message.cbegin();
  for (std::sregex_iterator m(message.begin(), message.end(), word), end; m != end; ++m) {
    out.append(at, (*m)[0].first);
    std::string name = (*m)[1].str();
    std::replace(name.begin(), name.end(), '-', dash);
    out += before + name + after;
    at = (*m)[0].second;
  }
  return out.append(at, message.cend());
}

void set_option(RenderOptions& o, const std::string& given_name, const std::string& text) {
  const SettingRow* row = find_setting(given_name);
  if (!row) {
    std::string list;
    for (const SettingRow& r : kRows) list += (list.empty() ? "" : ", ") + setting_word(r.name);
    throw InputError("'" + given_name + "' is not a render setting (known: " + list + ")");
  }
  RenderSettings scratch;  // the value checked on its own now; settings_from applies it in order
  named(row->name, [&] { row->set(scratch, text); });
  if (!row->repeatable)
    o.words.erase(std::remove_if(o.words.begin(), o.words.end(), [&](const auto& w) { return w.first == row->name; }),
                  o.words.end());
  o.words.emplace_back(row->name, text);
  if (!option_given(o, row->name)) o.given.push_back(row->name);
}

std::string option_text(const RenderOptions& o, const std::string& name) {
  const std::string n = canonical(name);
  for (auto w = o.words.rbegin(); w != o.words.rend(); ++w)
    if (w->first == n) return w->second;
  const SettingRow* row = find_setting(n);
  return row ? row->print(RenderSettings{}) : std::string();
}

bool option_given(const RenderOptions& o, const std::string& name) {
  return std::find(o.given.begin(), o.given.end(), canonical(name)) != o.given.end();
}

RenderSettings settings_from(const RenderOptions& o) {
  RenderSettings s;
  for (const SettingRow& row : kRows)
    for (const std::pair<std::string, std::string>& word : o.words)  // (no lambda captures a structured binding)
      if (word.first == row.name) named(row.name, [&] { row.set(s, word.second); });
  finish_layers(s);
  check(s.iso);
  return s;
}

void refuse_unused(const RenderSettings& s, const std::vector<std::string>& given) {
  std::string reads;
  for (const SettingRow& row : kRows)
    if (row.reads(s)) reads += (reads.empty() ? "" : ", ") + setting_word(row.name);
  for (const std::string& g : given) {
    const SettingRow* row = find_setting(g);
    if (row && !row->reads(s))
      throw InputError(setting_word(row->name) + " does not apply to " + setting_word("method") + " " +
                       render_method_name(s) + ", which reads " + reads);
  }
}

std::vector<std::pair<std::string, std::string>> settings_read(const RenderSettings& s) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const SettingRow& row : kRows)
    if (row.reads(s)) out.emplace_back(row.name, row.print(s));
  return out;
}

std::vector<int> parse_int_list(const std::string& name, const std::string& text) {
  return named(name, [&] { return list_of<int>(text); });
}
std::vector<double> parse_number_list(const std::string& name, const std::string& text) {
  return named(name, [&] { return list_of<double>(text); });
}

}  // namespace cellproj
