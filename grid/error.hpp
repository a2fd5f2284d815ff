#pragma once
// Errors at the API boundary: every message names the input (file), the element and what is wrong.
#include <stdexcept>
#include <string>

namespace cellproj {

// Bad input: a malformed file, a bad cell, a missing field, a bad scene, camera or transfer function.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "FILE: what" (or just "what" when the source is unnamed, e.g. a caller's arrays).
inline std::string where(const std::string& source, const std::string& what) {
  return source.empty() ? what : source + ": " + what;
}

}  // namespace cellproj
