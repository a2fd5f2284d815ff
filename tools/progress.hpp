#pragma once
// A progress bar on stderr for work that runs longer than a second, shown only when stderr is a
// terminal. Safe to call from worker threads.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

#include "io/read_mesh.hpp"

namespace cellproj {

class ProgressBar {
 public:
  explicit ProgressBar(std::string label)
      : label_(std::move(label)), enabled_(isatty(STDERR_FILENO) == 1), start_(std::chrono::steady_clock::now()) {}
  ~ProgressBar() { clear(); }
  // The bar's line erased (before a line of output; the next fraction draws it again).
  void clear() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (shown_) std::fprintf(stderr, "\r%*s\r", 60, "");
    shown_ = false, shown_percent_ = -1;
  }
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // A new label (frame 3/36) for a bar that spans several frames; drawn with the next fraction.
  void relabel(std::string label) {
    std::lock_guard<std::mutex> lock(mutex_);
    label_ = std::move(label);
    shown_percent_ = -1;
  }

  void operator()(double done) {
    if (!enabled_) return;
    std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
    if (!lock) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (elapsed < 1.0) return;
    const int percent = static_cast<int>(done * 100);
    if (percent == shown_percent_) return;  // redrawn when the number changes, not on every call
    shown_percent_ = percent;
    const int width = 30, filled = static_cast<int>(done * width);
    std::fprintf(stderr, "\r%s [%s%s] %3d%%", label_.c_str(), std::string(filled, '#').c_str(),
                 std::string(width - filled, ' ').c_str(), percent);
    std::fflush(stderr);
    shown_ = true;
  }

 private:
  std::string label_;
  bool enabled_;
  bool shown_ = false;
  int shown_percent_ = -1;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
};

// load_mesh, with "reading FILE ... 3 s" ticking on a terminal once it takes over a second (a
// reader gives no fraction done). The ticker writes with write(2), never through stdio's locks,
// since the read forks (io/isolated_read.hpp); off a terminal no thread is started.
inline LoadedMesh read_with_progress(const std::string& path, const ReadOptions& options) {
  if (isatty(STDERR_FILENO) != 1) return load_mesh(path, options);
  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  std::thread ticker([&] {
    const auto start = std::chrono::steady_clock::now();
    bool shown = false;
    std::unique_lock<std::mutex> lock(m);
    while (!cv.wait_for(lock, std::chrono::milliseconds(250), [&] { return done; })) {
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (s < 1.0) continue;
      char line[256];
      const int n = std::snprintf(line, sizeof line, "\rreading %.180s ... %.0f s", path.c_str(), s);
      if (n > 0) shown = ::write(STDERR_FILENO, line, static_cast<std::size_t>(std::min(n, 255))) >= 0;
    }
    if (shown) {
      const char clear[] = "\r                                                                  \r";
      [[maybe_unused]] const auto w = ::write(STDERR_FILENO, clear, sizeof clear - 1);
    }
  });
  const auto stop = [&] {
    {
      std::lock_guard<std::mutex> lock(m);
      done = true;
    }
    cv.notify_one();
    ticker.join();
  };
  try {
    LoadedMesh loaded = load_mesh(path, options);
    stop();
    return loaded;
  } catch (...) {
    stop();
    throw;
  }
}

}  // namespace cellproj
