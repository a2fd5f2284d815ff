// TetGen .node/.ele through tetgenio.
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include <tetgen.h>

#include "base/error.hpp"
#include "grid/read_mesh.hpp"
#include "grid/text_scanner.hpp"

namespace fs = std::filesystem;

namespace cellproj {
namespace {

// tetgenio reports progress ("Opening ...") on stdout, which belongs to our own output
// (`info --json`): send it to /dev/null while tetgenio runs.
class QuietStdout {
 public:
  QuietStdout() {
    std::fflush(stdout);
    saved_ = dup(STDOUT_FILENO);
    const int null = open("/dev/null", O_WRONLY);
    if (saved_ >= 0 && null >= 0) dup2(null, STDOUT_FILENO);
    if (null >= 0) close(null);
  }
  ~QuietStdout() {
    std::fflush(stdout);
    if (saved_ >= 0) {
      dup2(saved_, STDOUT_FILENO);
      close(saved_);
    }
  }
  QuietStdout(const QuietStdout&) = delete;
  QuietStdout& operator=(const QuietStdout&) = delete;

 private:
  int saved_ = -1;
};

// tetgenio trusts its headers and reads past the end of a short file; check the counts first so
// that a truncated file is an error, not undefined behaviour.
void check_records(const std::string& file, bool node) {
  TextScanner in(file);
  const std::int64_t n = in.integer("the record count in the header");
  if (n <= 0) throw InputError(where(file, "header record count " + std::to_string(n) + " must be positive"));
  std::int64_t fields = 0;  // numbers per record, its index included
  if (node) {               // <#points> <dimension> <#attributes> <boundary markers 0|1>
    const std::int64_t dim = in.integer("the dimension"), attrs = in.integer("the attribute count"),
                       markers = in.integer("the boundary-marker flag");
    if (dim != 3)
      throw InputError(where(file, "dimension " + std::to_string(dim) + " in the header; only 3D nodes are read"));
    fields = 1 + 3 + attrs + (markers ? 1 : 0);
  } else {  // <#tetrahedra> <nodes per tetrahedron> <region attribute 0|1>
    const std::int64_t corners = in.integer("the nodes per tetrahedron"), region = in.integer("the region flag");
    if (corners != 4 && corners != 10)
      throw InputError(
          where(file, "header says " + std::to_string(corners) + " nodes per tetrahedron; expected 4 (or 10)"));
    fields = 1 + corners + (region ? 1 : 0);
  }
  for (std::int64_t r = 0; r < n; ++r)
    for (std::int64_t k = 0; k < fields; ++k) in.number(node ? "a .node record field" : "an .ele record field");
}

}  // namespace

Mesh read_tetgen(const std::string& path) {
  const fs::path base = fs::path(path).replace_extension();
  const std::string node = base.string() + ".node", ele = base.string() + ".ele";
  for (const auto& f : {node, ele})
    if (!fs::exists(f))
      throw InputError(where(f, "not found (a TetGen mesh is a .node and an .ele of the same base name)"));
  check_records(node, true);
  check_records(ele, false);

  tetgenio io;
  std::string name = base.string();
  bool ok;
  {
    QuietStdout quiet;
    ok = io.load_node(name.data()) && io.load_tet(name.data());
  }
  if (!ok) throw InputError(where(path, "tetgenio could not read the .node/.ele pair"));

  Mesh m;
  for (int p = 0; p < io.numberofpoints; ++p)
    m.add_point({io.pointlist[3 * p], io.pointlist[3 * p + 1], io.pointlist[3 * p + 2]});
  for (int a = 0; a < io.numberofpointattributes; ++a) {
    PointField& f = m.add_field("attribute_" + std::to_string(a), "TetGen point attribute");
    for (int p = 0; p < io.numberofpoints; ++p) f.values[p] = io.pointattributelist[p * io.numberofpointattributes + a];
  }
  for (int t = 0; t < io.numberoftetrahedra; ++t) {
    std::int64_t ids[4];
    for (int k = 0; k < 4; ++k) ids[k] = io.tetrahedronlist[t * io.numberofcorners + k] - io.firstnumber;
    m.add_cell(CellType::Tetra, ids);
  }
  if (io.numberofcorners == 10)
    m.notes.push_back("quadratic (10-node) tetrahedra read as linear: mid-edge nodes ignored");
  if (io.numberofpointattributes == 0) m.notes.push_back("the .node file has no point attributes: no fields");
  return m;
}

}  // namespace cellproj
