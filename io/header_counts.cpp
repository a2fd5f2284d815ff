#include "io/header_counts.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <netcdf.h>
#include <vtk_cgns.h>  // VTK's copy of the CGNS library, the one its reader uses
#include VTK_CGNS(cgnslib.h)

#include "base/error.hpp"
#include "base/file_status.hpp"
#include "io/netcdf_check.hpp"
#include "io/plot3d_header.hpp"
#include "io/read_mesh.hpp"
#include "io/text_scanner.hpp"
#include "io/xml_attribute.hpp"

namespace fs = std::filesystem;

namespace cellproj {
namespace {

// Counts from a garbled header can be anything: sums and products saturate instead of overflowing.
std::int64_t saturated(double v) { return v <= 0 ? 0 : v >= 1e15 ? std::int64_t(1e15) : static_cast<std::int64_t>(v); }

// A read buffer of 1 byte to 1 MiB, no larger than the file (a small file does not pay for a
// megabyte; never empty, so that reading a block always moves on).
std::string block_for(const std::string& path) {
  constexpr std::uintmax_t most = std::uintmax_t(1) << 20;
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  return std::string(static_cast<std::size_t>(ec ? most : std::clamp<std::uintmax_t>(size, 1, most)), '\0');
}

HeaderCounts xml_counts(const std::string& path, const std::string& ext) {
  HeaderCounts c;
  std::ifstream in(path, std::ios::binary);
  std::string xml = block_for(path);  // the XML part: every Piece element comes before the data
  in.read(&xml[0], static_cast<std::streamsize>(xml.size()));
  xml.resize(static_cast<std::size_t>(in.gcount()));
  const std::size_t data = xml.find("<AppendedData");
  if (data != std::string::npos) xml.resize(data);
  each_xml_attribute(xml, "NumberOfPoints",
                     [&](const std::string& v) { c.points = saturated(double(c.points) + std::atof(v.c_str())); });
  each_xml_attribute(xml, "NumberOfCells",
                     [&](const std::string& v) { c.cells = saturated(double(c.cells) + std::atof(v.c_str())); });
  if (ext == ".vts")
    each_xml_attribute(xml, "Extent", [&](const std::string& v) {  // a Piece's extent: i0 i1 j0 j1 k0 k1
      std::istringstream s(v);
      double e[6] = {};
      for (auto& x : e) s >> x;
      c.points = saturated(double(c.points) + (e[1] - e[0] + 1) * (e[3] - e[2] + 1) * (e[5] - e[4] + 1));
      c.cells = saturated(double(c.cells) +
                          std::max(e[1] - e[0], 1.0) * std::max(e[3] - e[2], 1.0) * std::max(e[5] - e[4], 1.0));
    });
  return c;
}

// Legacy VTK: the counts after the keywords "POINTS" and "CELLS" at a line's start, or for the
// grids without them (structured points, rectilinear) the points and cells of "DIMENSIONS nx ny nz".
// In a binary file they sit between the arrays, so the whole file is scanned, a block at a time.
HeaderCounts legacy_counts(const std::string& path) {
  HeaderCounts c;
  std::ifstream in(path, std::ios::binary);
  std::string block = block_for(path), carry;
  bool points = false, cells = false, dimensions = false;
  HeaderCounts grid;  // from DIMENSIONS
  while (!(points && cells) && in) {
    in.read(&block[0], static_cast<std::streamsize>(block.size()));
    const std::string text = carry + block.substr(0, static_cast<std::size_t>(in.gcount()));
    for (auto [key, out, seen] :
         {std::make_tuple("\nPOINTS ", &c.points, &points), std::make_tuple("\nCELLS ", &c.cells, &cells)}) {
      const auto at = text.find(key);
      if (*seen || at == std::string::npos || text.find('\n', at + 1) == std::string::npos) continue;
      *out = saturated(std::atof(text.c_str() + at + std::strlen(key)));
      *seen = true;
    }
    if (const auto at = text.find("\nDIMENSIONS ");
        !dimensions && at != std::string::npos && text.find('\n', at + 1) != std::string::npos) {
      std::istringstream s(text.substr(at + 12, 96));
      double n[3] = {1, 1, 1};
      s >> n[0] >> n[1] >> n[2];
      grid.points = saturated(n[0] * n[1] * n[2]);
      grid.cells = saturated(std::max(n[0] - 1, 1.0) * std::max(n[1] - 1, 1.0) * std::max(n[2] - 1, 1.0));
      dimensions = true;
    }
    carry = text.substr(text.size() - std::min<std::size_t>(text.size(), 64));
  }
  c.points = std::max(c.points, grid.points), c.cells = std::max(c.cells, grid.cells);
  return c;
}

// The first number of a text file's first line that is not a comment.
std::int64_t first_count(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    const auto at = line.find_first_not_of(" \t\r");
    if (at == std::string::npos || line[at] == '#') continue;
    return saturated(std::atof(line.c_str() + at));
  }
  return 0;
}

// The format by name, or "" where the name says none (header_counts is asked of any file).
std::string format_for_counts(const std::string& path) {
  try {
    return format_for(path);
  } catch (const Error&) {
    return "";
  }
}

// The headers only the format's own library reads (CGNS: HDF5 or ADF inside; Exodus in netCDF-4
// form: HDF5). These libraries may crash or call exit() on a garbled file: asked in the isolated
// reader's child only (library_header_counts, io/read_mesh.cpp).
// Every zone of every base: an unstructured zone's size is (vertices, cells, boundary vertices); a
// structured one's the vertices along each index direction, then the cells along each (SIDS 6.3).
HeaderCounts cgns_counts(const std::string& path) {
  int fn = -1;
  if (cg_open(path.c_str(), CG_MODE_READ, &fn) != CG_OK) {
    const std::string error = cg_get_error();
    throw InputError(where(path, error.find("llocat") != std::string::npos  // the library out of memory
                                     ? "the CGNS library ran out of memory opening it (" + error +
                                           "): a garbled size, or a setting 'max-memory' below what it needs"
                                     : "not a readable CGNS file: " + error));
  }
  HeaderCounts c;
  int bases = 0;
  cg_nbases(fn, &bases);
  for (int b = 1; b <= bases; ++b) {
    int zones = 0;
    if (cg_nzones(fn, b, &zones) != CG_OK) continue;
    for (int z = 1; z <= zones; ++z) {
      int dim = 0;
      char name[33] = {};
      cgsize_t size[9] = {};
      if (cg_index_dim(fn, b, z, &dim) != CG_OK || dim < 1 || dim > 3 || cg_zone_read(fn, b, z, name, size) != CG_OK)
        continue;  // VTK's reader says what is wrong with the zone
      double points = 1, cells = 1;
      for (int i = 0; i < dim; ++i) points *= double(size[i]), cells *= double(size[dim + i]);
      c.points = saturated(double(c.points) + std::max(points, 0.0));
      c.cells = saturated(double(c.cells) + std::max(cells, 0.0));
    }
  }
  cg_close(fn);
  return c;
}

// Exodus II's dimensions num_nodes and num_elem, through netCDF, for the netCDF-4 (HDF5) form that
// header_counts cannot read itself. A classic file ("CDF" magic) is left to header_counts: a
// garbled classic header can make netCDF allocate hundreds of megabytes before it fails, and
// check_netcdf_readable opens it once more anyway.
HeaderCounts exodus_counts(const std::string& path) {
  char magic[3] = {};
  if (std::ifstream(path, std::ios::binary).read(magic, 3) && std::string(magic, 3) == "CDF") return {};
  int id = -1;
  if (nc_open(path.c_str(), NC_NOWRITE, &id) != NC_NOERR) return {};  // check_netcdf_readable says why
  auto length = [&](const char* name) {
    std::size_t len = 0;
    if (int dim; nc_inq_dimid(id, name, &dim) == NC_NOERR) nc_inq_dimlen(id, dim, &len);
    return saturated(double(len));
  };
  const HeaderCounts c{length("num_nodes"), length("num_elem")};
  nc_close(id);
  return c;
}

}  // namespace

HeaderCounts header_counts(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".vtu" || ext == ".vts") return xml_counts(path, ext);
  if (ext == ".vtk") return legacy_counts(path);
  if (ext == ".off") {  // the reader's own scanner, so that comments count as they do there
    try {
      TextScanner in(path);
      const std::int64_t points = in.integer("the vertex count");
      return {points, in.integer("the tetrahedron count")};
    } catch (const Error&) {
      return {};  // the reader's message
    }
  }
  if (ext == ".exo" || ext == ".ex2" || ext == ".e" || ext == ".exii") {
    const auto h = read_classic_header(path);
    return h ? HeaderCounts{saturated(double(h->dim("num_nodes"))), saturated(double(h->dim("num_elem")))}
             : HeaderCounts{};
  }
  if (format_for_counts(path) == "plot3d") try {
      return plot3d_counts(path).value_or(HeaderCounts{});
    } catch (const Error&) {
      return {};  // the reader refuses it, with the same message
    }
  if (ext == ".node" || ext == ".ele") {
    const fs::path base = fs::path(path).replace_extension();
    return {first_count(base.string() + ".node"), first_count(base.string() + ".ele")};
  }
  return {};
}

HeaderCounts library_header_counts(const std::string& path, const std::string& format) {
  if (format == "cgns") return cgns_counts(path);
  if (format == "exodus") return exodus_counts(path);
  return {};
}

std::uint64_t estimate_mesh_bytes(const HeaderCounts& counts) {
  // Points as doubles with a few fields, cells as 64-bit connectivity of up to 8 ids plus offsets
  // and types; twice: the reader's arrays and the Mesh made from them.
  return 2 * (static_cast<std::uint64_t>(std::max<std::int64_t>(counts.points, 0)) * 64 +
              static_cast<std::uint64_t>(std::max<std::int64_t>(counts.cells, 0)) * 80);
}

}  // namespace cellproj
