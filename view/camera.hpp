#pragma once
// The camera and the rays through pixel centres. Pixel (i, j) is column i from the left and row j
// from the top; its ray passes through (i + 0.5, j + 0.5).
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace cellproj {

enum class Projection { Orthographic, Perspective };

struct Camera {
  Projection projection = Projection::Orthographic;
  glm::dvec3 eye{0, 0, 5}, target{0, 0, 0}, up{0, 1, 0};
  double height = 2.0;  // orthographic: world-space height of the view
  double fov_y = 30.0;  // perspective: full vertical angle in degrees
};

// The view a mesh is framed from when nothing names one (scene files, `cellproj render MESH`):
// orthographic, the eye towards kDefaultFrom from the box's centre, kDefaultUp up.
inline const glm::dvec3 kDefaultFrom{0.6, 0.5, 1.0}, kDefaultUp{0.0, 1.0, 0.0};

// Throws InputError (prefixed with `source`) for eye == target, an up vector parallel to the view
// direction or zero, a non-positive height, a field of view outside (0, 180), non-finite values.
void check_camera(const Camera& camera, const std::string& source);

// The same camera in a frame whose origin is `centre` (the frame of RecentredPoints).
inline Camera recentred(Camera camera, const glm::dvec3& centre) {
  camera.eye -= centre;
  camera.target -= centre;
  return camera;
}

// A camera looking at the box [lo, hi] from direction `from` (towards the eye), framing it whole.
Camera frame_box(const glm::dvec3& lo, const glm::dvec3& hi, Projection projection, const glm::dvec3& from,
                 const glm::dvec3& up, double aspect);

// n unit directions spread evenly over the sphere (a Fibonacci lattice), for benchmark views.
std::vector<glm::dvec3> sphere_directions(int n);
// An up vector not parallel to `from` (z, or x when `from` is nearly vertical).
glm::dvec3 up_for(const glm::dvec3& from);

struct Ray {
  glm::dvec3 origin, dir;  // dir has unit length; t along it is world distance from the origin
};

// Whether a point of view depth z (from the eye, or from the eye's plane in orthographic
// projection) is out of sight: nothing at or behind the eye is drawn, in either projection.
inline bool behind_eye(double z) { return !(z > 0.0); }

// A camera fixed to an image size: the rays of its pixels and the projection of points onto them.
// In perspective rays start at the eye; in orthographic projection they start on the plane through
// the eye perpendicular to the view direction.
class PixelRays {
 public:
  PixelRays(const Camera& camera, int width, int height);
  Ray ray(double x, double y) const;  // (x, y) in pixel units: the centre of pixel (i, j) is (i + .5, j + .5)
  // Image position (x, y) of world point p; false when p is not in front of the eye (perspective).
  bool project(const glm::dvec3& p, double& x, double& y) const;
  // Image position and view depth z of p (distance along the view direction from the eye, or from
  // the eye's plane in orthographic projection); in perspective x, y mean something only for z > 0.
  void project(const glm::dvec3& p, double& x, double& y, double& z) const;
  // The same with x and y multiplied by z in perspective (hx = x z, hy = y z; in orthographic
  // hx = x, hy = y): each is affine in p, so it interpolates along straight lines and clips against
  // a near plane, even for points behind the eye; divide by z to get x, y.
  void project_homogeneous(const glm::dvec3& p, double& hx, double& hy, double& z) const;
  // The rows of the Jacobian at p of (x, y, t): image position and distance t along the ray from
  // its origin, EWA's ray space (Zwicker et al. 2001, section 4.2): the local affine map a splat
  // centred at p is projected through.
  std::array<glm::dvec3, 3> ray_space_jacobian(const glm::dvec3& p) const;
  // Ray length per unit of view depth through image position (x, y): 1 / cos of the ray's angle
  // with the view direction (1 in orthographic projection).
  double length_per_depth(double x, double y) const {
    if (!perspective()) return 1.0;
    const double u = (2.0 * x / width_ - 1.0) * half_w_, v = (1.0 - 2.0 * y / height_) * half_h_;
    return std::sqrt(1.0 + u * u + v * v);
  }
  // The same at the centre of pixel (i, j) (0 <= i < width, 0 <= j < height), from the squares of u
  // and v computed once per column and row: the same bits, without two divisions per pixel.
  double length_per_depth_at_pixel(int i, int j) const {
    if (!perspective()) return 1.0;
    return length_per_depth_from(u2_[static_cast<std::size_t>(i)], v2_[static_cast<std::size_t>(j)]);
  }
  // The same from a column's u^2 and a row's v^2 (u_squared(), v_squared()).
  static double length_per_depth_from(double u2, double v2) { return std::sqrt(1.0 + u2 + v2); }
  // Its terms for loops over many pixels: u^2 per column and v^2 per row (empty in orthographic);
  // u^2 has three more columns of 0, so that four SIMD lanes may start at the last column.
  const double* u_squared() const { return u2_.data(); }
  const double* v_squared() const { return v2_.data(); }
  bool perspective() const { return camera_.projection == Projection::Perspective; }
  int width() const { return width_; }
  int height() const { return height_; }
  const Camera& camera() const { return camera_; }
  const glm::dvec3& forward() const { return forward_; }

 private:
  Camera camera_;
  int width_, height_;
  glm::dvec3 forward_, right_, up_;
  double half_w_, half_h_;       // orthographic: world half extents; perspective: tangents of the half angles
  std::vector<double> u2_, v2_;  // perspective: u^2 per column and v^2 per row of length_per_depth
};

}  // namespace cellproj
