#pragma once
// Options shared by the commands that take a mesh file: how to read it, and how to look at it
// without a scene file (`render MESH`, `scene MESH`).
#include <limits>

#include <CLI/CLI.hpp>

#include "io/read_mesh.hpp"
#include "optics/colormaps.hpp"
#include "scene/quick_scene.hpp"

namespace cellproj {

inline void add_reader_options(CLI::App& cmd, ReadOptions& reader) {
  cmd.add_option("--format", reader.format,
                 "Override the format chosen by extension: vtk-xml, vtk-legacy, exodus, cgns, plot3d, tetgen, off, "
                 "points")
      ->check(CLI::Validator(
          [](std::string& format) -> std::string {  // a bad command line (exit 2), before any file is read
            std::string known;
            for (const auto& [name, extensions] : known_formats()) {
              if (name == format) return "";
              known += (known.empty() ? "" : ", ") + name;
            }
            return "unknown format '" + format + "' (known: " + known + ")";
          },
          "FORMAT"));
  cmd.add_option("--q", reader.q_file, "PLOT3D solution (q) file");
  cmd.add_option("--zone", reader.zone, "CGNS: read only this zone");
  cmd.add_option("--time-step", reader.time_step, "Exodus II: time step of the fields (from 0)")
      ->check(CLI::Range(0, std::numeric_limits<int>::max()));
}

// The look of a mesh rendered without a scene; the options given are listed in `given`.
inline std::vector<CLI::Option*> add_look_options(CLI::App& cmd, QuickLook& look) {
  return {cmd.add_option("--colormap", look.colormap,
                         "Built-in colour map over the field's range (default 'Cool to Warm'): " + colormap_names()),
          cmd.add_option("--opacity", look.opacity,
                         "Extinction over the field's range: ramp (default), reverse, flat, or S=DEPTH,S=DEPTH,... "
                         "(DEPTH: optical depth across the mesh's diagonal at field value S)"),
          cmd.add_option("--depth", look.depth,
                         "ramp, reverse, flat: optical depth across the mesh's diagonal where extinction is largest "
                         "(default 20)")};
}

// True for a scene file (.json), false for a mesh (a partition index, partition.json, is a mesh).
inline bool is_scene_file(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return (ext == ".json" || ext == ".JSON") && std::filesystem::path(path).filename() != "partition.json";
}

}  // namespace cellproj
