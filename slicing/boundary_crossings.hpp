#pragma once
// Where each pixel's ray crosses the mesh's boundary, as heights along the planes' normal: the
// boundary faces scan converted once per frame (internal to slicing/). A slab between two planes
// of which only one covers the pixel holds a boundary crossing; knowing its height gives the ray's
// length inside the mesh there exactly, instead of half the slab on average.
#include <array>
#include <cstdint>
#include <vector>

#include "mesh/mesh.hpp"
#include "slicing/slice_cut.hpp"

namespace cellproj {

using BoundaryTriangle = std::array<std::int64_t, 3>;

// The mesh's boundary faces (mesh/topology, seams glued) as triangles, quads split by their
// canonical diagonal.
std::vector<BoundaryTriangle> boundary_triangles(const MeshView& mesh);

class BoundaryCrossings {
 public:
  static constexpr int kMax = 6;  // crossings kept per pixel; a pixel with more keeps none

  // Triangles reaching behind the near plane (perspective) are left out: their pixels keep none.
  BoundaryCrossings(const std::vector<BoundaryTriangle>& triangles, const FramePoints& points, int width, int height);
  // The crossing of pixel `pixel` between heights lo < hi (ends included) nearest to hi (from_hi) or to
  // lo; infinity when it has none there, NaN when its crossings are not known (too many).
  double between(std::size_t pixel, double lo, double hi, bool from_hi) const;

 private:
  std::vector<float> h_;         // kMax per pixel, sorted
  std::vector<std::uint8_t> n_;  // per pixel (kMax + 1: too many)
};

}  // namespace cellproj
