#include "grid/write_mesh.hpp"

#include <cstdio>
#include <fstream>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "base/error.hpp"

namespace cellproj {

void write_vtu(const Mesh& mesh, const std::string& path) {
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
  for (const auto& f : mesh.fields) {
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(f.name.c_str());
    a->SetNumberOfValues(static_cast<vtkIdType>(f.values.size()));
    for (std::size_t i = 0; i < f.values.size(); ++i) a->SetValue(static_cast<vtkIdType>(i), f.values[i]);
    grid->GetPointData()->AddArray(a);
  }
  auto w = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
  w->SetFileName(path.c_str());
  w->SetInputData(grid);
  w->SetDataModeToAppended();
  w->SetCompressorTypeToZLib();
  if (!w->Write()) throw InputError(where(path, "cannot write"));
}

void write_off(const Mesh& mesh, const std::string& field, const std::string& path) {
  const PointField& f = mesh.field(field);
  std::ofstream out(path);
  if (!out) throw InputError(where(path, "cannot write"));
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
