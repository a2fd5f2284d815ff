#pragma once
// A cellproj mesh behind the Python module: numpy arrays taken as they are where cellproj can read
// them (kept alive here), or a mesh a reader made; committed once as a Volume.
#include <memory>
#include <string>
#include <vector>

#include <pybind11/numpy.h>

#include "render/volume.hpp"

namespace cellproj::python {

namespace py = pybind11;

class NumpyMesh {
 public:
  // Points (N, 3) float64 or float32 with rows at any stride; connectivity and offsets int64 or
  // int32 (int32 ids are widened once, in a copy); types uint8; scalars float64 (N,) or a dict
  // of them. Other dtypes and non-contiguous arrays are converted, and copies() says so.
  NumpyMesh(py::array points, py::array connectivity, py::array offsets, py::array types, py::object scalars,
            std::string source);
  explicit NumpyMesh(std::shared_ptr<const Mesh> read);  // from cellproj.read

  const Volume& volume() const { return *volume_; }
  const MeshView& view() const { return volume_->mesh(); }
  std::vector<std::string> field_names() const;
  Field field(const std::string& name) const;  // "" : the only one (InputError listing them otherwise)
  py::array field_array(const std::string& name, py::handle owner) const;  // read-only, no copy
  void add_field(const std::string& name, py::array values);
  std::vector<std::string> copies() const;  // what the module and the volume copied

 private:
  struct NamedField {
    std::string name;
    py::array_t<double> values;  // kept alive; empty for a read mesh's fields
    const double* data;
    std::int64_t size;
  };
  std::shared_ptr<const Mesh> read_;  // a reader's mesh, or null
  std::vector<py::array> keep_;       // the arrays the volume reads
  std::vector<NamedField> fields_;
  std::vector<std::string> conversions_;
  std::unique_ptr<Volume> volume_;
};

}  // namespace cellproj::python
