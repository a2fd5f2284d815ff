#pragma once
// View-dependent splitting of non-planar faces (MWSC section 4, figure 3). A quadrilateral face is
// split by the diagonal from its lowest-index vertex (mesh/tetrahedralize). Seen from a viewpoint,
// the two triangles of a warped face may turn opposite ways: the face is folded in this view, and
// on the side where the diagonal folds inward a ray can leave the cell through one triangle and
// enter it again through the other, so that whole cell has no one place in a visibility order.
// Those are the problem cells (also cells bent inward at one of their own edges, seen along it);
// only they are split into their canonical tetrahedra, for this view.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/geometry.hpp"
#include "mesh/mesh.hpp"

namespace cellproj {

// Where a view is from, in the frame of a RecentredPoints: the eye (perspective) or the direction
// the view looks along (orthographic).
struct Viewpoint {
  bool perspective = false;
  glm::dvec3 eye{0.0};
  glm::dvec3 dir{0.0, 0.0, -1.0};  // unit
};

// The inward folds of every cell's surface (its quads split by the diagonal from their lowest id):
// pairs of its triangles that share an edge at a reflex dihedral angle, found once per mesh,
// parallel over cells (oneTBB); pairs too near flat for doubles are kept and decided by the exact
// test (CGAL) in a view where they lie on the contour. A ray crosses a cell's surface more
// than twice only across a fold on the contour (figure 3's warped diagonal, or a cell bent at one
// of its own edges), so per view only the folds' two triangles are tested.
class CellFolds {
 public:
  // The mesh's arrays must outlive it; points = recentre(mesh).
  CellFolds(const MeshView& mesh, std::shared_ptr<const RecentredPoints> points);
  // Per cell: 1 when the cell is not a tetrahedron and, seen from `view`, one of its folds lies on
  // the contour (its two triangles face opposite ways), or one of its vertices is not in front of
  // the eye or its plane (such a cell is ray cast through its tetrahedra). Parallel over cells.
  std::vector<char> problem_cells(const Viewpoint& view, std::int64_t* count = nullptr) const;
  std::int64_t folds() const { return static_cast<std::int64_t>(folds_.size()); }

  struct Fold {
    std::uint8_t t[3], u[3];  // the two triangles, as the cell's own vertex indices
    std::uint8_t far;         // u's vertex off the shared edge
    bool unsure;              // too near flat for doubles: reflex only if the exact test says so
  };

 private:
  MeshView mesh_;
  std::shared_ptr<const RecentredPoints> points_;
  std::vector<std::int64_t> start_;  // per cell: its folds from start_[c] to start_[c + 1]
  std::vector<Fold> folds_;
};

// A mesh whose chosen cells are replaced by their canonical tetrahedra, over the original mesh's
// points and field (which must outlive it). Conforming, since both cells of a face split it alike.
struct SplitMesh {
  std::vector<std::int64_t> connectivity, offsets{0};
  std::vector<std::uint8_t> types;
  std::vector<std::int64_t> parent;  // per cell: the cell of the original mesh it is (part of)
  std::int64_t cells_split = 0;      // original cells replaced
  MeshView view;                     // over these arrays
};
// `which` (per cell, 1: split) may be empty: then every cell that is not a tetrahedron is split.
SplitMesh split_cells(const MeshView& mesh, const std::vector<char>& which);

}  // namespace cellproj
