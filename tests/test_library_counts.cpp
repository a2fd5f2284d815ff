// The --max-memory check for the formats whose headers only their own library reads (CGNS, Exodus
// in netCDF-4 form): the counts are asked in the isolated reader's child, before VTK's reader
// allocates, and a file declaring more than the limit is refused naming the file and the estimate.
#include <vtk_cgns.h>
#include VTK_CGNS(cgnslib.h)

#include <netcdf.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "base/error.hpp"
#include "io/header_counts.hpp"
#include "io/netcdf_check.hpp"
#include "io/read_mesh.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

// A CGNS file of zones that declare their sizes and hold no data: (vertices, cells) unstructured,
// or vertices and cells along i, j, k structured.
void write_cgns_zones(const std::string& path, const std::vector<std::vector<cgsize_t>>& zones) {
  int fn = 0, base = 0, zone = 0;
  ASSERT_EQ(cg_open(path.c_str(), CG_MODE_WRITE, &fn), CG_OK) << cg_get_error();
  cg_base_write(fn, "Base", 3, 3, &base);
  for (std::size_t z = 0; z < zones.size(); ++z) {
    const auto& size = zones[z];
    const std::string name = "Zone" + std::to_string(z);
    ASSERT_EQ(cg_zone_write(fn, base, name.c_str(), size.data(),
                            size.size() == 3 ? CGNS_ENUMV(Unstructured) : CGNS_ENUMV(Structured), &zone),
              CG_OK)
        << cg_get_error();
  }
  ASSERT_EQ(cg_close(fn), CG_OK);
}

std::string read_error(const std::string& path, double max_memory_gib) {
  ReadOptions o;
  o.max_memory_gib = max_memory_gib;
  return test::input_error([&] { read_mesh(path, o); });
}

}  // namespace

TEST(LibraryCounts, CgnsZonesAreSummedOverEveryZoneAndEachIndexDirection) {
  test::TempDir dir;
  const std::string path = dir.file("zones.cgns");
  // An unstructured zone (vertices, cells, boundary vertices) and a structured one of 4 x 5 x 6
  // vertices, 3 x 4 x 5 cells.
  write_cgns_zones(path, {{100, 300, 0}, {4, 5, 6, 3, 4, 5, 0, 0, 0}});
  const HeaderCounts c = library_header_counts(path, "cgns");
  EXPECT_EQ(c.points, 100 + 4 * 5 * 6);
  EXPECT_EQ(c.cells, 300 + 3 * 4 * 5);
  EXPECT_EQ(library_header_counts(path, "vtu").cells, 0);  // other formats: not asked
  const std::string garbled = dir.file("garbled.cgns");
  std::ofstream(garbled) << "not a CGNS file at all";
  const std::string message = test::input_error([&] { library_header_counts(garbled, "cgns"); });
  EXPECT_NE(message.find("garbled.cgns: not a readable CGNS file"), std::string::npos) << message;
}

TEST(LibraryCounts, ACgnsZoneBeyondTheMemoryLimitIsRefusedBeforeVtkReadsIt) {
  test::TempDir dir;
  const std::string path = dir.file("huge.cgns");
  write_cgns_zones(path, {{2000000000, 1000000000, 0}});
  const std::string message = read_error(path, 4);
  EXPECT_NE(message.find("huge.cgns: its header declares 2000000000 points and 1000000000 cells: reading them "
                         "needs about"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("more than the 4.0 GiB allowed by setting 'max-memory'"), std::string::npos) << message;
  // A structured zone of 2000^3 vertices.
  write_cgns_zones(path, {{2000, 2000, 2000, 1999, 1999, 1999, 0, 0, 0}});
  EXPECT_NE(read_error(path, 4).find("its header declares 8000000000 points and 7988005999 cells"), std::string::npos)
      << read_error(path, 4);
}

TEST(LibraryCounts, ANetcdf4ExodusFileBeyondTheMemoryLimitIsRefused) {
  // netCDF-4 is HDF5 inside: our classic-header walk cannot read it, netCDF can.
  test::TempDir dir;
  const std::string path = dir.file("huge.exo");
  int id = 0, dim = 0;
  ASSERT_EQ(nc_create(path.c_str(), NC_NETCDF4 | NC_CLOBBER, &id), NC_NOERR);
  nc_def_dim(id, "num_dim", 3, &dim);
  nc_def_dim(id, "num_nodes", 3000000000ull, &dim);
  nc_def_dim(id, "num_elem", 1000000000, &dim);
  ASSERT_EQ(nc_close(id), NC_NOERR);
  EXPECT_EQ(header_counts(path).points, 0);  // not classic: the parent's walk cannot say
  EXPECT_EQ(library_header_counts(path, "exodus").points, 3000000000);
  const std::string message = read_error(path, 4);
  EXPECT_NE(message.find("huge.exo: its header declares 3000000000 points and 1000000000 cells"), std::string::npos)
      << message;
}

TEST(LibraryCounts, ANetcdf4ExodusFileCutShortIsCalledTruncated) {
  // netCDF-4 is HDF5: its superblock says where the file ends. HDF5 alone refuses a cut file as
  // "NetCDF: HDF error"; the check names the truncation, wherever the cut.
  test::TempDir dir;
  const std::string path = dir.file("whole.exo");
  int id = 0, dim = 0, var = 0;
  ASSERT_EQ(nc_create(path.c_str(), NC_NETCDF4 | NC_CLOBBER, &id), NC_NOERR);
  nc_def_dim(id, "num_nodes", 4000, &dim);
  nc_def_var(id, "coordx", NC_DOUBLE, 1, &dim, &var);
  nc_enddef(id);
  const std::vector<double> x(4000, 0.5);
  nc_put_var_double(id, var, x.data());
  ASSERT_EQ(nc_close(id), NC_NOERR);
  const auto size = std::filesystem::file_size(path);
  ASSERT_EQ(hdf5_end_of_file(path).value_or(0), size);
  EXPECT_FALSE(hdf5_end_of_file(dir.file("absent.exo")).has_value());  // no file: no superblock
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (double part : {0.99, 0.5, 0.05}) {
    const std::string cut = dir.file("cut.exo");
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, static_cast<std::size_t>(part * bytes.size()));
    const std::string message = read_error(cut, 4);
    EXPECT_NE(message.find("cut.exo: truncated: its HDF5 superblock (netCDF-4) says the file ends at byte " +
                           std::to_string(size)),
              std::string::npos)
        << part << ": " << message;
  }
}

TEST(LibraryCounts, AClassicNetcdfHeaderCountingMoreThanTheFileHoldsIsRefusedByCount) {
  // netCDF sizes its tables by the header's counts before reading the entries: a fuzzed 530-byte
  // Exodus file declaring 16 million dimensions ran its hash map out of memory ("Argument list too
  // long" at best). The walk refuses such a count first, saying where and how much fits.
  test::TempDir dir;
  const std::string path = dir.file("classic.exo");
  int id = 0, dim = 0;
  ASSERT_EQ(nc_create(path.c_str(), NC_64BIT_OFFSET | NC_CLOBBER, &id), NC_NOERR);  // CDF-2
  nc_def_dim(id, "num_nodes", 4, &dim);
  nc_put_att_text(id, NC_GLOBAL, "title", 5, "cells");
  ASSERT_EQ(nc_close(id), NC_NOERR);
  EXPECT_NO_THROW(check_netcdf_readable(path));
  std::ifstream in(path, std::ios::binary);
  const std::string good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // CDF-2: "CDF\2", numrecs, NC_DIMENSION, the dimension count at byte 12 (big-endian).
  const auto with = [&](std::size_t at, const std::string& count) {
    std::string bytes = good;
    bytes.replace(at, 4, count);
    const std::string bad = dir.file("bad.exo");
    std::ofstream(bad, std::ios::binary) << bytes;
    return test::input_error([&] { check_netcdf_readable(bad); });
  };
  const std::string size = std::to_string(good.size() - 16);
  EXPECT_NE(with(12, std::string("\x00\xff\xff\xff", 4))
                .find("bad.exo: corrupt: its header declares 16777215 dimensions at byte 16, more than the " + size +
                      " bytes after it can hold (at least 8 bytes each)"),
            std::string::npos);
  // The attribute count follows the dimension "num_nodes" (4 + 12 name bytes + 4) and NC_ATTRIBUTE.
  const std::string message = with(40, std::string("\x7f\x00\x00\x00", 4));
  EXPECT_NE(message.find("corrupt: its header declares 2130706432 attributes at byte 44"), std::string::npos)
      << message;
}

TEST(LibraryCounts, ExodusBlocksWithoutNodesTypeOrShapeShortCoordinatesAndUnnamedResultsAreRefused) {
  // What VTK's Exodus reader takes for granted and crashed on in fuzzed files: blocks without a
  // num_nodes dimension (it indexed an empty point array), a coordinate shorter than num_nodes,
  // nodal results declared but not named (it ran strlen past unterminated names), a block
  // without its element type (it looked up a block it had not sorted), and a connectivity not
  // shaped by its block's dimensions (connect1 and connect2 swapped).
  test::TempDir dir;
  const auto write = [&](const std::string& name, bool nodes, std::size_t coordinates, bool names, bool typed = true,
                         bool shaped = true) {
    const std::string path = dir.file(name);
    int id = 0, d_nodes = 0, d_coord = 0, d_blk = 0, d_el = 0, d_per = 0, d_var = 0, v = 0;
    EXPECT_EQ(nc_create(path.c_str(), NC_64BIT_OFFSET | NC_CLOBBER, &id), NC_NOERR);
    nc_def_dim(id, nodes ? "num_nodes" : "num_points", 4, &d_nodes);
    nc_def_dim(id, "num_coord", coordinates, &d_coord);
    nc_def_dim(id, "num_el_blk", 1, &d_blk);
    nc_def_dim(id, "num_el_in_blk1", 1, &d_el);
    nc_def_dim(id, "num_nod_per_el1", 4, &d_per);
    nc_def_dim(id, "num_nod_var", 1, &d_var);
    nc_def_var(id, "coordx", NC_DOUBLE, 1, &d_coord, &v);
    const int connect_dims[2] = {shaped ? d_el : d_per, shaped ? d_per : d_el};
    int connect = 0;
    nc_def_var(id, "connect1", NC_INT, 2, connect_dims, &connect);
    if (typed) nc_put_att_text(id, connect, "elem_type", 5, "TETRA");
    if (names) nc_def_var(id, "name_nod_var", NC_CHAR, 1, &d_var, &v);
    nc_enddef(id);
    const int ids[4] = {1, 2, 3, 4};
    nc_put_var_int(id, connect, ids);
    EXPECT_EQ(nc_close(id), NC_NOERR);
    return test::input_error([&] { check_netcdf_readable(path); });
  };
  EXPECT_EQ(write("good.exo", true, 4, true), "");
  EXPECT_NE(write("blocks.exo", false, 4, true).find("blocks.exo: corrupt: 1 element blocks but no nodes"),
            std::string::npos);
  EXPECT_NE(
      write("short.exo", true, 3, true).find("short.exo: corrupt: coordinate 'coordx' holds 3 values for 4 nodes"),
      std::string::npos);
  EXPECT_NE(write("unnamed.exo", true, 4, false)
                .find("unnamed.exo: corrupt: it declares 1 result variables ('num_nod_var') but has no 'name_nod_var'"),
            std::string::npos);
  EXPECT_NE(write("untyped.exo", true, 4, true, false)
                .find("untyped.exo: corrupt: element block 1 of 1: its connectivity 'connect1' has no text attribute "
                      "'elem_type'"),
            std::string::npos);
  EXPECT_NE(write("swapped.exo", true, 4, true, true, false)
                .find("swapped.exo: corrupt: element block 1 of 1: its connectivity 'connect1' is not shaped "
                      "(num_el_in_blk1, num_nod_per_el1)"),
            std::string::npos);
}

TEST(LibraryCounts, ExodusRepeatedBlockIdsAndNameLengthsOutOfRangeAreRefused) {
  // Fuzzed files: element block ids all 0 crashed VTK's reader (BuildSIL), and ids 1, 1, 2, 3 lost
  // a block without a word; a maximum_name_length of 0 or below made netCDF write names past the
  // buffers VTK sized by it.
  test::TempDir dir;
  const auto write = [&](const std::string& name, std::vector<int> ids, int max_name_length) {
    const std::string path = dir.file(name);
    int id = 0, d_nodes = 0, d_blk = 0, v = 0;
    EXPECT_EQ(nc_create(path.c_str(), NC_64BIT_OFFSET | NC_CLOBBER, &id), NC_NOERR);
    nc_def_dim(id, "num_nodes", 4, &d_nodes);
    nc_def_dim(id, "num_el_blk", ids.size(), &d_blk);
    nc_def_var(id, "coordx", NC_DOUBLE, 1, &d_nodes, &v);
    int prop = 0;
    nc_def_var(id, "eb_prop1", NC_INT, 1, &d_blk, &prop);
    nc_put_att_text(id, prop, "name", 2, "ID");
    std::vector<int> connect(ids.size());
    for (std::size_t b = 0; b < ids.size(); ++b) {
      const std::string n = std::to_string(b + 1);
      int dims[2];
      nc_def_dim(id, ("num_el_in_blk" + n).c_str(), 1, &dims[0]);
      nc_def_dim(id, ("num_nod_per_el" + n).c_str(), 4, &dims[1]);
      nc_def_var(id, ("connect" + n).c_str(), NC_INT, 2, dims, &connect[b]);
      nc_put_att_text(id, connect[b], "elem_type", 5, "TETRA");
    }
    nc_put_att_int(id, NC_GLOBAL, "maximum_name_length", NC_INT, 1, &max_name_length);
    nc_enddef(id);
    nc_put_var_int(id, prop, ids.data());
    const int nodes[4] = {1, 2, 3, 4};
    for (int c : connect) nc_put_var_int(id, c, nodes);
    EXPECT_EQ(nc_close(id), NC_NOERR);
    return test::input_error([&] { check_netcdf_readable(path); });
  };
  EXPECT_EQ(write("good.exo", {7, 8, 0}, 32), "");
  EXPECT_EQ(write("longest.exo", {7}, 256), "");
  EXPECT_NE(write("zeros.exo", {0, 0}, 32)
                .find("zeros.exo: corrupt: element blocks 1 and 2 both have the id 0 ('eb_prop1'); ids must be unique"),
            std::string::npos);
  EXPECT_NE(write("repeat.exo", {1, 2, 1}, 32).find("repeat.exo: corrupt: element blocks 1 and 3 both have the id 1"),
            std::string::npos);
  EXPECT_NE(
      write("empty.exo", {1}, 0).find("empty.exo: corrupt: its attribute 'maximum_name_length' is 0, outside [1, 256]"),
      std::string::npos);
  EXPECT_NE(write("negative.exo", {1}, -2147483616).find("is -2147483616, outside [1, 256]"), std::string::npos);
  EXPECT_NE(write("long.exo", {1}, 257).find("is 257, outside [1, 256]"), std::string::npos);
  // Two variables of one name (a fuzzed file's connect1 renamed 'eb_prop1', the name of another:
  // netCDF opened it, and VTK's reader corrupted its heap). The netCDF API cannot write that: the
  // good file's header is edited, as the fuzzer did.
  std::ifstream in(dir.file("good.exo"), std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t connect1 = bytes.find("connect1");
  ASSERT_NE(connect1, std::string::npos);
  bytes.replace(connect1, 8, "eb_prop1");
  std::ofstream(dir.file("twice.exo"), std::ios::binary) << bytes;
  EXPECT_EQ(test::input_error([&] { check_netcdf_readable(dir.file("twice.exo")); }),
            dir.file("twice.exo") + ": corrupt: two variables are named 'eb_prop1'");
}

TEST(LibraryCounts, ExodusNodeCountsOfTheElementTypeIntegerStatusesAndRecordCountsAreChecked) {
  // Fuzzed files: a HEX block of 5 nodes per element (VTK's reader built hexahedra of 8 and read
  // past the block, crashing or shifting every node after), a text eb_status (VTK freed a block
  // twice), and a record count of 2^32 - 1 in a 5 kB file (netCDF reported that many records).
  test::TempDir dir;
  const auto write = [&](const std::string& name, const char* elem_type, int per_element, nc_type status_type,
                         bool streaming = false) {
    const std::string path = dir.file(name);
    int id = 0, d_nodes = 0, d_blk = 0, d_time = 0, dims[2], v = 0, connect = 0, status = 0;
    EXPECT_EQ(nc_create(path.c_str(), NC_CLOBBER, &id), NC_NOERR);
    nc_def_dim(id, "time_step", NC_UNLIMITED, &d_time);
    nc_def_dim(id, "num_nodes", 8, &d_nodes);
    nc_def_dim(id, "num_el_blk", 1, &d_blk);
    nc_def_dim(id, "num_el_in_blk1", 1, &dims[0]);
    nc_def_dim(id, "num_nod_per_el1", static_cast<std::size_t>(per_element), &dims[1]);
    nc_def_var(id, "time_whole", NC_DOUBLE, 1, &d_time, &v);
    nc_def_var(id, "eb_status", status_type, 1, &d_blk, &status);
    nc_def_var(id, "connect1", NC_INT, 2, dims, &connect);
    nc_put_att_text(id, connect, "elem_type", std::strlen(elem_type), elem_type);
    nc_enddef(id);
    const std::size_t first = 0;
    const double t = 0.0;
    nc_put_var1_double(id, v, &first, &t);
    if (status_type == NC_CHAR)
      nc_put_var_text(id, status, "\1");
    else
      nc_put_var1_int(id, status, &first, &per_element);
    std::vector<int> nodes(static_cast<std::size_t>(per_element));
    for (int k = 0; k < per_element; ++k) nodes[static_cast<std::size_t>(k)] = 1 + k % 8;
    nc_put_var_int(id, connect, nodes.data());
    EXPECT_EQ(nc_close(id), NC_NOERR);
    if (streaming) {  // numrecs, bytes 4 to 7 of a CDF-1 header: 2^32 - 1 means "streaming"
      std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
      f.seekp(4);
      f.write("\xff\xff\xff\xff", 4);
    }
    return test::input_error([&] { check_netcdf_readable(path); });
  };
  EXPECT_EQ(write("hex.exo", "HEX8", 8, NC_INT), "");
  EXPECT_EQ(write("wedge.exo", "wedge", 6, NC_SHORT), "");
  EXPECT_EQ(write("tet10.exo", "TETRA10", 10, NC_INT), "");  // quadratic: left to VTK, then refused by type
  EXPECT_NE(write("five.exo", "HEX", 5, NC_INT)
                .find("five.exo: corrupt: element block 1 of 1: its elements of type 'HEX' have 5 nodes each "
                      "(num_nod_per_el1); VTK's Exodus reader reads that type with 8, 20 or 27 (with other counts "
                      "it reads the wrong nodes)"),
            std::string::npos);
  // HEX9 and TETRA8 are Exodus II types, but VTK 9.1 makes linear cells of them and steps through
  // the connectivity by 8 and 4: every element after the first on the wrong nodes, with exit 0.
  EXPECT_NE(write("hex9.exo", "HEX9", 9, NC_INT).find("type 'HEX9' have 9 nodes each"), std::string::npos);
  EXPECT_NE(write("tet8.exo", "TETRA8", 8, NC_INT).find("type 'TETRA8' have 8 nodes each"), std::string::npos);
  EXPECT_NE(write("one.exo", "pyramid", 1, NC_INT).find("type 'pyramid' have 1 node each"), std::string::npos);
  EXPECT_NE(write("text.exo", "HEX", 8, NC_CHAR)
                .find("text.exo: corrupt: 'eb_status' is not one integer per element block (num_el_blk)"),
            std::string::npos);
  EXPECT_NE(write("stream.exo", "HEX", 8, NC_INT, true)
                .find("stream.exo: corrupt: variable 'time_whole' declares 4294967295 values of 8 bytes, more than "
                      "the file's"),
            std::string::npos);
}
