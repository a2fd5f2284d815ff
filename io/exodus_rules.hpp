#pragma once
// What VTK's Exodus II reader takes for granted about an open netCDF file and crashed on in fuzzed
// files, each asked of netCDF by check_netcdf_readable before the reader runs. The *_problem
// functions return what is wrong (empty when nothing is).
#include <cstddef>
#include <string>
#include <vector>

#include <netcdf.h>

namespace cellproj {

// netCDF's integer types: Exodus II stores ids, statuses and connectivity as int or int64.
bool integer_type(nc_type t);

// The node counts of an element type VTK's Exodus reader reads right, by the first three letters
// of its name (TETRA4, tet, ...); empty for a type it does not know (its reader refuses those).
std::vector<int> exodus_node_counts(const std::string& elem_type);

// Active element block b (1-based) of the open file `id`, after "element block b of n" (so
// starting with " " or ": ").
std::string block_problem(int id, std::size_t b);

// The global attribute maximum_name_length, when present.
std::string name_length_problem(int id);

// Object ids (eb_prop1, ns_prop1, ...): integers, unique within their kind.
std::string repeated_id_problem(int id);

}  // namespace cellproj
