#include "io/exodus_rules.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

namespace cellproj {

// netCDF's integer types: Exodus II stores ids, statuses and connectivity as int or int64.
bool integer_type(nc_type t) {
  return t == NC_BYTE || t == NC_SHORT || t == NC_INT || t == NC_UBYTE || t == NC_USHORT || t == NC_UINT ||
         t == NC_INT64 || t == NC_UINT64;
}

// The node counts of an element type that VTK's Exodus reader reads right, by the first three
// letters of the type's name as it matches them (TETRA4, tet, ...); empty for a type it does not
// know (its reader refuses those itself). VTK builds its cell from the type and the count and steps
// through the connectivity by its cell's size: for any other count it reads the wrong nodes (a
// HEX of 5 ran past the block and crashed; HEX9, TETRA8 or WEDGE12 read with exit 0 and every
// element after the first on the wrong nodes: bench/exodus_node_counts.py). The volume counts, as
// measured: linear, then the quadratic and Lagrange cells VTK makes of them (which cellproj refuses
// by type). The surface and line types, whose cells cellproj skips, keep Exodus II's counts: what
// matters there is a count below the linear one, which read past the block.
std::vector<int> exodus_node_counts(const std::string& elem_type) {
  std::string k = elem_type.substr(0, 3);
  for (char& ch : k) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  if (k == "TET") return {4, 10, 15};
  if (k == "HEX") return {8, 20, 27};
  if (k == "WED") return {6, 15, 18, 21};
  if (k == "PYR") return {5, 13};
  if (k == "TRI") return {3, 4, 6, 7};
  if (k == "QUA") return {4, 5, 8, 9};
  if (k == "SHE") return {3, 4, 6, 8, 9};
  if (k == "BAR" || k == "BEA" || k == "TRU" || k == "EDG") return {2, 3};
  if (k == "SPH" || k == "CIR") return {1};
  return {};
}

// What is wrong with active element block b (1-based) of an Exodus II file, after ": " (empty when
// nothing): VTK's reader indexes num_el_in_blkN, num_nod_per_elN and connectN without asking
// whether they exist, reads connectN by its block's dimensions whatever its own shape (connect1
// and connect2 swapped crashed it), registers the block by its elem_type (without one it looked up
// a block it never sorted) and sizes its cells by the type, not by num_nod_per_elN.
std::string block_problem(int id, std::size_t b) {
  const std::string n = std::to_string(b);
  int shape[2] = {-1, -1};  // the block's element count and nodes per element
  for (int k : {0, 1}) {
    const std::string dim = (k == 0 ? "num_el_in_blk" : "num_nod_per_el") + n;
    if (nc_inq_dimid(id, dim.c_str(), &shape[k]) != NC_NOERR) return " has no dimension '" + dim + "'";
  }
  const std::string connect = "connect" + n;
  int v = -1;
  if (nc_inq_varid(id, connect.c_str(), &v) != NC_NOERR) return " has no connectivity variable '" + connect + "'";
  int ndims = 0, dims[2] = {-1, -1};
  if (nc_inq_varndims(id, v, &ndims) != NC_NOERR || ndims != 2 || nc_inq_vardimid(id, v, dims) != NC_NOERR ||
      dims[0] != shape[0] || dims[1] != shape[1])
    return ": its connectivity '" + connect + "' is not shaped (num_el_in_blk" + n + ", num_nod_per_el" + n + ")";
  nc_type type;
  if (nc_inq_vartype(id, v, &type) != NC_NOERR || !integer_type(type))
    return ": its connectivity '" + connect + "' does not hold integers";
  std::size_t length = 0, per_element = 0;
  if (nc_inq_atttype(id, v, "elem_type", &type) != NC_NOERR || type != NC_CHAR ||
      nc_inq_attlen(id, v, "elem_type", &length) != NC_NOERR)
    return ": its connectivity '" + connect + "' has no text attribute 'elem_type'";
  std::string elem_type(length, '\0');
  nc_get_att_text(id, v, "elem_type", elem_type.data());
  elem_type = elem_type.c_str();  // up to a terminating NUL, as the reader reads it
  nc_inq_dimlen(id, shape[1], &per_element);
  const std::vector<int> counts = exodus_node_counts(elem_type);
  if (!counts.empty() && std::find(counts.begin(), counts.end(), static_cast<long long>(per_element)) == counts.end()) {
    std::string allowed;
    for (std::size_t k = 0; k < counts.size(); ++k)
      allowed += (k == 0 ? "" : k + 1 == counts.size() ? " or " : ", ") + std::to_string(counts[k]);
    return ": its elements of type '" + elem_type + "' have " + std::to_string(per_element) +
           (per_element == 1 ? " node" : " nodes") + " each (num_nod_per_el" + n + "); VTK's Exodus reader reads " +
           "that type with " + allowed + " (with other counts it reads the wrong nodes)";
  }
  return "";
}

// Exodus II's global "maximum_name_length" sizes VTK's name buffers, while netCDF copies names of
// up to len_name into them: outside 1..NC_MAX_NAME it overflowed them (fuzzed files with 0 and
// -2147483616). Empty when the attribute is absent or fine.
std::string name_length_problem(int id) {
  nc_type type;
  std::size_t len = 0;
  if (nc_inq_att(id, NC_GLOBAL, "maximum_name_length", &type, &len) != NC_NOERR) return "";
  long long value = 0;
  if (type == NC_CHAR || type == NC_STRING || type == NC_FLOAT || type == NC_DOUBLE || len != 1 ||
      nc_get_att_longlong(id, NC_GLOBAL, "maximum_name_length", &value) != NC_NOERR)
    return "its attribute 'maximum_name_length' is not one integer";
  if (value < 1 || value > NC_MAX_NAME)
    return "its attribute 'maximum_name_length' is " + std::to_string(value) + ", outside [1, " +
           std::to_string(NC_MAX_NAME) + "]";
  return "";
}

// Exodus II gives each object an id (its first property, "ID": eb_prop1 for element blocks) that
// must be unique within its kind: VTK's reader maps ids to objects, and repeated ids crashed it (all
// 0) or merged two blocks into one, silently (1, 1, 2, 3). Empty when every id is distinct.
std::string repeated_id_problem(int id) {
  static const std::pair<const char*, const char*> kinds[] = {
      {"eb", "element block"}, {"ns", "node set"},     {"ss", "side set"},   {"em", "element map"},
      {"nm", "node map"},      {"ed", "edge block"},   {"fa", "face block"}, {"es", "edge set"},
      {"fs", "face set"},      {"els", "element set"}, {"edm", "edge map"},  {"fam", "face map"}};
  for (const auto& [prefix, kind] : kinds) {
    const std::string name = std::string(prefix) + "_prop1";
    int v = -1, ndims = 0, dim = -1;
    std::size_t count = 0;
    if (nc_inq_varid(id, name.c_str(), &v) != NC_NOERR || nc_inq_varndims(id, v, &ndims) != NC_NOERR || ndims != 1 ||
        nc_inq_vardimid(id, v, &dim) != NC_NOERR || nc_inq_dimlen(id, dim, &count) != NC_NOERR || count == 0)
      continue;
    if (nc_type type; nc_inq_vartype(id, v, &type) != NC_NOERR || !integer_type(type))
      return std::string(kind) + " ids '" + name + "' are not integers";
    if (count < 2) continue;
    std::vector<long long> ids(count);
    if (nc_get_var_longlong(id, v, ids.data()) != NC_NOERR) continue;  // the read loop names the failure
    std::vector<std::size_t> order(count);
    for (std::size_t i = 0; i < count; ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return ids[a] < ids[b]; });
    for (std::size_t k = 1; k < count; ++k)
      if (ids[order[k]] == ids[order[k - 1]])
        return std::string(kind) + "s " + std::to_string(order[k - 1] + 1) + " and " + std::to_string(order[k] + 1) +
               " both have the id " + std::to_string(ids[order[k]]) + " ('" + name + "'); ids must be unique";
  }
  return "";
}

}  // namespace cellproj
