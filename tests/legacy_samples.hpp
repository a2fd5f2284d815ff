#pragma once
// Legacy .vtk text shared by the reader tests and the fuzz seeds.

namespace cellproj::test {

// A good structured grid whose point array is named field_strength: VTK 9.1's metadata pass took
// the name for a FIELD block and crashed (cellproj reads structured grids without that pass).
inline constexpr const char* kStructuredGridNamedField = R"(# vtk DataFile Version 3.0
sg
ASCII
DATASET STRUCTURED_GRID
DIMENSIONS 2 2 2
POINTS 8 float
0 0 0 1 0 0 0 1 0 1 1 0 0 0 1 1 0 1 0 1 1 1 1 1
POINT_DATA 8
SCALARS field_strength float 1
LOOKUP_TABLE default
0 1 2 3 4 5 6 7
)";

}  // namespace cellproj::test
