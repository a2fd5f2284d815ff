#pragma once
// Writing meshes: VTK XML (.vtu, through VTK) and the classic sorting-benchmark text (.off).
#include <string>

#include "grid/mesh.hpp"

namespace cellproj {

// Writes every point field; binary, zlib-compressed. Throws InputError when it cannot.
void write_vtu(const Mesh& mesh, const std::string& path);
// Tetrahedra only, with one field as the scalar.
void write_off(const Mesh& mesh, const std::string& field, const std::string& path);

}  // namespace cellproj
