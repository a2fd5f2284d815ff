#pragma once
// Synthetic meshes made by cellproj itself: structured boxes and curvilinear grids (hexahedra, or
// their canonical tetrahedra), for the default scene, the tests and the benchmarks.
#include <cmath>
#include <functional>
#include <string>

#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"

namespace cellproj {

// An nx x ny x nz grid of cells over the unit cube mapped through `map`; hexahedra, or each
// hexahedron split into its canonical tetrahedra (conforming, 6 per hexahedron).
Mesh make_curvilinear(int nx, int ny, int nz, const std::function<glm::dvec3(const glm::dvec3&)>& map, bool tetrahedra);
// The same grid with a conforming mix of cell types, by column of cells ((i + j) mod 3): hexahedra;
// two wedges per cell; four pyramids on the side faces and four tetrahedra on the top and bottom
// faces around a point added at the cell's centre.
Mesh make_mixed(int nx, int ny, int nz, const std::function<glm::dvec3(const glm::dvec3&)>& map);
// An axis-aligned box [lo, hi].
Mesh make_box(int nx, int ny, int nz, const glm::dvec3& lo, const glm::dvec3& hi, bool tetrahedra);
// The box [-1, 1]^3 in 2n cells per axis, thinning geometrically in x and y towards the z axis (the
// thinnest `first` wide), with a field "scalar" holding a hot filament of radius 0.004 along it: an
// adaptive mesh whose cells far below a pixel carry the picture (MWSC section 6).
Mesh make_graded(int n, double first, bool tetrahedra);
constexpr double kGradedFirstCell = 1e-4;  // about 1/50 of a pixel of a 512 x 512 frame of the box
// The field of `generate shells` at distance r from the centre: cos(3 pi r) inside the unit ball,
// -1 outside, so its iso-value 0 is the nested spheres r = 1/6, 1/2, 5/6 (a ray passing at distance
// b from the centre crosses it twice for each of them larger than b).
inline double shells_field(double r) { return r < 1.0 ? std::cos(3.0 * 3.14159265358979323846 * r) : -1.0; }
constexpr double kShellRadii[] = {1.0 / 6.0, 0.5, 5.0 / 6.0};
// Adds (or replaces) a point field f(x).
void set_field(Mesh& mesh, const std::string& name, const std::function<double(const glm::dvec3&)>& f);

// The named synthetic meshes of `cellproj generate` (see generated_kinds()); `n` is the resolution.
Mesh generate(const std::string& kind, int n);
std::string generated_kinds();

}  // namespace cellproj
