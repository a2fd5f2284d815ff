#pragma once
// Memory a render will need, estimated before anything large is allocated, so that a request
// beyond the machine is refused with a message instead of the process being killed.
#include <cstdint>
#include <string>

namespace cellproj {

struct RenderFootprint {
  std::int64_t width = 0, height = 0;
  std::int64_t points = 0, cells = 0;
  std::int64_t tets = 0;  // cells after the canonical split (an upper bound: 6 per hexahedron)
  bool exact = false;
};

// Bytes: the float image (and its copy), per-point and per-tetrahedron working arrays of the
// chosen renderer, and a fixed allowance for fragment buffers. Deliberately generous.
std::uint64_t estimate_render_bytes(const RenderFootprint& f);

// Points and cells of a VTK XML file (.vtu, .vts) read from its header alone, before the file is
// loaded; {0, 0} for other formats or when the header does not say.
struct HeaderCounts {
  std::int64_t points = 0, cells = 0;
};
HeaderCounts vtk_xml_header_counts(const std::string& path);

// Bytes to hold a mesh of these counts while it is read (the reader's arrays and our copy).
std::uint64_t estimate_mesh_bytes(const HeaderCounts& counts);

// MemAvailable from /proc/meminfo, or 0 when it cannot be read.
std::uint64_t available_memory_bytes();

// Throws InputError, prefixed with `source`, when `need` bytes exceed the limit: `max_memory_gib`
// when positive, else the memory available now. `what` names the work ("rendering 512x512 ...").
void refuse_beyond_memory(std::uint64_t need, double max_memory_gib, const std::string& what, const std::string& source);

// "3.2 GiB"
std::string format_bytes(std::uint64_t bytes);

}  // namespace cellproj
