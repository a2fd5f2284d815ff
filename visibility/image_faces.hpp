#pragma once
// The boundary faces off the hull as one view's image sees them: what the two ways of finding the
// relations across gaps (the A-buffer, visibility/abuffer.cpp, and the faces' overlaps,
// visibility/overlap_gaps.cpp) start from. Internal to visibility/.
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "view/raster.hpp"
#include "visibility/prepared.hpp"

namespace cellproj {

// A boundary face in the image: its depth key as a plane over the image, its cell and its side.
struct ImageFace {
  double k0, kx, ky;     // key(x, y) = k0 + kx x + ky y grows with distance along the pixel's ray
  std::uint32_t tagged;  // 2 cell + 1 when the face is front-facing (the ray enters the mesh there)
  std::int64_t cell() const { return tagged >> 1; }
  bool entering() const { return tagged & 1u; }
};

// A boundary face off the hull as the image sees it: its triangle, the pixels of its bounding box,
// its depth key as a plane and the range of that key over the face.
struct ProjectedFace {
  glm::dvec2 s[3];
  PixelBox box;
  ImageFace face;
  double kmin, kmax;  // over the face, widened by `rounding`
  double rounding;    // of the key's plane at the image's pixel centres
};

// Slack for comparing keys a and b: twice the A-buffer's tolerance for level faces (in_front,
// visibility/abuffer.cpp).
inline double key_slack(double a, double b) { return 2e-9 * (std::abs(a) + std::abs(b)); }

// The boundary faces off the hull projected into the image (those that cover a pixel centre and
// lie wholly in front of the eye); with `cull`, only those that can bound a gap at a pixel centre.
// Parallel over points, then over faces (oneTBB).
std::vector<ProjectedFace> project_faces(const VisibilitySorter::Prepared& p, const ViewFrame& v, const SortView& view,
                                         bool cull);

}  // namespace cellproj
