#include "mesh/cell_data.hpp"

#include <cmath>

#include "base/error.hpp"
#include "mesh/geometry.hpp"

namespace cellproj {

CellData cell_data_from_name(const std::string& name) {
  if (name == "cells") return CellData::cells;
  if (name == "points") return CellData::points;
  throw InputError("setting 'cell-data': expected cells or points, got '" + name + "'");
}

const char* cell_data_name(CellData mode) { return mode == CellData::cells ? "cells" : "points"; }

PointField cell_field_at_points(const Mesh& mesh, const PointField& f) {
  const MeshView view = mesh.view();
  const int nc = f.components;
  const std::size_t n = static_cast<std::size_t>(mesh.n_points());
  std::vector<double> sum(n * nc, 0.0), plain(n * nc, 0.0), weight(n, 0.0), count(n, 0.0);
  for (std::int64_t c = 0; c < mesh.n_cells(); ++c) {
    const double volume = is_supported(mesh.types[c]) && view.cell_size(c) == cell_def(view.type(c)).vertices
                              ? std::abs(cell_signed_volume(view, c))
                              : 0.0;
    const double* v = f.tuple(c);
    for (std::int64_t k = mesh.offsets[c]; k < mesh.offsets[c + 1]; ++k) {
      const std::int64_t p = mesh.connectivity[k];
      if (p < 0 || p >= mesh.n_points()) continue;  // validation reports it
      for (int i = 0; i < nc; ++i) sum[p * nc + i] += volume * v[i], plain[p * nc + i] += v[i];
      weight[p] += volume;
      count[p] += 1;
    }
  }
  PointField out{f.name, std::vector<double>(n * nc, 0.0), f.origin + ", volume-weighted average at points", nc};
  for (std::size_t p = 0; p < n; ++p)
    for (int i = 0; i < nc; ++i)
      out.values[p * nc + i] = weight[p] > 0  ? sum[p * nc + i] / weight[p]
                               : count[p] > 0 ? plain[p * nc + i] / count[p]
                                              : 0.0;
  return out;
}

Mesh cells_apart(const Mesh& mesh) {
  // The copies of each point numbered together, in the order of the points they copy, so that a
  // face's corners keep their order on both sides of a seam: a warped quad is split by the
  // diagonal from its lowest id (mesh/face_split.hpp), the same diagonal from either cell.
  const std::vector<std::int64_t>& corner_point = mesh.connectivity;
  std::vector<std::int64_t> first(static_cast<std::size_t>(mesh.n_points()) + 1, 0);
  for (std::int64_t p : corner_point) ++first[p + 1];
  for (std::size_t p = 1; p < first.size(); ++p) first[p] += first[p - 1];
  Mesh out;
  out.source = mesh.source;
  out.notes = mesh.notes;
  out.offsets = mesh.offsets;
  out.types = mesh.types;
  out.connectivity.resize(corner_point.size());
  std::vector<std::int64_t> copied(corner_point.size()), cell_of(corner_point.size());  // per new point
  for (std::int64_t c = 0; c < mesh.n_cells(); ++c)
    for (std::int64_t k = mesh.offsets[c]; k < mesh.offsets[c + 1]; ++k) {
      const std::int64_t id = first[corner_point[k]]++;
      out.connectivity[k] = id;
      copied[id] = corner_point[k], cell_of[id] = c;
    }
  out.points.reserve(copied.size() * 3);
  for (std::int64_t p : copied) out.points.insert(out.points.end(), &mesh.points[3 * p], &mesh.points[3 * p] + 3);
  for (const PointField& f : mesh.fields) out.fields.push_back(gather(f, copied));
  for (const PointField& f : mesh.cell_fields) {
    PointField g = gather(f, cell_of);
    g.origin += ", constant over each cell";
    g.per_cell = true;
    out.fields.push_back(std::move(g));
  }
  return out;
}

void apply_cell_data(Mesh& mesh, CellData mode) {
  if (mesh.cell_fields.empty()) return;
  std::string names;
  for (const PointField& f : mesh.cell_fields) names += (names.empty() ? "'" : ", '") + f.name + "'";
  if (mode == CellData::points) {
    for (const PointField& f : mesh.cell_fields) mesh.fields.push_back(cell_field_at_points(mesh, f));
    mesh.cell_fields.clear();
    mesh.notes.push_back("cell fields " + names +
                         " averaged to the points, volume-weighted (setting 'cell-data' cells keeps them constant "
                         "over each cell)");
    return;
  }
  const std::int64_t before = mesh.n_points();
  mesh = cells_apart(mesh);
  mesh.notes.push_back("cell fields " + names + " drawn constant over each cell: each cell has its own points (" +
                       std::to_string(mesh.n_points()) + " for " + std::to_string(before) +
                       "), its faces matched by position (setting 'cell-data' points averages them instead)");
}

}  // namespace cellproj
