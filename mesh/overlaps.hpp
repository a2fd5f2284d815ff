#pragma once
// Cells whose interiors overlap: inverted cells folded through their neighbours, or a mesh that
// passes through itself (a crushed shell, ../shared/data's can.vtu). Where cells overlap, no
// back-to-front order of whole cells is right, so projection cannot be; the exact ray integrator
// still is. Found over the cells' canonical tetrahedra (mesh/tetrahedralize): candidate pairs by
// CGAL's box intersection, then a separating-axis test.
#include <cstdint>

#include "mesh/mesh.hpp"

namespace cellproj {

struct OverlapReport {
  std::int64_t cell_pairs = 0;              // pairs of cells whose interiors overlap beyond rounding
  std::int64_t first_a = -1, first_b = -1;  // the pair with the lowest ids, for messages
  std::int64_t candidates = 0;              // tetrahedron pairs whose boxes meet (the test's work)
};

// Two tetrahedra overlap when no plane separates them: none of their 4 + 4 face normals and 6 x 6
// edge cross products has them on opposite sides, within 1e-9 of their size (touching at a face,
// an edge or a vertex is not overlapping). O(t log t + candidates) in the tetrahedra.
OverlapReport overlapping_cells(const MeshView& mesh);

}  // namespace cellproj
