#include "io/legacy_vtk_check.hpp"

#include <cctype>
#include <cstdint>
#include <fstream>

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

LegacyEncoding legacy_file_encoding(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line, word;
  for (int k = 0; k < 2; ++k) std::getline(in, line);  // the version, the title
  if (!(in >> word)) return LegacyEncoding::unknown;
  if (is_legacy_keyword(word.substr(0, 5), "ascii")) return LegacyEncoding::ascii;
  if (is_legacy_keyword(word.substr(0, 6), "binary")) return LegacyEncoding::binary;
  return LegacyEncoding::unknown;
}

std::string read_legacy_dataset_type(std::istream& in) {
  std::string line, word, type;
  for (int k = 0; k < 2; ++k) std::getline(in, line);  // the version, the title
  // (a vertical tab after ASCII put DATASET on the encoding's line in a fuzzed file: VTK read it)
  if (!(in >> word >> word >> type) || !is_legacy_keyword(word.substr(0, 7), "dataset")) return "";
  for (char& ch : type) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return type;
}

bool legacy_dataset_is(const std::string& path, const std::string& type) {
  std::ifstream in(path, std::ios::binary);
  return read_legacy_dataset_type(in).rfind(type, 0) == 0 && !type.empty();
}

void check_legacy_cells(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line)) return;
  const int major = major_version(line);
  if (major < 0)
    throw InputError(where(path, "line 1: the version is garbled (a VTK legacy file says N.M): " + line.substr(0, 60)));
  const LegacyEncoding encoding = legacy_file_encoding(path);
  if (encoding == LegacyEncoding::unknown) return;  // VTK says what is wrong
  const bool binary = encoding == LegacyEncoding::binary;
  check_legacy_fields(path, binary, major);
}

}  // namespace cellproj
