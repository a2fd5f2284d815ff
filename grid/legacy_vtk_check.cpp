#include "grid/legacy_vtk_check.hpp"

#include <cctype>
#include <cstdint>
#include <fstream>
#include <sstream>

#include "base/error.hpp"

namespace cellproj {
namespace {

// "# vtk DataFile Version N.M": N, or -1 when the line says something else after the prefix.
int major_version(const std::string& line) {
  static const std::string kPrefix = "# vtk DataFile Version";
  if (line.rfind(kPrefix, 0) != 0) return 0;  // not a legacy header: VTK's own message
  std::size_t at = kPrefix.size();
  while (at < line.size() && line[at] == ' ') ++at;
  auto digits = [&] {
    const std::size_t from = at;
    while (at < line.size() && std::isdigit(static_cast<unsigned char>(line[at]))) ++at;
    return at > from && at - from < 4;
  };
  if (!digits()) return -1;
  const int major = std::stoi(line.substr(kPrefix.size()));
  if (at >= line.size() || line[at++] != '.' || !digits()) return -1;
  while (at < line.size() && std::isspace(static_cast<unsigned char>(line[at]))) ++at;
  return at == line.size() ? major : -1;
}


// Format 5, binary: "OFFSETS type", `cells` values, "CONNECTIVITY type", `size` values, then
// "CELL_TYPES cells - 1". VTK reads each array where it expects it and trusts what it finds.
void check_binary_arrays(std::ifstream& in, const std::string& path, std::int64_t cells, std::int64_t size) {
  auto array = [&](const std::string& keyword, std::int64_t count) {
    std::string word, type, rest;
    in >> word >> type;
    std::getline(in, rest);  // VTK's binary values start on the next line
    if (!is_legacy_keyword(word, keyword))
      throw InputError(where(path, "the CELLS block has no " + keyword + " array where VTK reads it (it finds '" +
                                       word.substr(0, 40) + "')"));
    const int bytes = legacy_id_bytes(type);
    if (bytes == 0) throw InputError(where(path, keyword + ": unknown id type '" + type.substr(0, 40) + "'"));
    in.seekg(count * bytes, std::ios::cur);
  };
  array("OFFSETS", cells);
  array("CONNECTIVITY", size);
  std::string word;
  std::int64_t types = -1;
  in >> word >> types;
  if (!is_legacy_keyword(word, "CELL_TYPES") || types != cells - 1)
    throw InputError(where(path, "CELLS declares " + std::to_string(cells - 1) + " cells (" + std::to_string(cells) +
                                     " offsets), but its arrays are followed by '" + word.substr(0, 40) + " " +
                                     std::to_string(types) + "', not CELL_TYPES " + std::to_string(cells - 1)));
}

// The CELLS block of a file whose header was read from `in`.
void check_cells_block(std::ifstream& in, const std::string& path, bool binary, int major) {
  std::string line;
  std::int64_t cells = -1, size = -1;
  while (std::getline(in, line)) {
    if (line.rfind("CELLS ", 0) == 0 && (std::istringstream(line.substr(6)) >> cells >> size)) break;
    std::int64_t points = 0;
    std::string type;
    if (binary && line.rfind("POINTS ", 0) == 0 && (std::istringstream(line.substr(7)) >> points >> type) &&
        points > 0)  // the binary coordinates are no lines to look through
      in.seekg(3 * points * (type == "double" ? 8 : type == "float" ? 4 : 0), std::ios::cur);
  }
  if (cells < 0 || size < 0) return;  // no CELLS block, or VTK's message about its line
  if (major >= 5) {
    if (binary && cells >= 1) check_binary_arrays(in, path, cells, size);
    return;  // the offsets' values: checked once read (check_cell_array)
  }
  const std::string block =
      "the CELLS block (" + std::to_string(cells) + " cells, " + std::to_string(size) + " numbers)";
  if (cells > size) throw InputError(where(path, block + " cannot give each cell its count"));
  std::int64_t used = 0;
  auto next = [&](std::int64_t c) {  // one number of the block
    std::int64_t v = 0;
    if (binary) {
      unsigned char b[4];
      if (!in.read(reinterpret_cast<char*>(b), 4))
        v = -1;
      else
        v = static_cast<std::int32_t>(std::uint32_t(b[0]) << 24 | std::uint32_t(b[1]) << 16 | std::uint32_t(b[2]) << 8 |
                                      b[3]);
    } else if (!(in >> v)) {
      v = -1;
    }
    if (v == -1 && !in) throw InputError(where(path, block + " ends at cell " + std::to_string(c) + ": truncated"));
    return v;
  };
  for (std::int64_t c = 0; c < cells; ++c) {
    const std::int64_t count = next(c);
    if (count < 0 || count > size - used - 1)
      throw InputError(where(path, "cell " + std::to_string(c) + " has " + std::to_string(count) +
                                       " points, more than the " + std::to_string(size - used - 1) +
                                       " numbers left in " + block));
    used += 1 + count;
    if (binary)
      in.seekg(4 * count, std::ios::cur);
    else
      for (std::int64_t k = 0; k < count; ++k) next(c);
  }
  if (used != size)
    throw InputError(where(path, block + ": its cells' counts and ids add up to " + std::to_string(used)));
}

}  // namespace

bool is_legacy_keyword(std::string word, const std::string& keyword) {
  for (char& ch : word) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  std::string upper = keyword;
  for (char& ch : upper) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return word == upper;
}

int legacy_id_bytes(const std::string& type) {
  return is_legacy_keyword(type, "VTKTYPEINT64") ? 8 : is_legacy_keyword(type, "VTKTYPEINT32") ? 4 : 0;
}

bool legacy_dataset_is(const std::string& path, const std::string& type) {
  std::ifstream in(path, std::ios::binary);
  std::string line, word, name;
  for (int k = 0; k < 3; ++k) std::getline(in, line);  // the version, the title, ASCII or BINARY
  auto starts = [](std::string w, const std::string& prefix) {
    for (char& ch : w) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return w.rfind(prefix, 0) == 0;
  };
  return (in >> word >> name) && starts(word, "dataset") && starts(name, type);
}

void check_legacy_cells(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line)) return;
  const int major = major_version(line);
  if (major < 0)
    throw InputError(where(path, "line 1: the version is garbled (a VTK legacy file says N.M): " + line.substr(0, 60)));
  std::getline(in, line);  // the title
  std::getline(in, line);
  const bool binary = line.rfind("BINARY", 0) == 0;
  if (!binary && line.rfind("ASCII", 0) != 0) return;  // VTK says what is wrong
  check_cells_block(in, path, binary, major);
  check_legacy_fields(path, binary, major);  // after: a bad CELLS block has the plainer message
}

}  // namespace cellproj
