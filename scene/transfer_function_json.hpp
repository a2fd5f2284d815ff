#pragma once
// The transfer function of a scene file (docs/scene.md), from its JSON object.
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "optics/transfer_function.hpp"

namespace cellproj {

// From the scene's JSON object:
//   {"color": [[s, r, g, b], ...] | "color_preset": {"file": F, "name": N, "range": [s0, s1]},
//    "extinction": [[s, kappa], ...]}
// A ParaView colour-map preset (an exported JSON array of maps with "Name" and "RGBPoints") has its
// x range mapped onto `range` (default: `field_range`). Relative preset paths resolve against
// `base_dir`. Errors (InputError) name `source` and the key. With `log_axis` the points are in the
// field's units and placed at their log10 (a field on a log scale, mesh/field_choice.hpp), a
// preset spread evenly over the log of its range, as ParaView's log-scale colour maps; the
// extinction's points too unless `extinction_on_log_axis` is false (an opacity field of its own,
// Scene::opacity_field, is never on a log scale).
TransferFunction transfer_function_from_json(const nlohmann::json& j, const std::string& source,
                                             const std::string& base_dir, double field_min, double field_max,
                                             bool log_axis = false, bool extinction_on_log_axis = true);

}  // namespace cellproj
