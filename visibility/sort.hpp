#pragma once
// Visibility ordering (MWSC section 3): the cells of a mesh back to front for one view, so that
// compositing them in that order with "over" is right. One `VisibilitySorter` is prepared per mesh
// (face planes, centroids, boundary faces) and sorts any number of views.
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "base/huge_pages.hpp"
#include "mesh/geometry.hpp"
#include "mesh/mesh.hpp"
#include "mesh/topology.hpp"
#include "view/camera.hpp"
#include "visibility/methods.hpp"

namespace cellproj {

// A visibility cycle met by the topological sort: the cells of one strongly connected component
// (at most kMaxCycleCells listed), and the cell whose remaining relations were dropped to go on.
struct VisibilityCycle {
  static constexpr std::size_t kMaxCycleCells = 32;
  std::int64_t size = 0;            // cells in the component
  std::vector<std::int64_t> cells;  // the first kMaxCycleCells of them
  std::int64_t broken_at = -1;      // the cell emitted early
  std::int64_t relations_dropped = 0;
  bool across_gap = false;  // a relation across a gap lies inside it (not only face relations)
};

struct SortStats {
  SortMethod method = SortMethod::centroid;    // the method that ran (auto resolved)
  std::int64_t face_relations = 0;             // relations across shared faces
  std::int64_t gap_relations = 0;              // relations across gaps between boundary faces, distinct
  GapMethod gaps_from = GapMethod::automatic;  // overlaps or abuffer: what found them (mpvo-abuffer)
  std::int64_t gap_pair_tests = 0;      // pairs of faces tested for a gap between them (overlaps; varies with threads)
  std::int64_t gap_face_crossings = 0;  // of those, pairs passing through each other in depth (overlaps)
  std::int64_t pair_relations = 0;      // relations from pairwise occlusion tests
  std::int64_t abuffer_fragments = 0;   // pixel centres covered by boundary faces in the A-buffer
  std::int64_t abuffer_runs = 0;        // runs of them, one per face and row: the A-buffer's work
  std::int64_t abuffer_crossings = 0;   // stretches of a row where faces cross in depth, sampled per pixel
  std::vector<VisibilityCycle> cycles;
  std::vector<std::pair<std::string, double>> phase_seconds;  // in the order they ran
  double seconds = 0.0;                                       // the whole sort
};
// Each counter the report shows, with its key (render/report.hpp): f(key, value).
template <class F>
void each_counter(const SortStats& s, F&& f) {
  f("face_relations", s.face_relations), f("gap_relations", s.gap_relations), f("gap_pair_tests", s.gap_pair_tests);
  f("abuffer_runs", s.abuffer_runs), f("cycles", static_cast<std::int64_t>(s.cycles.size()));
}

struct SortResult {
  std::vector<std::int64_t> order;  // every cell once, back to front (empty when relations_only)
  SortStats stats;
  bool relations_only = false;  // the relations were handed back to be ordered by subsets (ViewRelations)
};

// The relations across shared faces for one view, without their order: for sorting subsets of the
// cells apart, each image tile its own (visibility/subset_order.hpp). Given only where they are
// the whole order (mpvo on a convex mesh, no quad split beside whole cells).
struct ViewRelations {
  FrameBuffer<std::uint8_t> ahead, behind;     // per cell: bit k, the cell across face k comes after / before it
  const std::int32_t* across = nullptr;        // per cell face: the cell across it (the sorter's: it outlives this)
  const std::int64_t* face_offsets = nullptr;  // where cell c's faces start (4 c for tetrahedra alone)
  bool tetrahedra = false;
  std::int64_t first_face(std::int64_t c) const { return tetrahedra ? 4 * c : face_offsets[c]; }
};

// The view a sort is for: the camera (eye point in perspective, direction in orthographic) and
// the image whose pixel centres the A-buffer samples (the rasterizer's, so the picture is right).
struct SortView {
  Camera camera;
  int width = 512, height = 512;
  // Orders the A-buffer's lists at every pixel centre instead of once per stretch of a row covered
  // by the same faces: the same relations, slower; the reference the sweep is tested against.
  bool abuffer_every_pixel = false;
  GapMethod gaps = GapMethod::automatic;  // every_pixel implies abuffer
};

class VisibilitySorter {
 public:
  // The mesh's arrays and the topology must outlive the sorter. The hull report
  // (boundary_convexity) decides what `automatic` runs, and which boundary faces can bound a gap.
  // `points` (recentre(mesh)) may be shared with other users of the same points; made when null.
  // A mesh made by splitting cells of another (mesh/face_split) may name that mesh's sorter
  // (`whole`, sharing `points`) and each cell's parent there: the face planes between cells that
  // stayed whole are copied from it instead of computed again.
  VisibilitySorter(const MeshView& mesh, const FaceTopology& topology, const HullReport& hull,
                   std::shared_ptr<const RecentredPoints> points = nullptr, const VisibilitySorter* whole = nullptr,
                   const std::vector<std::int64_t>* parent = nullptr);
  ~VisibilitySorter();
  VisibilitySorter(VisibilitySorter&&) noexcept;

  // With `relations` given, where the method is mpvo on a convex mesh with no split quad: those
  // relations filled and no order (SortResult::relations_only), for the caller to order by subsets.
  SortResult sort(SortMethod method, const SortView& view, ViewRelations* relations = nullptr) const;

  std::int64_t cells() const;
  bool convex_boundary() const;
  // Whether no view can make a visibility cycle: a Delaunay tetrahedralization (a convex mesh whose
  // every shared face is locally Delaunay, ties allowed; Edelsbrunner's acyclicity theorem), so that any order its face
  // relations allow, every tile's own among them, composites the same picture. Checked on first
  // call (exact predicates: 0.3 s for 1.08M Delaunay tetrahedra on 2 cores); false for other cells.
  bool acyclic() const;

  struct Prepared;  // face planes, centroids and boundary faces, recentred (visibility/prepared.hpp)

 private:
  std::unique_ptr<Prepared> p_;
};

}  // namespace cellproj
