#include "io/isolated_read.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <new>
#include <type_traits>

#include <vtkSMPTools.h>

#ifdef CELLPROJ_FUZZING
#include <sanitizer/common_interface_defs.h>
#endif

#include "base/bytes.hpp"
#include "base/error.hpp"
#include "base/huge_pages.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define CELLPROJ_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CELLPROJ_ASAN 1
#endif
#endif

namespace cellproj {
namespace {

constexpr std::uint32_t kMagic = 0x4d525043, kEnd = 0x444e4f44;  // "CPRM", "DONE"
constexpr int kLibraryExit = 121;                                // the child's exit code when a library called exit()
enum class Outcome : std::uint8_t { mesh, input_error, resource_error, out_of_memory, other_error };

// The child's end: writes everything straight to the pipe, no copy of the mesh.
class PipeWriter {
 public:
  explicit PipeWriter(int fd) : fd_(fd) {}
  void bytes(const void* data, std::size_t n) {
    const char* p = static_cast<const char*>(data);
    while (n > 0) {
      const ssize_t w = ::write(fd_, p, n);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) _exit(120);  // the parent went away: nothing left to tell
      p += w;
      n -= static_cast<std::size_t>(w);
    }
  }
  template <class T>
  void value(T v) {
    bytes(&v, sizeof v);
  }
  void text(const std::string& s) {
    value<std::uint64_t>(s.size());
    bytes(s.data(), s.size());
  }
  template <class T>
  void array(const std::vector<T>& v) {
    value<std::uint64_t>(v.size());
    bytes(v.data(), v.size() * sizeof(T));
  }

 private:
  int fd_;
};

// The parent's end. A short read means the child died mid-way: `ok` turns false and the values
// read are zeros, so the caller asks waitpid why.
class PipeReader {
 public:
  // Arrays up to `reserve_bytes` are reserved at once (below).
  PipeReader(int fd, std::uint64_t reserve_bytes) : fd_(fd), reserve_bytes_(reserve_bytes) {}
  bool ok = true;
  void bytes(void* data, std::size_t n) {
    char* p = static_cast<char*>(data);
    while (ok && n > 0) {
      const ssize_t r = ::read(fd_, p, n);
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0) {
        ok = false;
        std::memset(p, 0, n);
        return;
      }
      p += r;
      n -= static_cast<std::size_t>(r);
    }
  }
  template <class T>
  T value() {
    T v{};
    bytes(&v, sizeof v);
    return v;
  }
  std::string text() {
    std::string s;
    array_into(s);
    return s;
  }
  template <class T>
  std::vector<T> array() {
    std::vector<T> v;
    array_into(v);
    return v;
  }

 private:
  // Grown a chunk at a time, so that a count garbled by a dying child ends at the pipe's end
  // instead of in one huge allocation; a count within half the memory available and within the
  // child's memory limit (no array of a child that kept to it is larger) is reserved at once
  // (address space, touched only as the bytes arrive), in huge pages, so that the array is not
  // copied as it grows.
  template <class Container>
  void array_into(Container& v) {
    const auto n = value<std::uint64_t>();
    using T = typename Container::value_type;
    constexpr std::uint64_t chunk = (64u << 20) / sizeof(T);
    if constexpr (std::is_same_v<Container, std::vector<T>>)
      if (n > chunk / 16 && n <= reserve_bytes_ / sizeof(T)) reserve_in_huge_pages(v, n);
    for (std::uint64_t done = 0; ok && done < n;) {
      const std::uint64_t k = std::min(chunk, n - done);
      v.resize(static_cast<std::size_t>(done + k));
      bytes(&v[static_cast<std::size_t>(done)], static_cast<std::size_t>(k) * sizeof(typename Container::value_type));
      done += k;
    }
  }
  int fd_;
  std::uint64_t reserve_bytes_;
};

void write_mesh(PipeWriter& out, const Mesh& m) {
  out.text(m.source);
  out.array(m.points);
  out.array(m.connectivity);
  out.array(m.offsets);
  out.array(m.types);
  for (const std::vector<PointField>* list : {&m.fields, &m.cell_fields}) {
    out.value<std::uint64_t>(list->size());
    for (const PointField& f : *list) {
      out.text(f.name);
      out.text(f.origin);
      out.value<std::int32_t>(f.components);
      out.array(f.values);
    }
  }
  out.value<std::uint64_t>(m.notes.size());
  for (const std::string& n : m.notes) out.text(n);
}

Mesh read_mesh_from(PipeReader& in) {
  Mesh m;
  m.source = in.text();
  m.points = in.array<double>();
  m.connectivity = in.array<std::int64_t>();
  m.offsets = in.array<std::int64_t>();
  m.types = in.array<std::uint8_t>();
  for (std::vector<PointField>* list : {&m.fields, &m.cell_fields}) {
    const auto fields = in.value<std::uint64_t>();
    for (std::uint64_t i = 0; in.ok && i < fields; ++i) {
      PointField f;
      f.name = in.text();
      f.origin = in.text();
      f.components = in.value<std::int32_t>();
      f.values = in.array<double>();
      list->push_back(std::move(f));
    }
  }
  const auto notes = in.value<std::uint64_t>();
  for (std::uint64_t i = 0; in.ok && i < notes; ++i) m.notes.push_back(in.text());
  return m;
}

[[maybe_unused]] std::uint64_t address_space_now() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  statm >> pages;
  return pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

[[noreturn]] void child(int out_fd, int err_fd, [[maybe_unused]] const Isolation& isolation,
                        const std::function<Mesh()>& read) {
  // A library that calls exit() (the CGNS library does on some bad files) must not run the
  // parent's atexit handlers in the child: ours, registered last, runs first and ends it.
  std::atexit([] { _exit(kLibraryExit); });
#ifdef CELLPROJ_FUZZING
  // The fuzzer's crash handlers belong to the parent: a reader dying here is the parent's to report.
  __sanitizer_set_death_callback(nullptr);
  for (int sig : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL}) std::signal(sig, SIG_DFL);
#endif
  // A crash must end the child whatever the caller did with these signals (a parent that ignores
  // or blocks SIGSEGV would otherwise see a raised one return, and a half-read mesh come back).
  sigset_t crash;
  sigemptyset(&crash);
  for (int sig : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL}) {
    sigaddset(&crash, sig);
    struct sigaction now {};
    if (sigaction(sig, nullptr, &now) == 0 && now.sa_handler == SIG_IGN) std::signal(sig, SIG_DFL);
  }
  sigprocmask(SIG_UNBLOCK, &crash, nullptr);
  // TBB's workers were not copied by fork(): VTK's parallel loops run on this thread alone.
  vtkSMPTools::SetBackend("Sequential");
  dup2(err_fd, STDERR_FILENO);  // what the library prints as it fails, for the parent's message
#ifndef CELLPROJ_ASAN
  if (isolation.memory_limit > 0) {
    const rlim_t limit = address_space_now() + isolation.memory_limit;
    const rlimit r{limit, limit};
    setrlimit(RLIMIT_AS, &r);
  }
#endif
  PipeWriter out(out_fd);
  out.value(kMagic);
  try {
    Mesh m = read();
    out.value(Outcome::mesh);
    write_mesh(out, m);
  } catch (const InputError& e) {
    out.value(Outcome::input_error);
    out.text(e.what());
  } catch (const ResourceError& e) {
    out.value(Outcome::resource_error);
    out.text(e.what());
  } catch (const std::bad_alloc&) {
    out.value(Outcome::out_of_memory);
  } catch (const std::exception& e) {
    out.value(Outcome::other_error);
    out.text(e.what());
  } catch (...) {
    out.value(Outcome::other_error);
    out.text("an exception that is not a std::exception");
  }
  out.value(kEnd);
  _exit(0);  // no atexit handlers or static destructors: they belong to the parent
}

// The last line the child wrote to stderr that reads as a diagnosis (glibc's "malloc(): corrupted
// top size", an HDF5 "error" line), or "" when its output is only a library's dump.
std::string last_diagnosis(int fd) {
  const off_t size = lseek(fd, 0, SEEK_END);
  if (size <= 0) return "";
  const off_t from = std::max<off_t>(0, size - 16384);
  std::string text(static_cast<std::size_t>(size - from), '\0');
  if (pread(fd, text.data(), text.size(), from) <= 0) return "";
  text.erase(std::remove(text.begin(), text.end(), '\x1b'), text.end());
  std::size_t end = text.size();
  for (int lines = 0; lines < 40 && end > 0; ++lines) {
    const auto nl = text.rfind('\n', end - 1);
    const std::size_t start = nl == std::string::npos ? 0 : nl + 1;
    std::string line = text.substr(start, end - start);
    end = nl == std::string::npos ? 0 : nl;
    std::string low = line;
    std::transform(low.begin(), low.end(), low.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const char* word : {"error", "corrupt", "malloc", "assert", "abort", "invalid"})
      if (low.find(word) != std::string::npos) {
        line.erase(0, line.find_first_not_of(" \t#0123456789:"));
        return line.size() > 160 ? line.substr(0, 160) + "..." : line;
      }
  }
  return "";
}

#ifdef CELLPROJ_FUZZING
// Under the fuzzers (bench/fuzz.sh), a sanitizer's report from the child whose first frame outside
// the sanitizer runtime and libc is in cellproj's own sources is a finding, not a malformed file:
// the parent prints it and aborts. A third-party reader's crash stays an InputError.
void abort_on_own_finding(int fd) {
  std::string text(1 << 20, '\0');
  const ssize_t n = pread(fd, text.data(), text.size(), 0);
  text.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
  const std::string ours = std::string(CELLPROJ_SOURCE_DIR) + "/";
  bool own = false;
  if (const auto ub = text.find(": runtime error: "); ub != std::string::npos) {  // "FILE:LINE:COL: runtime error"
    const auto nl = text.rfind('\n', ub);
    own = text.compare(nl == std::string::npos ? 0 : nl + 1, ours.size(), ours) == 0;
  }
  for (auto at = text.find("    #"); !own && at != std::string::npos; at = text.find("    #", at + 1)) {
    const std::string frame = text.substr(at, text.find('\n', at) - at);
    if (frame.find("compiler-rt") != std::string::npos || frame.find("libclang_rt") != std::string::npos ||
        frame.find("libc.so") != std::string::npos || frame.find("sanitizer") != std::string::npos ||
        frame.find(" in __interceptor_") != std::string::npos || frame.find(" in __asan") != std::string::npos)
      continue;
    const auto src = frame.find(ours);  // a source file of ours (not a binary built under the tree)
    own = src != std::string::npos &&
          (frame.find(".cpp:", src) != std::string::npos || frame.find(".hpp:", src) != std::string::npos);
    break;
  }
  if (!own) return;
  std::fprintf(stderr, "cellproj: the isolated reader failed in cellproj's own code:\n%s\n", text.c_str());
  std::abort();
}
#endif

// Why the child gave no mesh, from its wait status.
std::string death(int status, int err_fd, const Isolation& isolation) {
  std::string why;
  const bool library_exit = WIFEXITED(status) && WEXITSTATUS(status) == kLibraryExit;
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    why = std::string("crashed (signal ") + std::to_string(sig) + ", " + strsignal(sig) + ")";
  } else if (library_exit) {
    why = "called exit() without a result";
  } else if (WIFEXITED(status)) {
    why = "exited with code " + std::to_string(WEXITSTATUS(status)) + " without a result";
  } else {
    why = "stopped without a result";
  }
  if (const std::string line = last_diagnosis(err_fd); !line.empty()) why += "; it said: \"" + line + "\"";
  why += "; the file is malformed";
  // A library out of memory under the limit crashes, or calls exit() (the CGNS library does).
  if (isolation.memory_limit > 0 && (WIFSIGNALED(status) || library_exit))
    why += ", or reading it needs more than the " + format_bytes(isolation.memory_limit) + " allowed" +
           (isolation.limit_source.empty() ? "" : " by " + isolation.limit_source);
  return why;
}

// One forked read at a time in this process: fork() copies only the calling thread, so another
// thread's read in flight would leave its locks held, forever, in the child.
std::mutex& isolated_read_lock() {
  static std::mutex m;
  return m;
}

// GCC 12's AddressSanitizer does not take its allocator's locks around fork(): a child forked while
// another thread allocates can wait forever. Sanitizer builds read in-process when threads run.
bool fork_is_unsafe() {
#ifdef CELLPROJ_ASAN
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("Threads:", 0) == 0) return std::atoi(line.c_str() + 8) > 1;
#endif
  return false;
}

}  // namespace

std::uint64_t available_memory_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("MemAvailable:", 0) != 0) continue;
    std::uint64_t kib = 0;
    std::sscanf(line.c_str() + 13, "%lu", &kib);
    return kib * 1024;
  }
  return 0;
}

Mesh read_isolated(const std::string& path, const std::string& reader, const Isolation& isolation,
                   const std::function<Mesh()>& read) {
  const std::lock_guard<std::mutex> one_at_a_time(isolated_read_lock());
  if (fork_is_unsafe()) return read();
  int fds[2];
  if (pipe(fds) != 0) throw ResourceError(where(path, std::string("cannot make a pipe: ") + std::strerror(errno)));
#ifdef F_SETPIPE_SZ
  fcntl(fds[0], F_SETPIPE_SZ, 1 << 20);  // 1 MB a switch between the two processes instead of 64 KB
#endif
  const int err_fd = memfd_create("cellproj-reader-stderr", 0);
  std::fflush(nullptr);  // nothing buffered may be written twice
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    if (err_fd >= 0) close(err_fd);
    throw ResourceError(where(path, std::string("cannot fork the reader: ") + std::strerror(errno)));
  }
  if (pid == 0) {
    close(fds[0]);
    child(fds[1], err_fd >= 0 ? err_fd : open("/dev/null", O_WRONLY), isolation, read);
  }
  close(fds[1]);
  const std::uint64_t available = available_memory_bytes() / 2;
  PipeReader in(fds[0], isolation.memory_limit > 0 ? std::min(isolation.memory_limit, available) : available);
  Outcome outcome = Outcome::other_error;
  std::string message;
  Mesh mesh;
  if (in.value<std::uint32_t>() == kMagic && in.ok) {
    outcome = in.value<Outcome>();
    if (outcome == Outcome::mesh)
      mesh = read_mesh_from(in);
    else if (outcome != Outcome::out_of_memory)
      message = in.text();
  }
  const bool complete = in.ok && in.value<std::uint32_t>() == kEnd && in.ok;
  close(fds[0]);
  if (!complete) kill(pid, SIGKILL);  // a half-written result: the child is not to be trusted
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
#ifdef CELLPROJ_FUZZING
  if (!complete && err_fd >= 0) abort_on_own_finding(err_fd);
#endif
  const std::string why = complete ? "" : death(status, err_fd, isolation);
  if (err_fd >= 0) close(err_fd);
  if (!complete) throw InputError(where(path, reader + " " + why));
  switch (outcome) {
    case Outcome::mesh: return mesh;
    case Outcome::input_error: throw InputError(message);
    case Outcome::resource_error: throw ResourceError(message);
    case Outcome::out_of_memory:
      throw InputError(where(path, "reading it asked for more memory than the " + format_bytes(isolation.memory_limit) +
                                       " allowed" +
                                       (isolation.limit_source.empty() ? "" : " by " + isolation.limit_source) +
                                       ": a count in it is garbled, or the mesh is too large"));
    default: throw InternalError(where(path, reader + ": " + message));
  }
}

}  // namespace cellproj
