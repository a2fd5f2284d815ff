#include "io/plot3d_header.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "base/error.hpp"

namespace cellproj {
namespace {

// The file's 4-byte integers, in the byte order VTK's reader settles on.
class Ints {
 public:
  Ints(const std::string& path, std::uint64_t size) : in_(path, std::ios::binary), size_(size) {
    unsigned char b[4] = {};
    in_.read(reinterpret_cast<char*>(b), 4);
    big_ = b[0] == 0 && b[3] != 0;  // VTK's test: a small first count or dimension, its high byte first
  }
  Ints(const std::string& path, std::uint64_t size, bool big_endian)  // the order given (a q file's is its grid's)
      : in_(path, std::ios::binary), size_(size), big_(big_endian) {}
  bool big_endian() const { return big_; }
  // The integer at byte `at`, or nullopt past the end of the file.
  std::optional<std::int64_t> at(std::uint64_t at) {
    if (at + 4 > size_) return std::nullopt;
    unsigned char b[4] = {};
    in_.seekg(static_cast<std::streamoff>(at));
    in_.read(reinterpret_cast<char*>(b), 4);
    std::uint32_t v = 0;
    for (int k = 0; k < 4; ++k) v |= std::uint32_t(b[k]) << (8 * (big_ ? 3 - k : k));
    return static_cast<std::int32_t>(v);
  }

 private:
  std::ifstream in_;
  std::uint64_t size_;
  bool big_ = false;
};

struct Grids {
  int ndims = 3;
  std::vector<std::array<std::int64_t, 3>> dims;  // 1 in the third for a 2D grid
  std::uint64_t header = 0;                       // bytes before the first grid's coordinates
};

std::uint64_t points(const std::array<std::int64_t, 3>& d) { return std::uint64_t(d[0]) * d[1] * d[2]; }

// The file's size under a layout, as VTK's reader computes it (saturating at 2^62).
std::uint64_t file_bytes(const Grids& g, int precision, bool iblank, bool records) {
  double bytes = double(g.header);
  for (const auto& d : g.dims)
    bytes += double(points(d)) * (g.ndims * precision + (iblank ? 4 : 0)) + (records ? 8 : 0);
  return bytes >= 4.6e18 ? std::uint64_t(1) << 62 : std::uint64_t(bytes);
}

HeaderCounts counts_of(const Grids& g) {
  double p = 0, c = 0;
  for (const auto& d : g.dims) {
    p += double(points(d));
    c += double(std::max<std::int64_t>(d[0] - 1, 1)) * std::max<std::int64_t>(d[1] - 1, 1) *
         std::max<std::int64_t>(d[2] - 1, 1);
  }
  return {static_cast<std::int64_t>(std::min(p, 1e15)), static_cast<std::int64_t>(std::min(c, 1e15))};
}

// `grids` grids of `ndims` dimensions each from byte `at`; false where one is below 1 or past the end.
bool read_dims(Ints& ints, std::uint64_t at, std::int64_t grids, int ndims, Grids& g) {
  g.ndims = ndims;
  for (std::int64_t k = 0; k < grids; ++k) {
    std::array<std::int64_t, 3> d{1, 1, 1};
    for (int a = 0; a < ndims; ++a) {
      const auto v = ints.at(at);
      if (!v || *v < 1) return false;
      d[a] = *v;
      at += 4;
    }
    g.dims.push_back(d);
  }
  g.header = at;
  return true;
}

}  // namespace

std::optional<HeaderCounts> plot3d_counts(const std::string& path) {
  const std::optional<Plot3dLayout> layout = plot3d_layout(path);
  if (!layout) return std::nullopt;
  Grids g;
  g.ndims = layout->ndims;
  g.dims = layout->dims;
  return counts_of(g);
}

std::optional<Plot3dLayout> plot3d_layout(const std::string& path) {
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) return std::nullopt;  // the reader names what is wrong with the file itself
  {
    std::ifstream in(path, std::ios::binary);
    char head[12] = {};
    in.read(head, 12);
    const auto text = [](char c) {
      return std::isdigit(static_cast<unsigned char>(c)) || (c != 0 && std::strchr(". \r\n\t", c));
    };
    if (size >= 12 && std::all_of(head, head + 12, text))
      return std::nullopt;  // ASCII PLOT3D (VTK's own test; a zero byte is binary): parsed as text
  }
  Ints ints(path, size);
  const std::string order = ints.big_endian() ? "big-endian" : "little-endian";
  const auto refuse = [&](const std::string& what) {
    return InputError(where(path, "PLOT3D grid (" + order + "): truncated or corrupt: " + what + "; the file has " +
                                      std::to_string(size) + " bytes"));
  };
  // Fortran records: the first integer is a record's length, repeated after it (VTK's test).
  const auto first = ints.at(0);
  if (!first) throw refuse("no header");
  const auto repeat = *first >= 0 ? ints.at(4 + std::uint64_t(*first)) : std::nullopt;
  Grids g;
  if (repeat && *repeat == *first) {
    const bool multi = *first == 4;  // a record of one integer: the number of grids
    std::int64_t grids = 1;
    std::uint64_t at = 0;
    if (multi) {
      const auto n = ints.at(4);
      if (!n || *n < 1 || *n > 10000000)
        throw refuse("the grid count record holds " + (n ? std::to_string(*n) : "nothing"));
      grids = *n;
      at = 12;
    }
    const auto marker = ints.at(at);
    const int ndims = marker && (*marker == 12 * grids + 8 || *marker == 12 * grids) ? 3 : 2;
    if (!read_dims(ints, at + 4, grids, ndims, g))
      throw refuse("the dimensions record of " + std::to_string(grids) +
                   " grid(s) holds a dimension below 1 or ends early");
    g.header += 4;
    // The first grid's record length gives the precision and IBLANK, as VTK reads them.
    const auto record = ints.at(g.header);
    for (int precision : {4, 8})
      for (bool iblank : {false, true})
        if (record && std::uint64_t(*record) == points(g.dims[0]) * (g.ndims * precision + (iblank ? 4 : 0))) {
          if (file_bytes(g, precision, iblank, true) > size)
            throw refuse("its dimensions, the first grid " + std::to_string(g.dims[0][0]) + " x " +
                         std::to_string(g.dims[0][1]) + " x " + std::to_string(g.dims[0][2]) + ", need " +
                         std::to_string(file_bytes(g, precision, iblank, true)) + " bytes");
          return Plot3dLayout{ints.big_endian(), true, multi, iblank, precision, g.ndims, g.dims};
        }
    throw refuse("the first grid's coordinate record is " +
                 (record ? std::to_string(*record) : std::string("missing")) +
                 " bytes long, which no precision (4 or 8 bytes) with or without IBLANK gives for its " +
                 std::to_string(points(g.dims[0])) + " points");
  }
  // Written from C, without records: the dimensions whose coordinates fill the file exactly, one
  // grid first, then a grid count and that many grids (VTK's search).
  for (bool multi : {false, true}) {
    std::int64_t grids = 1;
    if (multi) {
      grids = *first;
      if (grids < 1 || 4 + 12 * std::uint64_t(grids) > size) break;
    }
    for (int ndims : {3, 2}) {
      Grids c;
      if (!read_dims(ints, multi ? 4 : 0, grids, ndims, c)) continue;
      for (int precision : {4, 8})
        for (bool iblank : {false, true})
          if (file_bytes(c, precision, iblank, false) == size)
            return Plot3dLayout{ints.big_endian(), false, multi, iblank, precision, c.ndims, c.dims};
    }
  }
  const auto d = [&](std::uint64_t at) {
    const auto v = ints.at(at);
    return v ? std::to_string(*v) : "?";
  };
  throw refuse("no layout without record markers fits: read as one grid it declares " + d(0) + " x " + d(4) + " x " +
               d(8) + " points, as several " + d(0) + " grids");
}

void check_plot3d_q(const std::string& q, const Plot3dLayout& grid) {
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(q, ec);
  if (ec) return;  // the reader names what is wrong with the file itself
  Ints ints(q, size, grid.big_endian);
  const auto refuse = [&](const std::string& what) {
    return InputError(where(q, "PLOT3D solution (q) file: truncated or corrupt: " + what + "; the file has " +
                                   std::to_string(size) + " bytes"));
  };
  const std::uint64_t marker = grid.records ? 4 : 0;  // a Fortran record's length, before and after it
  std::uint64_t at = marker;
  const std::int64_t grids = static_cast<std::int64_t>(grid.dims.size());
  if (grid.multi_grid) {
    const auto n = ints.at(at);
    if (!n || *n != grids)
      throw refuse("its grid count is " + (n ? std::to_string(*n) : std::string("missing")) + ", the grid file has " +
                   std::to_string(grids));
    at += 4 + 2 * marker;
  }
  for (std::int64_t k = 0; k < grids; ++k)
    for (int a = 0; a < grid.ndims; ++a, at += 4) {
      const auto v = ints.at(at);
      if (!v || *v != grid.dims[k][a])
        throw refuse("grid " + std::to_string(k + 1) + "'s dimension " + std::to_string(a + 1) + " is " +
                     (v ? std::to_string(*v) : std::string("missing")) + ", the grid file's is " +
                     std::to_string(grid.dims[k][a]));
    }
  at += marker;
  // Per grid: the properties record (Mach number, angle of attack, Reynolds number, time), then
  // density, ndims momentum components and energy per point (VTK's ReadQHeader and its data loop).
  double need = double(at);
  for (const auto& d : grid.dims)
    need +=
        double(4 * grid.precision + 2 * marker) + double(points(d)) * (grid.ndims + 2) * grid.precision + 2 * marker;
  if (need > double(size))
    throw refuse("its " + std::to_string(grids) + " grid(s) of " + std::to_string(grid.ndims + 2) + " variables need " +
                 std::to_string(static_cast<std::uint64_t>(std::min(need, 4.6e18))) + " bytes");
}

}  // namespace cellproj
