#pragma once
// The size of a mesh file's content from its header alone, before anything is read, so that a
// file too large for memory (or a garbled count) is refused with a message instead of the reader
// allocating without bound.
#include <cstdint>
#include <string>

namespace cellproj {

struct HeaderCounts {
  std::int64_t points = 0, cells = 0;
};

// From the header of a VTK XML (.vtu, .vts: every Piece), legacy VTK (.vtk: POINTS and CELLS),
// TetGen (.node/.ele), classic netCDF Exodus (num_nodes, num_elem), binary PLOT3D grid (the layout
// its size admits) or .off file; {0, 0} for other formats or when the header does not say.
HeaderCounts header_counts(const std::string& path);

// The counts of a CGNS file (every zone of every base) or an Exodus file in either netCDF form, asked
// of the format's own library (VTK's CGNS, netCDF); {0, 0} for other formats. Those libraries may
// crash or call exit() on a garbled file: read_mesh asks this in the isolated reader's child, never
// in the caller's process. Throws InputError when the CGNS library cannot open the file.
HeaderCounts library_header_counts(const std::string& path, const std::string& format);

// Bytes to hold a mesh of these counts while it is read (the reader's arrays and our copy).
std::uint64_t estimate_mesh_bytes(const HeaderCounts& counts);

}  // namespace cellproj
