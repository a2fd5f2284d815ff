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

// MemAvailable from /proc/meminfo, or 0 when it cannot be read.
std::uint64_t available_memory_bytes();

// "3.2 GiB"
std::string format_bytes(std::uint64_t bytes);

}  // namespace cellproj
