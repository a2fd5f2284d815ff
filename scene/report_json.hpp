#pragma once
// A render report as JSON (the CLI's --stats line, Python's stats dict).
#include <nlohmann/json_fwd.hpp>

#include "render/report.hpp"
#include "render/settings.hpp"

namespace cellproj {

// The report's values and phases as one JSON object (choices by their names, monostate as null),
// with "phase_seconds" an object.
nlohmann::json report_json(const RenderReport& report);

// The settings the renderer of `settings` reads, each with its value as text (--stats' "settings").
nlohmann::json settings_json(const RenderSettings& settings);

}  // namespace cellproj
