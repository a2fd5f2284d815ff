#pragma once
// Checks what VTK's XML reader trusts in a file before it runs, from the file's XML header:
// - each appended DataArray's block header (its byte count, or the compressor's block count, block
//   sizes and compressed sizes) against the end of the file, against what deflate can expand to
//   (at most 1032 bytes per byte), and, where the Piece says how many points or cells there are
//   (or a rectilinear piece's extent, its axes' coordinates), against the size the array needs. A
//   garbled header otherwise makes the reader allocate what it claims or read past the file;
// - a structured file's (.vts, .vtr, .vti) extents, each six integers running from low to high, and
//   its pieces against its WholeExtent, which they must cover
//   (VTK's reader leaves the points no piece holds undefined), and a rectilinear piece's ASCII axes
//   against its extent.
// Throws InputError naming the file, the array or extent and what is wrong (docs/reliability.md).
#include <string>

namespace cellproj {

void check_vtk_xml(const std::string& path);

}  // namespace cellproj
