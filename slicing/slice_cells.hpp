#pragma once
// The cells slicing cuts, made once per mesh. A cell whose faces are planar and which is convex is
// cut whole: each plane gives one convex polygon. Any other cell (a warped quadrilateral face, a
// concave hexahedron) is cut as its canonical tetrahedra (mesh/tetrahedralize), which split each
// shared face as the neighbour does, so the sections of neighbours still meet edge to edge.
#include <cstdint>
#include <vector>

#include "mesh/geometry.hpp"
#include "mesh/mesh.hpp"
#include "visibility/methods.hpp"

namespace cellproj {

struct SliceCells {
  std::vector<std::int64_t> ids;  // the vertices of each slice cell, in its type's local order
  std::vector<std::int64_t> offsets{0};
  std::vector<std::uint8_t> types;  // CellType
  std::int64_t whole = 0;           // mesh cells cut whole
  std::int64_t split = 0;           // mesh cells cut as their canonical tetrahedra
  std::int64_t size() const { return static_cast<std::int64_t>(types.size()); }
};

// `points` are the mesh's, recentred (for the planarity and convexity tolerances). `mode` says
// which cells are cut as tetrahedra: problem, those not cut_whole(); all, every cell that is not a
// tetrahedron (slicing then renders the canonical tetrahedra's field, as exact with
// --interpolation canonical-tets); none, no cell (a warped face's section is then approximate).
SliceCells slice_cells(const MeshView& mesh, const RecentredPoints& points, Tetrahedralize mode);

// Whether cell c has planar faces and is convex, to 1e-9 of its size.
bool cut_whole(const MeshView& mesh, const RecentredPoints& points, std::int64_t c);

}  // namespace cellproj
