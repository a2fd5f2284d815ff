#pragma once
// A frame's opaque depth (view/opaque_depth.hpp) read along its rays, for the renderers that cut
// their segments at it.
#include <limits>
#include <vector>

#include "view/camera.hpp"
#include "view/opaque_depth.hpp"
#include "view/raster.hpp"

namespace cellproj {

// A depth buffer read for one frame's rays: each pixel's limit along its ray, and the nearest and
// farthest surface under a box of pixels (from blocks of kBlock x kBlock, so a box asks a few).
class DepthLimit {
 public:
  static constexpr int kBlock = 8;
  DepthLimit(const OpaqueDepth& depth, const PixelRays& rays);
  // How far along pixel (i, j)'s ray (from its origin, as Ray's t) the volume is seen.
  double t_max(int i, int j) const {
    return static_cast<double>(depth_.at(i, j)) * rays_.length_per_depth(i + 0.5, j + 0.5);
  }
  // The nearest and farthest surface depth over the pixels of `box` (a superset's: whole blocks).
  struct Range {
    float nearest = std::numeric_limits<float>::infinity(), farthest = 0.0f;
  };
  Range range(const PixelBox& box) const;
  // Whether some pixel has a surface: without one the frame is drawn as if there were no depth.
  bool any() const { return any_; }

 private:
  const OpaqueDepth& depth_;
  const PixelRays& rays_;
  int blocks_x_ = 0, blocks_y_ = 0;
  std::vector<Range> blocks_;
  bool any_ = false;
};

// Where a cell whose vertices' view depths span [z_near, z_far] lies against the surfaces under
// its pixels: wholly in front (drawn as usual), wholly behind (not drawn), or cut by one (its
// pixels' rays integrated up to the surface).
enum class DepthSide { in_front, behind, cut };
inline DepthSide side_of(double z_near, double z_far, const DepthLimit::Range& r) {
  if (z_far <= r.nearest) return DepthSide::in_front;
  if (z_near >= r.farthest) return DepthSide::behind;
  return DepthSide::cut;
}

}  // namespace cellproj
