// libFuzzer harness for one mesh reader: the input is written to a file of the reader's
// extension, read as `cellproj info` reads it (load_mesh: our checks, the library's reader,
// validation) but in this process, so that the fuzzer sees the coverage of the reading and every
// crash, the third-party readers' included; bench/fuzz.sh then replays each crash through the
// command line, whose isolated reader must turn it into an error. The mesh then gets its face
// topology. Built once per format with CELLPROJ_FUZZ_EXT (".vtk", ...); for TetGen the input is
// the .node file, a NUL byte, then the .ele file.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "base/error.hpp"
#include "fuzz_folder.hpp"
#include "io/read_mesh.hpp"
#include "mesh/topology.hpp"

namespace {

std::string& folder() {  // one per fuzzing process
  static std::string dir = [] {
    const std::string name = make_fuzz_folder();
    return name;
  }();
  return dir;
}

void write(const std::string& path, const std::uint8_t* data, std::size_t size) {
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string ext = CELLPROJ_FUZZ_EXT;
  const std::string path = folder() + "/input" + ext;
  if (ext == ".node") {
    std::size_t split = 0;
    while (split < size && data[split] != 0) ++split;
    write(path, data, split);
    write(folder() + "/input.ele", data + std::min(split + 1, size), size - std::min(split + 1, size));
  } else {
    write(path, data, size);
  }
  cellproj::ReadOptions options;
  options.isolate = false;
  // The header check's limit, a quarter of ASan's cap on one allocation (bench/fuzz.sh): a file of
  // 64 KiB claiming more is refused by our check or by a failed allocation, not zero-filled at
  // ASan's pace (a garbled netCDF header had every execution calloc 2 GiB: 6 exec/s).
  options.max_memory_gib = 0.125;
  try {
    const cellproj::LoadedMesh loaded = cellproj::load_mesh(path, options);
    cellproj::build_topology(loaded.mesh.view());
  } catch (const cellproj::InternalError&) {
    std::abort();  // a broken invariant of cellproj itself: a finding
  } catch (const cellproj::Error&) {
    // a clear refusal of a bad file: what the reader must give
  }
  return 0;
}
