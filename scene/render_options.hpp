#pragma once
// The render settings as a user gives them, by their command-line names ("method", "sort",
// "table-size", ...): one parser for every front end (the CLI, the Python module, the C API), so
// that the same words give the same RenderSettings, and so the same picture, everywhere.
#include <string>
#include <vector>

#include "render/renderer.hpp"
#include "render/settings.hpp"

namespace cellproj {

struct RenderOptions {
  std::string method = "pt-breakpoints", sort = "auto", gaps = "auto", backend = "software", tetrahedralize = "problem",
              interpolation = "isoparametric", slice_axis = "auto", slice_integral = "preintegrated",
              small_cells = "draw", layer = "1", layer_weights, silhouettes = "none", volume = "on",
              iso_mode = "ordered", iso_opacity = "constant", cull_transparent = "on", compositing = "tiles",
              early_termination = "off", whole_cells = "auto", tile_orders = "auto";
  std::vector<std::string> iso;  // --iso V[:R,G,B[,A]], repeatable
  int table_size = 256, slices = 256, tile_rows = 0;
  double splat_threshold = SplatOptions{}.threshold;  // NaN: the method's default
  double splat_prefilter = SplatOptions{}.prefilter;
  double silhouette_epsilon = LayerOptions{}.silhouette_epsilon;
  std::vector<std::string> given;  // the names set explicitly (set_option adds them), for refuse_unused
};

// "1,2,3": the comma-separated numbers an option `name` gives; InputError "--NAME: expected an
// integer (a number), got 'x'" for an item that is not one.
std::vector<int> parse_int_list(const std::string& name, const std::string& text);
std::vector<double> parse_number_list(const std::string& name, const std::string& text);

// The settings, every option checked (also those the method does not read: a typo never passes
// silently); InputError "--NAME: ..." for a bad value.
RenderSettings settings_from(const RenderOptions& options);

// Sets the option `name` (the command-line name, "table-size", or with underscores, "table_size")
// from its text; InputError for an unknown name (listing them) or a value that is not of its type.
// "iso" is repeatable: each call adds a surface.
void set_option(RenderOptions& options, const std::string& name, const std::string& value);
std::vector<std::string> render_option_names();  // "method", "sort", ...

// InputError when `given` names an option `renderer` does not read ("--sort does not apply to
// --method exact, which reads --interpolation").
void refuse_unused(const Renderer& renderer, const std::vector<std::string>& given);

}  // namespace cellproj
