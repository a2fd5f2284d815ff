#pragma once
// Sizes in messages: "3.2 GiB", or "12.5 MiB" below a tenth of a GiB (where "0.0 GiB" says nothing).
#include <cstdint>
#include <cstdio>
#include <string>

namespace cellproj {

inline std::string format_bytes(std::uint64_t bytes) {
  char buf[32];
  if (bytes < (1ull << 30) / 10)
    std::snprintf(buf, sizeof buf, "%.1f MiB", double(bytes) / double(1ull << 20));
  else
    std::snprintf(buf, sizeof buf, "%.1f GiB", double(bytes) / double(1ull << 30));
  return buf;
}

}  // namespace cellproj
