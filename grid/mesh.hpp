#pragma once
// The mesh model: double-precision points, cells in flat arrays (connectivity, offsets, VTK type
// codes) and named point fields. `MeshView` is the non-owning form every algorithm takes, so a
// solver can hand over its own arrays without copying.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "grid/cell_type.hpp"

namespace cellproj {

// A non-owning view over a caller's arrays. Nothing is copied; the arrays must outlive the view.
struct MeshView {
  const double* points = nullptr;           // x y z per point
  std::int64_t n_points = 0;
  const std::int64_t* connectivity = nullptr;
  const std::int64_t* offsets = nullptr;    // n_cells + 1 entries; cell c is [offsets[c], offsets[c+1])
  const std::uint8_t* types = nullptr;      // VTK codes: 10 tetra, 11 voxel, 12 hexahedron, 13 wedge, 14 pyramid
  std::int64_t n_cells = 0;
  const double* scalar = nullptr;           // one value per point (may be null for geometry-only use)
  std::string source;                       // named in error messages (a file, or "solver arrays")
  std::string field;                        // the scalar's name, for messages

  CellType type(std::int64_t c) const { return static_cast<CellType>(types[c]); }
  const std::int64_t* cell(std::int64_t c) const { return connectivity + offsets[c]; }
  int cell_size(std::int64_t c) const { return static_cast<int>(offsets[c + 1] - offsets[c]); }
  glm::dvec3 point(std::int64_t p) const { return {points[3 * p], points[3 * p + 1], points[3 * p + 2]}; }
};

struct PointField {
  std::string name;
  std::vector<double> values;  // one per point
  std::string origin;          // how it was made: "point data", "cell data, volume-weighted", ...
};

class Mesh {
 public:
  std::string source;                 // the file it came from
  std::vector<double> points;         // x y z per point
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets{0};
  std::vector<std::uint8_t> types;
  std::vector<PointField> fields;
  std::vector<std::string> notes;     // what reading did to the data (conversions, skipped cells)

  std::int64_t n_points() const { return static_cast<std::int64_t>(points.size() / 3); }
  std::int64_t n_cells() const { return static_cast<std::int64_t>(types.size()); }
  std::int64_t add_point(const glm::dvec3& p);
  void add_cell(CellType type, const std::int64_t* ids);
  void add_cell(CellType type, std::initializer_list<std::int64_t> ids) { add_cell(type, ids.begin()); }

  const PointField* find_field(const std::string& name) const;
  // The field, or an InputError that names the mesh and lists the fields that do exist.
  const PointField& field(const std::string& name) const;
  PointField& add_field(std::string name, std::string origin);

  MeshView view() const;
  MeshView view(const std::string& field_name) const;
};

// Merges points with bit-identical coordinates (the duplicated interface points of the pieces of a
// parallel file), keeping the first point's field values; returns how many were removed.
std::int64_t merge_coincident_points(Mesh& mesh);

}  // namespace cellproj
