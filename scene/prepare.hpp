#pragma once
// A scene made ready to render: the mesh loaded and validated, the field picked and checked, the
// transfer function parsed against the field's range, the camera chosen.
#include <functional>
#include <string>
#include <vector>

#include "io/read_mesh.hpp"
#include "io/series_files.hpp"
#include "optics/transfer_function.hpp"
#include "render/settings.hpp"
#include "scene/scene_file.hpp"
#include "view/camera.hpp"
#include "view/color_bar.hpp"

namespace cellproj {

struct PreparedScene {
  LoadedMesh loaded;
  std::string field;                    // the scalar rendered, as mesh/field_choice.hpp names it
  double field_min = 0, field_max = 0;  // its range (on a log scale, of the log10)
  bool log_scale = false;               // the field is log10(scalar): the legend labels 10^value
  std::string scalar;                   // the scalar before a log, for the legend ("p" of "log10(p)")
  TransferFunction tf;
  Camera camera;  // the scene's (or the framing of its view), its camera moves made
  // What a turntable turns about (view/camera_moves.hpp, orbit): the view's up before the moves,
  // so that a camera tilted by an elevation turns about the world's vertical.
  glm::dvec3 turn_axis{0.0, 1.0, 0.0};
  std::vector<std::string> warnings;  // mesh defects and what reading did, for stderr
  // The field the extinction comes from (Scene::opacity_field, as mesh/field_choice.hpp names it);
  // empty: `field`. The transfer function's extinction points are in its units.
  std::string opacity_field;
};

PreparedScene prepare_scene(const Scene& scene);
// The scene's field as mesh/field_choice.hpp reads it: its "field", on a log scale when it says so.
std::string scene_field(const Scene& scene);
// The same with the scene's mesh already read (as `cellproj render MESH` does, to make its scene).
PreparedScene prepare_scene(const Scene& scene, LoadedMesh loaded);

// A scene of several volumes (Scene::volumes) made ready: each volume prepared as a scene of its
// own (its field, its transfer function over its field's range), all with one camera, the scene's
// or one framing the union of their bounds. read(volume) reads each mesh (e.g. load_mesh).
struct PreparedVolumes {
  std::vector<PreparedScene> volumes;  // in the scene's order; each one's camera is `camera`
  Camera camera;
  glm::dvec3 turn_axis{0.0, 1.0, 0.0};  // as PreparedScene's
  std::vector<std::string> warnings;
};
PreparedVolumes prepare_volumes(const Scene& scene, const std::function<LoadedMesh(const SceneVolume&)>& read);

// A time series' first key frame as a mesh to prepare its scene from (colours and framing come from
// it whatever the time rendered): its points and the player's field; the cells stay with the player,
// which renders every frame (SeriesPlayer::view). The player plays scene_field(scene); the scene's
// field becomes the scalar the player chose (on a log scale, its name says so).
LoadedMesh first_key_frame(SeriesPlayer& player, Scene& scene);

// The range a legend of `tf` spans: its colour map's own points, as ParaView's legend shows its
// lookup table's range (the field's range for a preset stretched over it, a given range
// otherwise); the field's [lo, hi] when the map has no span (one colour).
std::pair<double, double> legend_range(const TransferFunction& tf, double field_lo, double field_hi);
// The legend of the picture: the transfer function's colours over legend_range, the field's
// name, text that reads on `background`.
ColorBar color_bar(const PreparedScene& scene, const glm::dvec3& background);
// The legend of what `settings` draw: the mean, maximum or minimum along each ray named in the
// title; iso-surfaces and layers marked on the bar in their colours, the bar's colours left out
// where the picture has none of them (layers, iso-surfaces without the volume). `text` names the
// field instead of its own name when given, and adds its unit.
struct LegendText {
  std::string title, unit;
};
ColorBar color_bar(const PreparedScene& scene, const RenderSettings& settings, const glm::dvec3& background,
                   const LegendText& text = {});
// InputError when `settings` draw iso-values (exact's surfaces, layers) of a field on a log scale:
// they would be read as logs of the field.
void refuse_iso_on_log_scale(const RenderSettings& settings, bool log_scale);

// The same for `tf` over [lo, hi] (in its own units: on a log scale, log10 of the values).
ColorBar color_bar(const TransferFunction& tf, double lo, double hi, bool log, const std::string& title,
                   const glm::dvec3& background);

// The box of the points, as {lo, hi}.
std::pair<glm::dvec3, glm::dvec3> bounds(const Mesh& mesh);
std::pair<glm::dvec3, glm::dvec3> bounds(const MeshView& mesh);

}  // namespace cellproj
