#include "io/write_mesh.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkExodusIIWriter.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "base/error.hpp"
#include "base/file_status.hpp"

namespace fs = std::filesystem;

namespace cellproj {

namespace {

vtkSmartPointer<vtkUnstructuredGrid> to_vtk(const Mesh& mesh) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh.n_points());
  for (std::int64_t p = 0; p < mesh.n_points(); ++p) points->SetPoint(p, &mesh.points[3 * p]);
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto conn = vtkSmartPointer<vtkIdTypeArray>::New();
  for (auto o : mesh.offsets) offsets->InsertNextValue(o);
  for (auto c : mesh.connectivity) conn->InsertNextValue(c);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, conn);
  auto types = vtkSmartPointer<vtkUnsignedCharArray>::New();
  for (auto t : mesh.types) types->InsertNextValue(t);
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->SetCells(types, cells);
  for (const auto* list : {&mesh.fields, &mesh.cell_fields})
    for (const auto& f : *list) {
      auto a = vtkSmartPointer<vtkDoubleArray>::New();
      a->SetName(f.name.c_str());
      a->SetNumberOfComponents(f.components);
      a->SetNumberOfValues(static_cast<vtkIdType>(f.values.size()));
      for (std::size_t i = 0; i < f.values.size(); ++i) a->SetValue(static_cast<vtkIdType>(i), f.values[i]);
      vtkDataSetAttributes* data =
          list == &mesh.fields ? static_cast<vtkDataSetAttributes*>(grid->GetPointData()) : grid->GetCellData();
      data->AddArray(a);
    }
  return grid;
}

// The folder of `path` exists (it is made when missing) and the file can be opened for writing:
// VTK's writers report neither in their return value.
void check_writable(const std::string& path) {
  create_folders(fs::path(path).parent_path().string());
  if (path_is_folder(path)) throw InputError(where(path, "is a folder, not a file to write"));
  std::ofstream probe(path, std::ios::binary | std::ios::app);
  if (!probe) throw InputError(where(path, "cannot be written (" + std::string(std::strerror(errno)) + ")"));
}

// The scalar field `name` of `mesh`, for a format with one value per point.
const PointField& scalar_field(const Mesh& mesh, const std::string& name, const std::string& path) {
  const PointField& f = mesh.field(name);
  if (!f.scalar())
    throw InputError(where(path, "this format holds one value per point; field '" + name + "' has " +
                                     std::to_string(f.components) + " components (write a .vtu)"));
  return f;
}

template <class Writer>
void write_with(Writer* w, const Mesh& mesh, const std::string& path) {
  check_writable(path);
  w->SetFileName(path.c_str());
  w->SetInputData(to_vtk(mesh));
  if (!w->Write() || w->GetErrorCode() != 0) throw InputError(where(path, "write failed"));
}

}  // namespace

void write_vtu(const Mesh& mesh, const std::string& path) {
  auto w = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
  w->SetDataModeToAppended();
  w->SetCompressorTypeToZLib();
  write_with(w.Get(), mesh, path);
}

void write_vtk_legacy(const Mesh& mesh, const std::string& path, bool binary) {
  auto w = vtkSmartPointer<vtkUnstructuredGridWriter>::New();
  if (binary) w->SetFileTypeToBinary();
  write_with(w.Get(), mesh, path);
}

void write_exodus(const Mesh& mesh, const std::string& path) {
  auto w = vtkSmartPointer<vtkExodusIIWriter>::New();
  w->WriteAllTimeStepsOff();
  write_with(w.Get(), mesh, path);
}

void write_tetgen(const Mesh& mesh, const std::string& field, const std::string& path) {
  const PointField& f = scalar_field(mesh, field, path);
  const fs::path base = fs::path(path).replace_extension();
  check_writable(base.string() + ".node");
  std::ofstream node(base.string() + ".node"), ele(base.string() + ".ele");
  node.precision(17);
  node << mesh.n_points() << " 3 1 0\n";  // points, dimension, one attribute (the field), no markers
  for (std::int64_t p = 0; p < mesh.n_points(); ++p)
    node << p << ' ' << mesh.points[3 * p] << ' ' << mesh.points[3 * p + 1] << ' ' << mesh.points[3 * p + 2] << ' '
         << f.values[p] << '\n';
  ele << mesh.n_cells() << " 4 0\n";
  for (std::int64_t c = 0; c < mesh.n_cells(); ++c) {
    if (mesh.types[c] != static_cast<std::uint8_t>(CellType::Tetra))
      throw InputError(where(path, "TetGen's .ele holds tetrahedra only; cell " + std::to_string(c) + " is not one"));
    ele << c;
    for (std::int64_t k = mesh.offsets[c]; k < mesh.offsets[c + 1]; ++k) ele << ' ' << mesh.connectivity[k];
    ele << '\n';
  }
  if (!node || !ele) throw InputError(where(path, "write failed"));
}

void write_mesh(const Mesh& mesh, const std::string& path, bool binary) {
  const std::string ext = fs::path(path).extension().string();
  if (ext == ".vtu") return write_vtu(mesh, path);
  if (ext == ".vtk") return write_vtk_legacy(mesh, path, binary);
  if (ext == ".exo" || ext == ".e" || ext == ".ex2") return write_exodus(mesh, path);
  if (ext == ".off" || ext == ".node" || ext == ".ele") {
    if (mesh.fields.empty()) throw InputError(where(path, "this format needs a point field; the mesh has none"));
    return ext == ".off" ? write_off(mesh, mesh.fields.front().name, path)
                         : write_tetgen(mesh, mesh.fields.front().name, path);
  }
  throw InputError(where(path, "cannot write '" + ext + "' files; write .vtu, .vtk, .exo, .node (TetGen) or .off"));
}

void write_off(const Mesh& mesh, const std::string& field, const std::string& path) {
  const PointField& f = scalar_field(mesh, field, path);
  check_writable(path);
  std::ofstream out(path);
  out.precision(17);
  out << mesh.n_points() << ' ' << mesh.n_cells() << '\n';
  for (std::int64_t p = 0; p < mesh.n_points(); ++p)
    out << mesh.points[3 * p] << ' ' << mesh.points[3 * p + 1] << ' ' << mesh.points[3 * p + 2] << ' ' << f.values[p]
        << '\n';
  for (std::int64_t c = 0; c < mesh.n_cells(); ++c) {
    if (mesh.types[c] != static_cast<std::uint8_t>(CellType::Tetra))
      throw InputError(where(path, "the .off format holds tetrahedra only; cell " + std::to_string(c) + " is not one"));
    for (std::int64_t k = mesh.offsets[c]; k < mesh.offsets[c + 1]; ++k)
      out << mesh.connectivity[k] << (k + 1 < mesh.offsets[c + 1] ? ' ' : '\n');
  }
  if (!out) throw InputError(where(path, "write failed"));
}

}  // namespace cellproj
