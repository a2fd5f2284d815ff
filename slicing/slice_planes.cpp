#include "slicing/slice_planes.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

namespace cellproj {

namespace {
// Below this cosine between a pixel's ray and an axis-aligned stack's normal, the ray crosses its
// planes more than 3.3 spacings apart, and nearly along them: the view family serves better.
constexpr double kMinCosine = 0.3;
}  // namespace

SliceAxis automatic_axis(const RecentredPoints& points, const PixelRays& rays) {
  const glm::dvec3 a = glm::abs(rays.forward());
  const int k = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
  const SliceAxis axis = static_cast<SliceAxis>(static_cast<int>(SliceAxis::x) + k);
  if (!rays.perspective()) return axis;
  // In perspective the rays fan out: an eye inside the mesh's box sees the stack from both sides,
  // and the image's corner rays may run nearly along its planes.
  const glm::dvec3& eye = rays.camera().eye;
  if (glm::all(glm::greaterThanEqual(eye, points.lo)) && glm::all(glm::lessThanEqual(eye, points.hi)))
    return SliceAxis::view;
  for (double x : {0.0, double(rays.width())})
    for (double y : {0.0, double(rays.height())})
      if (std::abs(rays.ray(x, y).dir[k]) < kMinCosine) return SliceAxis::view;
  return axis;
}

glm::dvec3 slice_normal(SliceAxis axis, const PixelRays& rays) {
  if (axis == SliceAxis::view) return -rays.forward();
  glm::dvec3 n(0.0);
  n[static_cast<int>(axis) - static_cast<int>(SliceAxis::x)] = 1.0;
  return glm::dot(n, rays.forward()) > 0.0 ? -n : n;  // towards the eye
}

SlicePlanes::SlicePlanes(const RecentredPoints& points, const PixelRays& rays, SliceAxis axis, int slices)
    : axis_(axis), count_(slices) {
  if (axis_ == SliceAxis::automatic) axis_ = automatic_axis(points, rays);
  normal_ = slice_normal(axis_, rays);
  const glm::dvec3 along = axis_ == SliceAxis::view ? normal_ : glm::abs(normal_);  // the lattice's direction
  flipped_ = along != normal_;
  // The eye's height: in perspective, and in orthographic views for the planes parallel to the eye's
  // plane (an orthographic axis stack crossing that plane has its polygons clipped instead).
  if (rays.perspective() || axis_ == SliceAxis::view) eye_height_ = glm::dot(rays.camera().eye, normal_);
  double lo = 0.0, hi = 0.0;
  if (axis_ != SliceAxis::view) {  // the mesh's extent along the axis: its bounding box, whatever the view
    const int k = static_cast<int>(axis_) - static_cast<int>(SliceAxis::x);
    lo = points.lo[k], hi = points.hi[k];
  } else {
    for (std::size_t p = 0, n = points.xyz.size() / 3; p < n; ++p) {
      const double h = glm::dot(points(static_cast<std::int64_t>(p)), along);
      lo = p == 0 ? h : std::min(lo, h), hi = p == 0 ? h : std::max(hi, h);
    }
    // The view family spends its planes on what lies in front of the eye (an eye inside the mesh
    // would leave the planes behind it unused); an axis stack keeps its lattice.
    if (std::isfinite(eye_height_) && eye_height_ > lo) hi = std::min(hi, eye_height_ - 1e-9 * (hi - lo));
  }
  lo_ = lo, extent_ = hi - lo;
  if (!(extent_ > 0.0)) extent_ = std::max(1.0, std::abs(lo)) * 1e-300;  // a flat mesh: no plane crosses it
  height_.resize(static_cast<std::size_t>(count_) + 2);
  for (int j = 0; j <= count_ + 1; ++j) height_[static_cast<std::size_t>(j)] = height_of(j);
  // Planes at or behind the eye are never drawn (their polygons would be clipped away).
  visible_end_ = std::isfinite(eye_height_) ? first_above(std::nextafter(eye_height_, -INFINITY)) : count_ + 1;
  front_end_ = std::min(height(visible_end_), eye_height_);
}

double SlicePlanes::lattice(int k) const {
  const int g = std::gcd(k, count_);
  return lo_ + extent_ * (k / g) / (count_ / g);
}

double SlicePlanes::height_of(int j) const { return flipped_ ? -lattice(count_ - j) : lattice(j); }

int SlicePlanes::first_above(double h) const {
  // Heights rise by about spacing() per plane from height(0); the estimate is corrected by the
  // exact comparisons, so the answer is exact however it rounds.
  const double h0 = flipped_ ? -(lo_ + extent_) : lo_;
  const double estimate = std::floor((h - h0) / spacing()) + 1;
  int j = !(estimate > 1) ? 1 : estimate > count_ ? count_ + 1 : static_cast<int>(estimate);
  while (j <= count_ && !(height(j) > h)) ++j;
  while (j > 1 && height(j - 1) > h) --j;
  return j;
}

void SlicePlanes::crossing(double lo, double hi, int& first, int& last) const {
  first = first_above(lo);
  last = first_above(hi) - 1;
}

}  // namespace cellproj
