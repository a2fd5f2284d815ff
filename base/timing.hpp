#pragma once
// Wall time for the stats every stage reports (internal: not installed).
#include <chrono>

namespace cellproj {

inline double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace cellproj
