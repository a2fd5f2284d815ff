// TetGen .node/.ele through tetgenio.
#include <fcntl.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include <tetgen.h>

#include "base/error.hpp"
#include "base/file_status.hpp"
#include "io/read_mesh.hpp"
#include "io/text_scanner.hpp"

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

// What the .node file holds, for checking the .ele's ids against it.
struct NodeRange {
  std::int64_t first = 0, count = 0;  // ids run first .. first + count - 1 (TetGen numbers from 0 or 1)
};

// tetgenio trusts its headers, reads past the end of a short file, skips a token it cannot parse
// (a NaN: the columns shift), throws an int on a bad id and dereferences null on a line shorter
// than its record: check every record first, one per line as tetgenio reads them, so that a bad
// file is an error naming its line.
NodeRange check_node(const std::string& file) {
  TextScanner in(file);
  NodeRange r;
  in.next_record("the header");
  r.count = in.integer_field("the point count in the header");
  if (r.count <= 0 || r.count > std::numeric_limits<int>::max())
    throw InputError(where(file, "header point count " + std::to_string(r.count) + " must be in [1, 2^31)"));
  // <#points> <dimension> <#attributes> <boundary markers 0|1>
  const std::int64_t dim = in.integer_field("the dimension"), attrs = in.integer_field("the attribute count"),
                     markers = in.integer_field("the boundary-marker flag");
  if (dim != 3)
    throw InputError(where(file, "dimension " + std::to_string(dim) + " in the header; only 3D nodes are read"));
  if (attrs < 0 || attrs > 1000 || (markers != 0 && markers != 1))
    throw InputError(where(file, "header: " + std::to_string(attrs) + " attributes, boundary-marker flag " +
                                     std::to_string(markers) + " (expected 0..1000 and 0 or 1)"));
  for (std::int64_t p = 0; p < r.count; ++p) {
    in.next_record("a point record");
    const std::int64_t id = in.integer_field("a point index");
    if (p == 0) r.first = id;
    if (id != r.first + p)
      throw InputError(where(file, "line " + std::to_string(in.line()) + ": point index " + std::to_string(id) +
                                       ", expected " + std::to_string(r.first + p) + " (indices run in order)"));
    for (std::int64_t k = 0; k < 3 + attrs; ++k)
      if (const double v = in.field(k < 3 ? "a coordinate" : "a point attribute"); !std::isfinite(v))
        throw InputError(where(file, "line " + std::to_string(in.line()) + ": point " + std::to_string(id) + " has a " +
                                         (k < 3 ? "non-finite coordinate" : "non-finite attribute")));
    if (markers) in.integer_field("a boundary marker");
  }
  if (r.first != 0 && r.first != 1)
    throw InputError(where(file, "point indices start at " + std::to_string(r.first) + "; TetGen numbers from 0 or 1"));
  return r;
}

void check_ele(const std::string& file, const NodeRange& nodes) {
  TextScanner in(file);
  in.next_record("the header");
  const std::int64_t n = in.integer_field("the tetrahedron count in the header");
  if (n <= 0 || n > std::numeric_limits<int>::max() / 10)
    throw InputError(where(file, "header tetrahedron count " + std::to_string(n) + " must be in [1, 2^31 / 10)"));
  // <#tetrahedra> <nodes per tetrahedron> <region attribute 0|1>
  const std::int64_t corners = in.integer_field("the nodes per tetrahedron"),
                     region = in.integer_field("the region flag");
  if (corners != 4 && corners != 10)
    throw InputError(
        where(file, "header says " + std::to_string(corners) + " nodes per tetrahedron; expected 4 (or 10)"));
  for (std::int64_t t = 0; t < n; ++t) {
    in.next_record("a tetrahedron record");
    in.integer_field("a tetrahedron index");
    for (std::int64_t k = 0; k < corners; ++k)
      if (const std::int64_t id = in.integer_field("a point id"); id < nodes.first || id >= nodes.first + nodes.count)
        throw InputError(where(file, "line " + std::to_string(in.line()) + ": tetrahedron " + std::to_string(t) +
                                         " refers to point " + std::to_string(id) + ", out of range [" +
                                         std::to_string(nodes.first) + ", " +
                                         std::to_string(nodes.first + nodes.count) + ")"));
    if (region) in.field("a region attribute");
  }
}

}  // namespace

Mesh read_tetgen(const std::string& path) {
  const fs::path base = fs::path(path).replace_extension();
  const std::string node = base.string() + ".node", ele = base.string() + ".ele";
  for (const auto& f : {node, ele})
    if (!path_exists(f))
      throw InputError(where(f, "not found (a TetGen mesh is a .node and an .ele of the same base name)"));
  check_ele(ele, check_node(node));

  tetgenio io;
  std::string name = base.string();
  bool ok;
  {
    QuietStdout quiet;
    try {
      ok = io.load_node(name.data()) && io.load_tet(name.data());
    } catch (int code) {  // tetgenio's way of failing; the checks above should leave none
      throw InputError(where(path, "tetgenio failed with code " + std::to_string(code)));
    }
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
