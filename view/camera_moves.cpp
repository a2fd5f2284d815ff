#include "view/camera_moves.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "base/whole_number.hpp"

namespace cellproj {
namespace {

constexpr double kPi = 3.14159265358979323846;
double radians(double degrees) { return degrees * kPi / 180.0; }

// v turned by `radians` about the unit axis k, right-handed (Rodrigues' rotation formula).
glm::dvec3 turned(const glm::dvec3& v, const glm::dvec3& k, double radians) {
  const double c = std::cos(radians), s = std::sin(radians);
  return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1 - c);
}

double number(const std::string& text, const char* what) {
  const std::optional<double> v = whole_number<double>(text);
  if (!v || !std::isfinite(*v)) throw InputError(std::string("expected ") + what + ", got '" + text + "'");
  return *v;
}
double positive(const std::string& text) {
  const double v = number(text, "a positive factor");
  if (!(v > 0.0)) throw InputError("expected a positive factor, got '" + text + "'");
  return v;
}

const std::vector<CameraMoveRow> kRows = {
    {"azimuth", "DEG", "Turn the camera DEG degrees about its view-up through the focal point (ParaView's Azimuth)",
     [](CameraMoves& m, const std::string& t) { m.azimuth += number(t, "an angle in degrees"); }},
    {"elevation", "DEG",
     "Turn the camera DEG degrees up about the focal point (ParaView's Elevation; its view-up follows)",
     [](CameraMoves& m, const std::string& t) { m.elevation += number(t, "an angle in degrees"); }},
    {"roll", "DEG", "Turn the view-up DEG degrees about the view direction (ParaView's Roll)",
     [](CameraMoves& m, const std::string& t) { m.roll += number(t, "an angle in degrees"); }},
    {"zoom", "F", "Magnify F times about the focal point: the world height seen there divided by F (ParaView's Zoom)",
     [](CameraMoves& m, const std::string& t) { m.zoom *= positive(t); }},
    {"dolly", "F", "Move the eye to 1/F of its distance from the focal point (ParaView's Dolly)",
     [](CameraMoves& m, const std::string& t) { m.dolly *= positive(t); }},
    {"focus", "X,Y,Z", "The focal point X,Y,Z, the eye kept (ParaView's CameraFocalPoint)",
     [](CameraMoves& m, const std::string& t) {
       glm::dvec3 p;
       std::size_t at = 0;
       for (int k = 0; k < 3; ++k) {
         const std::size_t comma = k < 2 ? t.find(',', at) : t.size();
         if (comma == std::string::npos) throw InputError("expected X,Y,Z, got '" + t + "'");
         p[k] = number(t.substr(at, comma - at), "X,Y,Z");
         at = comma + 1;
       }
       m.focus = p;
     }},
    {"perspective", "[DEG]",
     "Perspective projection with view angle DEG, or without one the angle that keeps what the camera shows at "
     "its focal point",
     [](CameraMoves& m, const std::string& t) {
       m.projection = Projection::Perspective, m.view_angle.reset();
       if (t.empty() || t == "on") return;
       const double a = number(t, "a view angle in degrees");
       if (!(a > 0.0 && a < 180.0)) throw InputError("expected a view angle in (0, 180) degrees, got '" + t + "'");
       m.view_angle = a;
     }},
    {"parallel", "", "Parallel (orthographic) projection, keeping what the camera shows at its focal point",
     [](CameraMoves& m, const std::string& t) {
       if (!t.empty() && t != "on") throw InputError("takes no value, got '" + t + "'");
       m.projection = Projection::Orthographic, m.view_angle.reset();
     }},
};

}  // namespace

Camera orbit(const Camera& c, double degrees, const glm::dvec3& axis) {
  if (degrees == 0.0) return c;  // bit for bit: target + (eye - target) need not round back to eye
  const glm::dvec3 k = glm::normalize(axis);
  Camera out = c;
  out.eye = c.target + turned(c.eye - c.target, k, radians(degrees));
  if (c.up != axis) out.up = turned(c.up, k, radians(degrees));
  return out;
}

Camera azimuth(const Camera& c, double degrees) { return orbit(c, degrees, c.up); }

Camera elevation(const Camera& c, double degrees) {
  if (degrees == 0.0) return c;
  const glm::dvec3 left = glm::normalize(glm::cross(c.up, c.target - c.eye));  // turning about it lifts the eye
  Camera out = c;
  out.eye = c.target + turned(c.eye - c.target, left, radians(degrees));
  out.up = turned(c.up, left, radians(degrees));
  return out;
}

Camera roll(const Camera& c, double degrees) {
  if (degrees == 0.0) return c;
  Camera out = c;
  out.up = turned(c.up, glm::normalize(c.target - c.eye), radians(degrees));
  return out;
}

Camera zoom(const Camera& c, double factor) {
  if (factor == 1.0) return c;
  Camera out = c;
  if (c.projection == Projection::Orthographic)
    out.height = c.height / factor;
  else
    out.fov_y = 2.0 * std::atan(std::tan(radians(c.fov_y) / 2.0) / factor) * 180.0 / kPi;
  return out;
}

Camera dolly(const Camera& c, double factor) {
  if (factor == 1.0) return c;
  Camera out = c;
  out.eye = c.target + (c.eye - c.target) / factor;
  return out;
}

Camera perspective(const Camera& c, std::optional<double> degrees) {
  Camera out = c;
  out.projection = Projection::Perspective;
  if (degrees)
    out.fov_y = *degrees;
  else if (c.projection == Projection::Orthographic)
    out.fov_y = 2.0 * std::atan(0.5 * c.height / glm::length(c.eye - c.target)) * 180.0 / kPi;
  return out;
}

Camera parallel(const Camera& c) {
  Camera out = c;
  if (c.projection == Projection::Perspective)
    out.height = 2.0 * glm::length(c.eye - c.target) * std::tan(radians(c.fov_y) / 2.0);
  out.projection = Projection::Orthographic;
  return out;
}

bool CameraMoves::any() const {
  return focus || projection || azimuth != 0.0 || elevation != 0.0 || roll != 0.0 || dolly != 1.0 || zoom != 1.0;
}

Camera moved(const Camera& camera, const CameraMoves& m) {
  Camera c = camera;
  if (m.focus) {
    if (*m.focus == c.eye) throw InputError("setting 'focus': the focal point is the eye");
    c.target = *m.focus;
  }
  if (m.projection == Projection::Perspective) c = perspective(c, m.view_angle);
  if (m.projection == Projection::Orthographic) c = parallel(c);
  c = roll(elevation(azimuth(c, m.azimuth), m.elevation), m.roll);
  c = zoom(dolly(c, m.dolly), m.zoom);
  if (m.any()) check_camera(c, "the camera moved");
  return c;
}

const std::vector<CameraMoveRow>& camera_moves() { return kRows; }

void set_camera_move(CameraMoves& moves, const std::string& name, const std::string& text) {
  for (const CameraMoveRow& row : kRows)
    if (name == row.name) try {
        return row.set(moves, text);
      } catch (const InputError& e) {
        throw InputError("setting '" + name + "': " + e.what());
      }
  std::string list;
  for (const CameraMoveRow& row : kRows) list += (list.empty() ? "" : ", ") + std::string(row.name);
  throw InputError("'" + name + "' is not a camera move (known: " + list + ")");
}

}  // namespace cellproj
