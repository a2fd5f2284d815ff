#include "slicing/cut_table.hpp"

#include <vector>

namespace cellproj {
namespace {

struct BuiltTable {
  CutTable table;
  std::vector<CutCase> cases;
};

int edge_index(BuiltTable& t, int a, int b) {
  for (int e = 0; e < t.table.n_edges; ++e) {
    const CellEdge& x = t.table.edges[e];
    if ((x.a == a && x.b == b) || (x.a == b && x.b == a)) return e;
  }
  t.table.edges[t.table.n_edges] = {static_cast<std::uint8_t>(a), static_cast<std::uint8_t>(b)};
  return t.table.n_edges++;
}

// Going around each face, the plane is crossed downwards (above to below) and upwards in turn; the
// section's boundary runs inside the face from a downward crossing to the next upward one. An edge
// shared by two faces is crossed upwards in one and downwards in the other (they run it in opposite
// directions), so these links join the crossed edges into closed polygons.
CutCase cut_case(const BuiltTable& t, const CellDef& def, const int face_edges[][4], unsigned mask) {
  int next[kMaxCellEdges];
  bool crossed[kMaxCellEdges] = {};
  for (int f = 0; f < def.faces; ++f) {
    const FaceDef& face = def.face[f];
    int order[4], n = 0;  // the face's crossed edges in its cyclic order, as +edge (up) or ~edge (down)
    for (int i = 0; i < face.size; ++i) {
      const bool below_a = mask >> face.v[i] & 1u, below_b = mask >> face.v[(i + 1) % face.size] & 1u;
      if (below_a != below_b) order[n++] = below_a ? face_edges[f][i] : ~face_edges[f][i];
    }
    for (int i = 0; i < n; ++i) {
      if (order[i] >= 0) continue;  // a downward crossing links to the next upward one
      for (int j = 1; j < n; ++j) {
        const int up = order[(i + j) % n];
        if (up >= 0) {
          next[~order[i]] = up, crossed[~order[i]] = crossed[up] = true;
          break;
        }
      }
    }
  }
  CutCase c;
  bool used[kMaxCellEdges] = {};
  int k = 0;
  for (int start = 0; start < t.table.n_edges; ++start) {
    if (!crossed[start] || used[start]) continue;
    int size = 0;
    for (int e = start; !used[e]; e = next[e]) used[e] = true, c.edge[k++] = static_cast<std::uint8_t>(e), ++size;
    c.size[c.polygons++] = static_cast<std::uint8_t>(size);
  }
  return c;
}

BuiltTable build(CellType type) {
  BuiltTable t;
  const CellDef& def = cell_def(type);
  t.table.vertices = def.vertices;
  int face_edges[6][4];
  for (int f = 0; f < def.faces; ++f)
    for (int i = 0; i < def.face[f].size; ++i)
      face_edges[f][i] = edge_index(t, def.face[f].v[i], def.face[f].v[(i + 1) % def.face[f].size]);
  t.cases.resize(std::size_t{1} << def.vertices);
  for (unsigned mask = 0; mask < t.cases.size(); ++mask) t.cases[mask] = cut_case(t, def, face_edges, mask);
  t.table.cases = t.cases.data();
  return t;
}

}  // namespace

const CutTable& cut_table(CellType type) {
  static const BuiltTable tables[] = {build(CellType::Tetra), build(CellType::Voxel), build(CellType::Hexahedron),
                                      build(CellType::Wedge), build(CellType::Pyramid)};
  return tables[static_cast<int>(type) - static_cast<int>(CellType::Tetra)].table;
}

}  // namespace cellproj
