#include "slicing/slice_cells.hpp"

#include <glm/geometric.hpp>

#include "mesh/tetrahedralize.hpp"

namespace cellproj {
namespace {
constexpr double kFlatness = 1e-9;  // relative to the cell's size: planar and convex enough
}

bool cut_whole(const MeshView& mesh, const RecentredPoints& points, std::int64_t c) {
  const CellType type = mesh.type(c);
  if (type == CellType::Tetra) return true;
  const CellDef& def = cell_def(type);
  const std::int64_t* id = mesh.cell(c);
  glm::dvec3 p[8];
  glm::dvec3 lo = points(id[0]), hi = lo;
  for (int v = 0; v < def.vertices; ++v) p[v] = points(id[v]), lo = glm::min(lo, p[v]), hi = glm::max(hi, p[v]);
  const double tolerance = kFlatness * glm::length(hi - lo);
  for (int f = 0; f < def.faces; ++f) {
    const FaceDef& face = def.face[f];
    glm::dvec3 corner[4], centre(0.0);
    for (int i = 0; i < face.size; ++i) corner[i] = p[face.v[i]], centre += corner[i];
    centre /= face.size;
    const glm::dvec3 n = newell_normal(corner, face.size);
    const double len = glm::length(n);
    if (!(len > 0.0)) return false;
    const glm::dvec3 unit = n / len;
    // Every vertex on or inside the face's plane (the face's own: on it, so the face is planar).
    for (int v = 0; v < def.vertices; ++v)
      if (glm::dot(p[v] - centre, unit) > tolerance) return false;
    for (int i = 0; i < face.size; ++i)
      if (std::abs(glm::dot(corner[i] - centre, unit)) > tolerance) return false;
  }
  return true;
}

SliceCells slice_cells(const MeshView& mesh, const RecentredPoints& points, Tetrahedralize mode) {
  SliceCells s;
  s.ids.reserve(static_cast<std::size_t>(mesh.offsets[mesh.n_cells]));
  s.types.reserve(static_cast<std::size_t>(mesh.n_cells));
  auto add = [&](CellType type, const std::int64_t* id, int n) {
    s.ids.insert(s.ids.end(), id, id + n);
    s.offsets.push_back(static_cast<std::int64_t>(s.ids.size()));
    s.types.push_back(static_cast<std::uint8_t>(type));
  };
  for (std::int64_t c = 0; c < mesh.n_cells; ++c) {
    const bool whole = mode == Tetrahedralize::none || mesh.type(c) == CellType::Tetra ||
                       (mode == Tetrahedralize::problem && cut_whole(mesh, points, c));
    if (whole) {
      add(mesh.type(c), mesh.cell(c), mesh.cell_size(c));
      ++s.whole;
      continue;
    }
    Tet tets[kMaxTetsPerCell];
    for (int t = 0, n = canonical_tetrahedra(mesh, c, tets); t < n; ++t) add(CellType::Tetra, tets[t].data(), 4);
    ++s.split;
  }
  return s;
}

}  // namespace cellproj
