#include "grid/netcdf_check.hpp"

#include <filesystem>
#include <limits>
#include <vector>

#include <netcdf.h>

#include "base/error.hpp"

namespace cellproj {

void check_netcdf_readable(const std::string& path) {
  int id = -1;
  if (int err = nc_open(path.c_str(), NC_NOWRITE, &id); err != NC_NOERR)
    throw InputError(where(path, std::string("not a readable Exodus II (netCDF) file: ") + nc_strerror(err)));
  int nvars = 0;
  nc_inq_nvars(id, &nvars);
  std::size_t nodes = 0;
  if (int dim; nc_inq_dimid(id, "num_nodes", &dim) == NC_NOERR) nc_inq_dimlen(id, dim, &nodes);
  // What the header promises, before anything is read: netCDF reads past the end of a truncated
  // classic file as fill values, silently (and VTK then sees node 0 in the connectivity).
  auto elements = [&](int v, std::size_t& count, std::size_t& size) {
    int ndims = 0;
    nc_type type;
    nc_inq_var(id, v, nullptr, &type, &ndims, nullptr, nullptr);
    std::vector<int> dims(static_cast<std::size_t>(ndims));
    nc_inq_vardimid(id, v, dims.data());
    count = 1;
    for (int d : dims) {
      std::size_t len = 0;
      nc_inq_dimlen(id, d, &len);
      count = len != 0 && count > std::numeric_limits<std::size_t>::max() / 16 / len
                  ? std::numeric_limits<std::size_t>::max() / 16
                  : count * len;
    }
    nc_inq_type(id, type, nullptr, &size);
    return type;
  };
  int format = 0;
  nc_inq_format(id, &format);
  if (format == NC_FORMAT_CLASSIC || format == NC_FORMAT_64BIT_OFFSET || format == NC_FORMAT_CDF5) {
    std::uintmax_t data_bytes = 0;  // the header promises at least this much data after it
    for (int v = 0; v < nvars; ++v) {
      std::size_t count = 0, size = 0;
      elements(v, count, size);
      data_bytes += (static_cast<std::uintmax_t>(count) * size + 3) / 4 * 4;
    }
    if (const std::uintmax_t file = std::filesystem::file_size(path); file < data_bytes) {
      nc_close(id);
      throw InputError(where(path, "truncated: the header describes " + std::to_string(data_bytes) +
                                       " bytes of data, the file has " + std::to_string(file) + " bytes in all"));
    }
  }
  std::vector<unsigned char> buf;
  for (int v = 0; v < nvars; ++v) {
    std::size_t count = 0, size = 0;
    const nc_type type = elements(v, count, size);
    if (count == 0 || type == NC_CHAR) continue;
    buf.resize(count * size);
    if (int err = nc_get_var(id, v, buf.data()); err != NC_NOERR) {
      char name[NC_MAX_NAME + 1] = {};
      nc_inq_varname(id, v, name);
      nc_close(id);
      throw InputError(where(path, std::string("truncated or corrupt: variable '") + name + "' cannot be read (" +
                                       nc_strerror(err) + ")"));
    }
    // Element connectivity (1-based node numbers): VTK's reader indexes with it unchecked.
    char name[NC_MAX_NAME + 1] = {};
    nc_inq_varname(id, v, name);
    if (std::string(name).rfind("connect", 0) == 0 && nodes > 0) {
      std::vector<long long> ids(count);
      nc_get_var_longlong(id, v, ids.data());
      for (std::size_t i = 0; i < count; ++i)
        if (ids[i] < 1 || ids[i] > static_cast<long long>(nodes)) {
          nc_close(id);
          throw InputError(where(path, std::string("corrupt: ") + name + " entry " + std::to_string(i) + " is node " +
                                           std::to_string(ids[i]) + ", outside [1, " + std::to_string(nodes) + "]"));
        }
    }
  }
  nc_close(id);
}

}  // namespace cellproj
