#pragma once
// Points and their point fields from a VTK polydata file (.vtp), for point-cloud input.
#include <string>

#include "mesh/mesh.hpp"

namespace cellproj {
Mesh read_vtk_points(const std::string& path);
}
