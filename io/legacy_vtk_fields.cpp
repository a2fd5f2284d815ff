#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "io/legacy_vtk_check.hpp"
#include "mesh/validate.hpp"

namespace cellproj {
namespace {

std::string lower(std::string word) {
  for (char& ch : word) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return word;
}

std::string upper(std::string word) {
  for (char& ch : word) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
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

// A signed big-endian integer of 4 or 8 bytes: how legacy binary files store ids and counts.
std::int64_t big_endian(const unsigned char* b, int bytes) {
  std::uint64_t v = 0;
  for (int m = 0; m < bytes; ++m) v = v << 8 | b[m];
  return bytes == 4 ? static_cast<std::int32_t>(v) : static_cast<std::int64_t>(v);
}

// A walk through the dataset section of a legacy unstructured or structured grid, block by block
// as VTK's reader reads it (vtkUnstructuredGridReader::ReadMeshSimple and its structured-grid
// twin), then through its point and cell data (vtkDataReader::ReadPointData).
class DatasetWalk {
 public:
  DatasetWalk(const std::string& path, bool binary, int major)
      : path_(path), in_(path, std::ios::binary), binary_(binary), major_(major) {
    in_.seekg(0, std::ios::end);
    size_ = static_cast<std::int64_t>(in_.tellg());
    in_.seekg(0);
  }

  void run() {
    std::string word, type = read_legacy_dataset_type(in_);  // VTK matches the type by prefix
    if (starts(type, "polydata"))  // VTK's reader indexed POLYGONS' ids unchecked (a crash), for nothing
      throw InputError(where(path_,
                             "its dataset is POLYDATA (surfaces, lines and points), which holds no volume "
                             "cells: cellproj renders unstructured, structured and rectilinear grids and "
                             "structured points"));
    const bool unstructured = starts(type, "unstructured_grid"), structured = starts(type, "structured_grid");
    const bool rectilinear = starts(type, "rectilinear_grid");
    if (!unstructured && !structured && !rectilinear) return;
    std::int64_t dims[3] = {-1, -1, -1};  // a rectilinear grid's, once read
    while (in_ >> word) {
      word = lower(word);
      if (starts(word, "field")) {
        if (!field()) return;
      } else if (starts(word, "points")) {
        std::int64_t n = 0;
        if (!(in_ >> n >> type)) return;
        if (n < 0) refuse_count("POINTS", n);  // VTK reads it as a huge size and writes past its array
        if (!skip("POINTS", 3 * n, coordinate_bytes("POINTS", type))) return;
      } else if (unstructured && starts(word, "cells")) {
        std::int64_t n = 0, size = 0;
        if (!(in_ >> n >> size)) return;
        if (n < 0 || size < 0) refuse_count("CELLS", std::min(n, size));
        if (major_ < 5) {
          legacy_cells(n, size);
        } else if (!binary_) {
          if (!ascii_arrays(n, size)) return;
        } else if (n >= 1) {
          if (!cell_types(binary_arrays(n, size))) return;
        } else if (!array("offsets", n) || !array("connectivity", size)) {
          return;
        }
      } else if (unstructured && starts(word, "cell_types")) {
        std::int64_t n = 0;
        if (!(in_ >> n)) return;
        if (n < 0) refuse_count("CELL_TYPES", n);
        if (!cell_types(n)) return;
      } else if (structured && (starts(word, "dimensions") || starts(word, "extent"))) {
        std::int64_t unused[3];
        if (!grid_size(word[0] == 'd', unused)) return;  // VTK's message
      } else if (rectilinear && starts(word, "dimensions")) {
        if (!grid_size(true, dims)) return;  // VTK's message
      } else if (rectilinear && word.size() > 1 && word[0] >= 'x' && word[0] <= 'z' &&
                 word.substr(1) == "_coordinates") {
        // VTK's reader builds the points from DIMENSIONS and reads each axis's values unchecked: an
        // axis with fewer values than its dimension gave coordinates from past the array.
        const int axis = word[0] - 'x';
        const std::string block = std::string(1, static_cast<char>('X' + axis)) + "_COORDINATES";
        std::int64_t n = 0;
        if (!(in_ >> n >> type)) return;
        if (n < 0) refuse_count(block, n);
        if (dims[axis] >= 0 && n != dims[axis])
          throw InputError(where(path_, block + " holds " + std::to_string(n) + " values for the " +
                                            std::to_string(dims[axis]) +
                                            " points along its axis that DIMENSIONS gives"));
        if (!skip(block, n, coordinate_bytes(block, type))) return;
      } else if (starts(word, "metadata")) {
        metadata();
      } else if (starts(word, "point_data") || starts(word, "cell_data")) {
        return attributes(word);
      } else {
        return;  // a keyword VTK refuses (or a structured grid's BLANKING: not followed)
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

  // Past `block`'s `count` values of `bytes` each (binary) or numbers (ASCII); false where the walk
  // must stop.
  bool skip(const std::string& block, std::int64_t count, int bytes) {
    if (binary_) {
      if (bytes <= 0) return false;  // strings and bits: not followed further
      std::string rest;
      std::getline(in_, rest);  // VTK's binary values start on the next line
      fits(block, count, bytes);
      in_.seekg(count * bytes, std::ios::cur);
      return true;
    }
    fits(block, count, 1);
    numbers(count);  // VTK's look for METADATA clears the stream's error: the walk goes on from there
    return true;
  }

  // `block`'s `count` values of `bytes` each (binary; ASCII: numbers, a byte each at the least)
  // refused where the rest of the file cannot hold them: VTK's reader sizes its array by the count
  // before it reads a value (a fuzzed CELL_TYPES of 552020666 in a 1 KB file asked for 2.2 GB).
  void fits(const std::string& block, std::int64_t count, int bytes) {
    if (double(count) * (binary_ ? bytes : 1) > double(left()))  // (in double: no overflow)
      throw InputError(where(path_, block + " declares " + std::to_string(count) +
                                        (binary_ ? " values of " + std::to_string(bytes) + " bytes" : " numbers") +
                                        ", more than the " + std::to_string(left()) +
                                        " bytes left in the file hold: truncated or corrupt"));
  }

  // Before format 5, the CELLS block of `cells` cells in `size` numbers: each cell a count and that
  // many ids. VTK's reader follows the counts unchecked (one that runs past the block corrupted
  // its heap), so every count is checked against what is left of the block.
  void legacy_cells(std::int64_t cells, std::int64_t size) {
    const std::string block =
        "the CELLS block (" + std::to_string(cells) + " cells, " + std::to_string(size) + " numbers)";
    if (cells > size) throw InputError(where(path_, block + " cannot give each cell its count"));
    if (binary_) {
      std::string rest;
      std::getline(in_, rest);  // VTK's binary values start on the next line
    }
    fits("CELLS", size, 4);
    std::int64_t used = 0;
    auto next = [&](std::int64_t c) {  // one number of the block
      std::int64_t v = 0;
      if (binary_) {
        unsigned char b[4];
        v = in_.read(reinterpret_cast<char*>(b), 4) ? big_endian(b, 4) : -1;
      } else if (!(in_ >> v)) {
        v = -1;
      }
      if (v == -1 && !in_) throw InputError(where(path_, block + " ends at cell " + std::to_string(c) + ": truncated"));
      return v;
    };
    for (std::int64_t c = 0; c < cells; ++c) {
      const std::int64_t count = next(c);
      if (count < 0 || count > size - used - 1)
        throw InputError(where(path_, "cell " + std::to_string(c) + " has " + std::to_string(count) +
                                          " points, more than the " + std::to_string(size - used - 1) +
                                          " numbers left in " + block));
      used += 1 + count;
      if (binary_)
        in_.seekg(4 * count, std::ios::cur);
      else
        for (std::int64_t k = 0; k < count; ++k) next(c);
    }
    if (used != size)
      throw InputError(where(path_, block + ": its cells' counts and ids add up to " + std::to_string(used)));
  }

  // Format 5's offsets against its `ids` connectivity entries (check_offsets), naming the file.
  void offsets_fit(const std::vector<std::int64_t>& offsets, std::int64_t ids) {
    try {
      check_offsets([&](std::int64_t c) { return offsets[static_cast<std::size_t>(c)]; },
                    static_cast<std::int64_t>(offsets.size()) - 1, ids);
    } catch (const InputError& e) {
      throw InputError(where(path_, e.what()));
    }
  }

  // Format 5, ASCII: "OFFSETS type" and `cells` numbers, checked; then the connectivity. False
  // where the walk stops (VTK's own message: a keyword or a number missing).
  // An array shorter than the block declares is refused: VTK's reader took a connectivity one id
  // short with exit 0 and 21 degenerate cells, and crashed on a fuzzed file's short offsets.
  bool ascii_arrays(std::int64_t cells, std::int64_t size) {
    std::string word, type;
    if (!(in_ >> word >> type) || !is_legacy_keyword(word, "offsets")) return false;
    const auto short_array = [&](const char* name, std::int64_t got, std::int64_t want) {
      return InputError(where(path_, "CELLS " + std::to_string(cells) + " " + std::to_string(size) + ": its " + name +
                                         " array holds " + std::to_string(got) + " numbers where the block declares " +
                                         std::to_string(want) + ": truncated or corrupt"));
    };
    std::vector<std::int64_t> offsets;
    std::int64_t v = 0;
    while (static_cast<std::int64_t>(offsets.size()) < cells && in_ >> v)  // as many as the file holds
      offsets.push_back(v);
    if (static_cast<std::int64_t>(offsets.size()) < cells)
      throw short_array("OFFSETS", static_cast<std::int64_t>(offsets.size()), cells);
    offsets_fit(offsets, size);
    if (!(in_ >> word >> type) || !is_legacy_keyword(word, "connectivity")) return false;
    const std::int64_t ids = numbers(size);
    if (ids < size) throw short_array("CONNECTIVITY", ids, size);
    return true;
  }

  // Format 5, binary: "OFFSETS type", `cells` values, "CONNECTIVITY type", `size` values, then
  // "CELL_TYPES cells - 1". VTK reads each array where it expects it and trusts what it finds.
  // Returns the cell types' count, the stream at their values.
  std::int64_t binary_arrays(std::int64_t cells, std::int64_t size) {
    std::vector<std::int64_t> offsets;
    auto array = [&](const std::string& keyword, std::int64_t count) {
      std::string word, type, rest;
      in_ >> word >> type;
      std::getline(in_, rest);  // VTK's binary values start on the next line
      if (!is_legacy_keyword(word, keyword))
        throw InputError(where(path_, "the CELLS block has no " + keyword + " array where VTK reads it (it finds '" +
                                          word.substr(0, 40) + "')"));
      const int bytes = legacy_id_bytes(type);
      if (bytes == 0) throw InputError(where(path_, keyword + ": unknown id type '" + type.substr(0, 40) + "'"));
      fits(keyword, count, bytes);
      if (keyword != "OFFSETS") {  // the ids are checked once read (check_cell_array)
        in_.seekg(count * bytes, std::ios::cur);
        return;
      }
      offsets.resize(static_cast<std::size_t>(count));  // big-endian integers of `bytes` bytes
      std::vector<unsigned char> b(static_cast<std::size_t>(count * bytes));
      in_.read(reinterpret_cast<char*>(b.data()), static_cast<std::streamsize>(b.size()));
      for (std::int64_t k = 0; k < count; ++k) offsets[k] = big_endian(&b[static_cast<std::size_t>(k * bytes)], bytes);
    };
    array("OFFSETS", cells);
    array("CONNECTIVITY", size);
    if (!offsets.empty()) offsets_fit(offsets, size);
    std::string word;
    std::int64_t types = -1;
    in_ >> word >> types;
    if (!is_legacy_keyword(word, "CELL_TYPES") || types != cells - 1)
      throw InputError(where(path_, "CELLS declares " + std::to_string(cells - 1) + " cells (" + std::to_string(cells) +
                                        " offsets), but its arrays are followed by '" + word.substr(0, 40) + " " +
                                        std::to_string(types) + "', not CELL_TYPES " + std::to_string(cells - 1)));
    return types;
  }

  // The cell types: a polyhedron (VTK type 42) is refused here, as validate() would refuse it
  // after the read, because VTK's reader decomposes its face stream unchecked and a garbled one
  // crashes it. VTK keeps only each type's low byte (its types are unsigned char): 298 or
  // 1847604522 is a polyhedron to it too. False where the walk must stop.
  bool cell_types(std::int64_t n) {
    UnsupportedCellTypes polyhedra;
    if (binary_) {
      std::string rest;
      std::getline(in_, rest);  // the values start on the next line: big-endian 32-bit integers
      fits("CELL_TYPES", n, 4);
      std::vector<unsigned char> b(4 * static_cast<std::size_t>(n));
      in_.read(reinterpret_cast<char*>(b.data()), static_cast<std::streamsize>(b.size()));
      for (std::int64_t c = 0; c < n; ++c)
        if (b[4 * c + 3] == kPolyhedron) polyhedra.add(kPolyhedron, c);  // the low byte (see above)
    } else {
      fits("CELL_TYPES", n, 1);
      long long v;
      for (std::int64_t c = 0; c < n; ++c) {
        if (!(in_ >> v)) {
          in_.clear();  // as numbers(): VTK's message, or its look for METADATA
          break;
        }
        if ((v & 0xFF) == kPolyhedron) polyhedra.add(kPolyhedron, c);
      }
    }
    polyhedra.throw_if_any(path_);
    return true;
  }

  // ASCII: reads up to `count` numbers as VTK does, stopping at one that is not; how many were.
  // A grid's DIMENSIONS nx ny nz (else EXTENT x0 x1 y0 y1 z0 z1) into `dims`, false when they are
  // not integers (VTK's message). VTK's reader sizes its arrays from them: an axis of fewer than
  // one point ended in std::length_error (an internal error), or read as no cells at all.
  bool grid_size(bool dimensions, std::int64_t dims[3]) {
    std::int64_t v[6];
    for (int k = 0; k < (dimensions ? 3 : 6); ++k)
      if (!(in_ >> v[k])) return in_.clear(), false;
    for (int a = 0; a < 3; ++a) {
      dims[a] = dimensions ? v[a] : v[2 * a + 1] - v[2 * a] + 1;
      if (dims[a] < 1)
        throw InputError(where(path_, std::string(dimensions ? "DIMENSIONS" : "EXTENT") + " gives " +
                                          std::to_string(dims[a]) + " points along " +
                                          std::string(1, static_cast<char>('x' + a)) +
                                          ": a grid has at least one point along each axis"));
    }
    return true;
  }

  std::int64_t numbers(std::int64_t count) {
    double v;
    for (std::int64_t k = 0; k < count; ++k)
      if (!(in_ >> v)) {
        in_.clear();
        return k;
      }
    return count;
  }

  // "METADATA" after an array (VTK looks at its first 8 characters only): lines up to a blank one,
  // blank as VTK sees it: nothing before its end or a NUL byte.
  void metadata() {
    std::string line;
    std::getline(in_, line);
    while (std::getline(in_, line) && !line.empty() && line[0] != '\0' && line != "\r") {
    }
  }

  // Format 5: "OFFSETS type" (or "CONNECTIVITY type") and its values.
  bool array(const char* keyword, std::int64_t count) {
    std::string word, type;
    return (in_ >> word >> type) && is_legacy_keyword(word, keyword) && skip(keyword, count, legacy_id_bytes(type));
  }

  // The bytes of one value of a coordinate block (POINTS, X_COORDINATES, ...) of `type`; a string
  // type is refused: VTK's reader of string arrays wrote past its buffer on a fuzzed one.
  int coordinate_bytes(const std::string& block, const std::string& type) {
    const int bytes = value_bytes(lower(type));
    if (bytes == kVariable)
      throw InputError(where(path_, block + " has the type '" + type.substr(0, 40) +
                                        "', which VTK reads as strings: coordinates are numbers"));
    return bytes;
  }

  [[noreturn]] void refuse_count(const std::string& block, std::int64_t n) {
    throw InputError(where(path_, block + " declares a negative count (" + std::to_string(n) + ")"));
  }

  // The FIELD block's section: the dataset's (where VTK's reader crashes on what its field reader
  // gives up on) or POINT_DATA's or CELL_DATA's (where it stops with a message).
  std::string section_ = "the dataset's";

  [[noreturn]] void refuse(const std::string& what) {
    const bool dataset = section_ == "the dataset's";
    throw InputError(
        where(path_, section_ + " FIELD block " + what + (dataset ? " (VTK's legacy reader would crash on it)" : "")));
  }

  // POINT_DATA n or CELL_DATA n (the keyword in `word`), and the arrays that follow, each of n
  // tuples: a negative count, of tuples or of components, made VTK's reader write past the array
  // it sized with it. Stops where VTK's reader would stop with a message, or at values not followed.
  void attributes(std::string word) {
    std::int64_t n = 0;
    for (;;) {
      const std::string block = starts(word, "point_data") ? "POINT_DATA" : "CELL_DATA";
      if (!(in_ >> n)) return;
      if (n < 0) refuse_count(block, n);
      section_ = block + "'s";
      for (;;) {
        std::string name, type, key;
        if (!(in_ >> word)) return;
        word = lower(word);
        if (starts(word, "point_data") || starts(word, "cell_data")) break;
        bool go_on = false;
        if (starts(word, "scalars")) {  // SCALARS name type [components] LOOKUP_TABLE table
          std::int64_t components = 1;
          if (!(in_ >> name >> type >> key)) return;
          if (lower(key) != "lookup_table") {
            components = std::strtoll(key.c_str(), nullptr, 10);
            if (components < 1 || !(in_ >> key) || lower(key) != "lookup_table") return;  // VTK's message
          }
          go_on = (in_ >> key) && values(n, components, type, "SCALARS '" + name.substr(0, 40) + "'");
        } else if (starts(word, "vectors") || starts(word, "normals") || starts(word, "tensors")) {
          const int components = starts(word, "tensors6") ? 6 : starts(word, "tensors") ? 9 : 3;
          go_on = (in_ >> name >> type) && values(n, components, type, upper(word) + " '" + name.substr(0, 40) + "'");
        } else if (starts(word, "texture_coordinates")) {
          int dim = 0;
          go_on = (in_ >> name >> dim >> type) && dim >= 1 && dim <= 3 &&
                  values(n, dim, type, "TEXTURE_COORDINATES '" + name.substr(0, 40) + "'");
        } else if (starts(word, "global_ids") || starts(word, "pedigree_ids")) {
          go_on = (in_ >> name >> type) && values(n, 1, type, upper(word) + " '" + name.substr(0, 40) + "'");
        } else if (starts(word, "color_scalars")) {
          int components = 0;
          if (!(in_ >> name >> components)) return;
          if (components < 1)
            throw InputError(where(path_, block + "'s COLOR_SCALARS '" + name.substr(0, 40) + "' declares " +
                                              std::to_string(components) + " components"));
          go_on =
              values(n, components, binary_ ? "unsigned_char" : "float", "COLOR_SCALARS '" + name.substr(0, 40) + "'");
        } else if (starts(word, "lookup_table")) {
          std::int64_t entries = 0;
          if (!(in_ >> name >> entries)) return;
          if (entries < 0) refuse_count(block + "'s LOOKUP_TABLE '" + name.substr(0, 40) + "'", entries);
          go_on = values(entries, 4, binary_ ? "unsigned_char" : "float", "LOOKUP_TABLE '" + name.substr(0, 40) + "'");
        } else if (starts(word, "field")) {
          go_on = field();
        }
        if (!go_on) return;  // a keyword VTK refuses, or values not followed
      }
    }
  }

  // An attribute array's values: `tuples` x `components` of `type`, and its METADATA. False where
  // the walk stops (a type VTK refuses, strings, more values than the file holds).
  // `what` names the array ("SCALARS 'pressure'"). More values than the rest of the file holds are
  // refused here: VTK's reader sizes the array first (SCALARS of 44444444441 components, a fuzzed
  // file, asked for 12 GB).
  bool values(std::int64_t tuples, std::int64_t components, const std::string& type, const std::string& what) {
    const int bytes = value_bytes(lower(type));
    if (bytes == kUnknown || bytes == kVariable || (bytes == kBit && binary_)) return false;
    if (double(tuples) * double(components) > double(left()))
      throw InputError(where(path_, section_ + " " + what + " declares " + std::to_string(tuples) + " tuples of " +
                                        std::to_string(components) + " components, more values than the " +
                                        std::to_string(left()) + " bytes left in the file hold: truncated or corrupt"));
    if (!skip(section_ + " " + what, tuples * components, bytes)) return false;
    skip_metadata();
    return true;
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
      if (components < 0 || tuples < 0)
        refuse(which + ": a negative count (" + std::to_string(components) + " components of " +
               std::to_string(tuples) + " tuples)");
      double per_value = bytes == kVariable ? 1 : 2;  // ASCII: a string's line end, a digit and a space
      if (binary_) per_value = bytes > 0 ? bytes : bytes == kBit ? 0.125 : 1;  // a string: its length byte
      if (double(components) * double(tuples) * per_value > double(left()))    // in double: no overflow
        refuse(which + ": " + std::to_string(components) + " x " + std::to_string(tuples) +
               " values, more than the file's remaining " + std::to_string(left()) +
               " bytes hold (truncated, or a wrong count)");
      const std::int64_t values = static_cast<std::int64_t>(components) * tuples;
      if (bytes == kVariable || (bytes == kBit && binary_)) return false;  // VTK reads strings line by line
      if (binary_) {
        skip(which, values, bytes);
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
    if (in_ >> word && starts(lower(word), "metadata")) return metadata();
    in_.clear();
    in_.seekg(at);
  }
};

}  // namespace

void check_legacy_fields(const std::string& path, bool binary, int major) { DatasetWalk(path, binary, major).run(); }

}  // namespace cellproj
