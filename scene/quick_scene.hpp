#pragma once
// A scene made from a mesh alone, for `cellproj render MESH` and `cellproj scene MESH`: a field, a
// built-in colour map over its range, an extinction ramp whose optical depth across the mesh is
// given, and a camera framing the mesh from a named view.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "io/read_mesh.hpp"
#include "optics/transfer_function.hpp"
#include "view/camera.hpp"

namespace cellproj {

struct QuickLook {
  std::string field;  // as mesh/field_choice.hpp reads it; empty: the mesh's only field
  bool log = false;   // the field on a log scale (Scene::log_scale), the colour map over its log
  std::optional<double> log_floor;
  std::string colormap = "Cool to Warm";  // optics/colormaps.hpp
  // The field the extinction comes from (Scene::opacity_field): `opacity` is then shaped over its
  // range and values, never on a log scale; `range` spans the colour map only. Empty: `field`.
  std::string opacity_field;
  // Extinction over the field's range: auto (scene/auto_opacity.hpp: faint where the field holds its
  // background value, the scale that leaves the picture neither opaque nor empty), a named shape
  // (ramp: 0 at the minimum, most at the maximum; reverse, flat, sigmoid, geometric), or explicit
  // points "S=K,S=K,..." (K the optical depth across the mesh's diagonal at S).
  std::string opacity = "auto";
  // Optical depth across the mesh's diagonal where the extinction is largest; 0: auto's own scale,
  // 20 for the named shapes.
  double depth = 0.0;
  // The range the colour map and the opacity shape span, in the field's units, instead of the
  // field's own (ParaView's custom range, PyVista's clim): values beyond it take its ends' colours.
  std::optional<std::pair<double, double>> range;
  std::string view;  // +x, -x, +y, -y, +z, -z, iso; empty: the scene files' default framing
  int width = 512, height = 512;
};

// The camera framing the box [lo, hi] from `view` (as QuickLook::view), orthographic; InputError
// listing the views for an unknown name.
Camera view_camera(const std::string& view, const glm::dvec3& lo, const glm::dvec3& hi, double aspect);
std::string view_names();

// What opacity auto looks at (optics/auto_opacity.hpp): the mesh and the field's values at its
// points (on a log scale, their logs), or its extinction found before (a partition index's).
struct OpacityInput {
  MeshView mesh;
  const double* field = nullptr;
  bool log = false;
  const std::vector<ExtinctionPoint>* known = nullptr;
};

// The transfer function (as docs/scene.md) of `look` for a field ranging over [lo, hi] (in its
// units) on a mesh whose bounding box has this diagonal; opacity auto needs `input`.
nlohmann::json quick_transfer_function(const QuickLook& look, double lo, double hi, double diagonal,
                                       const OpacityInput* input = nullptr);

// The same for the field `field.field` (on a log scale, the logs of its values) of `field.mesh`:
// its range and the mesh's diagonal taken from them. `lo` and `hi` are the range in the field's
// units (what transfer_function_from_json takes with the transfer function). With `opacity`, the
// extinction is shaped over that field instead (QuickLook::opacity_field).
struct FieldTransferFunction {
  nlohmann::json json;
  double lo = 0, hi = 0;
};
FieldTransferFunction quick_transfer_function(const QuickLook& look, const OpacityInput& field,
                                              const OpacityInput* opacity = nullptr);

// The scene (as docs/scene.md) for `loaded`, read from `mesh_path` with `reader`, with the mesh's
// path written relative to `scene_dir` (absolute when empty). InputError for a bad look, naming
// the option. The field chosen from a vector or tensor is kept in the mesh (mesh/field_choice.hpp).
// `known_auto`: opacity auto's extinction found before, for a mesh whose cells are not at hand (a
// partition index's extent).
nlohmann::json quick_scene(LoadedMesh& loaded, const std::string& mesh_path, const ReadOptions& reader,
                           const QuickLook& look, const std::string& scene_dir = "",
                           const std::vector<ExtinctionPoint>* known_auto = nullptr);

}  // namespace cellproj
