#pragma once
// Moves of a camera with ParaView's (VTK's vtkCamera) meanings, composable with any starting
// camera (a named view, a scene's camera): turn it about the focal point, roll it, zoom, dolly,
// refocus, switch its projection. Each move is one row of kCameraMoves, its name the front ends'
// (--azimuth, "camera_moves": {"azimuth": 30}, azimuth=30, cp_camera_move(c, "azimuth", "30")).
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "view/camera.hpp"

namespace cellproj {

// Turns the camera by `degrees` about its view-up axis through the focal point (vtkCamera::Azimuth).
Camera azimuth(const Camera& camera, double degrees);
// Turns it by `degrees` about the axis through the focal point along the image's right-hand side
// (vtkCamera::Elevation), the view-up turned with it so that it stays orthogonal to the view (and
// elevation 90 looks down on the focal point without a degenerate camera).
Camera elevation(const Camera& camera, double degrees);
// Turns the view-up by `degrees` about the view direction (vtkCamera::Roll).
Camera roll(const Camera& camera, double degrees);
// Magnifies by `factor` about the focal point: orthographic, the world height over factor;
// perspective, the view angle whose half-tangent is the old one's over factor, so the world height
// seen at the focal point is divided by factor in both (VTK divides the angle itself).
Camera zoom(const Camera& camera, double factor);
// Moves the eye towards the focal point to 1 / factor of its distance (vtkCamera::Dolly).
Camera dolly(const Camera& camera, double factor);
// Perspective with the view angle `degrees`; without one, the angle that shows what the camera
// showed at the focal point. Parallel: the height the camera showed at the focal point.
Camera perspective(const Camera& camera, std::optional<double> degrees = std::nullopt);
Camera parallel(const Camera& camera);

// A turntable's frame: the camera turned rigidly by `degrees` about `axis` through its focal point
// (its eye, and its view-up unless the view-up is the axis itself). With the axis the view's up
// before any move, a tilted camera (elevation) turns about the world's vertical, not its own.
Camera orbit(const Camera& camera, double degrees, const glm::dvec3& axis);
inline Camera orbit(const Camera& camera, double degrees) { return orbit(camera, degrees, camera.up); }

// The moves a user asked for, applied in ParaView's order by moved().
struct CameraMoves {
  std::optional<glm::dvec3> focus;  // the focal point, the eye kept (vtkCamera::SetFocalPoint)
  std::optional<Projection> projection;
  std::optional<double> view_angle;  // with projection perspective
  double azimuth = 0.0, elevation = 0.0, roll = 0.0;
  double dolly = 1.0, zoom = 1.0;
  bool any() const;
};
// The camera refocused, its projection switched, then turned (azimuth, elevation, roll), dollied
// and zoomed; InputError naming the move for a result that is no camera (a zero distance).
Camera moved(const Camera& camera, const CameraMoves& moves);

// A move by name, as the front ends give it: help, and its text set into CameraMoves (InputError
// "setting 'zoom': ..." for a bad value).
struct CameraMoveRow {
  const char* name;
  const char* value;  // what it takes, for help: "DEG", "F", "X,Y,Z", "[DEG]" (optional), "" (none: a switch)
  const char* help;
  void (*set)(CameraMoves& moves, const std::string& text);
};
const std::vector<CameraMoveRow>& camera_moves();
// Sets move `name` from `text`; InputError for an unknown name (listing them) or a bad value.
void set_camera_move(CameraMoves& moves, const std::string& name, const std::string& text);

}  // namespace cellproj
