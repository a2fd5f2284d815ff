#pragma once
#include <string>

namespace cellproj {
// Reads every variable of a netCDF file (Exodus II is netCDF) and throws InputError if any read
// fails: VTK's Exodus reader does not check and crashes on a truncated file.
void check_netcdf_readable(const std::string& path);
}  // namespace cellproj
