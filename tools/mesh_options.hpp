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
  if (!reader.cell_data) return;  // a command that shows cell data as it is (info)
  cmd.add_option_function<std::string>(
         "--cell-data", [&reader](const std::string& mode) { reader.cell_data = cell_data_from_name(mode); },
         "Cell data (a finite-volume solver's cell averages): cells (default) draws each cell's value constant over "
         "the cell, exactly, in every method; points averages them to the points, volume-weighted")
      ->check(CLI::IsMember({"cells", "points"}));
}

// The field the extinction comes from (scene key "opacity_field").
inline void add_opacity_field_option(CLI::App& cmd, std::string& field) {
  cmd.add_option("--opacity-field", field,
                 "Extinction from this field, colour from --field (ParaView's separate opacity array); --opacity and "
                 "a scene's extinction points are then over its values, never on a log scale; spelt as --field");
}

// The look of a mesh rendered without a scene; the options given are listed in `given`.
inline std::vector<CLI::Option*> add_look_options(CLI::App& cmd, QuickLook& look) {
  return {cmd.add_option("--colormap", look.colormap,
                         "Built-in colour map over the field's range (default 'Cool to Warm'): " + colormap_names()),
          cmd.add_option("--opacity", look.opacity,
                         "Extinction over the field's range: auto (default: faint where the field holds its background "
                         "value, rising away from it; scaled so the picture is neither an opaque slab nor a haze), "
                         "ramp, reverse, flat, sigmoid, geometric, or S=DEPTH,S=DEPTH,... (DEPTH: optical depth across "
                         "the mesh's diagonal at field value S)"),
          cmd.add_option("--depth", look.depth,
                         "Optical depth across the mesh's diagonal where extinction is largest (default: auto's own "
                         "scale; 20 for the named shapes)"),
          cmd.add_option_function<std::vector<double>>(
                 "--range", [&look](const std::vector<double>& r) { look.range = std::make_pair(r[0], r[1]); },
                 "LO,HI: the range the colour map and opacity span instead of the field's (ParaView's custom range; "
                 "values beyond it take its ends' colours)")
              ->expected(2)
              ->delimiter(',')
              ->type_name("LO,HI")};
}

// The field on a log scale, and its floor (scene keys "log" and "log_floor").
inline void add_log_options(CLI::App& cmd, bool& log, std::optional<double>& floor) {
  cmd.add_flag("--log", log,
               "The field on a log scale: log10 of its values at the points, interpolated (exact in every method); "
               "the transfer function's points stay in the field's units, a colour map spreads over the log of the "
               "range, the legend labels values");
  cmd.add_option("--log-floor", floor,
                 "With --log: values below this (> 0) count as it; without it, a value not above 0 is an error");
}

// True for a scene file (.json), false for a mesh (a partition index, partition.json, is a mesh).
inline bool is_scene_file(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return (ext == ".json" || ext == ".JSON") && std::filesystem::path(path).filename() != "partition.json";
}

}  // namespace cellproj
