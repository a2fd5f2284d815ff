#pragma once
// The header of a binary PLOT3D grid (xyz) file, read before VTK's reader sees the file: its
// layouts (byte order, Fortran record markers or none, one grid or several, float or double
// coordinates, IBLANK or none: those VTK's auto-detection tries) are matched against the file's
// size, so that a truncated or corrupt header is refused with a message instead of the reader
// allocating what it claims or reading past the file (docs/reliability.md).
#include <optional>
#include <string>

#include "grid/header_counts.hpp"

namespace cellproj {

// The points and cells of the first layout whose data fills the file exactly, else of the first
// whose data fits in it (trailing bytes); nullopt for a text file. InputError naming the file when
// the file is binary and no layout fits (what the header declares, and the file's size).
std::optional<HeaderCounts> plot3d_counts(const std::string& path);

}  // namespace cellproj
