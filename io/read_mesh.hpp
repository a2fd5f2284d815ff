#pragma once
// Reading meshes: the format is chosen by extension (overridable), every reader goes through the
// real library for its format, and every failure is an InputError naming the file.
#include <optional>
#include <string>
#include <vector>

#include "mesh/cell_data.hpp"
#include "mesh/mesh.hpp"
#include "mesh/validate.hpp"

namespace cellproj {

struct ReadOptions {
  std::string format;  // "" = by extension; else one of known_formats()
  std::string q_file;  // PLOT3D solution; default: the grid's name with "xyz" replaced by "q"
  std::string zone;    // CGNS: read this zone only (default: all zones)
  int time_step = 0;   // Exodus II: which time step's fields
  // Cell data (mesh/cell_data.hpp): drawn constant over each cell (the default: a finite-volume
  // solver's cells as it computed them) or averaged to the points; none: kept as cell fields (info).
  std::optional<CellData> cell_data = CellData::cells;
  // Read in a child process (io/isolated_read.hpp), so that a reader's crash on a malformed file
  // is an InputError; its memory is bounded by max_memory_gib (0: the memory available now).
  bool isolate = true;
  double max_memory_gib = 0;
};

// The format names accepted in ReadOptions::format, with the extensions that select them.
std::vector<std::pair<std::string, std::string>> known_formats();
std::string format_for(const std::string& path);  // by extension; throws InputError if unknown

// Reads the file as stored (no validation). A trailing ".gz" is decompressed first.
Mesh read_mesh(const std::string& path, const ReadOptions& options = {});

// read_mesh, then validate (errors throw) and re-orient inverted cells.
LoadedMesh load_mesh(const std::string& path, const ReadOptions& options = {});
}  // namespace cellproj
class vtkDataObject;
namespace cellproj {
// The same for a VTK data object in memory (an unstructured or structured grid, a multiblock or
// partitioned collection: assembled as the readers assemble a file's), named `source` in messages;
// the object is read, not kept. What Python's from_vtk takes, so that it gives read()'s mesh.
LoadedMesh load_vtk_object(vtkDataObject* data, const std::string& source, const ReadOptions& options = {});
// The version of the VTK cellproj was built with ("9.1.0"): a VTK object from another cannot be read.
std::string vtk_library_version();

// One reader per file family (io/read_*.cpp); `path` is the file to open, `name` the one to
// report in messages.
Mesh read_vtk_family(const std::string& path, const std::string& format, const ReadOptions& options);
Mesh assemble_vtk_object(vtkDataObject* data, const std::string& source);
Mesh read_tetgen(const std::string& path);
Mesh read_off(const std::string& path);
Mesh read_point_cloud(const std::string& path);

}  // namespace cellproj
