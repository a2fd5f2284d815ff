#pragma once
#include <string>

namespace cellproj {

// Checks what VTK's legacy reader follows without bounds, before it runs: the version line (a
// garbled one makes it read a format-5 file as the older layout) and, before format 5, the CELLS
// block, where each cell is a count and that many ids, `size` numbers in all; a count that runs
// past the block corrupts the reader's heap. Throws InputError naming the file and the cell.
void check_legacy_cells(const std::string& path);

}  // namespace cellproj
