#include "view/camera.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "base/error.hpp"

namespace cellproj {
namespace {

constexpr double kPi = 3.14159265358979323846;

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

void check_camera(const Camera& c, const std::string& source) {
  const std::string at = source + ": camera";
  if (!finite(c.eye) || !finite(c.target) || !finite(c.up))
    throw InputError(at + ": eye, target and up must be finite");
  const glm::dvec3 view = c.target - c.eye;
  if (glm::length(view) == 0.0) throw InputError(at + ": eye and target are the same point");
  if (glm::length(c.up) == 0.0) throw InputError(at + ": up is the zero vector");
  if (glm::length(glm::cross(glm::normalize(view), glm::normalize(c.up))) < 1e-9)
    throw InputError(at + ": up is parallel to the view direction (target - eye)");
  if (c.projection == Projection::Orthographic && !(c.height > 0.0 && std::isfinite(c.height)))
    throw InputError(at + ": height must be positive for an orthographic camera, got " + std::to_string(c.height));
  if (c.projection == Projection::Perspective && !(c.fov_y > 0.0 && c.fov_y < 180.0))
    throw InputError(at + ": fov_y must be in (0, 180) degrees, got " + std::to_string(c.fov_y));
}

Camera frame_box(const glm::dvec3& lo, const glm::dvec3& hi, Projection projection, const glm::dvec3& from,
                 const glm::dvec3& up, double aspect) {
  Camera c;
  c.projection = projection;
  c.target = 0.5 * (lo + hi);
  c.up = up;
  const double radius = 0.5 * glm::length(hi - lo);
  const double fit = radius * (aspect < 1.0 ? 1.0 / aspect : 1.0) * 1.05;
  c.height = 2.0 * fit;
  c.fov_y = 30.0;
  const double distance = projection == Projection::Perspective ? fit / std::sin(c.fov_y * kPi / 360.0) : 3.0 * radius;
  c.eye = c.target + glm::normalize(from) * distance;
  return c;
}

std::vector<glm::dvec3> sphere_directions(int n) {
  std::vector<glm::dvec3> out;
  constexpr double kGoldenAngle = 2.399963229728653;  // pi (3 - sqrt 5)
  for (int k = 0; k < n; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / n, r = std::sqrt(std::max(0.0, 1 - z * z)), phi = k * kGoldenAngle;
    out.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  return out;
}

glm::dvec3 up_for(const glm::dvec3& from) {
  return std::abs(glm::normalize(from).z) > 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1);
}

PixelRays::PixelRays(const Camera& c, int width, int height) : camera_(c), width_(width), height_(height) {
  check_camera(c, "view");
  if (width < 1 || height < 1) throw InputError("image size must be at least 1x1");
  forward_ = glm::normalize(c.target - c.eye);
  right_ = glm::normalize(glm::cross(forward_, c.up));
  up_ = glm::cross(right_, forward_);
  const double aspect = double(width) / height;
  if (c.projection == Projection::Orthographic) {
    half_h_ = 0.5 * c.height;
  } else {
    half_h_ = std::tan(0.5 * c.fov_y * kPi / 180.0);
  }
  half_w_ = half_h_ * aspect;
  if (!perspective()) return;
  u2_.assign(static_cast<std::size_t>(width) + 3, 0.0), v2_.resize(static_cast<std::size_t>(height));
  for (int i = 0; i < width; ++i) {  // as length_per_depth(i + 0.5, j + 0.5) computes them
    const double u = (2.0 * (i + 0.5) / width_ - 1.0) * half_w_;
    u2_[static_cast<std::size_t>(i)] = u * u;
  }
  for (int j = 0; j < height; ++j) {
    const double v = (1.0 - 2.0 * (j + 0.5) / height_) * half_h_;
    v2_[static_cast<std::size_t>(j)] = v * v;
  }
}

Ray PixelRays::ray(double x, double y) const {
  const double u = (2.0 * x / width_ - 1.0) * half_w_, v = (1.0 - 2.0 * y / height_) * half_h_;
  if (camera_.projection == Projection::Orthographic) return {camera_.eye + u * right_ + v * up_, forward_};
  return {camera_.eye, glm::normalize(forward_ + u * right_ + v * up_)};
}

void PixelRays::project(const glm::dvec3& p, double& x, double& y, double& z) const {
  const glm::dvec3 d = p - camera_.eye;
  double u = glm::dot(d, right_), v = glm::dot(d, up_);
  z = glm::dot(d, forward_);
  if (perspective()) u /= z, v /= z;
  x = (u / half_w_ + 1.0) * 0.5 * width_;
  y = (1.0 - v / half_h_) * 0.5 * height_;
}

std::array<glm::dvec3, 3> PixelRays::ray_space_jacobian(const glm::dvec3& p) const {
  const double sx = 0.5 * width_ / half_w_, sy = -0.5 * height_ / half_h_;  // pixels per unit of u and v
  if (!perspective()) return {sx * right_, sy * up_, forward_};
  const glm::dvec3 d = p - camera_.eye;
  const double u = glm::dot(d, right_), v = glm::dot(d, up_), z = glm::dot(d, forward_);
  // x = (u / (z half_w) + 1) W / 2: d x / d p = sx (right / z - u forward / z^2), and so for y.
  return {sx * (right_ / z - (u / (z * z)) * forward_), sy * (up_ / z - (v / (z * z)) * forward_), d / glm::length(d)};
}

void PixelRays::project_homogeneous(const glm::dvec3& p, double& hx, double& hy, double& z) const {
  const glm::dvec3 d = p - camera_.eye;
  const double u = glm::dot(d, right_), v = glm::dot(d, up_);
  z = glm::dot(d, forward_);
  const double w = perspective() ? z : 1.0;  // x = (u / (z half_w) + 1) W / 2, times z
  hx = (u / half_w_ + w) * 0.5 * width_;
  hy = (w - v / half_h_) * 0.5 * height_;
}

bool PixelRays::project(const glm::dvec3& p, double& x, double& y) const {
  double z;
  project(p, x, y, z);
  return !perspective() || z > 0.0;
}

}  // namespace cellproj
