#pragma once
// What a render call measured and what the user should know about its picture, in a form any
// front end can print without knowing the renderer (the CLI's --stats JSON, Python's dict).
#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "projection/method.hpp"
#include "raycast/interpolation.hpp"
#include "raycast/iso_options.hpp"
#include "raycast/layer_options.hpp"
#include "slicing/slicing_options.hpp"
#include "splat/splat_options.hpp"
#include "visibility/methods.hpp"

namespace cellproj {

// A counter, a time, a text, or a choice the renderer made (printed by its name, scene/names.hpp);
// monostate where a value does not apply to this frame (JSON null).
using ReportValue =
    std::variant<std::monostate, std::int64_t, double, std::string, Backend, SortMethod, GapMethod, Tetrahedralize,
                 CellInterpolation, SliceAxis, SliceIntegral, SmallCells, Silhouettes, IsoMode, IsoOpacity>;

struct RenderReport {
  double seconds = 0.0;          // the frame, preparation excluded
  double prepare_seconds = 0.0;  // the preparations this call made (0 when the volume had them)
  std::vector<std::pair<std::string, double>> phase_seconds;
  std::vector<std::pair<std::string, ReportValue>> values;  // by name, as --stats prints them
  std::vector<std::string> warnings;                        // where the picture may be wrong, and what to do about it

  void add(std::string name, ReportValue value) { values.emplace_back(std::move(name), std::move(value)); }
  // A stage's counters, each under its key: the stage lists them once, beside its stats struct
  // (each_counter(stats, f)), and a new counter is one line there.
  template <class Stats>
  void add_counters(const Stats& stats) {
    each_counter(stats, [this](const char* name, auto value) { add(name, ReportValue(value)); });
  }
  // The value of `name`, or nullptr.
  const ReportValue* find(const std::string& name) const {
    for (const auto& [n, v] : values)
      if (n == name) return &v;
    return nullptr;
  }
};

}  // namespace cellproj
