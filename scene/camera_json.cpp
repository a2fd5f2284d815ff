#include "scene/camera_json.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "base/error.hpp"

namespace cellproj {
glm::dvec3 vec3(const nlohmann::json& j, const std::string& at) {
  if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())
    throw InputError(at + ": expected [x, y, z], got " + j.dump());
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

Camera camera_from_json(const nlohmann::json& j, const std::string& source) {
  const std::string at = source + ": camera";
  if (!j.is_object()) throw InputError(at + ": expected an object");
  Camera c;
  for (const auto& [k, v] : j.items()) {
    if (k == "projection") {
      const std::string p = v.is_string() ? v.get<std::string>() : "";
      if (p == "orthographic")
        c.projection = Projection::Orthographic;
      else if (p == "perspective")
        c.projection = Projection::Perspective;
      else
        throw InputError(at + ".projection: expected \"orthographic\" or \"perspective\", got " + v.dump());
    } else if (k == "eye")
      c.eye = vec3(v, at + ".eye");
    else if (k == "target")
      c.target = vec3(v, at + ".target");
    else if (k == "up")
      c.up = vec3(v, at + ".up");
    else if (k == "height" || k == "fov_y") {
      if (!v.is_number()) throw InputError(at + "." + k + ": expected a number, got " + v.dump());
      (k == "height" ? c.height : c.fov_y) = v.get<double>();
    } else {
      throw InputError(at + ": unknown key '" + k + "' (known: projection, eye, target, up, height, fov_y)");
    }
  }
  check_camera(c, source);
  return c;
}

nlohmann::json camera_to_json(const Camera& c) {
  const auto v = [](const glm::dvec3& x) { return nlohmann::json::array({x.x, x.y, x.z}); };
  nlohmann::json j = {{"projection", c.projection == Projection::Perspective ? "perspective" : "orthographic"},
                      {"eye", v(c.eye)},
                      {"target", v(c.target)},
                      {"up", v(c.up)}};
  if (c.projection == Projection::Perspective)
    j["fov_y"] = c.fov_y;
  else
    j["height"] = c.height;
  return j;
}

CameraMoves camera_moves_from_json(const nlohmann::json& j, const std::string& at) {
  if (!j.is_object()) throw InputError(at + ": expected an object of camera moves, e.g. {\"azimuth\": 30}");
  CameraMoves moves;
  for (const auto& [key, v] : j.items()) {
    const std::string here = at + "." + key;
    if (key == "focus") {  // a point, as the camera's other points
      moves.focus = vec3(v, here);
      continue;
    }
    const bool flag = key == "perspective" || key == "parallel";
    if (flag && v.is_boolean() && !v.get<bool>()) continue;  // false asks for nothing
    if (!v.is_number() && !(flag && v.is_boolean()))
      throw InputError(here + ": expected a number" + (flag ? " or true" : "") + ", got " + v.dump());
    try {
      set_camera_move(moves, key, v.is_boolean() ? std::string("on") : v.dump());
    } catch (const InputError& e) {
      throw InputError(here + ": " + e.what());
    }
  }
  return moves;
}

}  // namespace cellproj
