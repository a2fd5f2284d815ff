#pragma once
// Where a plane cuts a cell (Yagel et al. 1996, the marching-cubes idea for one plane): for each
// cell type and each set of its vertices below the plane, the edges the plane crosses, in order
// around the section polygon. Built once from the cell's faces (mesh/cell_type), so it holds for
// every supported type.
#include <cstdint>

#include "mesh/cell_type.hpp"

namespace cellproj {

constexpr int kMaxCellEdges = 12;  // a hexahedron

struct CellEdge {
  std::uint8_t a, b;  // local vertex indices
};

// The section by a plane of a cell whose vertices in `mask` (bit v: vertex v) lie strictly below
// it: its polygons, each as the crossed edges in order around it. A convex cell with planar faces
// has one polygon (or none); more arise only for cells that are not, and are listed all the same.
struct CutCase {
  std::uint8_t polygons = 0;
  std::uint8_t size[4] = {};              // crossed edges of each polygon
  std::uint8_t edge[kMaxCellEdges] = {};  // local edge indices, polygon after polygon
};

struct CutTable {
  int vertices = 0;
  int n_edges = 0;
  CellEdge edges[kMaxCellEdges] = {};
  const CutCase* cases = nullptr;  // 1 << vertices entries, indexed by the mask
};
const CutTable& cut_table(CellType type);

}  // namespace cellproj
