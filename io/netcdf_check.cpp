#include "io/netcdf_check.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <system_error>
#include <vector>

#include <netcdf.h>

#include "base/error.hpp"
#include "io/exodus_rules.hpp"

namespace cellproj {
namespace {

// Big-endian fields of a classic netCDF header (CDF-1, CDF-2 64-bit offset, CDF-5), bounds-checked.
struct HeaderCursor {
  const std::vector<unsigned char>& bytes;  // the file's first bytes (or all of it)
  std::uint64_t file_size = 0;
  std::string* problem = nullptr;  // set (and the walk stopped) when a count exceeds what the file holds
  std::size_t at = 0;
  bool ok = true;
  bool started = false;  // past the magic number and version: a classic file's header
  std::uint64_t read(int n) {
    if (!ok || at + static_cast<std::size_t>(n) > bytes.size()) return ran_out(), 0;
    std::uint64_t v = 0;
    for (int k = 0; k < n; ++k) v = v << 8 | bytes[at++];
    return v;
  }
  void skip(std::uint64_t n) {
    if (!ok || n > bytes.size() - at)
      ran_out();
    else
      at += static_cast<std::size_t>(n);
  }
  // Past the bytes read: when they are the whole file, the header is cut short, and netCDF reads
  // on past the end (a 15-byte file took it 15 s of zero-filled dimensions before it gave up).
  void ran_out() {
    if (started && bytes.size() >= file_size)
      refuse("its classic netCDF header is cut short: the file ends at byte " + std::to_string(file_size) +
             ", inside it");
    ok = false;
  }
  // Stops the walk with *problem = what (a header netCDF itself misreads).
  void refuse(const std::string& what) {
    if (problem && ok) *problem = what;
    ok = false;
  }
  // Whether `count` entries of at least `each` bytes fit in the rest of the file; if not, refuses:
  // netCDF sizes its tables by such counts before it reads the entries (a 530-byte file declaring
  // 16 million dimensions ran its hash map out of memory).
  bool fits(std::uint64_t count, std::uint64_t each, const char* what) {
    const std::uint64_t rest = file_size > at ? file_size - at : 0;
    if (!ok || count <= rest / each) return ok;
    refuse("its header declares " + std::to_string(count) + " " + what + " at byte " + std::to_string(at) +
           ", more than the " + std::to_string(rest) + " bytes after it can hold (at least " + std::to_string(each) +
           " bytes each)");
    return false;
  }
};

std::uint64_t type_size(std::uint64_t type) {
  static constexpr int kSize[12] = {0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8};  // NC_BYTE .. NC_UINT64
  return type < 12 ? static_cast<std::uint64_t>(kSize[type]) : 0;
}

// The header walked as the classic format specifies (NetCDF Users Guide, "File Format
// Specification"): magic numrecs dim_list gatt_list var_list, each var = name dimids vatt_list
// nc_type vsize begin. Unpadded sizes, so that a last variable written without its padding still
// counts as complete.
std::optional<ClassicHeader> walk_classic_header(const std::vector<unsigned char>& bytes, std::uint64_t file_size,
                                                 std::string* problem) {
  HeaderCursor c{bytes, file_size, problem};
  if (c.read(3) != 0x434446) return std::nullopt;  // "CDF"
  const std::uint64_t version = c.read(1);
  if (version != 1 && version != 2 && version != 5) return std::nullopt;
  c.started = true;
  const int word = version == 5 ? 8 : 4, offset = version == 1 ? 4 : 8;
  const std::uint64_t numrecs = c.read(word);
  const bool streaming = numrecs == (word == 8 ? ~0ull : 0xFFFFFFFFull);
  auto name = [&] {
    const std::uint64_t n = c.read(word);
    if (!c.fits(n, 1, "name bytes")) return std::string();
    const std::size_t from = c.at;
    c.skip((n + 3) / 4 * 4);
    return c.ok ? std::string(bytes.begin() + from, bytes.begin() + from + n) : std::string();
  };
  auto attributes = [&] {
    c.read(4);  // NC_ATTRIBUTE, or ZERO when absent
    const std::uint64_t n = c.read(word);
    c.fits(n, 2 * word + 4, "attributes");  // name, type, count
    for (std::uint64_t a = 0; a < n && c.ok; ++a) {
      name();
      const std::uint64_t size = type_size(c.read(4)), count = c.read(word);
      if (size == 0 || !c.fits(count, size, "attribute values")) return void(c.ok = false);
      c.skip((count * size + 3) / 4 * 4);
    }
  };
  ClassicHeader out;
  c.read(4);  // NC_DIMENSION, or ZERO when absent
  const std::uint64_t n_dims = c.read(word);
  c.fits(n_dims, 2 * word, "dimensions");  // name, length
  for (std::uint64_t d = 0; d < n_dims && c.ok; ++d) {
    std::string dim_name = name();
    out.dims.emplace_back(std::move(dim_name), c.read(word));
  }
  attributes();
  struct Var {
    std::string name;
    std::uint64_t begin, record_bytes;  // record_bytes: the bytes of one record (or of all, if fixed)
    bool record;
  };
  std::vector<Var> vars;
  c.read(4);  // NC_VARIABLE, or ZERO when absent
  const std::uint64_t n_vars = c.read(word);
  c.fits(n_vars, 4 * word + 8 + offset, "variables");  // name, dimensions, attributes, type, vsize, begin
  for (std::uint64_t v = 0; v < n_vars && c.ok; ++v) {
    Var var{name(), 0, 1, false};
    const std::uint64_t nd = c.read(word);
    c.fits(nd, word, "dimension ids of a variable");
    for (std::uint64_t k = 0; k < nd && c.ok; ++k) {
      const std::uint64_t id = c.read(word);
      if (id >= out.dims.size()) return std::nullopt;
      const std::uint64_t len = out.dims[id].second;
      // netCDF divides by the product of a variable's later dimensions (NC_check_vlen): the record
      // dimension (length 0) past the first made it divide by zero (a fuzzed Exodus file).
      if (k > 0 && len == 0)
        c.refuse("variable '" + var.name + "' has the record dimension '" + out.dims[id].first + "' as its dimension " +
                 std::to_string(k + 1) + ": only the first may be");
      if (k == 0 && len == 0)
        var.record = true;
      else if (len != 0)
        var.record_bytes = len > (1ull << 62) / var.record_bytes ? 1ull << 62 : var.record_bytes * len;
    }
    attributes();
    const std::uint64_t type = c.read(4), size = type_size(type);
    if (c.ok && (size == 0 || (version != 5 && type > 6)))  // NC_BYTE .. NC_DOUBLE; CDF-5 up to NC_UINT64
      c.refuse("variable '" + var.name + "' has the unknown type " + std::to_string(type));
    var.record_bytes *= size;
    c.read(word);  // vsize, padded and 32 bits only in CDF-1 and CDF-2: computed above instead
    var.begin = c.read(offset);
    vars.push_back(var);
  }
  // Names are unique within a file (the netCDF data model), and netCDF's lookup by name finds one
  // of two alike: a fuzzed Exodus file with two 'eb_prop1' (its connect1 renamed) corrupted the
  // heap of VTK's reader.
  std::set<std::string> seen_dims, seen_vars;
  for (const auto& d : out.dims)
    if (c.ok && !seen_dims.insert(d.first).second) c.refuse("two dimensions are named '" + d.first + "'");
  for (const Var& v : vars)
    if (c.ok && !seen_vars.insert(v.name).second) c.refuse("two variables are named '" + v.name + "'");
  if (!c.ok) return std::nullopt;
  std::uint64_t record_size = 0;  // one record of every record variable, padded (one alone: unpadded)
  int records = 0;
  for (const Var& v : vars) record_size += v.record ? (v.record_bytes + 3) / 4 * 4 : 0, records += v.record;
  for (const Var& v : vars) {
    if (v.record && (streaming || numrecs == 0)) continue;
    const std::uint64_t end =
        v.begin + (v.record ? (numrecs - 1) * (records == 1 ? v.record_bytes : record_size) : 0) + v.record_bytes;
    if (end > out.data_end) out.data_end = end, out.last_variable = v.name;
  }
  return out;
}

}  // namespace

std::optional<ClassicHeader> read_classic_header(const std::string& path, std::string* problem) {
  // The header's size is not known before it is walked: read more until it fits (or 256 MB).
  std::error_code error;
  const std::uint64_t file_size = std::filesystem::file_size(path, error);
  if (error) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> bytes;
  std::string refused;  // a problem is final (counts are checked against the whole file): read no more
  for (std::size_t want = 1 << 16;; want *= 16) {
    const std::size_t had = bytes.size();
    bytes.resize(want);
    in.read(reinterpret_cast<char*>(bytes.data() + had), static_cast<std::streamsize>(want - had));
    bytes.resize(had + static_cast<std::size_t>(in.gcount()));
    auto header = walk_classic_header(bytes, file_size, &refused);
    if (!refused.empty() && problem) *problem = refused;
    if (header || !refused.empty() || bytes.size() < want || want >= (std::size_t(1) << 28)) return header;
  }
}

std::uint64_t ClassicHeader::dim(const std::string& name) const {
  for (const auto& [n, len] : dims)
    if (n == name) return len;
  return 0;
}

std::optional<std::uint64_t> hdf5_end_of_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char b[64] = {};
  in.read(reinterpret_cast<char*>(b), sizeof b);
  static const unsigned char kSignature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
  if (in.gcount() < 48 || std::memcmp(b, kSignature, 8) != 0) return std::nullopt;  // or a user block first
  // HDF5 file format, the superblock: versions 0 and 1 give the sizes of offsets at byte 13 and
  // their addresses (base, free space, end of file) from byte 24 or 28; versions 2 and 3 give the
  // size at byte 9 and the addresses (base, extension, end of file) from byte 12.
  const int version = b[8];
  const int size = version <= 1 ? b[13] : b[9];
  const int first = version == 0 ? 24 : version == 1 ? 28 : 12;
  if (version > 3 || (size != 4 && size != 8) || first + 3 * size > in.gcount()) return std::nullopt;
  auto address = [&](int k) {  // little-endian
    std::uint64_t v = 0;
    for (int m = size - 1; m >= 0; --m) v = v << 8 | b[first + k * size + m];
    return v;
  };
  const std::uint64_t base = address(0), end = address(2);
  if (end > std::numeric_limits<std::uint64_t>::max() - base) return std::nullopt;
  return base + end;
}

void check_netcdf_readable(const std::string& path) {
  // A netCDF-4 file is HDF5: its superblock says where the file ends, and HDF5 refuses a file cut
  // before that only with "HDF error".
  if (const auto end = hdf5_end_of_file(path))
    if (const std::uintmax_t file = std::filesystem::file_size(path); file < *end)
      throw InputError(where(path, "truncated: its HDF5 superblock (netCDF-4) says the file ends at byte " +
                                       std::to_string(*end) + ", the file has " + std::to_string(file) + " bytes"));
  // A classic header's counts, before netCDF sizes its tables by them.
  std::string problem;
  const auto placed = read_classic_header(path, &problem);  // classic formats only: netCDF-4 is HDF5
  if (!problem.empty()) throw InputError(where(path, "corrupt: " + problem));
  int id = -1;
  if (int err = nc_open(path.c_str(), NC_NOWRITE, &id); err != NC_NOERR)
    throw InputError(where(path, std::string("not a readable Exodus II (netCDF) file: ") + nc_strerror(err)));
  const auto refuse = [&](const std::string& what) {  // closes the file, then throws
    nc_close(id);
    throw InputError(where(path, what));
  };
  int nvars = 0;
  nc_inq_nvars(id, &nvars);
  std::size_t nodes = 0;
  if (int dim; nc_inq_dimid(id, "num_nodes", &dim) == NC_NOERR) nc_inq_dimlen(id, dim, &nodes);
  // Exodus II's element blocks, which VTK's reader indexes without asking whether they exist: for
  // each of num_el_blk blocks, num_el_in_blkN, num_nod_per_elN and connectN.
  // A null block (eb_status 0, no elements) has none of them: netCDF has no empty dimensions.
  std::size_t blocks = 0;
  if (int dim; nc_inq_dimid(id, "num_el_blk", &dim) == NC_NOERR) nc_inq_dimlen(id, dim, &blocks);
  blocks = std::min<std::size_t>(blocks, 1000000);
  std::vector<int> status(blocks, 1);
  if (int var; blocks > 0 && nc_inq_varid(id, "eb_status", &var) == NC_NOERR) {
    std::size_t len = 0;
    int dim = 0, ndims = 0;
    nc_type type;
    if (nc_inq_varndims(id, var, &ndims) != NC_NOERR || ndims != 1 || nc_inq_vardimid(id, var, &dim) != NC_NOERR ||
        nc_inq_dimlen(id, dim, &len) != NC_NOERR || len != blocks || nc_inq_vartype(id, var, &type) != NC_NOERR ||
        !integer_type(type))  // VTK's reader read a text eb_status as numbers and freed a block twice
      refuse("corrupt: 'eb_status' is not one integer per element block (num_el_blk)");
    nc_get_var_int(id, var, status.data());
  }
  for (std::size_t b = 1; b <= blocks; ++b)
    if (status[b - 1] != 0)
      if (const std::string problem = block_problem(id, b); !problem.empty())
        refuse("corrupt: element block " + std::to_string(b) + " of " + std::to_string(blocks) + problem);
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
  // What VTK's Exodus reader takes for granted (fuzzed files crashed it): element blocks come with
  // nodes, each coordinate holds one value per node, and declared results are named.
  if (blocks > 0 && nodes == 0)
    refuse("corrupt: " + std::to_string(blocks) + " element blocks but no nodes (no dimension 'num_nodes')");
  for (const char* coordinate : {"coordx", "coordy", "coordz"})
    if (int v; nodes > 0 && nc_inq_varid(id, coordinate, &v) == NC_NOERR) {
      std::size_t count = 0, size = 0;
      elements(v, count, size);
      if (count != nodes)
        refuse(std::string("corrupt: coordinate '") + coordinate + "' holds " + std::to_string(count) + " values for " +
               std::to_string(nodes) + " nodes");
    }
  for (const char* kind : {"nod", "elem", "glo", "nset", "sset"}) {
    const std::string count_dim = std::string("num_") + kind + "_var", names = std::string("name_") + kind + "_var";
    std::size_t declared = 0;
    if (int dim; nc_inq_dimid(id, count_dim.c_str(), &dim) == NC_NOERR) nc_inq_dimlen(id, dim, &declared);
    if (int v; declared > 0 && nc_inq_varid(id, names.c_str(), &v) != NC_NOERR)
      refuse("corrupt: it declares " + std::to_string(declared) + " result variables ('" + count_dim +
             "') but has no '" + names + "' naming them");
  }
  // What the header promises, before anything is read: netCDF reads past the end of a truncated
  // classic file as fill values, silently (and VTK then sees node 0 in the connectivity).
  if (placed) {
    if (const std::uintmax_t file = std::filesystem::file_size(path); file < placed->data_end)
      refuse("truncated: the header places variable '" + placed->last_variable + "' up to byte " +
             std::to_string(placed->data_end) + ", the file has " + std::to_string(file) + " bytes");
  }
  for (const std::string& problem : {name_length_problem(id), repeated_id_problem(id)})
    if (!problem.empty()) refuse("corrupt: " + problem);
  std::vector<unsigned char> buf;
  const std::uintmax_t file_size = std::filesystem::file_size(path);
  for (int v = 0; v < nvars; ++v) {
    std::size_t count = 0, size = 0;
    const nc_type type = elements(v, count, size);
    if (count == 0 || type == NC_CHAR) continue;
    char name[NC_MAX_NAME + 1] = {};
    nc_inq_varname(id, v, name);
    // A classic file stores every value: no variable holds more bytes than the file (a record count
    // of 2^32 - 1, "streaming", made netCDF report 4294967295 records of a 5 kB file).
    if (placed && count > file_size / size)
      refuse(std::string("corrupt: variable '") + name + "' declares " + std::to_string(count) + " values of " +
             std::to_string(size) + " bytes, more than the file's " + std::to_string(file_size) + " bytes hold");
    buf.resize(count * size);
    if (int err = nc_get_var(id, v, buf.data()); err != NC_NOERR)
      refuse(std::string("truncated or corrupt: variable '") + name + "' cannot be read (" + nc_strerror(err) + ")");
    // Element connectivity (1-based node numbers): VTK's reader indexes with it unchecked.
    if (std::string(name).rfind("connect", 0) == 0 && nodes > 0) {
      std::vector<long long> ids(count);
      nc_get_var_longlong(id, v, ids.data());
      for (std::size_t i = 0; i < count; ++i)
        if (ids[i] < 1 || ids[i] > static_cast<long long>(nodes))
          refuse(std::string("corrupt: ") + name + " entry " + std::to_string(i) + " is node " +
                 std::to_string(ids[i]) + ", outside [1, " + std::to_string(nodes) + "]");
    }
  }
  nc_close(id);
}

}  // namespace cellproj
