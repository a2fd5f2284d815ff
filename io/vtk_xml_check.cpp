#include "io/vtk_xml_check.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "base/error.hpp"
#include "io/xml_attribute.hpp"

namespace cellproj {
namespace {

std::uint64_t type_size(const std::string& type) {
  if (type == "Int8" || type == "UInt8") return 1;
  if (type == "Int16" || type == "UInt16") return 2;
  if (type == "Int32" || type == "UInt32" || type == "Float32") return 4;
  if (type == "Int64" || type == "UInt64" || type == "Float64") return 8;
  return 0;  // String, Bit, ...: not checked
}

// An array's encoded data: the appended data section (raw bytes, or base64) in the file, or an
// inline binary array's base64 text. As VTK writes it, an uncompressed array's byte count and data
// are one base64 run; a compressed one's header and its data are each encoded on their own.
class EncodedData {
 public:
  // The appended section, from byte data_start of the file.
  EncodedData(const std::string& path, std::uint64_t data_start, std::uint64_t file_size, bool uint64, bool big,
              bool base64)
      : in_(path, std::ios::binary),
        start_(data_start),
        size_(file_size),
        word_(uint64 ? 8 : 4),
        big_(big),
        base64_(base64) {}
  // An inline array's base64 text, white space removed.
  EncodedData(std::string text, bool uint64, bool big)
      : text_(std::move(text)), start_(0), size_(text_.size()), word_(uint64 ? 8 : 4), big_(big), base64_(true) {}
  std::uint64_t word() const { return word_; }
  std::string encoding() const { return base64_ ? "base64" : "raw"; }
  // The stored bytes that `n` bytes of a unit take.
  std::uint64_t stored(std::uint64_t n) const { return base64_ ? (n + 2) / 3 * 4 : n; }
  // The stored bytes after position `at`.
  std::uint64_t left(std::uint64_t at) const { return start_ + at >= size_ ? 0 : size_ - start_ - at; }
  // The first `words` header integers of the unit at `at`, or nullopt past the end or not base64.
  std::optional<std::vector<std::uint64_t>> header(std::uint64_t at, std::uint64_t words) {
    const std::uint64_t n = words * word_;
    if (stored(n) > left(at)) return std::nullopt;
    std::string text(static_cast<std::size_t>(stored(n)), '\0');
    if (in_.is_open()) {
      in_.seekg(static_cast<std::streamoff>(start_ + at));
      in_.read(&text[0], static_cast<std::streamsize>(text.size()));
    } else {
      text = text_.substr(static_cast<std::size_t>(at), text.size());
    }
    std::vector<unsigned char> bytes;
    if (!base64_)
      bytes.assign(text.begin(), text.end());
    else if (!decode(text, bytes) || bytes.size() < n)
      return std::nullopt;
    std::vector<std::uint64_t> out(static_cast<std::size_t>(words));
    for (std::uint64_t w = 0; w < words; ++w)
      for (std::uint64_t k = 0; k < word_; ++k)
        out[w] |= std::uint64_t(bytes[w * word_ + k]) << (8 * (big_ ? word_ - 1 - k : k));
    return out;
  }

 private:
  static bool decode(const std::string& text, std::vector<unsigned char>& out) {
    std::uint32_t acc = 0;
    int bits = 0;
    for (char c : text) {
      int v = c >= 'A' && c <= 'Z'   ? c - 'A'
              : c >= 'a' && c <= 'z' ? c - 'a' + 26
              : c >= '0' && c <= '9' ? c - '0' + 52
              : c == '+'             ? 62
              : c == '/'             ? 63
              : c == '='             ? -2
                                     : -1;
      if (v == -1) return false;
      if (v == -2) break;
      acc = (acc << 6) | std::uint32_t(v), bits += 6;
      if (bits >= 8) out.push_back(static_cast<unsigned char>(acc >> (bits -= 8)));
    }
    return true;
  }
  std::ifstream in_;
  std::string text_;
  std::uint64_t start_, size_, word_;
  bool big_, base64_;
};

// The file's first 4 MiB (its XML, before any appended data) and its size; nullopt when its size
// cannot be read (the reader says what is wrong with the file itself).
std::optional<std::pair<std::string, std::uint64_t>> xml_head(const std::string& path) {
  std::error_code ec;
  const std::uint64_t file_size = std::filesystem::file_size(path, ec);
  if (ec) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  std::string xml(static_cast<std::size_t>(std::min<std::uint64_t>(file_size, 1 << 22)), '\0');
  in.read(&xml[0], static_cast<std::streamsize>(xml.size()));
  xml.resize(static_cast<std::size_t>(in.gcount()));
  return std::make_pair(std::move(xml), file_size);
}

// An extent's six integers i0 i1 j0 j1 k0 k1, or nullopt when it has fewer.
std::optional<std::array<long long, 6>> extent(const std::string& text) {
  std::array<long long, 6> e{};
  std::istringstream in(text);
  for (long long& v : e)
    if (!(in >> v)) return std::nullopt;
  return e;
}

// Whether the pieces' point boxes cover every point of `whole`: on the grid of the intervals their
// bounds cut each axis into, every interval box lies in some piece.
bool pieces_cover(const std::array<long long, 6>& whole, const std::vector<std::array<long long, 6>>& pieces) {
  std::vector<long long> cuts[3];
  for (int a = 0; a < 3; ++a) {
    cuts[a] = {whole[2 * a], whole[2 * a + 1] + 1};
    for (const auto& p : pieces)
      for (long long c : {p[2 * a], p[2 * a + 1] + 1})
        if (c > whole[2 * a] && c <= whole[2 * a + 1]) cuts[a].push_back(c);
    std::sort(cuts[a].begin(), cuts[a].end());
    cuts[a].erase(std::unique(cuts[a].begin(), cuts[a].end()), cuts[a].end());
  }
  for (std::size_t i = 0; i + 1 < cuts[0].size(); ++i)
    for (std::size_t j = 0; j + 1 < cuts[1].size(); ++j)
      for (std::size_t k = 0; k + 1 < cuts[2].size(); ++k) {
        const long long lo[3] = {cuts[0][i], cuts[1][j], cuts[2][k]};  // the interval box's first point
        const bool covered = std::any_of(pieces.begin(), pieces.end(), [&](const auto& p) {
          return p[0] <= lo[0] && lo[0] <= p[1] && p[2] <= lo[1] && lo[1] <= p[3] && p[4] <= lo[2] && lo[2] <= p[5];
        });
        if (!covered) return false;
      }
  return true;
}

// An extent attribute of a structured file read as six integers, low to high on each axis (VTK's
// reader sizes its arrays from them: an inverted one ended in std::length_error); InputError
// naming `what` otherwise.
std::array<long long, 6> checked_extent(const std::string& path, const std::string& what, const std::string& text) {
  const auto e = extent(text);
  if (!e) throw InputError(where(path, "its " + what + " '" + text.substr(0, 60) + "' is not six integers"));
  for (int a = 0; a < 3; ++a)
    if ((*e)[2 * a + 1] < (*e)[2 * a])
      throw InputError(where(path, "its " + what + " '" + text.substr(0, 60) + "' runs backwards along " +
                                       std::string(1, static_cast<char>('x' + a)) + " (" + std::to_string((*e)[2 * a]) +
                                       " to " + std::to_string((*e)[2 * a + 1]) +
                                       "): a structured grid's extent goes from its low index to its high one"));
  return *e;
}

// A structured file's pieces against its WholeExtent, and a rectilinear piece's ASCII axes.
void check_extents(const std::string& path, const std::string& xml) {
  const std::size_t end = std::min(xml.find("<AppendedData"), xml.size());
  std::optional<std::array<long long, 6>> whole;
  std::vector<std::array<long long, 6>> pieces;
  int axis = -1;  // inside a rectilinear piece's Coordinates: the axis of its next DataArray
  for (std::size_t at = xml.find('<'); at < end; at = xml.find('<', at + 1)) {
    const std::size_t close = std::min(xml.find('>', at), end);
    const std::string tag = xml.substr(at, close - at);
    if (tag.rfind("<StructuredGrid", 0) == 0 || tag.rfind("<RectilinearGrid", 0) == 0 ||
        tag.rfind("<ImageData", 0) == 0) {
      if (const auto w = xml_attribute(tag, "WholeExtent")) whole = checked_extent(path, "WholeExtent", *w);
      // VTK's reader keeps its default for an Origin or Spacing it cannot parse ("1 nan 1" read as
      // spacing 1 without a word): the points would be placed where the file does not say.
      for (const char* name : {"Origin", "Spacing"})
        if (const auto value = xml_attribute(tag, name); value && tag.rfind("<ImageData", 0) == 0) {
          std::istringstream words(*value);
          double v[3];
          if (!(words >> v[0] >> v[1] >> v[2]) || !std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
            throw InputError(where(path, std::string("its ImageData ") + name + " '" + value->substr(0, 60) +
                                             "' is not three finite numbers"));
        }
    } else if (tag.rfind("<Piece", 0) == 0) {
      if (const auto e = xml_attribute(tag, "Extent"))
        pieces.push_back(checked_extent(path, "piece " + std::to_string(pieces.size()) + "'s Extent", *e));
    } else if (tag.rfind("<Coordinates", 0) == 0) {
      axis = 0;
    } else if (tag.rfind("</Coordinates", 0) == 0) {
      axis = -1;
    } else if (axis >= 0 && axis < 3 && tag.rfind("<DataArray", 0) == 0 && !pieces.empty()) {
      // VTK's XML reader takes an axis's ASCII coordinates short without a word and reads the
      // missing ones from past its array (a .vtr read with exit 0 and an inverted cell).
      const auto& e = pieces.back();
      const long long need = e[2 * axis + 1] - e[2 * axis] + 1;
      if (xml_attribute(tag, "format").value_or("") == "ascii" && need > 0) {
        std::istringstream values(xml.substr(close + 1, xml.find("</DataArray", close) - close - 1));
        long long n = 0;
        for (std::string word; n < need && values >> word;) ++n;
        if (n < need)
          throw InputError(where(path, "piece " + std::to_string(pieces.size() - 1) + "'s " +
                                           std::string(1, static_cast<char>('x' + axis)) + " coordinates hold " +
                                           std::to_string(n) + " values for the " + std::to_string(need) +
                                           " points of its extent along that axis"));
      }
      ++axis;
    }
  }
  // VTK's reader allocates the whole extent's points and fills each piece's: points no piece holds
  // keep whatever the memory held (a fuzzed file's bounds reached 7.6e31), read without a word.
  // Few pieces: the cover is checked exactly; many (a file rarely has them): left to VTK.
  if (!whole || pieces.empty() || pieces.size() > 16) return;
  const auto& w = *whole;
  if (!pieces_cover(w, pieces))
    throw InputError(where(path, "its pieces' extents do not cover its WholeExtent (" + std::to_string(w[0]) + " " +
                                     std::to_string(w[1]) + " " + std::to_string(w[2]) + " " + std::to_string(w[3]) +
                                     " " + std::to_string(w[4]) + " " + std::to_string(w[5]) +
                                     "): the points no piece holds would be undefined"));
}

// The uncompressed bytes of the array at `offset` of `data`: its byte count, or what its compression
// header declares, each checked against the data there. `fail(why)` makes the error naming the array.
template <class Fail>
std::uint64_t data_bytes(EncodedData& data, std::uint64_t offset, bool compressed, const Fail& fail) {
  if (compressed) {
    const auto head = data.header(offset, 3);
    if (!head) throw fail("its compression header runs past the end of its data, or is not " + data.encoding());
    const std::uint64_t blocks = (*head)[0], block = (*head)[1], last = (*head)[2];
    if (blocks > data.left(offset) / data.word())
      throw fail("its compression header declares " + std::to_string(blocks) + " blocks, more than its data holds");
    const auto sizes = data.header(offset, 3 + blocks);
    if (!sizes) throw fail("its compression header runs past the end of its data, or is not " + data.encoding());
    std::uint64_t packed = 0;
    for (std::uint64_t k = 0; k < blocks; ++k) packed += (*sizes)[3 + k];
    const std::uint64_t after = offset + data.stored((3 + blocks) * data.word());
    if (data.stored(packed) > data.left(after))
      throw fail("its " + std::to_string(blocks) + " compressed blocks declare " + std::to_string(packed) +
                 " bytes, past the end of its data");
    const std::uint64_t bytes = blocks == 0 ? 0 : (blocks - 1) * block + (last == 0 ? block : last);
    if (blocks > 0 && (block == 0 || last > block || bytes / 1032 > packed + 64))
      throw fail("its compression header declares " + std::to_string(bytes) + " bytes from " + std::to_string(packed) +
                 " compressed ones (block size " + std::to_string(block) + ", last block " + std::to_string(last) +
                 "): deflate expands at most 1032 times");
    return bytes;
  }
  const auto n = data.header(offset, 1);
  if (!n) throw fail("its byte count runs past the end of its data, or is not " + data.encoding());
  if (data.stored(data.word() + (*n)[0]) > data.left(offset))  // count and data: one run
    throw fail("it declares " + std::to_string((*n)[0]) + " bytes, past the end of its data (" +
               std::to_string(data.left(offset)) + (data.encoding() == "base64" ? " base64 characters" : " bytes") +
               " from its start)");
  return (*n)[0];
}

// Each binary DataArray's byte count or compression header against its data and the Piece's
// counts: those in the appended data section, and those inline as base64 text.
void check_binary_arrays(const std::string& path, const std::string& xml, std::uint64_t file_size) {
  const std::size_t appended = xml.find("<AppendedData");
  const std::size_t end = std::min(appended, xml.size());  // the XML before any appended data
  const std::size_t file_tag = xml.find("<VTKFile");
  const std::string file =
      file_tag == std::string::npos ? "" : xml.substr(file_tag, xml.find('>', file_tag) - file_tag);
  const bool compressed = xml_attribute(file, "compressor").has_value();
  const bool uint64 = xml_attribute(file, "header_type").value_or("UInt32") == "UInt64";
  const bool big = xml_attribute(file, "byte_order").value_or("LittleEndian") == "BigEndian";
  std::optional<EncodedData> section;  // the appended data, from its underscore on
  if (appended != std::string::npos) {
    const std::size_t open_end = xml.find('>', appended);
    if (open_end == std::string::npos) return;
    const std::string encoding = xml_attribute(xml.substr(appended, open_end - appended), "encoding").value_or("raw");
    if (encoding != "raw" && encoding != "base64")
      throw InputError(where(path, "the AppendedData encoding '" + encoding + "' is neither raw nor base64"));
    // The data starts after an underscore, the section's first character (VTK's reader, not finding
    // one there, read fuzzed files for 13 to 97 s and asked for 20 GB).
    const std::size_t first = xml.find_first_not_of(" \t\r\n", open_end + 1);
    if (first != std::string::npos && xml[first] != '_')
      throw InputError(where(path, "its AppendedData section does not begin with '_' (byte " + std::to_string(first) +
                                       "): where its arrays' offsets count from is unknown"));
    if (first != std::string::npos) section.emplace(path, first + 1, file_size, uint64, big, encoding == "base64");
  }
  // One Piece: its counts give the arrays' sizes (several: only the blocks are checked).
  std::int64_t points = -1, cells = -1;
  std::optional<std::array<long long, 6>> piece_extent;  // a rectilinear grid's: its axes' lengths
  if (xml.find("<Piece") == xml.rfind("<Piece", end) && xml.find("<Piece") != std::string::npos) {
    const std::size_t p = xml.find("<Piece");
    const std::string piece = xml.substr(p, xml.find('>', p) - p);
    points = std::atoll(xml_attribute(piece, "NumberOfPoints").value_or("-1").c_str());
    cells = std::atoll(xml_attribute(piece, "NumberOfCells").value_or("-1").c_str());
    if (const auto e = xml_attribute(piece, "Extent")) piece_extent = extent(*e);
  }
  std::string section_name;  // PointData, CellData, Points, Cells, Coordinates
  int axis = 0;              // in Coordinates: the axis of the next DataArray
  for (std::size_t at = xml.find('<'); at < end; at = xml.find('<', at + 1)) {
    const std::size_t close = std::min(xml.find('>', at), xml.size());
    const std::string tag = xml.substr(at, close - at);
    for (const char* s : {"<PointData", "<CellData", "<Points", "<Cells", "<FieldData", "<Coordinates"})
      if (tag.rfind(s, 0) == 0) section_name = s + 1, axis = 0;
    const int this_axis = tag.rfind("<DataArray", 0) == 0 && section_name == "Coordinates" ? axis++ : -1;
    if (tag.rfind("<DataArray", 0) != 0) continue;
    // An array VTK reads from the appended data: "appended", or a format it does not know with an
    // offset (a fuzzed format="appe" was read as appended, its garbled header sizing 16 GB).
    const std::string format = xml_attribute(tag, "format").value_or("");
    const std::string name = xml_attribute(tag, "Name").value_or("?");
    std::optional<EncodedData> inline_data;
    std::uint64_t offset = 0;
    std::string what = "DataArray '" + name + "'";
    if (format == "binary") {  // VTK reads an inline array cut short without a word: a wrong mesh
      const std::size_t stop = xml.find('<', close);          // the data ends at </DataArray> or an InformationKey
      if (stop == std::string::npos || stop > end) continue;  // past the head: not checked
      std::string text;
      for (std::size_t k = close + 1; k < stop; ++k)
        if (!std::isspace(static_cast<unsigned char>(xml[k]))) text += xml[k];
      inline_data.emplace(std::move(text), uint64, big);
      what += " (inline binary)";
    } else if (format != "ascii" && (format == "appended" || xml_attribute(tag, "offset")) && section) {
      offset = std::strtoull(xml_attribute(tag, "offset").value_or("0").c_str(), nullptr, 10);
      what += " (appended at offset " + std::to_string(offset) + ")";
    } else {
      continue;
    }
    EncodedData& data = inline_data ? *inline_data : *section;
    const auto fail = [&](const std::string& why) { return InputError(where(path, what + ": " + why)); };
    // What the Piece says it holds, in bytes (0: unknown).
    const std::uint64_t item = type_size(xml_attribute(tag, "type").value_or(""));
    const std::uint64_t comps =
        std::strtoull(xml_attribute(tag, "NumberOfComponents").value_or("1").c_str(), nullptr, 10);
    std::int64_t tuples = -1;
    if (section_name == "PointData" || section_name == "Points") tuples = points;
    if (section_name == "CellData" || (section_name == "Cells" && (name == "types" || name == "offsets")))
      tuples = cells;
    // VTK's reader takes an axis's coordinates short without a word and reads the missing ones from
    // past its array (a .vtr read with exit 0 and an inverted cell).
    if (this_axis >= 0 && this_axis < 3 && piece_extent)
      tuples = (*piece_extent)[2 * this_axis + 1] - (*piece_extent)[2 * this_axis] + 1;
    const std::uint64_t expected = tuples >= 0 && item > 0 ? std::uint64_t(tuples) * comps * item : 0;
    const std::uint64_t bytes = data_bytes(data, offset, compressed, fail);
    if (expected > 0 && bytes != expected)
      throw fail("it holds " + std::to_string(bytes) + " bytes where " + std::to_string(tuples) + " " +
                 (section_name == "CellData" || section_name == "Cells" ? "cells" : "points") + " of " +
                 std::to_string(comps) + " " + xml_attribute(tag, "type").value_or("") + " need " +
                 std::to_string(expected));
  }
}

}  // namespace

void check_vtk_xml(const std::string& path) {
  const auto head = xml_head(path);  // read once for both checks
  if (!head) return;
  check_binary_arrays(path, head->first, head->second);
  check_extents(path, head->first);
}

}  // namespace cellproj
