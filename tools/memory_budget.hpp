#pragma once
// Memory a render will need, estimated before anything large is allocated, so that a request
// beyond the machine is refused with a message instead of the process being killed. Each renderer
// estimates its own frame (Renderer::estimate_bytes); this adds reading the mesh.
#include <cstdint>
#include <string>

#include "grid/isolated_read.hpp"  // available_memory_bytes

namespace cellproj {

// Points and cells of a VTK XML file (.vtu, .vts) read from its header alone, before the file is
// loaded; {0, 0} for other formats or when the header does not say.
struct HeaderCounts {
  std::int64_t points = 0, cells = 0;
};
HeaderCounts vtk_xml_header_counts(const std::string& path);

// Bytes to hold a mesh of these counts while it is read (the reader's arrays and our copy).
std::uint64_t estimate_mesh_bytes(const HeaderCounts& counts);

// Throws InputError, prefixed with `source`, when `need` bytes exceed the limit: `max_memory_gib`
// when positive, else the memory available now. `what` names the work ("rendering 512x512 ...").
void refuse_beyond_memory(std::uint64_t need, double max_memory_gib, const std::string& what,
                          const std::string& source);

// "3.2 GiB"
std::string format_bytes(std::uint64_t bytes);

}  // namespace cellproj
