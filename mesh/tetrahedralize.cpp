#include "mesh/tetrahedralize.hpp"

#include <algorithm>

namespace cellproj {

void split_quad(const std::int64_t q[4], std::int64_t tri[2][3]) {
  const int k = static_cast<int>(std::min_element(q, q + 4) - q);
  const std::int64_t a = q[k], b = q[(k + 1) % 4], c = q[(k + 2) % 4], d = q[(k + 3) % 4];
  tri[0][0] = a;
  tri[0][1] = b;
  tri[0][2] = c;
  tri[1][0] = a;
  tri[1][1] = c;
  tri[1][2] = d;
}

int surface_triangles(const MeshView& mesh, std::int64_t c, std::int64_t out[kMaxSurfaceTriangles][3]) {
  return surface_triangles(mesh.cell(c), mesh.type(c), out);
}

int surface_triangles(const std::int64_t* ids, CellType type, std::int64_t out[kMaxSurfaceTriangles][3]) {
  const CellDef& def = cell_def(type);
  int n = 0;
  for (int f = 0; f < def.faces; ++f) {
    const FaceDef& face = def.face[f];
    std::int64_t q[4];
    for (int k = 0; k < face.size; ++k) q[k] = ids[face.v[k]];
    if (face.size == 3) {
      std::copy(q, q + 3, out[n++]);
      continue;
    }
    std::int64_t t[2][3];
    split_quad(q, t);
    std::copy(t[0], t[0] + 3, out[n++]);
    std::copy(t[1], t[1] + 3, out[n++]);
  }
  return n;
}

int canonical_tetrahedra(const MeshView& mesh, std::int64_t c, Tet out[kMaxTetsPerCell]) {
  return canonical_tetrahedra(mesh.cell(c), mesh.type(c), out);
}

int canonical_tetrahedra(const std::int64_t* ids, CellType type, Tet out[kMaxTetsPerCell]) {
  const CellDef& def = cell_def(type);
  if (def.vertices == 4) {
    out[0] = {ids[0], ids[1], ids[2], ids[3]};
    return 1;
  }
  const std::int64_t apex = *std::min_element(ids, ids + def.vertices);
  std::int64_t tri[kMaxSurfaceTriangles][3];
  const int ntri = surface_triangles(ids, type, tri);
  int n = 0;
  for (int t = 0; t < ntri; ++t) {
    if (tri[t][0] == apex || tri[t][1] == apex || tri[t][2] == apex) continue;
    // The face is outward, so its triangle turns clockwise seen from the apex: swap to make
    // (t0, t2, t1) counter-clockwise from the apex, VTK's positive orientation.
    out[n++] = {tri[t][0], tri[t][2], tri[t][1], apex};
  }
  return n;
}

}  // namespace cellproj
