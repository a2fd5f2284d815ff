#pragma once
// The boundary faces off the hull as one view's image sees them: what the two ways of finding the
// relations across gaps (the A-buffer, visibility/abuffer.cpp, and the faces' overlaps,
// visibility/overlap_gaps.cpp) start from. Internal to visibility/.
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "base/huge_pages.hpp"
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

// A view's projected faces, written afresh every frame (huge_pages.hpp's FrameBuffer).
using ProjectedFaces = FrameBuffer<ProjectedFace>;

// Slack for comparing keys a and b: twice the A-buffer's tolerance for level faces (in_front,
// visibility/abuffer.cpp).
inline double key_slack(double a, double b) { return 2e-9 * (std::abs(a) + std::abs(b)); }

// The boundary faces off the hull projected into the image (those that cover a pixel centre and
// lie wholly in front of the eye); with `cull`, only those that can bound a gap at a pixel centre.
// Parallel over points, then over faces (oneTBB).
ProjectedFaces project_faces(const VisibilitySorter::Prepared& p, const ViewFrame& v, const SortView& view, bool cull);

// The (cell entered, cell left) pairs across gaps as they are found. The next stretches, rows and
// faces mostly pair the same two cells again: a small table of the pairs met lately keeps the list
// near its distinct size.
class GapPairs {
 public:
  std::vector<std::pair<std::int64_t, std::int64_t>> pairs;

  // Whether the pair is among those met lately (then it is in `pairs`).
  bool met(std::int64_t entered, std::int64_t left) const {
    return recent_[slot(key(entered, left))] == key(entered, left);
  }
  void add(std::int64_t entered, std::int64_t left) {
    const std::uint64_t k = key(entered, left);
    std::uint64_t& seen = recent_[slot(k)];
    if (seen == k) return;
    seen = k;
    pairs.emplace_back(entered, left);
  }

 private:
  static constexpr int kRecentBits = 12;
  static std::uint64_t key(std::int64_t entered, std::int64_t left) {
    return static_cast<std::uint64_t>(entered) << 32 | static_cast<std::uint64_t>(left);
  }
  static std::size_t slot(std::uint64_t k) { return (k * 0x9E3779B97F4A7C15ull) >> (64 - kRecentBits); }
  std::vector<std::uint64_t> recent_ = std::vector<std::uint64_t>(std::size_t(1) << kRecentBits, ~0ull);
};

// Relations across the gaps of a non-convex mesh between the faces of project_faces, from an
// A-buffer at the view's pixel centres (visibility/abuffer.cpp).
Relations gap_relations(const VisibilitySorter::Prepared& p, const ProjectedFaces& faces, const SortView& view,
                        SortStats& stats);
// The same from the overlaps of those faces (culled) in the image: a superset, true wherever rays
// go (visibility/overlap_gaps.cpp). Counts the pairs of faces that pass through each other; with
// stop_at_crossing, stops at the first (the relations are then incomplete).
Relations overlap_gap_relations(const VisibilitySorter::Prepared& p, const ProjectedFaces& faces, const SortView& view,
                                SortStats& stats, bool stop_at_crossing);

}  // namespace cellproj
