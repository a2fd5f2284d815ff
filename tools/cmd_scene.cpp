// cellproj scene MESH -o scene.json: the scene `cellproj render MESH` renders, written to edit.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <tuple>

#include <nlohmann/json.hpp>

#include "base/file_status.hpp"
#include "scene/quick_scene.hpp"
#include "scene/scene_file.hpp"
#include "tools/commands.hpp"
#include "tools/mesh_options.hpp"
#include "tools/progress.hpp"

namespace cellproj {
namespace {

struct SceneArgs {
  std::string mesh, output, size, background;
  ReadOptions reader;
  QuickLook look;
};

// Objects one key a line, the scene's sections in docs/scene.md's order; arrays on one line.
std::string pretty(const nlohmann::json& j, const std::string& indent = "") {
  if (!j.is_object() || j.empty()) return j.dump();
  std::vector<std::string> keys;
  for (const char* k : {"mesh", "reader", "field", "transfer_function", "camera", "image"})
    if (j.contains(k)) keys.emplace_back(k);
  for (const auto& [k, v] : j.items())
    if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
  std::string out = "{\n";
  for (std::size_t i = 0; i < keys.size(); ++i)
    out += indent + "  " + nlohmann::json(keys[i]).dump() + ": " + pretty(j[keys[i]], indent + "  ") +
           (i + 1 < keys.size() ? ",\n" : "\n");
  return out + indent + "}";
}

int run_scene(SceneArgs a) {
  if (!a.size.empty()) usage([&] { parse_size(a.size, a.look.width, a.look.height); });
  std::optional<glm::dvec3> background;
  if (!a.background.empty()) background = usage([&] { return parse_color(a.background, "--background"); });
  if (!a.look.view.empty()) usage([&] { return view_camera(a.look.view, {0, 0, 0}, {1, 1, 1}, 1.0); });
  LoadedMesh loaded = read_with_progress(a.mesh, a.reader);
  const std::string dir = a.output.empty() ? std::filesystem::current_path().string()
                                           : std::filesystem::path(a.output).parent_path().string();
  nlohmann::json scene = usage([&] { return quick_scene(loaded, a.mesh, a.reader, a.look, dir.empty() ? "." : dir); });
  if (background) scene["image"]["background"] = {background->r, background->g, background->b};
  const std::string text = pretty(scene) + "\n";
  if (a.output.empty()) {
    std::fputs(text.c_str(), stdout);
    return kExitOk;
  }
  create_folders(dir);
  std::ofstream out(a.output);
  if (!(out << text)) throw InputError(where(a.output, "cannot write the scene file"));
  std::printf("wrote %s (render it with: cellproj render %s)\n", a.output.c_str(), a.output.c_str());
  return kExitOk;
}

}  // namespace

Action add_scene(CLI::App& app) {
  auto args = std::make_shared<SceneArgs>();
  CLI::App* cmd = app.add_subcommand(
      "scene", "Write the scene `cellproj render MESH` renders (field, colour map, extinction, camera) to edit");
  cmd->add_option("mesh", args->mesh, "Mesh file (any format `info` reads)")->required();
  cmd->add_option("-o,--output", args->output,
                  "Scene file to write (default: print it); the mesh is named relative to it");
  cmd->add_option(
      "--field", args->look.field,
      "Point field to render (default: the mesh's only one); of a vector NAME:x, NAME_X, NAME:magnitude, ...");
  add_log_options(*cmd, args->look.log, args->look.log_floor);
  add_opacity_field_option(*cmd, args->look.opacity_field);
  add_look_options(*cmd, args->look);
  cmd->add_option("--view", args->look.view, "Frame the mesh from a named view: " + view_names());
  cmd->add_option("--size", args->size, "Image size WxH (default 512x512)");
  cmd->add_option("--background", args->background, "Background colour: R,G,B in [0, 1], #rrggbb, black or white");
  add_reader_options(*cmd, args->reader);
  add_max_memory_option(*cmd, args->reader.max_memory_gib, "Refuse meshes");
  return [args] { return run_scene(*args); };
}

}  // namespace cellproj
