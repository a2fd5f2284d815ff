#pragma once
// The mesh model: points, cells in flat arrays (connectivity, offsets, VTK type codes) and named
// point fields. `MeshView` is the non-owning form every algorithm takes, so a solver can hand over
// its own arrays without copying; `Mesh` owns its arrays (what the readers make). A field holds one
// value per point or a vector or tensor of `components` values per point; mesh/field_choice.hpp
// picks the scalar a picture shows (a component, the magnitude, the von Mises stress).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/cell_type.hpp"

namespace cellproj {

// A caller's point coordinates as they are: float or double, x y z packed or every `stride` bytes
// (an array of structures, a column of a larger record). Read through operator(), never copied.
class PointArray {
 public:
  PointArray() = default;
  PointArray(const double* xyz) : data_(xyz), stride_(3 * sizeof(double)) {}  // NOLINT: packed doubles, implicitly
  PointArray(const float* xyz) : data_(xyz), stride_(3 * sizeof(float)), is_float_(true) {}  // NOLINT
  // x, y, z of point p at first + p * stride bytes (T: float or double); stride 0 means packed.
  template <class T>
  static PointArray strided(const T* first, std::ptrdiff_t stride_bytes) {
    PointArray a(first);
    if (stride_bytes != 0) a.stride_ = stride_bytes;
    return a;
  }

  glm::dvec3 operator()(std::int64_t p) const {
    const char* at = static_cast<const char*>(data_) + p * stride_;
    if (is_float_) {
      const float* f = reinterpret_cast<const float*>(at);
      return {f[0], f[1], f[2]};
    }
    const double* d = reinterpret_cast<const double*>(at);
    return {d[0], d[1], d[2]};
  }
  bool empty() const { return data_ == nullptr; }

 private:
  const void* data_ = nullptr;
  std::ptrdiff_t stride_ = 0;
  bool is_float_ = false;
};

// A non-owning view over a caller's arrays. Nothing is copied; the arrays must outlive the view.
// Point ids are 64-bit here; render/volume.hpp takes 32-bit ones too (widening them once).
struct MeshView {
  PointArray points;  // x y z per point
  std::int64_t n_points = 0;
  const std::int64_t* connectivity = nullptr;
  const std::int64_t* offsets = nullptr;  // n_cells + 1 entries; cell c is [offsets[c], offsets[c+1])
  const std::uint8_t* types = nullptr;    // VTK codes: 10 tetra, 11 voxel, 12 hexahedron, 13 wedge, 14 pyramid
  std::int64_t n_cells = 0;
  std::string source;  // named in error messages (a file, or "solver arrays")

  CellType type(std::int64_t c) const { return static_cast<CellType>(types[c]); }
  const std::int64_t* cell(std::int64_t c) const { return connectivity + offsets[c]; }
  int cell_size(std::int64_t c) const { return static_cast<int>(offsets[c + 1] - offsets[c]); }
  glm::dvec3 point(std::int64_t p) const { return points(p); }
};

struct PointField {
  std::string name;
  std::vector<double> values;  // `components` per point, interleaved (x y z x y z ... for a vector)
  std::string origin;          // how it was made: "point data", "cell data, volume-weighted", ...
  int components = 1;
  bool per_cell = false;  // cell data drawn constant over each cell (mesh/cell_data.hpp): no iso-value inside a cell

  bool scalar() const { return components == 1; }
  const double* tuple(std::int64_t p) const { return values.data() + p * components; }
  // Appends point p's tuple of `from` (a field with as many components).
  void append_tuple(const PointField& from, std::int64_t p) {
    values.insert(values.end(), from.tuple(p), from.tuple(p) + components);
  }
};

// `f` with only the tuples of `points`, in that order (a sub-mesh's field).
PointField gather(const PointField& f, const std::vector<std::int64_t>& points);

class Mesh {
 public:
  std::string source;          // the file it came from
  std::vector<double> points;  // x y z per point
  std::vector<std::int64_t> connectivity;
  std::vector<std::int64_t> offsets{0};
  std::vector<std::uint8_t> types;
  std::vector<PointField> fields;
  // Cell data as read, one tuple per cell (mesh/cell_data.hpp makes point fields of them; a loaded
  // mesh has none left).
  std::vector<PointField> cell_fields;
  std::vector<std::string> notes;  // what reading did to the data (conversions, skipped cells)

  std::int64_t n_points() const { return static_cast<std::int64_t>(points.size() / 3); }
  std::int64_t n_cells() const { return static_cast<std::int64_t>(types.size()); }
  std::int64_t add_point(const glm::dvec3& p);
  void add_cell(CellType type, const std::int64_t* ids);
  void add_cell(CellType type, std::initializer_list<std::int64_t> ids) { add_cell(type, ids.begin()); }

  const PointField* find_field(const std::string& name) const;
  // The field, or an InputError that names the mesh and lists the fields that do exist.
  const PointField& field(const std::string& name) const;
  PointField& add_field(std::string name, std::string origin, int components = 1);  // zeros

  MeshView view() const;
};

// Merges points with bit-identical coordinates (the duplicated interface points of the pieces of a
// parallel file), keeping the first point's field values; returns how many were removed.
std::int64_t merge_coincident_points(Mesh& mesh);

}  // namespace cellproj
