#pragma once
// A scene made from a mesh alone, for `cellproj render MESH` and `cellproj scene MESH`: a field, a
// built-in colour map over its range, an extinction ramp whose optical depth across the mesh is
// given, and a camera framing the mesh from a named view.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "io/read_mesh.hpp"
#include "view/camera.hpp"

namespace cellproj {

struct QuickLook {
  std::string field;  // as mesh/field_choice.hpp reads it; empty: the mesh's only field
  bool log = false;   // the field on a log scale (Scene::log_scale), the colour map over its log
  std::optional<double> log_floor;
  std::string colormap = "Cool to Warm";  // optics/colormaps.hpp
  // Extinction over the field's range: ramp (0 at the minimum, most at the maximum), reverse, flat,
  // or explicit points "S=K,S=K,..." (K the optical depth across the mesh's diagonal at S).
  std::string opacity = "ramp";
  double depth = 20.0;  // optical depth across the mesh's diagonal where the extinction is largest
  std::string view;     // +x, -x, +y, -y, +z, -z, iso; empty: the scene files' default framing
  int width = 512, height = 512;
};

// The camera framing the box [lo, hi] from `view` (as QuickLook::view), orthographic; InputError
// listing the views for an unknown name.
Camera view_camera(const std::string& view, const glm::dvec3& lo, const glm::dvec3& hi, double aspect);
std::string view_names();

// The transfer function (as docs/scene.md) of `look` for a field ranging over [lo, hi] on a mesh
// whose bounding box has this diagonal.
nlohmann::json quick_transfer_function(const QuickLook& look, double lo, double hi, double diagonal);

// The scene (as docs/scene.md) for `loaded`, read from `mesh_path` with `reader`, with the mesh's
// path written relative to `scene_dir` (absolute when empty). InputError for a bad look, naming
// the option. The field chosen from a vector or tensor is kept in the mesh (mesh/field_choice.hpp).
nlohmann::json quick_scene(LoadedMesh& loaded, const std::string& mesh_path, const ReadOptions& reader,
                           const QuickLook& look, const std::string& scene_dir = "");

}  // namespace cellproj
