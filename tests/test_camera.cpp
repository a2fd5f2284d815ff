#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "scene/camera_json.hpp"
#include "view/camera.hpp"

using namespace cellproj;

TEST(Camera, OrthographicRaysPassThroughPixelCentres) {
  Camera c;  // looks down -z from (0, 0, 5), up +y, 2 units tall
  c.height = 4.0;
  const PixelRays rays(c, 8, 4);     // 4 units tall, 8 wide: a pixel is one unit square
  const Ray r = rays.ray(0.5, 0.5);  // the top-left pixel's centre
  EXPECT_NEAR(r.origin.x, -3.5, 1e-12);
  EXPECT_NEAR(r.origin.y, 1.5, 1e-12);
  EXPECT_NEAR(r.dir.z, -1.0, 1e-12);
  double x, y;
  ASSERT_TRUE(rays.project({-3.5, 1.5, -10.0}, x, y));
  EXPECT_NEAR(x, 0.5, 1e-12);
  EXPECT_NEAR(y, 0.5, 1e-12);
}

TEST(Camera, PerspectiveRaysStartAtTheEyeWithTheFieldOfView) {
  Camera c;
  c.projection = Projection::Perspective;
  c.fov_y = 90.0;
  const PixelRays rays(c, 2, 2);
  const Ray top = rays.ray(1.0, 0.0);  // top edge, centre column: 45 degrees up
  EXPECT_NEAR(glm::dot(top.dir, glm::dvec3(0, 0, -1)), std::cos(M_PI / 4), 1e-12);
  double x, y;
  EXPECT_FALSE(rays.project({0, 0, 6}, x, y));  // behind the eye
}

TEST(Camera, TheRayLengthPerDepthAtAPixelCentreIsTheSameFromItsTables) {
  // length_per_depth_at_pixel takes u^2 and v^2 from tables made once: the same bits as the
  // general formula at every pixel centre, and 1 / cos of the ray's angle with the view axis.
  Camera c;
  c.projection = Projection::Perspective;
  c.fov_y = 53.0;
  const PixelRays rays(c, 37, 23);
  for (int j = 0; j < 23; ++j)
    for (int i = 0; i < 37; ++i) {
      ASSERT_EQ(rays.length_per_depth_at_pixel(i, j), rays.length_per_depth(i + 0.5, j + 0.5)) << i << " " << j;
      const Ray r = rays.ray(i + 0.5, j + 0.5);
      EXPECT_NEAR(rays.length_per_depth_at_pixel(i, j), 1.0 / glm::dot(r.dir, rays.forward()), 1e-12);
    }
  c.projection = Projection::Orthographic;
  EXPECT_EQ(PixelRays(c, 5, 5).length_per_depth_at_pixel(4, 0), 1.0);
}

TEST(Camera, OrbitTurnsAboutTheUpAxis) {
  Camera c;
  const Camera d = orbit(c, 90.0);
  EXPECT_NEAR(d.eye.x, 5.0, 1e-12);
  EXPECT_NEAR(d.eye.z, 0.0, 1e-12);
}

TEST(Camera, BadCamerasAreRejected) {
  Camera c;
  c.target = c.eye;
  EXPECT_THROW(check_camera(c, "s"), InputError);
  c = Camera{};
  c.up = {0, 0, 1};  // parallel to the view direction
  EXPECT_THROW(check_camera(c, "s"), InputError);
  c = Camera{};
  c.height = 0;
  EXPECT_THROW(check_camera(c, "s"), InputError);
  c = Camera{};
  c.projection = Projection::Perspective;
  c.fov_y = 180;
  EXPECT_THROW(check_camera(c, "s"), InputError);
}
