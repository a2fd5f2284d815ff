#pragma once
// The camera of a scene file (docs/scene.md), and the camera path of `render --frames`.
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "view/camera.hpp"
#include "view/camera_moves.hpp"

namespace cellproj {

// {"projection": "orthographic" | "perspective", "eye", "target", "up", "height", "fov_y"}; throws
// InputError naming `source` and the key, and check_camera's errors.
Camera camera_from_json(const nlohmann::json& j, const std::string& source);

// The camera as camera_from_json reads it (doubles printed so that they read back bit for bit).
nlohmann::json camera_to_json(const Camera& camera);

// {"azimuth": 30, "zoom": 2, "focus": [x, y, z], "perspective": 40 or true, "parallel": true}: the
// scene's camera moves (view/camera_moves.hpp), each by the move's name; InputError naming the key.
CameraMoves camera_moves_from_json(const nlohmann::json& j, const std::string& at);

// [x, y, z] from JSON; InputError "AT: expected [x, y, z], got ..." otherwise.
glm::dvec3 vec3(const nlohmann::json& j, const std::string& at);

}  // namespace cellproj
