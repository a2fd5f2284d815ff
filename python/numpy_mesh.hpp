#pragma once
// A cellproj mesh behind the Python module: numpy arrays taken as they are where cellproj can read
// them (kept alive here), or a mesh a reader made; committed once as a Volume.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <pybind11/numpy.h>

#include "mesh/cell_data.hpp"
#include "render/field_set.hpp"
#include "render/volume.hpp"

namespace cellproj::python {

namespace py = pybind11;

// `a` marked read-only (a view of arrays the volume reads).
py::array read_only(py::array a);

class NumpyMesh {
 public:
  // Points (N, 3) float64 or float32 with rows at any stride; connectivity and offsets int64 or
  // int32 (int32 ids are widened once, in a copy); types uint8; scalars float64 (N,) or a dict
  // of them. Other dtypes and non-contiguous arrays are converted, and copies() says so.
  NumpyMesh(py::array points, py::array connectivity, py::array offsets, py::array types, py::object scalars,
            std::string source);
  // A reader's mesh (cellproj.read), validated there unless `trusted` is false.
  explicit NumpyMesh(std::shared_ptr<const Mesh> read, bool trusted = true);

  const Volume& volume() const { return *volume_; }
  const MeshView& view() const { return volume_->mesh(); }
  std::vector<FieldShape> field_shapes() const { return fields_.shapes(); }
  // The scalar `spec` chooses (mesh/field_choice.hpp); "": the only field.
  Field field(const std::string& spec) const { return fields_.scalar(spec, view().source); }
  // Read-only, no copy: a field as it is stored ((N,) or (N, k)), or the scalar a spec chooses.
  py::array field_array(const std::string& spec, py::handle owner) const;
  void add_field(const std::string& name, py::array values);  // (N,) or (N, k)
  std::vector<std::string> copies() const;                    // what the module and the volume copied
  // The points moved: the same cells over `points` (N, 3), taken as the constructor takes them,
  // validated; every preparation made again on the next render.
  void set_points(py::array points);
  // The points as x, y, z doubles, a copy (they may be float32 or strided in the caller's array).
  std::vector<double> point_coordinates() const;
  // The stored field a scalar choice reads ('V' of 'V:x'); "" the only one.
  std::string stored_name(const std::string& spec) const;

 private:
  std::shared_ptr<const Mesh> read_;         // a reader's mesh, or null
  std::vector<py::array> keep_;              // the arrays the volume reads
  py::array moved_points_;                   // set_points' array, which the volume reads instead
  std::map<std::string, py::array> arrays_;  // the caller's field arrays, kept alive
  FieldSet fields_;
  std::vector<std::string> conversions_;
  std::unique_ptr<Volume> volume_;
};

// A mesh copied from arrays as NumpyMesh takes them, with cell data (`cell_fields`: name -> (n,)
// or (n, k) per cell) made point fields the `cell_data` way (mesh/cell_data.hpp), validated as a
// read mesh is: what from_vtk and from_meshio hand over when the data has cell fields.
std::shared_ptr<const Mesh> mesh_with_cell_data(py::array points, py::array connectivity, py::array offsets,
                                                py::array types, const py::dict& point_fields,
                                                const py::dict& cell_fields, CellData cell_data, std::string source);

}  // namespace cellproj::python
