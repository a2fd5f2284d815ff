#include "io/read_mesh.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <zlib.h>

#include "base/bytes.hpp"
#include "base/error.hpp"
#include "base/file_status.hpp"
#include "io/header_counts.hpp"
#include "io/isolated_read.hpp"

namespace fs = std::filesystem;

namespace cellproj {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// Decompresses a gzip file into a fresh temporary folder; the folder is removed with the object.
class Gunzipped {
 public:
  explicit Gunzipped(const std::string& path) {
    dir_ = fs::temp_directory_path() / ("cellproj-" + std::to_string(std::hash<std::string>{}(path)) + "-" +
                                        std::to_string(reinterpret_cast<std::uintptr_t>(this)));
    fs::create_directories(dir_);
    try {
      decompress(path);
    } catch (...) {  // the destructor does not run for an object whose constructor threw
      remove();
      throw;
    }
  }
  ~Gunzipped() { remove(); }
  const std::string& file() const { return file_; }

 private:
  void remove() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  void decompress(const std::string& path) {
    file_ = (dir_ / fs::path(path).stem()).string();
    gzFile in = gzopen(path.c_str(), "rb");
    if (!in) throw InputError(where(path, "cannot open"));
    std::ofstream out(file_, std::ios::binary);
    char buf[1 << 16];
    int n;
    while ((n = gzread(in, buf, sizeof buf)) > 0) out.write(buf, n);
    int err = 0;
    const char* msg = gzerror(in, &err);
    const bool bad = n < 0 || (err != Z_OK && err != Z_STREAM_END);
    const std::string what = bad ? std::string(msg) : "";
    gzclose(in);
    if (bad) throw InputError(where(path, "corrupt or truncated gzip data (" + what + ")"));
  }

  fs::path dir_;
  std::string file_;
};

// Who reads the format, for the message when it fails; "" for an unknown format.
std::string reader_name(const std::string& format) {
  if (format == "vtk-xml") return "VTK's XML reader";
  if (format == "vtk-legacy") return "VTK's legacy reader";
  if (format == "exodus") return "VTK's Exodus II reader";
  if (format == "cgns") return "VTK's CGNS reader";
  if (format == "plot3d") return "VTK's PLOT3D reader";
  if (format == "tetgen") return "TetGen's reader";
  if (format == "off") return "the .off reader";
  if (format == "points") return "the point-cloud reader";
  return "";
}

}  // namespace

std::vector<std::pair<std::string, std::string>> known_formats() {
  return {{"vtk-xml", ".vtu .pvtu .vts .pvts .vtr .vti .vtm"},
          {"vtk-legacy", ".vtk"},
          {"exodus", ".exo .ex2 .e .exii"},
          {"cgns", ".cgns"},
          {"plot3d", ".xyz .p3d, or a .bin whose name contains 'xyz' (solution: the same name with 'q')"},
          {"tetgen", ".node .ele (the pair of one base name)"},
          {"off", ".off (classic sorting-benchmark text: 'nverts ntets', 'x y z s' lines, 'a b c d' lines)"},
          {"points", ".xyzs .pts (text 'x y z s' per line) .vtp (points): Delaunay-tetrahedralized with CGAL"}};
}

std::string format_for(const std::string& path) {
  const std::string name = lower(fs::path(path).filename().string());
  const std::string ext = lower_extension(path);
  for (const char* e : {".vtu", ".pvtu", ".vts", ".pvts", ".vtr", ".vti", ".vtm"})
    if (ext == e) return "vtk-xml";
  if (ext == ".vtk") return "vtk-legacy";
  if (ext == ".exo" || ext == ".ex2" || ext == ".e" || ext == ".exii") return "exodus";
  if (ext == ".cgns") return "cgns";
  if (ext == ".xyz" || ext == ".p3d" || (ext == ".bin" && name.find("xyz") != std::string::npos)) return "plot3d";
  if (ext == ".node" || ext == ".ele") return "tetgen";
  if (ext == ".off") return "off";
  if (ext == ".xyzs" || ext == ".pts" || ext == ".vtp") return "points";
  std::string list;
  for (const auto& [f, exts] : known_formats()) list += "\n  " + f + ": " + exts;
  throw InputError(where(path, "unknown mesh format '" + ext + "'; give setting 'format', one of:" + list));
}

Mesh read_mesh(const std::string& path, const ReadOptions& options) {
  if (lower_extension(path) == ".gz") {
    if (!path_exists(path)) throw InputError(where(path, "no such file"));
    Gunzipped plain(path);
    try {
      Mesh m = read_mesh(plain.file(), options);
      m.source = path;
      return m;
    } catch (const InputError& e) {  // name the file the user gave, not the temporary copy
      std::string what = e.what();
      for (auto at = what.find(plain.file()); at != std::string::npos; at = what.find(plain.file()))
        what.replace(at, plain.file().size(), path);
      throw InputError(what);
    }
  }
  if (!path_exists(path)) throw InputError(where(path, "no such file"));
  if (path_is_folder(path)) throw InputError(where(path, "is a folder, not a mesh file"));
  if (std::ifstream probe(path, std::ios::binary); !probe)
    throw InputError(where(path, "cannot be read (" + std::string(std::strerror(errno)) + ")"));
  const std::string format = options.format.empty() ? format_for(path) : options.format;
  const std::string reader = reader_name(format);
  if (reader.empty()) throw InputError(where(path, "unknown setting 'format' '" + format + "'"));
  Isolation isolation;
  isolation.memory_limit = options.max_memory_gib > 0
                               ? static_cast<std::uint64_t>(options.max_memory_gib * double(1ull << 30))
                               : available_memory_bytes();
  isolation.limit_source = options.max_memory_gib > 0 ? "setting 'max-memory'" : "this machine's available memory";
  const auto refuse_beyond_limit = [&](const HeaderCounts& h) {
    if (isolation.memory_limit > 0 && estimate_mesh_bytes(h) > isolation.memory_limit)
      throw InputError(where(path, "its header declares " + std::to_string(h.points) + " points and " +
                                       std::to_string(h.cells) + " cells: reading them needs about " +
                                       format_bytes(estimate_mesh_bytes(h)) + ", more than the " +
                                       format_bytes(isolation.memory_limit) + " allowed by " + isolation.limit_source));
  };
  auto read = [&] {
    // In the child when isolated: the CGNS and HDF5 libraries read these headers, and may crash.
    refuse_beyond_limit(library_header_counts(path, format));
    if (format == "tetgen") return read_tetgen(path);
    if (format == "off") return read_off(path);
    if (format == "points") return read_point_cloud(path);
    return read_vtk_family(path, format, options);
  };
  refuse_beyond_limit(header_counts(path));  // the headers we read ourselves, in this process
  Mesh m = options.isolate ? read_isolated(path, reader, isolation, read) : read();
  m.source = path;
  return m;
}

namespace {

// A mesh as read, validated (errors throw), its inverted cells re-oriented, its cell data applied.
LoadedMesh loaded(Mesh read, const ReadOptions& options) {
  LoadedMesh out{std::move(read), {}};
  out.report = validate(out.mesh.view());
  reorient_inverted(out.mesh, out.report);
  if (options.cell_data)
    apply_cell_data(out.mesh, *options.cell_data);  // after validation: it counts the file's points
  return out;
}

}  // namespace

LoadedMesh load_mesh(const std::string& path, const ReadOptions& options) {
  return loaded(read_mesh(path, options), options);
}

LoadedMesh load_vtk_object(vtkDataObject* data, const std::string& source, const ReadOptions& options) {
  if (!data) throw InputError(where(source, "no VTK object"));
  return loaded(assemble_vtk_object(data, source), options);
}

}  // namespace cellproj
