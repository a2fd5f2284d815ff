#include "tools/memory_budget.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "base/error.hpp"

namespace cellproj {

namespace {
// The integers of attribute `name` (e.g. NumberOfPoints="12") at every occurrence in `xml`.
template <class F>
void each_attribute(const std::string& xml, const std::string& name, F&& f) {
  const std::string key = " " + name + "=\"";  // the whole name: Extent, not WholeExtent
  for (std::size_t at = xml.find(key); at != std::string::npos; at = xml.find(key, at + key.size())) {
    const std::size_t end = xml.find('"', at + key.size());
    if (end != std::string::npos) f(xml.substr(at + key.size(), end - at - key.size()));
  }
}
}  // namespace

HeaderCounts vtk_xml_header_counts(const std::string& path) {
  HeaderCounts c;
  const auto dot = path.rfind('.');
  const std::string ext = dot == std::string::npos ? "" : path.substr(dot);
  if (ext != ".vtu" && ext != ".vts") return c;
  std::ifstream in(path, std::ios::binary);
  std::string xml(1 << 20, '\0');  // the XML part: every Piece element comes before the data
  in.read(&xml[0], static_cast<std::streamsize>(xml.size()));
  xml.resize(static_cast<std::size_t>(in.gcount()));
  const std::size_t data = xml.find("<AppendedData");
  if (data != std::string::npos) xml.resize(data);
  each_attribute(xml, "NumberOfPoints", [&](const std::string& v) { c.points += std::atoll(v.c_str()); });
  each_attribute(xml, "NumberOfCells", [&](const std::string& v) { c.cells += std::atoll(v.c_str()); });
  if (ext == ".vts")
    each_attribute(xml, "Extent", [&](const std::string& v) {  // a Piece's extent: i0 i1 j0 j1 k0 k1
      std::istringstream s(v);
      std::int64_t e[6] = {};
      for (auto& x : e) s >> x;
      c.points += (e[1] - e[0] + 1) * (e[3] - e[2] + 1) * (e[5] - e[4] + 1);
      c.cells += std::max<std::int64_t>(e[1] - e[0], 1) * std::max<std::int64_t>(e[3] - e[2], 1) *
                 std::max<std::int64_t>(e[5] - e[4], 1);
    });
  return c;
}

std::uint64_t estimate_mesh_bytes(const HeaderCounts& counts) {
  // Points as doubles with a few fields, cells as 64-bit connectivity of up to 8 ids plus offsets
  // and types; twice: the reader's arrays and the Mesh made from them.
  return 2 * (static_cast<std::uint64_t>(std::max<std::int64_t>(counts.points, 0)) * 64 +
              static_cast<std::uint64_t>(std::max<std::int64_t>(counts.cells, 0)) * 80);
}

void refuse_beyond_memory(std::uint64_t need, double max_memory_gib, const std::string& what,
                          const std::string& source) {
  const std::uint64_t limit =
      max_memory_gib > 0 ? static_cast<std::uint64_t>(max_memory_gib * double(1ull << 30)) : available_memory_bytes();
  if (limit == 0 || need <= limit) return;
  throw InputError(
      where(source, what + " needs about " + format_bytes(need) + ", more than the " + format_bytes(limit) +
                        (max_memory_gib > 0 ? " allowed by --max-memory"
                                            : " this machine has available (raise it with --max-memory GiB)") +
                        "; use a smaller --size or mesh"));
}

std::string format_bytes(std::uint64_t bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f GiB", double(bytes) / double(1ull << 30));
  return buf;
}

}  // namespace cellproj
