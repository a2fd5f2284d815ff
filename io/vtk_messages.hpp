#pragma once
// VTK's error and warning text while a file is read, collected so that a failure becomes one
// InputError naming the file instead of text on stderr (internal: not installed).
#include <memory>
#include <string>

namespace cellproj {

// While it lives, VTK's messages are collected; the caller's output window and logger verbosity
// come back afterwards. VTK's output window is process-wide, so the objects take turns (a lock).
class VtkMessages {
 public:
  VtkMessages();
  ~VtkMessages();
  VtkMessages(const VtkMessages&) = delete;
  VtkMessages& operator=(const VtkMessages&) = delete;

  // InputError "PATH: cannot be read: FIRST ERROR (and N more VTK errors)" when VTK reported an error.
  void throw_if_failed(const std::string& path) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Whether a VTK error is the pipeline's "Algorithm X(0x..) returned failure for request:
// vtkInformation ..." (with the request's nine-line dump), which follows a reader's own error or
// stands for one it did not give; vtk_error_text gives it as "VTK's X failed without saying why",
// and any other error as it is.
bool failed_request(const std::string& error);
std::string vtk_error_text(const std::string& error);

}  // namespace cellproj
