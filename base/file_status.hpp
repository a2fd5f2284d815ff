#pragma once
// The file system's word on a path the user gave, as the API's errors: std::filesystem throws its
// own filesystem_error for a name too long, a loop of symbolic links or a folder it may not
// search, which would reach the caller unnamed (and the command line as an internal error).
#include <cctype>
#include <filesystem>
#include <string>
#include <system_error>

#include "base/error.hpp"

namespace cellproj {

// The status of `path` (not_found when nothing is there); any other failure to look it up is an
// InputError naming the path and the reason.
inline std::filesystem::file_status path_status(const std::string& path) {
  std::error_code ec;
  const std::filesystem::file_status s = std::filesystem::status(path, ec);
  if (ec && s.type() != std::filesystem::file_type::not_found)
    throw InputError(where(path, "cannot be looked up (" + ec.message() + ")"));
  return s;
}
inline bool path_exists(const std::string& path) { return std::filesystem::exists(path_status(path)); }
inline bool path_is_folder(const std::string& path) { return std::filesystem::is_directory(path_status(path)); }
inline bool path_is_file(const std::string& path) { return std::filesystem::is_regular_file(path_status(path)); }

// ".vtu" of "A.VTU": a path's extension in lower case, by which the readers and writers know a
// file's format.
inline std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// Creates folder `dir` and its parents where missing (nothing for ""); an InputError naming it
// when that fails (a file in the way, no permission, a name too long).
inline void create_folders(const std::string& dir) {
  if (dir.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !path_is_folder(dir))
    throw InputError(where(dir, "cannot create the folder" + (ec ? " (" + ec.message() + ")" : std::string())));
}

}  // namespace cellproj
