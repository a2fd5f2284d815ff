#pragma once
// Writing meshes: VTK XML (.vtu), legacy VTK (.vtk) and Exodus II through VTK, TetGen's .node/.ele
// and the classic sorting-benchmark text (.off). Every writer makes a missing folder and throws
// InputError naming the file when it cannot write.
#include <string>

#include "mesh/mesh.hpp"

namespace cellproj {

// Writes every point field; binary, zlib-compressed. Throws InputError when it cannot.
void write_vtu(const Mesh& mesh, const std::string& path);
// Tetrahedra only, with one field as the scalar.
void write_off(const Mesh& mesh, const std::string& field, const std::string& path);
void write_vtk_legacy(const Mesh& mesh, const std::string& path, bool binary);
void write_exodus(const Mesh& mesh, const std::string& path);
// BASE.node (the field as its one attribute) and BASE.ele; tetrahedra only.
void write_tetgen(const Mesh& mesh, const std::string& field, const std::string& path);
// By extension: .vtu, .vtk (`binary` or ASCII), .exo/.e/.ex2, .node/.ele, .off (the first field).
void write_mesh(const Mesh& mesh, const std::string& path, bool binary = false);

}  // namespace cellproj
