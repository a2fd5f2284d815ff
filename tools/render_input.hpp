#pragma once
// What `cellproj render` was asked (its arguments) and the scene it renders: a scene file with the
// command line's overrides, or a mesh with its default scene; a time series' player; the clipped
// mesh. Internal to the command line.
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "io/read_mesh.hpp"
#include "io/series_files.hpp"
#include "mesh/clip.hpp"
#include "partition/partition_index.hpp"
#include "render/renderer.hpp"
#include "render/settings_table.hpp"
#include "scene/prepare.hpp"
#include "scene/quick_scene.hpp"
#include "scene/scene_file.hpp"
#include "tools/frame_output.hpp"

namespace cellproj {

struct RenderArgs {
  std::string input, png, npy, size, field, progressive, view, background;
  RenderOptions options;                // the render settings, by their command-line names
  ReadOptions reader;                   // for a mesh given instead of a scene
  QuickLook look;                       // the same
  std::vector<std::string> look_given;  // --colormap, --opacity, --depth when given
  int threads = 0, frames = 1;
  int png_bits = 8;    // --png-bits: 8 or 16 a sample
  double fps = 24.0;   // --fps: a movie's frames per second
  double orbit = 0.0;  // degrees over the frames; 0: one degree per frame (--frames as a timing run)
  bool legend = false;
  std::string legend_orientation = "vertical";  // --legend-orientation
  std::string legend_title, legend_unit;        // --legend-title (instead of the field's name), --legend-unit
  bool outline = false, axes = false;           // --outline, --axes: over the picture
  bool cell_data_given = false;                 // --cell-data, over a scene's reader block
  std::string title;                            // --title, above the picture
  bool time_label = false;                      // --time-label: a series' frames labelled with their time
  std::string time_format = "t = %.2f";         // --time-format
  bool log = false;                             // --log: the field on a log scale
  std::optional<double> log_floor;              // --log-floor
  double max_memory_gib = 0.0;                  // 0: the machine's available memory
  bool stats = false;
  std::optional<double> time;     // --time T: a series' frame at T
  std::vector<std::string> clip;  // --clip x,y,z,nx,ny,nz, repeatable: replaces the scene's planes
  std::string animate;            // --animate T0:T1:FRAMES
  // --azimuth, --zoom, ... (view/camera_moves.hpp) by name, in the moves table's order: made on the
  // scene's camera (after its own moves) or on --view's.
  std::vector<std::pair<std::string, std::string>> camera_moves;
  bool no_prefetch = false;  // make each frame of a series in turn, not on a background thread
};

// The scene of the input: a scene file with the command line's overrides, or a mesh with the
// default scene of `cellproj scene`. The mesh is read once either way.
struct Input {
  Scene scene;
  PreparedScene prepared;
  std::unique_ptr<SeriesPlayer> player;     // a time series: its frames (prepared.loaded has no cells then)
  SeriesFrame first;                        // the series' first frame
  std::vector<double> times;                // the series' frame times
  ClipReport clipped;                       // what --clip (or the scene's planes) did to the mesh
  std::optional<PartitionIndex> partition;  // a partitioned mesh: prepared.loaded is its extent (no cells)
};

// What the legend's text is set against: the background, or for a transparent picture the light
// page (a slide) it is likely laid on.
inline glm::dvec3 legend_page(const Scene& scene) { return scene.transparent ? glm::dvec3(1.0) : scene.background; }

// How the PNGs of `scene` are written: its background (or transparent), --png-bits, --title,
// --time-label, and --outline and --axes (the outline that of `box`, the meshes' bounds).
inline PngFormat png_format(const RenderArgs& a, const Scene& scene, const std::pair<glm::dvec3, glm::dvec3>& box) {
  PngFormat f{
      scene.background, scene.transparent, a.png_bits, {a.title, "", text_color_for(legend_page(scene)), ""}, {}, {}};
  if (a.time_label) f.time_format = a.time_format;
  f.annotations.outline = a.outline, f.annotations.axes = a.axes, f.annotations.color = f.caption.text;
  std::tie(f.annotations.lo, f.annotations.hi) = box;
  return f;
}

// How a movie (-o turn.mp4) is encoded: --fps.
inline MovieOptions movie_options(const RenderArgs& a) {
  MovieOptions m;
  m.frames_per_second = a.fps;
  return m;
}

// The legend of what `settings` draw (scene/prepare.hpp), across the bottom with
// --legend-orientation horizontal.
inline ColorBar legend_of(const RenderArgs& a, const PreparedScene& p, const RenderSettings& settings,
                          const Scene& scene) {
  ColorBar bar = color_bar(p, settings, legend_page(scene), {a.legend_title, a.legend_unit});
  bar.horizontal = a.legend_orientation == "horizontal";
  return bar;
}

// --view (replacing the scene's camera and its moves), the camera moves (after the scene's), and
// --clip (replacing its planes); UsageError for a bad one.
void apply_view_and_clip(const RenderArgs& a, Scene& scene);

// Reads the input once (a series: lists it and makes its first frame), refusing what would not fit
// in memory before allocating it; usage errors as UsageError (exit 2), bad input as InputError.
// `given_scene`: the scene file already loaded, if it was (else it is loaded here).
Input load_input(const RenderArgs& a, const Renderer& renderer, const RenderSettings& settings,
                 const std::vector<int>& levels, std::optional<Scene> given_scene = std::nullopt);

}  // namespace cellproj
