#include "mesh/validate.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include "base/error.hpp"
#include "mesh/geometry.hpp"

namespace cellproj {
namespace {

void check_cells(const MeshView& m) {
  UnsupportedCellTypes unsupported;
  for (std::int64_t c = 0; c < m.n_cells; ++c) {
    const std::uint8_t t = m.types[c];
    if (!is_supported(t)) {
      unsupported.add(t, c);
      continue;
    }
    const int expected = cell_def(static_cast<CellType>(t)).vertices;
    if (m.offsets[c + 1] - m.offsets[c] != expected)
      throw InputError(where(m.source, "cell " + std::to_string(c) + " (" + cell_name(m.type(c)) + ") has " +
                                           std::to_string(m.offsets[c + 1] - m.offsets[c]) + " vertices, expected " +
                                           std::to_string(expected)));
    const std::int64_t* ids = m.cell(c);
    for (int k = 0; k < expected; ++k)
      if (ids[k] < 0 || ids[k] >= m.n_points)
        throw InputError(where(m.source, "cell " + std::to_string(c) + " (" + cell_name(m.type(c)) +
                                             ") refers to point " + std::to_string(ids[k]) + ", out of range [0, " +
                                             std::to_string(m.n_points) + ")"));
  }
  unsupported.throw_if_any(m.source);
}

void check_points(const MeshView& m) {
  for (std::int64_t p = 0; p < m.n_points; ++p) {
    const glm::dvec3 x = m.point(p);
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(x[k]))
        throw InputError(where(m.source, "point " + std::to_string(p) + " has a non-finite coordinate (" + "xyz"[k] +
                                             " = " + std::to_string(x[k]) + ")"));
  }
}

// Every point of a group at the same place but its lowest id is a duplicate.
void count_duplicates(const MeshView& m, ValidationReport& r) {
  std::vector<std::int64_t> all(static_cast<std::size_t>(m.n_points));
  std::iota(all.begin(), all.end(), 0);
  const PointGroups groups = coincident_points(m, all);
  for (std::size_t g = 0; g + 1 < groups.start.size(); ++g) {
    r.duplicate_points += groups.start[g + 1] - groups.start[g] - 1;
    const std::int64_t second = groups.ids[groups.start[g] + 1];
    if (r.first_duplicate < 0 || second < r.first_duplicate) r.first_duplicate = second;
  }
}

}  // namespace

void UnsupportedCellTypes::throw_if_any(const std::string& source) const {
  if (types_.empty()) return;
  std::string what = "unsupported cell types:";
  for (const auto& [t, u] : types_)
    what += " " + vtk_type_name(t) + ": " + std::to_string(u.first) + " cells (first: cell " +
            std::to_string(u.second) + ");";
  what += " cellproj renders tetra, voxel, hexahedron, wedge and pyramid";
  throw InputError(where(source, what));
}

void check_finite(const std::string& source, const PointField& field) {
  for (std::size_t p = 0; p < field.values.size(); ++p)
    if (!std::isfinite(field.values[p]))
      throw InputError(where(source, "field '" + field.name + "' is not finite at point " + std::to_string(p) + " (" +
                                         std::to_string(field.values[p]) + ")"));
}

void check_offsets(const std::string& source, const std::int64_t* offsets, std::int64_t n_cells) {
  if (offsets[0] != 0) throw InputError(where(source, "offsets[0] must be 0"));
  for (std::int64_t c = 0; c < n_cells; ++c)
    if (offsets[c + 1] < offsets[c]) throw InputError(where(source, "offsets decrease at cell " + std::to_string(c)));
}

ValidationReport validate(const MeshView& m) {
  if (m.n_cells <= 0) throw InputError(where(m.source, "the mesh has no 3D cells"));
  check_offsets(m.source, m.offsets, m.n_cells);
  check_cells(m);
  check_points(m);

  ValidationReport r;
  r.volumes.resize(static_cast<std::size_t>(m.n_cells));
  tbb::parallel_for(std::int64_t(0), m.n_cells, [&](std::int64_t c) { r.volumes[c] = cell_signed_volume(m, c); });
  for (std::int64_t c = 0; c < m.n_cells; ++c) {
    const double v = r.volumes[c], size = cell_size(m, c);
    if (degenerate_volume(v, size)) {
      if (r.degenerate_cells++ == 0) r.first_degenerate = c;
    } else if (v < 0) {
      r.inverted.push_back(c);
    }
  }
  r.inverted_cells = static_cast<std::int64_t>(r.inverted.size());
  if (!r.inverted.empty()) r.first_inverted = r.inverted.front();
  count_duplicates(m, r);
  return r;
}

std::vector<std::string> ValidationReport::warnings(const std::string& source) const {
  std::vector<std::string> w;
  if (inverted_cells)
    w.push_back(where(source, std::to_string(inverted_cells) + " inverted cells (negative volume; first: cell " +
                                  std::to_string(first_inverted) + ") re-oriented"));
  if (degenerate_cells)
    w.push_back(where(source, std::to_string(degenerate_cells) + " degenerate cells (zero volume; first: cell " +
                                  std::to_string(first_degenerate) + ") contribute nothing"));
  if (duplicate_points)
    w.push_back(where(source, std::to_string(duplicate_points) + " duplicate points (first: point " +
                                  std::to_string(first_duplicate) +
                                  "): faces of cells joined only through them are matched by position (seams)"));
  return w;
}

std::int64_t reorient_inverted(Mesh& mesh, const ValidationReport& r) {
  return reorient_inverted(mesh.connectivity.data(), mesh.offsets.data(), mesh.types.data(), r);
}

std::int64_t reorient_inverted(std::int64_t* connectivity, const std::int64_t* offsets, const std::uint8_t* types,
                               const ValidationReport& r) {
  for (std::int64_t c : r.inverted) {
    std::int64_t* ids = connectivity + offsets[c];
    switch (static_cast<CellType>(types[c])) {
      case CellType::Tetra: std::swap(ids[1], ids[2]); break;
      case CellType::Pyramid: std::swap(ids[1], ids[3]); break;  // reverse the base
      case CellType::Wedge: std::swap_ranges(ids, ids + 3, ids + 3); break;
      case CellType::Hexahedron:
      case CellType::Voxel: std::swap_ranges(ids, ids + 4, ids + 4); break;
    }
  }
  return static_cast<std::int64_t>(r.inverted.size());
}

}  // namespace cellproj
