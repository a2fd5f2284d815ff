#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "grid/legacy_vtk_check.hpp"
#include "grid/validate.hpp"

namespace cellproj {
namespace {

std::string lower(std::string word) {
  for (char& ch : word) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return word;
}
bool starts(const std::string& word, const char* prefix) { return word.rfind(prefix, 0) == 0; }

// How VTK's legacy reader takes an array type (vtkDataReader::ReadArray, which matches most names
// by prefix): the bytes of one binary value, kVariable for strings, kUnknown where it gives up
// (and its caller, for a dataset's FIELD, crashes).
constexpr int kUnknown = -1, kVariable = 0, kBit = -2;
constexpr int kPolyhedron = 42;  // VTK_POLYHEDRON
int value_bytes(const std::string& type) {
  if (starts(type, "bit")) return kBit;
  if (type == "char" || type == "signed_char" || starts(type, "unsigned_char")) return 1;
  if (starts(type, "short") || starts(type, "unsigned_short")) return 2;
  if (starts(type, "vtkidtype") || starts(type, "int") || starts(type, "unsigned_int")) return 4;
  if (starts(type, "long") || starts(type, "unsigned_long")) return static_cast<int>(sizeof(long));
  if (starts(type, "vtktypeint64") || starts(type, "vtktypeuint64")) return 8;
  if (starts(type, "float")) return 4;
  if (starts(type, "double")) return 8;
  if (starts(type, "string") || starts(type, "utf8_string") || starts(type, "variant")) return kVariable;
  return kUnknown;
}

// A walk through the dataset section of a legacy unstructured grid, block by block as VTK's
// reader reads it (vtkUnstructuredGridReader::ReadMeshSimple).
class DatasetWalk {
 public:
  DatasetWalk(const std::string& path, bool binary, int major)
      : path_(path), in_(path, std::ios::binary), binary_(binary), major_(major) {
    in_.seekg(0, std::ios::end);
    size_ = static_cast<std::int64_t>(in_.tellg());
    in_.seekg(0);
  }

  void run() {
    std::string line;
    for (int k = 0; k < 3; ++k) std::getline(in_, line);  // the version, the title, ASCII or BINARY
    std::string word, type;
    if (!(in_ >> word >> type) || !is_legacy_keyword(word, "dataset") || !is_legacy_keyword(type, "unstructured_grid"))
      return;
    while (in_ >> word) {
      word = lower(word);
      if (starts(word, "field")) {
        if (!field()) return;
      } else if (starts(word, "points")) {
        std::int64_t n = 0;
        if (!(in_ >> n >> type)) return;
        if (n < 0) refuse_count("POINTS", n);  // VTK reads it as a huge size and writes past its array
        if (!skip(3 * n, value_bytes(lower(type)))) return;
      } else if (starts(word, "cells")) {
        std::int64_t n = 0, size = 0;
        if (!(in_ >> n >> size)) return;
        if (n < 0 || size < 0) refuse_count("CELLS", std::min(n, size));
        if (major_ < 5) {
          if (!skip(size, 4)) return;
        } else if (!array("offsets", n) || !array("connectivity", size)) {
          return;
        }
      } else if (starts(word, "cell_types")) {
        std::int64_t n = 0;
        if (!(in_ >> n)) return;
        if (n < 0) refuse_count("CELL_TYPES", n);
        if (!cell_types(n)) return;
      } else if (is_legacy_keyword(word, "metadata")) {
        metadata();
      } else {
        return;  // POINT_DATA or CELL_DATA, whose FIELDs VTK checks, or a keyword VTK refuses
      }
    }
  }

 private:
  std::string path_;
  std::ifstream in_;
  bool binary_;
  int major_;
  std::int64_t size_ = 0;

  std::int64_t left() { return size_ - static_cast<std::int64_t>(in_.tellg()); }

  // Past `count` values of `bytes` each (binary) or numbers (ASCII); false where the walk must stop.
  bool skip(std::int64_t count, int bytes) {
    if (binary_) {
      if (bytes <= 0) return false;  // strings and bits: not followed further
      std::string rest;
      std::getline(in_, rest);  // VTK's binary values start on the next line
      if (count > left() / bytes) return false;
      in_.seekg(count * bytes, std::ios::cur);
      return true;
    }
    numbers(count);  // VTK's look for METADATA clears the stream's error: the walk goes on from there
    return true;
  }

  // The cell types: a polyhedron (VTK type 42) is refused here, as validate() would refuse it
  // after the read, because VTK's reader decomposes its face stream unchecked and a garbled one
  // crashes it. False where the walk must stop.
  bool cell_types(std::int64_t n) {
    UnsupportedCellTypes polyhedra;
    if (binary_) {
      std::string rest;
      std::getline(in_, rest);  // the values start on the next line: big-endian 32-bit integers
      if (n > left() / 4) return false;
      std::vector<unsigned char> b(4 * static_cast<std::size_t>(n));
      in_.read(reinterpret_cast<char*>(b.data()), static_cast<std::streamsize>(b.size()));
      for (std::int64_t c = 0; c < n; ++c)
        if (b[4 * c] == 0 && b[4 * c + 1] == 0 && b[4 * c + 2] == 0 && b[4 * c + 3] == kPolyhedron)
          polyhedra.add(kPolyhedron, c);
    } else {
      double v;
      for (std::int64_t c = 0; c < n; ++c) {
        if (!(in_ >> v)) {
          in_.clear();  // as numbers(): VTK's message, or its look for METADATA
          break;
        }
        if (v == kPolyhedron) polyhedra.add(kPolyhedron, c);
      }
    }
    polyhedra.throw_if_any(path_);
    return true;
  }

  // ASCII: reads up to `count` numbers as VTK does, stopping at one that is not; how many were.
  std::int64_t numbers(std::int64_t count) {
    double v;
    for (std::int64_t k = 0; k < count; ++k)
      if (!(in_ >> v)) {
        in_.clear();
        return k;
      }
    return count;
  }

  // "METADATA" after an array: lines up to a blank one.
  void metadata() {
    std::string line;
    std::getline(in_, line);
    while (std::getline(in_, line) && !line.empty() && line != "\r") {
    }
  }

  // Format 5: "OFFSETS type" (or "CONNECTIVITY type") and its values.
  bool array(const char* keyword, std::int64_t count) {
    std::string word, type;
    return (in_ >> word >> type) && is_legacy_keyword(word, keyword) && skip(count, legacy_id_bytes(type));
  }

  [[noreturn]] void refuse_count(const char* block, std::int64_t n) {
    throw InputError(where(path_, std::string(block) + " declares a negative count (" + std::to_string(n) + ")"));
  }

  [[noreturn]] void refuse(const std::string& what) {
    throw InputError(where(path_, "the dataset's FIELD block " + what + " (VTK's legacy reader would crash on it)"));
  }

  // "FIELD name arrays", then per array "name components tuples type" and its values, or
  // "NULL_ARRAY". VTK's reader uses what its field reader returns unchecked, so everything that
  // makes that reader give up is refused here. False where the walk stops (string or binary bit
  // values, not followed).
  bool field() {
    std::string name;
    int arrays = 0;
    if (!(in_ >> name >> arrays)) refuse("has no name and array count");
    if (arrays < 0 || arrays > left()) refuse("'" + name + "' declares " + std::to_string(arrays) + " arrays");
    for (int a = 0; a < arrays; ++a) {
      std::string array, type;
      if (!(in_ >> array)) refuse("'" + name + "', array " + std::to_string(a) + ": the file ends before it");
      if (array == "NULL_ARRAY") continue;
      const std::string which = "'" + name + "', array " + std::to_string(a) + " ('" + array.substr(0, 40) + "')";
      int components = 0;
      std::int64_t tuples = 0;
      if (!(in_ >> components >> tuples >> type)) refuse(which + ": its components, tuples and type are not all there");
      const int bytes = value_bytes(lower(type));
      if (bytes == kUnknown) refuse(which + ": unknown type '" + type.substr(0, 40) + "'");
      if (components < 0 || tuples < 0) refuse(which + ": a negative count");
      double per_value = bytes == kVariable ? 1 : 2;  // ASCII: a string's line end, a digit and a space
      if (binary_) per_value = bytes > 0 ? bytes : bytes == kBit ? 0.125 : 1;  // a string: its length byte
      if (double(components) * double(tuples) * per_value > double(left()))    // in double: no overflow
        refuse(which + ": " + std::to_string(components) + " x " + std::to_string(tuples) +
               " values, more than the file's remaining " + std::to_string(left()) + " bytes hold");
      const std::int64_t values = static_cast<std::int64_t>(components) * tuples;
      if (bytes == kVariable || (bytes == kBit && binary_)) return false;  // VTK reads strings line by line
      if (binary_) {
        skip(values, bytes);
      } else if (const std::int64_t read = numbers(values); read < values) {
        refuse(which + ": its values end, or stop being numbers, after " + std::to_string(read) + " of " +
               std::to_string(values));
      }
      skip_metadata();
    }
    return true;
  }

  // VTK looks for a METADATA block after every array (component names, information keys).
  void skip_metadata() {
    const std::streampos at = in_.tellg();
    std::string word;
    if (in_ >> word && is_legacy_keyword(word, "metadata")) return metadata();
    in_.clear();
    in_.seekg(at);
  }
};

}  // namespace

void check_legacy_fields(const std::string& path, bool binary, int major) { DatasetWalk(path, binary, major).run(); }

}  // namespace cellproj
