#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cellproj {

// What a classic netCDF header (CDF-1, CDF-2 64-bit offset, CDF-5) says, read by our own
// bounds-checked walk, so that the parent process can ask it before any library parses the file.
struct ClassicHeader {
  std::vector<std::pair<std::string, std::uint64_t>> dims;  // name, length (0: the record dimension)
  std::uint64_t data_end = 0;  // the first byte after every variable's data, where the header places it
  std::string last_variable;   // the variable ending there
  std::uint64_t dim(const std::string& name) const;  // 0 when absent
};
// nullopt when the file is not classic netCDF (netCDF-4 is HDF5) or its header is malformed; then
// *problem, when given, says what when a count of the header (dimensions, attributes, variables,
// a name's or values' length) exceeds what the rest of the file can hold.
std::optional<ClassicHeader> read_classic_header(const std::string& path, std::string* problem = nullptr);

// Where an HDF5 file (netCDF-4) ends by its superblock (base address plus end-of-file address);
// nullopt when the file does not start with an HDF5 superblock this reads (versions 0 to 3).
std::optional<std::uint64_t> hdf5_end_of_file(const std::string& path);

// Checks a netCDF file (Exodus II is netCDF) before VTK's Exodus reader, which does not check and
// crashes on a truncated file: a classic file must hold every byte its header places, a netCDF-4
// one every byte its HDF5 superblock says the file has; a classic header's counts must fit in the
// file and its variables have known types; element blocks need nodes, an elem_type and a
// connectivity of their shape holding integers and a node count their elem_type has, coordinates
// one value per node, declared results their names, object ids (eb_prop1, ...) and eb_status
// integers, ids unique, maximum_name_length within 1..NC_MAX_NAME, no classic variable more
// values than the file's bytes; every variable must read, and element connectivity must name
// existing nodes. Throws InputError.
void check_netcdf_readable(const std::string& path);
}  // namespace cellproj
