#include "io/vtk_messages.hpp"

#include <algorithm>
#include <mutex>
#include <vector>

#include <vtkLogger.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

#include "base/error.hpp"

namespace cellproj {
namespace {

// Collects VTK's error and warning text.
class CaptureWindow : public vtkOutputWindow {
 public:
  static CaptureWindow* New();
  vtkTypeMacro(CaptureWindow, vtkOutputWindow) void DisplayText(const char* text) override {
    if (GetCurrentMessageType() == MESSAGE_TYPE_ERROR)
      errors.push_back(clean(text));
    else if (GetCurrentMessageType() != MESSAGE_TYPE_TEXT)
      warnings.push_back(clean(text));
  }
  std::vector<std::string> errors, warnings;

 private:
  // "ERROR: In file.cxx, line 12\nvtkReader (0x1): what\n\n" -> "what"
  static std::string clean(std::string t) {
    if (auto nl = t.find('\n'); t.rfind("ERROR", 0) == 0 || t.rfind("Warning", 0) == 0) t = t.substr(nl + 1);
    if (auto p = t.find("): "); p != std::string::npos && p < 80) t = t.substr(p + 3);
    while (!t.empty() && (t.back() == '\n' || t.back() == ' ')) t.pop_back();
    return t;
  }
};
vtkStandardNewMacro(CaptureWindow);

// VTK's output window and logger are process-wide, so the reads that swap them take turns: this
// lock is the one piece of process state cellproj keeps, and only for VTK's own.
std::mutex& vtk_output_lock() {
  static std::mutex m;
  return m;
}

}  // namespace

bool failed_request(const std::string& error) {
  return error.rfind("Algorithm ", 0) == 0 && error.find(" returned failure for request") != std::string::npos;
}

std::string vtk_error_text(const std::string& error) {
  if (!failed_request(error)) return error;
  // "Algorithm vtkUnstructuredGridReader(0x55..) returned failure for request: vtkInformation
  // (0x55..)" and the request's dump, nine lines: the class is all it says.
  const std::size_t from = 10, to = error.find_first_of("( ", from);
  return "VTK's " + error.substr(from, to - from) + " failed without saying why";
}

struct VtkMessages::State {
  std::lock_guard<std::mutex> lock{vtk_output_lock()};
  vtkSmartPointer<vtkOutputWindow> previous{vtkOutputWindow::GetInstance()};
  vtkSmartPointer<CaptureWindow> window{vtkSmartPointer<CaptureWindow>::New()};
  vtkLogger::Verbosity verbosity{
      vtkLogger::GetCurrentVerbosityCutoff()};  // stderr's, the only sink unless the caller added one
};

VtkMessages::VtkMessages() : state_(std::make_unique<State>()) {
  vtkOutputWindow::SetInstance(state_->window);
  // Some readers (CGNS) also log through vtkLogger straight to stderr.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

VtkMessages::~VtkMessages() {
  vtkOutputWindow::SetInstance(state_->previous);
  vtkLogger::SetStderrVerbosity(state_->verbosity);
}

void VtkMessages::throw_if_failed(const std::string& path) const {
  const auto& errors = state_->window->errors;
  if (errors.empty()) return;
  // The reader's own words first: the pipeline's "returned failure" comes after them, if at all.
  const auto own = std::find_if(errors.begin(), errors.end(), [](const std::string& e) { return !failed_request(e); });
  std::string what = own != errors.end() ? *own : vtk_error_text(errors.front());
  if (errors.size() > 1) what += " (and " + std::to_string(errors.size() - 1) + " more VTK errors)";
  throw InputError(where(path, "cannot be read: " + what));
}

}  // namespace cellproj
