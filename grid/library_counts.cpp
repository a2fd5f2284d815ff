// Counts from the headers that only the format's own library can read: CGNS (HDF5 or ADF inside)
// and Exodus in netCDF-4 form (HDF5). Asked in the isolated reader's child, before VTK's reader:
// these libraries may crash or call exit() on a garbled file (docs/reliability.md).
#include <vtk_cgns.h>  // VTK's copy of the CGNS library, the one its reader uses
#include VTK_CGNS(cgnslib.h)

#include <netcdf.h>

#include <algorithm>

#include "base/error.hpp"
#include "grid/header_counts.hpp"

namespace cellproj {
namespace {

// Counts from a garbled header can be anything: products and sums saturate instead of overflowing.
std::int64_t saturated_add(std::int64_t a, double b) {
  const double s = double(a) + std::max(b, 0.0);
  return s >= 1e15 ? std::int64_t(1e15) : static_cast<std::int64_t>(s);
}

// Every zone of every base: an unstructured zone's size is (vertices, cells, boundary vertices); a
// structured one's the vertices along each index direction, then the cells along each (SIDS 6.3).
HeaderCounts cgns_counts(const std::string& path) {
  int fn = -1;
  if (cg_open(path.c_str(), CG_MODE_READ, &fn) != CG_OK)
    throw InputError(where(path, std::string("not a readable CGNS file: ") + cg_get_error()));
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
      c.points = saturated_add(c.points, points);
      c.cells = saturated_add(c.cells, cells);
    }
  }
  cg_close(fn);
  return c;
}

// Exodus II's dimensions num_nodes and num_elem, through netCDF (either form: classic or HDF5).
HeaderCounts exodus_counts(const std::string& path) {
  int id = -1;
  if (nc_open(path.c_str(), NC_NOWRITE, &id) != NC_NOERR) return {};  // check_netcdf_readable says why
  auto length = [&](const char* name) {
    std::size_t len = 0;
    if (int dim; nc_inq_dimid(id, name, &dim) == NC_NOERR) nc_inq_dimlen(id, dim, &len);
    return saturated_add(0, double(len));
  };
  const HeaderCounts c{length("num_nodes"), length("num_elem")};
  nc_close(id);
  return c;
}

}  // namespace

HeaderCounts library_header_counts(const std::string& path, const std::string& format) {
  if (format == "cgns") return cgns_counts(path);
  if (format == "exodus") return exodus_counts(path);
  return {};
}

}  // namespace cellproj
