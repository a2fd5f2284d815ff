#pragma once
// A scene file (docs/scene.md): which mesh and field, the transfer function, the camera, the image.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "io/read_mesh.hpp"
#include "mesh/clip.hpp"
#include "raycast/iso_options.hpp"
#include "render/settings_table.hpp"
#include "scene/camera_json.hpp"
#include "view/camera.hpp"

namespace cellproj {

// One volume of a scene of several (docs/scene.md, "Several volumes"): its mesh, field, transfer
// function and iso-surfaces.
struct SceneVolume {
  std::string mesh;  // resolved against the scene file's folder
  ReadOptions reader;
  std::string field;                 // empty: the mesh's only field
  nlohmann::json transfer_function;  // parsed once the field's range is known
  std::vector<IsoSurface> iso;       // without a colour: this volume's transfer function's at the value
  bool volume = true;                // its transfer function's volume drawn, else its iso-surfaces alone
};

struct Scene {
  std::string source;  // the scene file, for messages
  std::string mesh;    // resolved against the scene file's folder
  ReadOptions reader;
  std::string field;  // empty: the mesh's only field
  // The field on a log scale (mesh/field_choice.hpp: the log of the values at the points,
  // interpolated), the transfer function's points still in the field's units; values not above 0
  // are an error unless a floor is given.
  bool log_scale = false;
  std::optional<double> log_floor;
  // The extinction from another field (ParaView's separate opacity array), as mesh/field_choice.hpp
  // reads it: the transfer function's colour over `field`, its extinction over this field's values
  // (never on a log scale). Empty: both over `field`.
  std::string opacity_field;
  nlohmann::json transfer_function;  // parsed once the field's range is known
  std::optional<Camera> camera;      // absent: frame the mesh from `view`
  CameraMoves camera_moves;          // the "camera_moves" block: turns, zoom, focus... applied to the camera
  std::string view;                  // a named view (scene/quick_scene.hpp); empty: the default framing
  int width = 512, height = 512;
  glm::dvec3 background{0.0};
  bool transparent = false;  // "background": "none": PNGs with straight alpha, no background
  std::string base_dir;      // the scene file's folder
  // The "layers" block as render options by their command-line names ("iso" -> "0.5:1,0,0",
  // "layer" -> "1,2"): what method layers draws unless the command line says otherwise.
  std::vector<std::pair<std::string, std::string>> layer_options;
  // The "iso" list with "iso_mode", "iso_opacity", "volume", as options: what method exact draws
  // besides the volume unless the command line says otherwise.
  std::vector<std::pair<std::string, std::string>> iso_options;
  // The "render" block: any render setting of the table (render/settings_table.hpp) by name, as
  // text ("method" -> "pt-table", "table_size" -> "64"): what the scene renders with unless the
  // command line says otherwise.
  std::vector<std::pair<std::string, std::string>> render_options;
  std::vector<ClipPlane> clip;  // the mesh clipped by these planes before any method draws it
  // A "volumes" list: the volumes drawn together (mesh, reader, field and transfer_function above
  // are then the first one's, and iso_options holds the list's iso_mode and iso_opacity only).
  std::vector<SceneVolume> volumes;
};

// Throws InputError naming the file and the key for unknown keys, wrong types and missing keys.
Scene load_scene(const std::string& path);
// The same from a parsed scene: `source` names it in messages, relative paths are taken from `base_dir`.
Scene scene_from_json(const nlohmann::json& j, const std::string& source, const std::string& base_dir);

// The scene's render options (its "render" block, then its "layers" block for method layers and
// its "iso" list for exact) as defaults of `options`: those the options do not give already, not marked as given.
// Returns the warnings, such as iso-surfaces a method does not draw.
std::vector<std::string> apply_scene_options(const Scene& scene, RenderOptions& options);

// "x,y,z,nx,ny,nz": a clipping plane through (x, y, z) with normal (nx, ny, nz); InputError naming setting 'clip'.
ClipPlane parse_clip_plane(const std::string& text);

// "WxH" -> width, height; throws InputError.
void parse_size(const std::string& text, int& width, int& height);
// "R,G,B" (each in [0, 1]), "#rrggbb", "black" or "white"; InputError naming `what` otherwise.
glm::dvec3 parse_color(const std::string& text, const std::string& what);

}  // namespace cellproj
