#pragma once
// Sizes in messages: "3.2 GiB".
#include <cstdint>
#include <cstdio>
#include <string>

namespace cellproj {

inline std::string format_bytes(std::uint64_t bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f GiB", double(bytes) / double(1ull << 30));
  return buf;
}

}  // namespace cellproj
