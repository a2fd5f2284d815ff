#pragma once
// Memory a render will need, estimated before anything large is allocated, so that a request
// beyond the machine is refused with a message instead of the process being killed. Each renderer
// estimates its own frame (Renderer::estimate_bytes); this adds reading the mesh.
#include <cstdint>
#include <string>

#include "base/bytes.hpp"
#include "io/header_counts.hpp"
#include "io/isolated_read.hpp"  // available_memory_bytes

namespace cellproj {

// Throws InputError, prefixed with `source`, when `need` bytes exceed the limit: `max_memory_gib`
// when positive, else the memory available now. `what` names the work ("rendering 512x512 ..."),
// `remedy` what the user can do about it.
void refuse_beyond_memory(std::uint64_t need, double max_memory_gib, const std::string& what, const std::string& source,
                          const std::string& remedy = "use a smaller --size or mesh");

}  // namespace cellproj
