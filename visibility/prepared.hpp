#pragma once
// What a VisibilitySorter prepares once per mesh, and the pieces each sort is built from.
// Internal to visibility/.
#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

#include <glm/vec3.hpp>

#include "base/huge_pages.hpp"
#include "mesh/geometry.hpp"
#include "visibility/sort.hpp"

namespace cellproj {

constexpr std::uint8_t kNoLocalFace = 255;

struct VisibilitySorter::Prepared {
  MeshView mesh;
  const FaceTopology* topo = nullptr;
  bool convex = false;
  std::shared_ptr<const RecentredPoints> points;  // coordinates below are relative to points->centre
  std::vector<glm::dvec3> centroid;               // per cell
  // Shared faces, each once: cells a and b, the face's unit normal outward from a, and its plane
  // offset (normal . x on the face; a quad's at its centroid).
  std::vector<std::int32_t> face_a, face_b;
  std::vector<glm::dvec3> normal;
  std::vector<double> offset;
  std::vector<std::int64_t> face_start;        // per cell: the shared faces it makes start here (n + 1)
  std::vector<std::uint8_t> local_a, local_b;  // per shared face: its index among face_a's / face_b's faces
                                               // (local_b kNoLocalFace: face_b's side is a split quad)
  std::vector<std::int32_t> across;            // per cell face (topology order): the cell across a shared face, or -1
  std::vector<std::int32_t> split_faces;       // the shared faces whose face_b side is a split quad
  bool all_tetrahedra = false;                 // then cell c's faces start at 4 c
  mutable std::once_flag acyclic_checked;      // VisibilitySorter::acyclic, on its first call
  mutable bool acyclic = false;
  // Boundary faces off the convex hull as triangles (quads split by the diagonal from their lowest
  // id), outward, over the points they use (indices into boundary_point, so that a view projects
  // each point once).
  std::vector<std::int64_t> boundary_cell;
  std::vector<std::array<std::uint32_t, 3>> boundary_tri;
  std::vector<std::int64_t> boundary_point;

  glm::dvec3 point(std::int64_t p) const { return (*points)(p); }
  // Shared face f's ids turning with its normal, when it is a triangle (false for a quad): made
  // from face_a's cell when needed (the rare face nearly in line with the eye) instead of stored.
  bool face_triangle(std::size_t f, std::int64_t tri[3]) const;
};

// The view in the recentred frame: the eye, the view direction, and how far each cell is.
struct ViewFrame {
  bool perspective = false;
  glm::dvec3 eye{0.0}, dir{0.0, 0.0, -1.0};
  double eye_scale = 1.0;  // |eye| plus the mesh's extent: the scale of plane tests in perspective
  Camera camera;           // recentred
  // Larger is farther: distance along the view direction (orthographic), squared distance from the eye (perspective).
  double far_key(const glm::dvec3& p) const {
    const glm::dvec3 d = p - eye;
    return perspective ? d.x * d.x + d.y * d.y + d.z * d.z : d.x * dir.x + d.y * dir.y + d.z * dir.z;
  }
};
ViewFrame view_frame(const VisibilitySorter::Prepared& p, const SortView& view);

// Relations "a is composited before b" (a behind b), as a successor list per cell.
struct Relations {
  FrameBuffer<std::int64_t> start;  // n + 1
  FrameBuffer<std::int64_t> to;
  // Sorts and deduplicates (from, to) pairs into the lists; returns how many distinct pairs.
  std::int64_t build(std::int64_t n, std::vector<std::pair<std::int64_t, std::int64_t>>& pairs);
};

// The relations across shared faces for one view, laid out for the topological sort: bit k of
// ahead[c] is set when the cell across c's k-th face comes after c; in[c] counts the cells that
// must come before c. A face seen exactly edge-on makes no relation.
struct FaceOrder {
  FrameBuffer<std::uint8_t> ahead;   // fresh every view (base/huge_pages.hpp)
  FrameBuffer<std::uint8_t> behind;  // bit k: the cell across face k comes before (kept when asked: ViewRelations)
  FrameBuffer<std::int32_t> in;
  Relations split;  // from a cell with a split quad to the tetrahedra across it (no bit on that side)
  std::int64_t relations = 0;
};
FaceOrder face_relations(const VisibilitySorter::Prepared& p, const ViewFrame& v, bool behind = false);
// Relations across the gaps of a non-convex mesh: visibility/image_faces.hpp.
// Relations from pairwise occlusion tests between every two cells whose projections overlap.
Relations pairwise_relations(const VisibilitySorter::Prepared& p, const ViewFrame& v, const SortView& view,
                             SortStats& stats);
// Cells by centroid depth, far first (LSD radix sort on the float keys).
std::vector<std::int64_t> centroid_order(const VisibilitySorter::Prepared& p, const ViewFrame& v);

// Kahn's topological sort (in-counts and a FIFO queue, O(n + relations)) over the face relations
// and extra relation lists; when it stalls, the visibility cycles are found (strongly connected
// components), reported, and broken at their farthest cell; a cycle holding a relation of `gaps`
// is marked across_gap. Consumes faces.in.
std::vector<std::int64_t> topological_order(const VisibilitySorter::Prepared& p, const ViewFrame& v, FaceOrder& faces,
                                            const std::vector<const Relations*>& extra, SortStats& stats,
                                            const Relations* gaps = nullptr);

class PhaseClock {
 public:
  explicit PhaseClock(SortStats& s) : stats_(s), t_(std::chrono::steady_clock::now()) {}
  void lap(const char* phase) {
    const auto now = std::chrono::steady_clock::now();
    stats_.phase_seconds.emplace_back(phase, std::chrono::duration<double>(now - t_).count());
    t_ = now;
  }
  // A phase timed apart (one of two that ran side by side); restart() then skips their time.
  void add(const char* phase, double seconds) { stats_.phase_seconds.emplace_back(phase, seconds); }
  void restart() { t_ = std::chrono::steady_clock::now(); }

 private:
  SortStats& stats_;
  std::chrono::steady_clock::time_point t_;
};

}  // namespace cellproj
