#pragma once
// Invariants of cellproj itself (pbrt-v4's CHECK and DCHECK): a broken one is a bug, reported as an
// InternalError naming the condition and the place, never a wrong picture.
// - CELLPROJ_CHECK(cond, what): always checked; for what is cheap next to the work around it.
// - CELLPROJ_DCHECK(cond, what): checked only in builds with CELLPROJ_DCHECKS (the sanitizer build
//   and the tests' -DCELLPROJ_DCHECK=ON), for invariants that cost a pass over a frame's data: a
//   visibility order a permutation, a finite image. In release builds the condition is not
//   evaluated (it is still compiled, so it cannot rot).
#include <string>

#include "base/error.hpp"

namespace cellproj {

[[noreturn]] inline void check_failed(const char* condition, const std::string& what, const char* file, int line) {
  throw InternalError(std::string(file) + ":" + std::to_string(line) + ": " + what + " (" + condition +
                      " does not hold)");
}

}  // namespace cellproj

#define CELLPROJ_CHECK(cond, what) \
  ((cond) ? static_cast<void>(0) : ::cellproj::check_failed(#cond, (what), __FILE__, __LINE__))

#if defined(CELLPROJ_DCHECKS)
#define CELLPROJ_DCHECK(cond, what) CELLPROJ_CHECK(cond, what)
#else
#define CELLPROJ_DCHECK(cond, what) static_cast<void>(sizeof((cond) ? 1 : 0))
#endif
