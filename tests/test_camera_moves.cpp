// Camera moves with ParaView's meanings (view/camera_moves.hpp): the properties a user relies on.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "view/camera_moves.hpp"

using namespace cellproj;

namespace {

Camera some_camera(Projection projection) {
  Camera c;
  c.projection = projection;
  c.eye = {3.0, -4.0, 2.5}, c.target = {0.2, 0.1, -0.3}, c.up = {0.0, 0.2, 1.0};
  c.height = 2.4, c.fov_y = 35.0;
  return c;
}

void expect_near(const Camera& a, const Camera& b, double tol = 1e-12) {
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(a.eye[k], b.eye[k], tol) << "eye " << k;
    EXPECT_NEAR(a.target[k], b.target[k], tol) << "target " << k;
    EXPECT_NEAR(glm::normalize(a.up)[k], glm::normalize(b.up)[k], tol) << "up " << k;
  }
  EXPECT_NEAR(a.height, b.height, tol);
  EXPECT_NEAR(a.fov_y, b.fov_y, tol);
  EXPECT_EQ(a.projection, b.projection);
}

// The world height the camera shows at its focal point.
double height_at_focus(const Camera& c) {
  return c.projection == Projection::Orthographic
             ? c.height
             : 2.0 * glm::length(c.eye - c.target) * std::tan(c.fov_y * 3.14159265358979323846 / 360.0);
}

}  // namespace

TEST(CameraMoves, TurnsComposeAndAFullTurnReturnsTheCamera) {
  for (Projection p : {Projection::Orthographic, Projection::Perspective}) {
    const Camera c = some_camera(p);
    expect_near(azimuth(c, 360.0), c);
    expect_near(elevation(c, 360.0), c);
    expect_near(roll(c, 360.0), c);
    expect_near(azimuth(azimuth(c, 25.0), 47.0), azimuth(c, 72.0));
    expect_near(elevation(elevation(c, -30.0), 75.0), elevation(c, 45.0));
    expect_near(roll(roll(c, 10.0), 80.0), roll(c, 90.0));
    // Turns keep the distance to the focal point and the focal point itself.
    const Camera t = roll(elevation(azimuth(c, 33.0), 71.0), 12.0);
    EXPECT_NEAR(glm::length(t.eye - t.target), glm::length(c.eye - c.target), 1e-12);
    EXPECT_EQ(t.target, c.target);
  }
}

TEST(CameraMoves, ElevationNinetyLooksDownAndKeepsAValidCamera) {
  Camera c;  // eye on +z looking at the origin, up +y
  c.eye = {0, -5, 0}, c.up = {0, 0, 1};
  const Camera top = elevation(c, 90.0);
  EXPECT_NEAR(top.eye.z, 5.0, 1e-12);  // up, over the focal point
  EXPECT_NO_THROW(check_camera(top, "test"));
  EXPECT_NEAR(glm::dot(glm::normalize(top.up), glm::normalize(top.target - top.eye)), 0.0, 1e-12);
  const Camera right = azimuth(c, 90.0);  // about +z, counterclockwise seen from above
  EXPECT_NEAR(right.eye.x, 5.0, 1e-12);
}

TEST(CameraMoves, ZoomDividesTheWorldHeightAndDollyTheDistance) {
  for (Projection p : {Projection::Orthographic, Projection::Perspective}) {
    const Camera c = some_camera(p);
    EXPECT_NEAR(height_at_focus(zoom(c, 2.0)), height_at_focus(c) / 2.0, 1e-12);
    expect_near(zoom(zoom(c, 1.5), 4.0), zoom(c, 6.0));
    const Camera d = dolly(c, 4.0);
    EXPECT_NEAR(glm::length(d.eye - d.target), glm::length(c.eye - c.target) / 4.0, 1e-12);
  }
}

TEST(CameraMoves, SwitchingProjectionKeepsWhatTheFocalPointShows) {
  const Camera o = some_camera(Projection::Orthographic);
  const Camera p = perspective(o);
  EXPECT_EQ(p.projection, Projection::Perspective);
  EXPECT_NEAR(height_at_focus(p), o.height, 1e-12);
  EXPECT_NEAR(parallel(p).height, o.height, 1e-12);
  EXPECT_EQ(perspective(o, 50.0).fov_y, 50.0);
}

TEST(CameraMoves, MovesByNameComposeAndBadOnesNameTheMove) {
  CameraMoves m;
  set_camera_move(m, "azimuth", "30");
  set_camera_move(m, "azimuth", "15");  // angles add
  set_camera_move(m, "zoom", "2");
  set_camera_move(m, "zoom", "1.5");  // factors multiply
  set_camera_move(m, "focus", "0.5,0,-1");
  EXPECT_EQ(m.azimuth, 45.0);
  EXPECT_EQ(m.zoom, 3.0);
  const Camera c = some_camera(Projection::Orthographic);
  const Camera moved_c = moved(c, m);
  EXPECT_EQ(moved_c.target, glm::dvec3(0.5, 0, -1));
  EXPECT_NEAR(moved_c.height, c.height / 3.0, 1e-12);
  EXPECT_EQ(moved(c, CameraMoves{}).eye, c.eye);  // no move: the camera, bit for bit
  const auto message = [&](const char* name, const char* text) {
    try {
      CameraMoves x;
      set_camera_move(x, name, text);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("zoom", "0").find("setting 'zoom': expected a positive factor"), 0u);
  EXPECT_EQ(message("azimuth", "nan").find("setting 'azimuth':"), 0u);
  EXPECT_EQ(message("focus", "1,2").find("setting 'focus': expected X,Y,Z"), 0u);
  EXPECT_EQ(message("perspective", "180").find("setting 'perspective': expected a view angle in (0, 180)"), 0u);
  EXPECT_EQ(message("pan", "1").find("'pan' is not a camera move"), 0u);
  CameraMoves onto_eye;
  onto_eye.focus = c.eye;
  EXPECT_THROW(moved(c, onto_eye), InputError);
}

// A turntable of a moved camera turns about the view's up before the moves (the world's
// vertical): the same as turning first and then moving, so an elevated camera circles the focal
// point level, as ParaView's orbit of a tilted view does.
TEST(CameraMoves, ATiltedTurntableTurnsAboutTheViewsUp) {
  for (Projection p : {Projection::Orthographic, Projection::Perspective}) {
    const Camera c = some_camera(p);
    CameraMoves tilt;
    tilt.elevation = 30.0, tilt.roll = 10.0, tilt.zoom = 2.0, tilt.dolly = 1.5;
    for (double d : {45.0, 120.0, -200.0}) {
      CameraMoves turned = tilt;
      turned.azimuth = d;
      expect_near(orbit(moved(c, tilt), d, c.up), moved(c, turned));
    }
    EXPECT_EQ(orbit(c, 30.0).up, c.up);  // an unmoved camera: its view-up is the axis, kept as it is
  }
}
