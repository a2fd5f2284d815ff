#include "tools/memory_budget.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace cellproj {

std::uint64_t estimate_render_bytes(const RenderFootprint& f) {
  const std::uint64_t pixels = static_cast<std::uint64_t>(f.width) * static_cast<std::uint64_t>(f.height);
  // Image: float RGBA, plus the copy kept for output; 8-bit PNG rows.
  std::uint64_t bytes = pixels * (16 * 2 + 4);
  // Per point: coordinates (twice: recentred), screen positions, optics or isoparametric data.
  bytes += static_cast<std::uint64_t>(f.points) * 120;
  // Per tetrahedron: connectivity, faces and neighbours, sorter planes and centroids (projection),
  // or the tracer's planes and tile bins (exact).
  bytes += static_cast<std::uint64_t>(f.tets) * (f.exact ? 400 : 320);
  return bytes + (64ull << 20);  // fragment and triangle buffers, thread stacks
}

std::uint64_t available_memory_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("MemAvailable:", 0) != 0) continue;
    std::istringstream s(line.substr(13));
    std::uint64_t kib = 0;
    s >> kib;
    return kib * 1024;
  }
  return 0;
}

std::string format_bytes(std::uint64_t bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f GiB", double(bytes) / double(1ull << 30));
  return buf;
}

}  // namespace cellproj
