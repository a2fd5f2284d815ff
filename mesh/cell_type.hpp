#pragma once
// The linear 3D cell types cellproj renders, with VTK's type codes and local vertex numbering.
#include <cstdint>
#include <string>

namespace cellproj {

enum class CellType : std::uint8_t { Tetra = 10, Voxel = 11, Hexahedron = 12, Wedge = 13, Pyramid = 14 };

// One face of a cell: 3 or 4 local vertex indices, ordered so the normal (right-hand rule) points out
// of a positively oriented cell.
struct FaceDef {
  std::uint8_t size;
  std::uint8_t v[4];
};

struct CellDef {
  const char* name;
  int vertices;
  int faces;
  const FaceDef* face;
};

bool is_supported(std::uint8_t vtk_type);
const CellDef& cell_def(CellType type);
inline const char* cell_name(CellType type) { return cell_def(type).name; }
// A readable name for any VTK cell type code, supported or not ("quadratic_tetra (24)").
std::string vtk_type_name(int vtk_type);
// Dimension of a VTK cell type (0..3), or -1 when unknown.
int vtk_type_dimension(int vtk_type);

}  // namespace cellproj
