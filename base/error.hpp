#pragma once
// Errors at the API boundary. Everything cellproj throws on purpose derives from cellproj::Error,
// and every message names the input (file or arrays), the element and what is wrong.
#include <stdexcept>
#include <string>

namespace cellproj {

// The root: catch this to catch every error of the library.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Bad input: a malformed file, a bad cell, a missing field, a bad scene, camera, transfer function
// or render setting. The CLI exits 1.
class InputError : public Error {
 public:
  using Error::Error;
};

// A valid request this version does not draw yet (two settings that do not go together yet, a
// feature of one method asked of another): an InputError to the CLI (exit 1), Python's
// UnsupportedError.
class UnsupportedError : public InputError {
 public:
  using InputError::InputError;
};

// A resource the machine lacks: an OpenGL context, a back end not built in. The CLI exits 3.
class ResourceError : public Error {
 public:
  using Error::Error;
};

// A broken invariant of cellproj itself (a bug). The CLI exits 3.
class InternalError : public Error {
 public:
  using Error::Error;
};

// "FILE: what" (or just "what" when the source is unnamed, e.g. a caller's arrays).
inline std::string where(const std::string& source, const std::string& what) {
  return source.empty() ? what : source + ": " + what;
}

}  // namespace cellproj
