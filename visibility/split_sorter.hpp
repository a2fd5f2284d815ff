#pragma once
// Sorting a mixed mesh whose quadrilateral faces may be warped (MWSC sections 3 and 4): per view
// the problem cells (mesh/face_split) are split into their canonical tetrahedra and the resulting
// mesh is sorted, so that the cycles and wrong orders made by folded faces do not arise.
// Visibility cycles that still involve whole cells split those cells too, and the view is sorted
// once more.
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "mesh/face_split.hpp"
#include "mesh/topology.hpp"
#include "visibility/methods.hpp"
#include "visibility/sort.hpp"

namespace cellproj {

// Where a camera looks from, in the frame of points recentred on `centre` (RecentredPoints): what
// CellFolds::problem_cells takes.
Viewpoint viewpoint(const Camera& camera, const glm::dvec3& centre);

// A mesh ready to sort: its cells (possibly some of them split), face topology, boundary convexity.
struct SortableMesh {
  SplitMesh split;  // the cells when some were split; empty otherwise
  MeshView cells;
  FaceTopology topology;
  std::shared_ptr<const BoundaryHull> boundary_hull;  // the mesh's, shared by its split meshes
  HullReport hull;
  std::unique_ptr<VisibilitySorter> sorter;
  std::vector<char> problem;  // per original cell, what was split (problem mode)
  std::int64_t parent(std::int64_t c) const { return split.parent.empty() ? c : split.parent[c]; }
};

struct ViewOrder {
  std::shared_ptr<const SortableMesh> mesh;  // whose cells `sorted.order` lists
  SortResult sorted;
  std::int64_t problem_cells = 0;  // cells a ray may cross more than twice in this view (problem and none modes)
  std::int64_t cycle_splits = 0;   // whole cells split further because they were in a visibility cycle
};

class SplittingSorter {
 public:
  // The mesh's arrays must outlive the sorter.
  SplittingSorter(const MeshView& mesh, Tetrahedralize mode);
  ~SplittingSorter();
  // Thread-safe; the last view's split mesh is kept and reused while the problem cells stay the same.
  // `relations`: as VisibilitySorter::sort's, where no cell folds in this view (none split).
  ViewOrder sort(SortMethod method, const SortView& view, ViewRelations* relations = nullptr) const;
  Tetrahedralize mode() const { return mode_; }
  const RecentredPoints& points() const { return *points_; }
  // The mesh sorted when no cell needs splitting (the input mesh, or all its cells split).
  const SortableMesh& base() const;

 private:
  std::shared_ptr<const SortableMesh> split_for(const std::vector<char>& problem) const;
  std::shared_ptr<const SortableMesh> base_mesh() const;

  MeshView mesh_;
  Tetrahedralize mode_;
  std::shared_ptr<const RecentredPoints> points_;  // shared with every sorter it prepares
  std::unique_ptr<const CellFolds> folds_;         // the cells' inward folds (not in mode all)
  mutable std::mutex mutex_;
  mutable std::shared_ptr<const SortableMesh> base_;  // also the topology and hull each split patches
  mutable std::shared_ptr<const SortableMesh> last_;  // the last view's split mesh
  mutable std::shared_ptr<const BoundaryHull> hull_;  // the boundary's hull, from the first mesh prepared
};

// Prepares a mesh for sorting: topology, convexity, sorter (and the split, when `which` is given);
// `points` are the mesh's recentred points and `hull` its boundary's convex hull when the caller
// has them (every split of the mesh shares both). A split given the prepared unsplit mesh `whole`
// patches its topology (mesh/split_topology) and copies the face planes of the cells left whole
// from it, and shares its hull.
std::shared_ptr<SortableMesh> sortable_mesh(const MeshView& mesh, const std::vector<char>* which,
                                            std::shared_ptr<const RecentredPoints> points = nullptr,
                                            std::shared_ptr<const BoundaryHull> hull = nullptr,
                                            const SortableMesh* whole = nullptr);

}  // namespace cellproj
