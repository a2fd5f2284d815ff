#pragma once
// The header of a binary PLOT3D grid (xyz) file, read before VTK's reader sees the file: its
// layouts (byte order, Fortran record markers or none, one grid or several, float or double
// coordinates, IBLANK or none: those VTK's auto-detection tries) are matched against the file's
// size, so that a truncated or corrupt header is refused with a message instead of the reader
// allocating what it claims or reading past the file (docs/reliability.md).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/header_counts.hpp"

namespace cellproj {

// How a binary PLOT3D grid file is laid out, as VTK's reader detects it; its solution (q) file is
// read with the same byte order, records, grid count and precision.
struct Plot3dLayout {
  bool big_endian = false, records = false, multi_grid = false, iblank = false;
  int precision = 4, ndims = 3;
  std::vector<std::array<std::int64_t, 3>> dims;  // per grid; 1 in the third for a 2D grid
};

// The layout of the first layout whose data fills the file exactly, else of the first whose data
// fits in it (trailing bytes); nullopt for a text file. InputError naming the file when the file
// is binary and no layout fits (what the header declares, and the file's size).
std::optional<Plot3dLayout> plot3d_layout(const std::string& path);

// The solution (q) file of the grid laid out as `grid`: its header's grid count and dimensions must
// be the grid's, and its records (the 4 properties, then density, momentum and energy per grid)
// must fit in the file. InputError naming the q file and what is wrong, before VTK reads it.
void check_plot3d_q(const std::string& q, const Plot3dLayout& grid);

// The points and cells of the first layout whose data fills the file exactly, else of the first
// whose data fits in it (trailing bytes); nullopt for a text file. InputError naming the file when
// the file is binary and no layout fits (what the header declares, and the file's size).
std::optional<HeaderCounts> plot3d_counts(const std::string& path);

}  // namespace cellproj
