#pragma once
// Cell data (one value or tuple per cell, as finite-volume solvers write their cell averages)
// made into point fields the renderers take, one of two ways:
//  - cells: every cell keeps its own copies of its points, each carrying the cell's value, so the
//    field is constant over each cell and jumps at its faces. The faces between cells are seams,
//    matched by position (mesh/seams.cpp), so sorting and the gaps of non-convex meshes see the
//    mesh as it was. A constant over a segment is the case where the volume rendering integral is
//    simplest (MWSC: constant extinction), and every method integrates it exactly: the cells the
//    solver computed, as ParaView's projected tetrahedra draw cell scalars.
//  - points: each point takes the volume-weighted mean of the cells around it (a smooth field,
//    the values no longer the solver's).
// The point fields a mesh had are kept either way (with the cells apart, copied to each cell's points).
#include <optional>
#include <string>

#include "mesh/mesh.hpp"

namespace cellproj {

enum class CellData { cells, points };
CellData cell_data_from_name(const std::string& name);  // InputError naming setting 'cell-data'
const char* cell_data_name(CellData mode);

// The mesh's cell fields as point fields the `mode` way (nothing when it has none); `mesh.notes`
// says what was done.
void apply_cell_data(Mesh& mesh, CellData mode);

// Each cell with its own points (in connectivity order), the point fields copied to them and the
// cell fields made point fields constant over each cell.
Mesh cells_apart(const Mesh& mesh);

// One tuple per point of `field` (one tuple per cell of `mesh`): the volume-weighted mean of the
// cells around each point.
PointField cell_field_at_points(const Mesh& mesh, const PointField& field);

}  // namespace cellproj
