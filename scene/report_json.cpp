#include "scene/report_json.hpp"

#include <type_traits>
#include <variant>

#include <nlohmann/json.hpp>

#include "render/names.hpp"
#include "render/settings_table.hpp"

namespace cellproj {

nlohmann::json report_json(const RenderReport& report) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, value] : report.values)
    j[name] = std::visit(
        [](const auto& v) -> nlohmann::json {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, std::monostate>)
            return nullptr;
          else if constexpr (std::is_arithmetic_v<T> || std::is_same_v<T, std::string>)
            return v;
          else
            return name_of(v);
        },
        value);
  nlohmann::json phases = nlohmann::json::object();
  for (const auto& [name, seconds] : report.phase_seconds) phases[name] = seconds;
  j["phase_seconds"] = phases;
  return j;
}

nlohmann::json settings_json(const RenderSettings& settings) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, value] : settings_read(settings)) j[name] = value;
  return j;
}

}  // namespace cellproj
