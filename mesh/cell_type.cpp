#include "mesh/cell_type.hpp"

#include "base/error.hpp"

namespace cellproj {
namespace {

// VTK local numbering; outward orientation checked against each type's positive reference cell.
constexpr FaceDef kTetraFaces[] = {{3, {0, 1, 3}}, {3, {1, 2, 3}}, {3, {2, 0, 3}}, {3, {0, 2, 1}}};
constexpr FaceDef kHexFaces[] = {{4, {0, 4, 7, 3}}, {4, {1, 2, 6, 5}}, {4, {0, 1, 5, 4}},
                                 {4, {3, 7, 6, 2}}, {4, {0, 3, 2, 1}}, {4, {4, 5, 6, 7}}};
// Voxel vertex i sits at (i&1, i>>1&1, i>>2&1): the hexahedron faces with 2<->3 and 6<->7 swapped.
constexpr FaceDef kVoxelFaces[] = {{4, {0, 4, 6, 2}}, {4, {1, 3, 7, 5}}, {4, {0, 1, 5, 4}},
                                   {4, {2, 6, 7, 3}}, {4, {0, 2, 3, 1}}, {4, {4, 5, 7, 6}}};
constexpr FaceDef kWedgeFaces[] = {
    {3, {0, 1, 2}}, {3, {3, 5, 4}}, {4, {0, 3, 4, 1}}, {4, {1, 4, 5, 2}}, {4, {2, 5, 3, 0}}};
constexpr FaceDef kPyramidFaces[] = {{4, {0, 3, 2, 1}}, {3, {0, 1, 4}}, {3, {1, 2, 4}}, {3, {2, 3, 4}}, {3, {3, 0, 4}}};

constexpr CellDef kTetra{"tetra", 4, 4, kTetraFaces};
constexpr CellDef kVoxel{"voxel", 8, 6, kVoxelFaces};
constexpr CellDef kHex{"hexahedron", 8, 6, kHexFaces};
constexpr CellDef kWedge{"wedge", 6, 5, kWedgeFaces};
constexpr CellDef kPyramid{"pyramid", 5, 5, kPyramidFaces};

struct VtkName {
  int code;
  const char* name;
  int dim;
};
constexpr VtkName kVtkNames[] = {
    {0, "empty_cell", 0},
    {1, "vertex", 0},
    {2, "poly_vertex", 0},
    {3, "line", 1},
    {4, "poly_line", 1},
    {5, "triangle", 2},
    {6, "triangle_strip", 2},
    {7, "polygon", 2},
    {8, "pixel", 2},
    {9, "quad", 2},
    {10, "tetra", 3},
    {11, "voxel", 3},
    {12, "hexahedron", 3},
    {13, "wedge", 3},
    {14, "pyramid", 3},
    {15, "pentagonal_prism", 3},
    {16, "hexagonal_prism", 3},
    {21, "quadratic_edge", 1},
    {22, "quadratic_triangle", 2},
    {23, "quadratic_quad", 2},
    {24, "quadratic_tetra", 3},
    {25, "quadratic_hexahedron", 3},
    {26, "quadratic_wedge", 3},
    {27, "quadratic_pyramid", 3},
    {28, "biquadratic_quad", 2},
    {29, "triquadratic_hexahedron", 3},
    {42, "polyhedron", 3},
    {68, "lagrange_curve", 1},
    {69, "lagrange_triangle", 2},
    {70, "lagrange_quadrilateral", 2},
    {71, "lagrange_tetrahedron", 3},
    {72, "lagrange_hexahedron", 3},
    {73, "lagrange_wedge", 3},
    {74, "lagrange_pyramid", 3},
};

}  // namespace

bool is_supported(std::uint8_t t) { return t >= 10 && t <= 14; }

const CellDef& cell_def(CellType type) {
  switch (type) {
    case CellType::Tetra: return kTetra;
    case CellType::Voxel: return kVoxel;
    case CellType::Hexahedron: return kHex;
    case CellType::Wedge: return kWedge;
    case CellType::Pyramid: return kPyramid;
  }
  throw InputError("not a supported cell type code " + std::to_string(static_cast<int>(type)));
}

std::string vtk_type_name(int vtk_type) {
  for (const auto& n : kVtkNames)
    if (n.code == vtk_type) return std::string(n.name) + " (" + std::to_string(vtk_type) + ")";
  return "unknown type (" + std::to_string(vtk_type) + ")";
}

int vtk_type_dimension(int vtk_type) {
  for (const auto& n : kVtkNames)
    if (n.code == vtk_type) return n.dim;
  return -1;
}

}  // namespace cellproj
