#pragma once
// Reading a file in a child process, so that a third-party reader that crashes, corrupts its heap,
// calls exit() or allocates without bound on a malformed file fails as an InputError naming the
// file, instead of taking the caller's process with it. See docs/reliability.md.
#include <cstdint>
#include <functional>
#include <string>

#include "mesh/mesh.hpp"

namespace cellproj {

struct Isolation {
  // Bytes of address space the child may add beyond the parent's at the fork (0: no limit). Not
  // applied under AddressSanitizer, whose shadow memory needs the whole address space.
  std::uint64_t memory_limit = 0;
  std::string limit_source;  // how the limit was set, for the message (the max-memory option)
};

// MemAvailable from /proc/meminfo, or 0 when it cannot be read.
std::uint64_t available_memory_bytes();

// Runs `read` in a forked child and returns the mesh it made, moved through a pipe. Errors the
// child throws come back as the same kind (InputError, ResourceError) with the same message; a
// child that dies (a signal, an exit without a result, the memory limit) becomes an InputError
// that names `path`, `reader` (e.g. "VTK's legacy reader") and how it died.
// One isolated read runs at a time per process (fork copies only the calling thread); a
// sanitizer build with other threads running reads in-process instead (docs/reliability.md).
Mesh read_isolated(const std::string& path, const std::string& reader, const Isolation& isolation,
                   const std::function<Mesh()>& read);

}  // namespace cellproj
