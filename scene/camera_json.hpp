#pragma once
// The camera of a scene file (docs/scene.md), and the camera path of `render --frames`.
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "view/camera.hpp"

namespace cellproj {

// {"projection": "orthographic" | "perspective", "eye", "target", "up", "height", "fov_y"}; throws
// InputError naming `source` and the key, and check_camera's errors.
Camera camera_from_json(const nlohmann::json& j, const std::string& source);

// The camera as camera_from_json reads it (doubles printed so that they read back bit for bit).
nlohmann::json camera_to_json(const Camera& camera);

// The camera turned by `degrees` about the up axis through the target (frame f of --frames: f degrees).
Camera orbit(const Camera& camera, double degrees);

// [x, y, z] from JSON; InputError "AT: expected [x, y, z], got ..." otherwise.
glm::dvec3 vec3(const nlohmann::json& j, const std::string& at);

}  // namespace cellproj
