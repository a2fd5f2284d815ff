#pragma once
// Checks what VTK's XML reader trusts in a file's appended data before it runs: each appended
// DataArray's block header (its byte count, or the compressor's block count, block sizes and
// compressed sizes) against the end of the file, against what deflate can expand to (at most 1032
// bytes per byte), and, where the Piece says how many points or cells there are, against the size
// the array needs. A garbled header otherwise makes the reader allocate what it claims or read
// past the file (docs/reliability.md). Throws InputError naming the file, the array and what is wrong.
#include <string>

namespace cellproj {

void check_vtk_xml_appended(const std::string& path);

// A structured file's (.vts, .vtr, .vti) pieces must cover its WholeExtent: VTK's reader leaves the
// points no piece holds undefined. Throws InputError naming the file and the extent.
void check_vtk_xml_extents(const std::string& path);

}  // namespace cellproj
