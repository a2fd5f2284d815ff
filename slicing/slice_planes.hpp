#pragma once
// A family of evenly spaced parallel planes through the mesh (MWSC section 5): dot(p, normal) = h
// for the heights h of a lattice spanning the mesh's extent along the normal. The normal points
// towards the eye, so planes run back to front as their index grows.
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/geometry.hpp"
#include "slicing/slicing_options.hpp"
#include "view/camera.hpp"

namespace cellproj {

// The family `automatic` picks: the axis-aligned stack closest to the view direction (MWSC section
// 5), except in perspective when the eye is inside the points' bounding box or a corner ray of the
// image runs within 73 degrees of that stack's planes, where the view family is used.
SliceAxis automatic_axis(const RecentredPoints& points, const PixelRays& rays);

// The unit normal of family `axis` (not automatic) in this view, pointing towards the eye: the view
// direction reversed, or the axis or its negation.
glm::dvec3 slice_normal(SliceAxis axis, const PixelRays& rays);

class SlicePlanes {
 public:
  // The planes of `axis` (automatic: automatic_axis) for the
  // recentred points and the camera of `rays` (recentred too). An axis-aligned family lies on the
  // lattice lo + k extent / slices of that coordinate whatever the view, so its planes stay put
  // while the camera turns; the view family spans the mesh's depth in this view, in front of the
  // eye.
  SlicePlanes(const RecentredPoints& points, const PixelRays& rays, SliceAxis axis, int slices);

  SliceAxis axis() const { return axis_; }  // x, y, z or view: the family used
  const glm::dvec3& normal() const { return normal_; }
  int count() const { return count_; }  // planes 1..count(), back to front
  double spacing() const { return extent_ / count_; }
  // The height of plane j (1 <= j <= count()), increasing with j. The same lattice point gives the
  // same bits for any count it belongs to (a refinement's planes coincide with the coarser ones).
  double height(int j) const { return height_[static_cast<std::size_t>(j)]; }
  // The first plane j with height(j) > h (count() + 1 when none): the planes strictly above h.
  int first_above(double h) const;
  // The planes j with lo < height(j) <= hi: [first, last] (empty when last < first).
  void crossing(double lo, double hi, int& first, int& last) const;
  // Planes j >= visible_end() lie at or behind the eye (perspective, or the view family's planes
  // in orthographic views), count() + 1 when none does.
  int visible_end() const { return visible_end_; }
  // The front end of the slab in front of the last visible plane: the next plane's height, or the
  // eye's where that lies beyond the eye (perspective).
  double front_end() const { return front_end_; }
  double eye_height() const { return eye_height_; }  // infinity for an orthographic axis stack

 private:
  double lattice(int k) const;  // lo_ + extent_ * k / count_, k reduced by its gcd with count_
  double height_of(int j) const;
  SliceAxis axis_;
  glm::dvec3 normal_{0.0};
  bool flipped_ = false;  // axis-aligned: the normal is the axis negated (heights are -coordinate)
  double lo_ = 0.0, extent_ = 0.0;
  int count_ = 1;
  int visible_end_ = 2;
  double front_end_ = 0.0, eye_height_ = INFINITY;
  std::vector<double> height_;  // plane j's at [j], 0 <= j <= count_ + 1 (the ends for lookups)
};

}  // namespace cellproj
