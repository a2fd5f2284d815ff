#pragma once
#include <string>

namespace cellproj {
// Checks a netCDF file (Exodus II is netCDF) before VTK's Exodus reader, which does not check and
// crashes on a truncated file: a classic file must hold every byte its header places, every
// variable must read, and element connectivity must name existing nodes. Throws InputError.
void check_netcdf_readable(const std::string& path);
}  // namespace cellproj
