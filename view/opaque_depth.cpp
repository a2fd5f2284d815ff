#include "view/depth_limit.hpp"

#include <cmath>

#include "base/error.hpp"

namespace cellproj {

void check_opaque_depth(const OpaqueDepth& depth, int width, int height, const std::string& source) {
  if (depth.width != width || depth.height != height ||
      depth.z.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    throw InputError(source + ": the opaque depth is " + std::to_string(depth.width) + "x" +
                     std::to_string(depth.height) + " with " + std::to_string(depth.z.size()) + " values, the image " +
                     std::to_string(width) + "x" + std::to_string(height));
  for (std::size_t p = 0; p < depth.z.size(); ++p)
    if (!(depth.z[p] > 0.0f))
      throw InputError(source + ": the opaque depth at pixel (" + std::to_string(p % width) + ", " +
                       std::to_string(p / width) + ") is " + std::to_string(depth.z[p]) +
                       " (a view depth must be positive, or infinity where no surface is)");
}

DepthLimit::DepthLimit(const OpaqueDepth& depth, const PixelRays& rays) : depth_(depth), rays_(rays) {
  blocks_x_ = (depth.width + kBlock - 1) / kBlock, blocks_y_ = (depth.height + kBlock - 1) / kBlock;
  blocks_.resize(static_cast<std::size_t>(blocks_x_) * static_cast<std::size_t>(blocks_y_));
  for (int j = 0; j < depth.height; ++j)
    for (int i = 0; i < depth.width; ++i) {
      Range& b = blocks_[static_cast<std::size_t>(j / kBlock) * blocks_x_ + i / kBlock];
      const float z = depth.at(i, j);
      b.nearest = std::min(b.nearest, z), b.farthest = std::max(b.farthest, z);
      any_ = any_ || std::isfinite(z);
    }
}

DepthLimit::Range DepthLimit::range(const PixelBox& box) const {
  Range r;
  if (box.empty()) return r;
  for (int by = box.j0 / kBlock; by <= box.j1 / kBlock; ++by)
    for (int bx = box.i0 / kBlock; bx <= box.i1 / kBlock; ++bx) {
      const Range& b = blocks_[static_cast<std::size_t>(by) * blocks_x_ + bx];
      r.nearest = std::min(r.nearest, b.nearest), r.farthest = std::max(r.farthest, b.farthest);
    }
  return r;
}

}  // namespace cellproj
