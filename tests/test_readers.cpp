// Every reader on a small file, and on truncated and corrupted copies (an InputError, never a crash).
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <thread>
#include <tuple>

#include <gtest/gtest.h>
#include <vtkDoubleArray.h>
#include <vtkLogger.h>
#include <vtkRectilinearGrid.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLRectilinearGridWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "base/bytes.hpp"
#include "base/error.hpp"
#include "io/header_counts.hpp"
#include "io/isolated_read.hpp"
#include "io/read_mesh.hpp"
#include "io/vtk_messages.hpp"
#include "io/write_mesh.hpp"
#include "legacy_samples.hpp"
#include "mesh/topology.hpp"
#include "test_util.hpp"

using namespace cellproj;
namespace fs = std::filesystem;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void spit(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// The message of the InputError that loading `path` throws ("" when it loads fine).
std::string read_error(const std::string& path, const ReadOptions& o = {}) {
  return test::input_error([&] { load_mesh(path, o); });
}

const char* kLegacy = R"(# vtk DataFile Version 3.0
two cells
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 5 double
0 0 0  1 0 0  0 1 0  0 0 1  1 1 1
CELLS 3 13
4 0 1 2 3
4 1 2 3 4
2 0 4
CELL_TYPES 3
10
10
3
POINT_DATA 5
SCALARS temp double 1
LOOKUP_TABLE default
0 1 2 3 4
CELL_DATA 3
SCALARS heat double 1
LOOKUP_TABLE default
1 4 9
)";

}  // namespace

TEST(Readers, VtuRoundTrip) {
  test::TempDir dir;
  Mesh m = make_box(2, 2, 2, glm::dvec3(0), glm::dvec3(1), false);
  set_field(m, "f", [](const glm::dvec3& x) { return x.x; });
  write_vtu(m, dir.file("box.vtu"));
  const Mesh r = read_mesh(dir.file("box.vtu"));
  EXPECT_EQ(r.n_points(), 27);
  EXPECT_EQ(r.n_cells(), 8);
  EXPECT_EQ(r.points, m.points);
  EXPECT_EQ(r.field("f").values, m.fields[0].values);
}

// VTK's output window and logger are process-wide: a read leaves the caller's logger verbosity
// as it found it, and reads on two threads (one of a broken file) each get their own result.
TEST(Readers, ReadsRestoreVtksLoggingAndAreSafeFromTwoThreads) {
  test::TempDir dir;
  Mesh m = make_box(6, 6, 6, glm::dvec3(0), glm::dvec3(1), true);
  set_field(m, "f", [](const glm::dvec3& x) { return x.x; });
  write_vtu(m, dir.file("box.vtu"));
  spit(dir.file("broken.vtu"), slurp(dir.file("box.vtu")).substr(0, 400));
  const vtkLogger::Verbosity before = vtkLogger::GetCurrentVerbosityCutoff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_INFO);
  read_mesh(dir.file("box.vtu"));
  EXPECT_EQ(vtkLogger::GetCurrentVerbosityCutoff(), vtkLogger::VERBOSITY_INFO);
  vtkLogger::SetStderrVerbosity(before);
  std::vector<std::int64_t> cells(8, -1);
  std::vector<std::string> errors(8);
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&, t] {
      try {
        cells[t] = read_mesh(dir.file(t % 2 ? "broken.vtu" : "box.vtu")).n_cells();
      } catch (const InputError& e) {
        errors[t] = e.what();
      }
    });
  for (auto& t : threads) t.join();
  for (int t = 0; t < 8; ++t) {
    if (t % 2) {
      EXPECT_EQ(cells[t], -1);
      EXPECT_NE(errors[t].find("broken.vtu"), std::string::npos) << errors[t];
    } else {
      EXPECT_EQ(cells[t], m.n_cells()) << errors[t];
    }
  }
}

// A corrupt .gz is an error, and the folder it was being decompressed into goes with it.
TEST(Readers, CorruptGzipLeavesNoTemporaryFolder) {
  test::TempDir dir;
  const std::string path = dir.file("mesh.vtu.gz");
  spit(path, std::string("\x1f\x8b\x08\x00\x00\x00\x00\x00\x00\x03", 10) + std::string(300, 'x'));
  EXPECT_NE(read_error(path).find("mesh.vtu.gz: corrupt or truncated gzip data"), std::string::npos)
      << read_error(path);
  const std::string prefix = "cellproj-" + std::to_string(std::hash<std::string>{}(path)) + "-";
  for (const auto& e : fs::directory_iterator(fs::temp_directory_path()))
    EXPECT_NE(e.path().filename().string().rfind(prefix, 0), 0u) << "left behind: " << e.path();
}

TEST(Readers, LegacyVtkCellDataIsVolumeWeightedAndLineCellsSkipped) {
  test::TempDir dir;
  spit(dir.file("two.vtk"), kLegacy);
  Mesh m = read_mesh(dir.file("two.vtk"));
  apply_cell_data(m, CellData::points);
  EXPECT_EQ(m.n_cells(), 2);  // the line is skipped, with a note
  ASSERT_FALSE(m.notes.empty());
  EXPECT_NE(m.notes[0].find("line (3) x1"), std::string::npos);
  // Cell 0 has volume 1/6, cell 1 volume 1/3 (|det| = 2): shared point 1 gets (1/6 + 4/3)/(1/2).
  const auto& heat = m.field("heat").values;
  EXPECT_NEAR(heat[0], 1.0, 1e-12);
  EXPECT_NEAR(heat[1], (1.0 / 6 + 4.0 / 3) / 0.5, 1e-12);
  EXPECT_NEAR(heat[4], 4.0, 1e-12);
  EXPECT_EQ(m.field("temp").values[4], 4.0);
}

TEST(Readers, OffTetgenAndPointCloud) {
  test::TempDir dir;
  Mesh m = make_box(2, 1, 1, glm::dvec3(0), glm::dvec3(1), true);
  set_field(m, "s", [](const glm::dvec3& x) { return x.y; });
  write_off(m, "s", dir.file("m.off"));
  const Mesh off = read_mesh(dir.file("m.off"));
  EXPECT_EQ(off.n_cells(), 12);
  EXPECT_EQ(off.field("scalar").values, m.fields[0].values);

  spit(dir.file("t.node"), "5 3 1 0\n1 0 0 0 10\n2 1 0 0 11\n3 0 1 0 12\n4 0 0 1 13\n5 1 1 1 14\n");
  spit(dir.file("t.ele"), "2 4 0\n1 1 2 3 4\n2 2 3 4 5\n");
  const Mesh tg = read_mesh(dir.file("t.ele"));
  EXPECT_EQ(tg.n_points(), 5);
  ASSERT_EQ(tg.n_cells(), 2);
  EXPECT_EQ(tg.connectivity[4], 1);  // 1-based ids made 0-based
  EXPECT_EQ(tg.field("attribute_0").values[4], 14.0);

  spit(dir.file("c.xyzs"), "# x y z s\n0 0 0 1\n1 0 0 2\n0 1 0 3\n0 0 1 4\n1 1 1 5\n1 1 0 6\n");
  const Mesh pc = read_mesh(dir.file("c.xyzs"));
  EXPECT_GE(pc.n_cells(), 2);
  EXPECT_EQ(pc.field("scalar").values[5], 6.0);
  const auto report = validate(pc.view());
  double volume = 0;
  for (double v : report.volumes) volume += v;
  EXPECT_NEAR(volume, 2.0 / 3, 1e-12);  // the hull: the unit cube less two corner tetrahedra
}

TEST(Readers, APathTheFileSystemCannotLookUpIsAnInputErrorNamingIt) {
  // A file name longer than the file system allows: std::filesystem throws its own error, which
  // must reach a library caller as an InputError naming the path (the scene fuzzer found it).
  const std::string name = "/tmp/" + std::string(300, 'n') + ".vtu";
  for (const std::string& path : {name, name + ".gz"}) {
    const std::string what = test::input_error([&] { load_mesh(path); });
    EXPECT_NE(what.find(path + ": cannot be looked up (File name too long)"), std::string::npos) << what;
  }
  EXPECT_NE(test::input_error([&] { write_vtu(Mesh{}, "/tmp/" + std::string(300, 'w') + "/x.vtu"); }), "");
}

TEST(Readers, BadTextFilesNameTheFileAndTheLine) {
  test::TempDir dir;
  spit(dir.file("short.off"), "5 2\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n1 1 1 1\n0 1 2 3\n");
  EXPECT_NE(read_error(dir.file("short.off")).find("truncated"), std::string::npos);
  spit(dir.file("bad.off"), "4 1\n0 0 0 1\n1 0 zero 1\n");
  EXPECT_NE(read_error(dir.file("bad.off")).find("line 3: 'zero' is not a number"), std::string::npos);
  spit(dir.file("t.node"), "5 3 0 0\n1 0 0 0\n2 1 0 0\n");
  spit(dir.file("t.ele"), "1 4 0\n1 1 2 3 4\n");
  EXPECT_NE(read_error(dir.file("t.node")).find("t.node: file ends"), std::string::npos);
  spit(dir.file("flat.xyzs"), "0 0 0 1\n1 0 0 1\n0 1 0 1\n1 1 0 1\n");
  EXPECT_NE(read_error(dir.file("flat.xyzs")).find("coplanar"), std::string::npos);
  EXPECT_NE(read_error(dir.file("none.vtu")).find("no such file"), std::string::npos);
  spit(dir.file("x.stl"), "solid x\n");
  EXPECT_NE(read_error(dir.file("x.stl")).find("unknown mesh format"), std::string::npos);
}

// Truncations and corruptions of real files of every VTK-family format.
TEST(Readers, TruncatedAndCorruptedFilesAreErrors) {
  test::TempDir dir;
  Mesh m = make_box(4, 4, 4, glm::dvec3(0), glm::dvec3(1), true);
  set_field(m, "f", [](const glm::dvec3& x) { return x.z; });
  write_vtu(m, dir.file("gen.vtu"));
  spit(dir.file("legacy.vtk"), kLegacy);
  std::vector<std::string> files = {dir.file("gen.vtu"), dir.file("legacy.vtk")};
  for (const char* rel :
       {"exodus_disk_out_ref/disk_out_ref.ex2", "cgns_static_mixer/StaticMixer.cgns.gz",
        "nasa_bluntfin/bluntfinxyz.bin", "vtkdata_hexa/hexa.vtk", "vtkdata_post_tets/post_tets.vtu",
        "nasa_bluntfin/bluntfin.vts", "vtkdata_post_tets/post.vtk", "vtkdata_notch_stress/notch_stress_fixed.vtk"})
    if (fs::exists(test::shared_data(rel))) files.push_back(test::shared_data(rel));
  for (const auto& f : files) {
    const std::string bytes = slurp(f), name = fs::path(f).filename().string();
    for (double keep : {0.0, 0.1, 0.5, 0.9}) {
      const std::string cut = dir.file("cut_" + std::to_string(int(keep * 10)) + "_" + name);
      spit(cut, bytes.substr(0, static_cast<std::size_t>(bytes.size() * keep)));
      const std::string err = read_error(cut);
      EXPECT_FALSE(err.empty()) << cut << " read without error";
      if (!err.empty()) EXPECT_NE(err.find(cut), std::string::npos) << err;
    }
    std::string garbled = bytes;  // a stretch of the middle overwritten
    for (std::size_t i = garbled.size() / 3; i < garbled.size() / 3 + 64 && i < garbled.size(); ++i)
      garbled[i] = '\x7f';
    const std::string bad = dir.file("garbled_" + name);
    spit(bad, garbled);
    try {
      const Mesh g = read_mesh(bad);
      validate(g.view());  // it may parse: then validation must accept or reject it cleanly
    } catch (const InputError&) {
    }
  }
}

// VTK's legacy reader zero-fills a binary file cut inside its last array; we count the bytes its
// arrays and text lines need. Cutting one 4-byte value and its newline must be caught.
TEST(Readers, LegacyBinaryCutInsideTheLastArray) {
  test::TempDir dir;
  int tried = 0;
  for (const char* rel : {"vtkdata_post_tets/post.vtk", "vtkdata_notch_stress/notch_stress_fixed.vtk"}) {
    if (!fs::exists(test::shared_data(rel))) continue;
    ++tried;
    const std::string bytes = slurp(test::shared_data(rel));
    EXPECT_NO_THROW(read_mesh(test::shared_data(rel)));
    for (std::size_t cut : {8, 100, 5000}) {
      const std::string f = dir.file("cut" + std::to_string(cut) + ".vtk");
      spit(f, bytes.substr(0, bytes.size() - cut));
      EXPECT_NE(read_error(f).find("truncated"), std::string::npos) << rel << " less " << cut << " bytes";
    }
  }
  if (tried == 0) GTEST_SKIP() << "no ../shared/data beside this clone";
}

// VTK's legacy unstructured-grid reader uses the FIELD data it reads at the dataset level without
// a check: a block its field reader gives up on crashed it (11 of the 13 vtk crash inputs of the
// last fuzz run). Such blocks are refused by name first; good ones, anywhere among the dataset's
// blocks, ASCII or binary, still read.
TEST(Readers, ALegacyDatasetFieldVtkCannotReadIsRefusedBeforeItsReaderCrashes) {
  test::TempDir dir;
  const std::string legacy = kLegacy;
  const std::size_t after_dataset = legacy.find("POINTS"), before_data = legacy.find("POINT_DATA");
  // kLegacy with `block` after its DATASET line (or, with at_end, before its POINT_DATA).
  auto with = [&](const std::string& block, bool at_end = false) {
    const std::size_t at = at_end ? before_data : after_dataset;
    const std::string f = dir.file("field.vtk");
    spit(f, legacy.substr(0, at) + block + legacy.substr(at));
    return read_error(f);
  };
  const std::string good = "FIELD FieldData 3\nTIME 1 1 double\n0.5\nNULL_ARRAY\nCYCLE 1 1 int\n3\n";
  EXPECT_EQ(with(good), "");
  EXPECT_EQ(with(good, true), "");
  // ParaView writes a METADATA block after an array; a string array ends the walk (not followed).
  EXPECT_EQ(with("FIELD FieldData 2\nTIME 1 1 double\n0.5\nMETADATA\nINFORMATION 0\n\nCYCLE 1 1 int\n3\n"), "");
  EXPECT_EQ(with("FIELD FieldData 2\nnames 1 2 string\nfield one\nFIELD two\nCYCLE 1 1 int\n3\n"), "");
  EXPECT_NE(with("FIELD FieldData 1\nfoo 1 2 nonsense\n1 2\n")
                .find("the dataset's FIELD block 'FieldData', array 0 ('foo'): unknown type 'nonsense' (VTK's legacy "
                      "reader would crash on it)"),
            std::string::npos);
  EXPECT_NE(with("FIELD FieldData 1\nfoo 1 1 bogus\n7\n", true).find("unknown type 'bogus'"), std::string::npos);
  EXPECT_NE(with("FIELD FieldData x\n").find("has no name and array count"), std::string::npos);
  EXPECT_NE(with("FIELD F 2\na 1 3 double\n1 2\nb 1 1 double\n4\n")
                .find("array 0 ('a'): its values end, or stop being numbers, after 2 of 3"),
            std::string::npos);
  EXPECT_NE(with("FIELD F 1\na 1 x double\n").find("its components, tuples and type are not all there"),
            std::string::npos);
  EXPECT_NE(with("FIELD F 1\na 1 1000000000 double\n").find("more than the file's remaining"), std::string::npos);

  // Binary (format 5 and its OFFSETS and CONNECTIVITY arrays): the walk steps over the binary blocks.
  Mesh m = make_box(2, 2, 2, glm::dvec3(0), glm::dvec3(1), true);
  set_field(m, "f", [](const glm::dvec3& x) { return x.x; });
  write_vtk_legacy(m, dir.file("bin.vtk"), true);
  const std::string bin = slurp(dir.file("bin.vtk"));
  ASSERT_NE(bin.find("BINARY"), std::string::npos);
  const std::size_t data = bin.find("POINT_DATA");
  ASSERT_NE(data, std::string::npos);
  auto binary_with = [&](const std::string& block) {
    const std::string f = dir.file("field_bin.vtk");
    spit(f, bin.substr(0, data) + block + bin.substr(data));
    return read_error(f);
  };
  EXPECT_EQ(binary_with("FIELD FieldData 1\nTIME 1 1 double\n" + std::string(8, '\0') + "\n"), "");
  EXPECT_NE(binary_with("FIELD FieldData 1\nTIME 1 1 nonsense\n").find("unknown type 'nonsense'"), std::string::npos);
}

// A block whose count the rest of the file cannot hold (CELL_TYPES, POINTS, CELLS; ASCII or
// binary): VTK's legacy reader sizes its array by the count before reading a value (fuzzed files:
// a CELL_TYPES of 552020666 in 1 KB asked for 2.2 GB, and under --max-memory printed the
// pipeline's nine-line request dump). Refused by count, naming the block; the good file reads.
TEST(Readers, ALegacyBlockCountingMoreValuesThanTheFileHoldsIsRefusedByCount) {
  test::TempDir dir;
  const std::string f = dir.file("count.vtk");
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string text = kLegacy;
    text.replace(text.find(from), from.size(), to);
    spit(f, text);
    return read_error(f);
  };
  EXPECT_EQ(with("CELL_TYPES 3", "CELL_TYPES 3"), "");
  const auto refused = [&](const std::string& block, const std::string& error) {
    return error.rfind(where(f, block + " declares "), 0) == 0 &&
           error.find(" numbers, more than the ") != std::string::npos &&
           error.find(" bytes left in the file hold: truncated or corrupt") != std::string::npos;
  };
  EXPECT_TRUE(refused("CELL_TYPES", with("CELL_TYPES 3", "CELL_TYPES 552020666"))) << read_error(f);
  EXPECT_TRUE(refused("POINTS", with("POINTS 5 double", "POINTS 50000000 double"))) << read_error(f);
  EXPECT_TRUE(refused("CELLS", with("CELLS 3 13", "CELLS 3 1300000000"))) << read_error(f);
  // The fuzzed shape: POINTS cut short by a CELL_TYPES line, which VTK's reader then reads.
  EXPECT_TRUE(refused("CELL_TYPES", with("1 0 0  0 1 0", "\nCELL_TYPES 552020666 -1\n"))) << read_error(f);

  Mesh m = make_box(2, 2, 2, glm::dvec3(0), glm::dvec3(1), true);
  write_vtk_legacy(m, dir.file("bin.vtk"), true);
  std::string bin = slurp(dir.file("bin.vtk"));
  const std::size_t at = bin.find("CELL_TYPES ");
  ASSERT_NE(at, std::string::npos);
  const std::size_t end = bin.find('\n', at);
  bin.replace(at, end - at, "CELL_TYPES 552020666");
  spit(f, bin);
  EXPECT_NE(read_error(f).find("CELLS declares "), std::string::npos) << read_error(f);  // format 5: the arrays' count
  // Binary, cut inside its connectivity: named, with its values' size.
  bin = slurp(dir.file("bin.vtk"));
  spit(f, bin.substr(0, bin.find("CONNECTIVITY") + 40));
  EXPECT_NE(read_error(f).find("CONNECTIVITY declares "), std::string::npos) << read_error(f);
  EXPECT_NE(read_error(f).find(" values of 8 bytes, more than the "), std::string::npos) << read_error(f);
}

// The pipeline's "returned failure" error, which follows a reader's own or stands for one it did
// not give, is shortened to the class that failed (it carried the request's nine-line dump).
TEST(Readers, VtksFailedRequestDumpIsShortenedToTheReadersName) {
  const std::string dump =
      "Algorithm vtkUnstructuredGridReader(0x55c3e7322d60) returned failure for request: vtkInformation "
      "(0x55c3e73254c0)\n  Debug: Off\n  Modified Time: 279\n  Reference Count: 1\n  Request: REQUEST_DATA";
  EXPECT_TRUE(failed_request(dump));
  EXPECT_EQ(vtk_error_text(dump), "VTK's vtkUnstructuredGridReader failed without saying why");
  EXPECT_FALSE(failed_request("Error reading cell types!"));
  EXPECT_EQ(vtk_error_text("Error reading cell types!"), "Error reading cell types!");
}

// Inside POINT_DATA and CELL_DATA, VTK's legacy reader sizes each array with the counts it reads
// and does not check them: a negative one (a fuzzer's FIELD array of -9 tuples) made it write past
// the array. Refused by name; good arrays of every kind, and every count VTK checks itself, pass.
TEST(Readers, ALegacyArrayOfANegativeCountInPointOrCellDataIsRefusedByName) {
  test::TempDir dir;
  const std::string legacy = kLegacy;
  const std::size_t at = legacy.find("CELL_DATA");
  auto with = [&](const std::string& block) {  // kLegacy with `block` at the end of its POINT_DATA
    const std::string f = dir.file("data.vtk");
    spit(f, legacy.substr(0, at) + block + legacy.substr(at));
    return read_error(f);
  };
  EXPECT_EQ(with("FIELD F 1\na 1 5 double\n0 1 2 3 4\n"), "");
  EXPECT_EQ(with("VECTORS v double\n0 1 2 3 4 5 6 7 8 9 0 1 2 3 4\nCOLOR_SCALARS c 2\n0 1 0 1 0 1 0 1 0 1\n"
                 "LOOKUP_TABLE t 1\n0 0 0 1\n"),
            "");
  EXPECT_EQ(with("FIELD F 1\na 1 -9 double\n1 2\n"),
            where(dir.file("data.vtk"),
                  "POINT_DATA's FIELD block 'F', array 0 ('a'): a negative count (1 components of -9 tuples)"));
  EXPECT_EQ(with("COLOR_SCALARS c 0\n"),
            where(dir.file("data.vtk"), "POINT_DATA's COLOR_SCALARS 'c' declares 0 components"));
  EXPECT_EQ(with("LOOKUP_TABLE t -2\n"),
            where(dir.file("data.vtk"), "POINT_DATA's LOOKUP_TABLE 't' declares a negative count (-2)"));
  // A count beyond the file: VTK sizes the array first (44444444441 components asked for 12 GB).
  const std::string huge = with("SCALARS s float 44444444441\nLOOKUP_TABLE default\n0 1 2 3 4\n");
  EXPECT_NE(huge.find("POINT_DATA's SCALARS 's' declares 5 tuples of 44444444441 components, more values than the "),
            std::string::npos)
      << huge;
  std::string negative = legacy;
  negative.replace(negative.find("CELL_DATA 3"), 11, "CELL_DATA -3");
  spit(dir.file("neg.vtk"), negative);
  EXPECT_EQ(read_error(dir.file("neg.vtk")), where(dir.file("neg.vtk"), "CELL_DATA declares a negative count (-3)"));
}

// A legacy structured grid: VTK 9.1's metadata pass took every word starting with "field" for a
// FIELD block, so a good file with an array named field_strength crashed it. Read by the mesh
// pass alone, it renders; its dataset FIELD block is checked as an unstructured grid's is.
TEST(Readers, ALegacyStructuredGridWithAnArrayNamedFieldSomethingReads) {
  test::TempDir dir;
  const std::string grid = test::kStructuredGridNamedField;
  spit(dir.file("sg.vtk"), grid);
  const Mesh m = read_mesh(dir.file("sg.vtk"));
  ASSERT_EQ(m.n_cells(), 1);
  const auto& f = m.field("field_strength").values;
  ASSERT_EQ(f.size(), 8u);
  for (int p = 0; p < 8; ++p) EXPECT_EQ(f[p], p);
  std::string bad = grid;
  bad.insert(bad.find("DIMENSIONS"), "FIELD FieldData 1\nfoo 1 1 bogus\n7\n");
  spit(dir.file("bad.vtk"), bad);
  EXPECT_NE(
      read_error(dir.file("bad.vtk")).find("the dataset's FIELD block 'FieldData', array 0 ('foo'): unknown type"),
      std::string::npos);
}

// A parallel file: two pieces of one box, their interface points repeated. Read as one conforming
// mesh, the interface points merged and its faces shared again.
TEST(Readers, StructuredXmlPiecesMustCoverTheWholeExtent) {
  // VTK's reader fills each piece's points of the WholeExtent's array and leaves the rest as the
  // memory held: a fuzzed .vts whose WholeExtent outgrew its one piece read with bounds of 1e31.
  test::TempDir dir;
  const auto vts = [&](const std::string& name, const std::string& whole, const std::vector<std::string>& pieces) {
    std::ofstream f(dir.file(name));
    f << "<?xml version=\"1.0\"?>\n<VTKFile type=\"StructuredGrid\" version=\"0.1\">\n<StructuredGrid WholeExtent=\""
      << whole << "\">\n";
    for (const std::string& e : pieces) {
      std::istringstream in(e);
      int x[6];
      for (int& v : x) in >> v;
      f << "<Piece Extent=\"" << e
        << "\"><Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">";
      for (int k = x[4]; k <= x[5]; ++k)
        for (int j = x[2]; j <= x[3]; ++j)
          for (int i = x[0]; i <= x[1]; ++i) f << i << " " << j << " " << k << " ";
      f << "</DataArray></Points></Piece>\n";
    }
    f << "</StructuredGrid>\n</VTKFile>\n";
    return dir.file(name);
  };
  // Two pieces sharing the plane i = 1 cover 0..2: read whole.
  const Mesh m = read_mesh(vts("two.vts", "0 2 0 1 0 1", {"0 1 0 1 0 1", "1 2 0 1 0 1"}));
  EXPECT_EQ(m.n_cells(), 2);
  for (const std::string& gap : {std::string("0 3 0 1 0 1"), std::string("0 2 0 2 0 1")}) {
    const std::string what = test::input_error([&] { read_mesh(vts("gap.vts", gap, {"0 1 0 1 0 1", "1 2 0 1 0 1"})); });
    EXPECT_NE(what.find("gap.vts: its pieces' extents do not cover its WholeExtent (" + gap + ")"), std::string::npos)
        << what;
  }
  // An extent that runs backwards (VTK's reader sized its arrays from it and ended in
  // std::length_error, an internal error) or is not six integers: an InputError naming it.
  const std::string backwards = test::input_error([&] {
    read_mesh(vts("back.vts", "2 0 0 1 0 1", {"0 1 0 1 0 1", "1 2 0 1 0 1"}));
  });
  EXPECT_NE(backwards.find("its WholeExtent '2 0 0 1 0 1' runs backwards along x (2 to 0)"), std::string::npos)
      << backwards;
  const std::string piece = test::input_error([&] { read_mesh(vts("piece.vts", "0 2 0 1 0 1", {"0 1 1 0 0 1"})); });
  EXPECT_NE(piece.find("its piece 0's Extent '0 1 1 0 0 1' runs backwards along y (1 to 0)"), std::string::npos)
      << piece;
  const std::string words = test::input_error([&] { read_mesh(vts("words.vts", "0 2 0 one 0 1", {"0 2 0 1 0 1"})); });
  EXPECT_NE(words.find("its WholeExtent '0 2 0 one 0 1' is not six integers"), std::string::npos) << words;
}

TEST(Readers, AnImageDatasOriginAndSpacingMustBeThreeFiniteNumbers) {
  // VTK's reader keeps its default for an Origin or Spacing it cannot parse: "1 nan 1" read as
  // spacing 1, with exit 0.
  test::TempDir dir;
  const auto vti = [&](const std::string& name, const std::string& origin, const std::string& spacing) {
    std::ofstream(dir.file(name)) << "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"0.1\">\n"
                                  << "<ImageData WholeExtent=\"0 2 0 1 0 1\" Origin=\"" << origin << "\" Spacing=\""
                                  << spacing
                                  << "\">\n<Piece Extent=\"0 2 0 1 0 1\"></Piece>\n</ImageData>\n</VTKFile>\n";
    return dir.file(name);
  };
  const Mesh m = read_mesh(vti("good.vti", "0 0 0", "0.5 2 1"));
  EXPECT_EQ(m.n_cells(), 2);
  for (const auto& [origin, spacing, bad] :
       {std::tuple("0 0 0", "1 nan 1", "Spacing '1 nan 1'"), std::tuple("0 x 0", "1 1 1", "Origin '0 x 0'"),
        std::tuple("0 0", "1 1 1", "Origin '0 0'"), std::tuple("0 0 0", "1 inf 1", "Spacing '1 inf 1'")}) {
    const std::string what = test::input_error([&, o = origin, sp = spacing] { read_mesh(vti("bad.vti", o, sp)); });
    EXPECT_NE(what.find(std::string("bad.vti: its ImageData ") + bad + " is not three finite numbers"),
              std::string::npos)
        << what;
  }
}

TEST(Readers, ARectilinearAxisShorterThanItsExtentIsRefused) {
  // VTK's XML reader takes a short axis of coordinates without a word and reads the missing ones
  // from past its array: a .vtr of 3 x-points with 2 x-coordinates read with an inverted cell.
  test::TempDir dir;
  enum Mode { appended, ascii, inline_binary };
  const auto write = [&](const std::string& name, int nx, Mode mode) {
    auto g = vtkSmartPointer<vtkRectilinearGrid>::New();
    g->SetDimensions(3, 2, 2);
    const int n[3] = {nx, 2, 2};
    vtkSmartPointer<vtkDoubleArray> axis[3];
    for (int a = 0; a < 3; ++a) {
      axis[a] = vtkSmartPointer<vtkDoubleArray>::New();
      for (int k = 0; k < n[a]; ++k) axis[a]->InsertNextValue(k);
    }
    g->SetXCoordinates(axis[0]), g->SetYCoordinates(axis[1]), g->SetZCoordinates(axis[2]);
    auto w = vtkSmartPointer<vtkXMLRectilinearGridWriter>::New();
    w->SetInputData(g);
    w->SetFileName(dir.file(name).c_str());
    if (mode == ascii) w->SetDataModeToAscii();
    if (mode == inline_binary) w->SetDataModeToBinary();
    w->Write();
    return dir.file(name);
  };
  EXPECT_EQ(read_mesh(write("good.vtr", 3, appended)).n_cells(), 2);
  EXPECT_EQ(read_mesh(write("good_ascii.vtr", 3, ascii)).n_cells(), 2);
  EXPECT_EQ(read_mesh(write("good_inline.vtr", 3, inline_binary)).n_cells(), 2);
  for (const auto& [name, mode] : {std::pair("short.vtr", appended), std::pair("short_inline.vtr", inline_binary)}) {
    const std::string what = test::input_error([&, n = name, m = mode] { read_mesh(write(n, 2, m)); });
    EXPECT_NE(what.find(std::string(name) + ": DataArray"), std::string::npos) << what;
    EXPECT_NE(what.find("it holds 16 bytes where 3 points of 1 Float64 need 24"), std::string::npos) << what;
  }
  const std::string what = test::input_error([&] { read_mesh(write("short_ascii.vtr", 2, ascii)); });
  EXPECT_NE(what.find("short_ascii.vtr: piece 0's x coordinates hold 2 values for the 3 points of its extent"),
            std::string::npos)
      << what;
}

TEST(Readers, XmlAttributesAreReadAsXmlWritesThem) {
  // White space around '=' and single quotes are XML too: VTK's reader takes them, and so must the
  // checks before it. A fuzzed offset   ="808" went past the appended-data check, and VTK sized
  // that array's garbled block header, 7 GB (59 s and 7 GB before the child's limit stopped it).
  test::TempDir dir;
  write_vtu(make_box(2, 2, 2, {0, 0, 0}, {1, 1, 1}, true), dir.file("box.vtu"));
  const std::string good = slurp(dir.file("box.vtu"));
  const std::size_t data = good.find("<AppendedData");
  ASSERT_NE(data, std::string::npos);
  const std::string head = std::regex_replace(good.substr(0, data), std::regex("(\\w+)=\"([^\"]*)\""), "$1 = '$2'");
  ASSERT_NE(head.find("NumberOfCells = '48'"), std::string::npos);
  spit(dir.file("spaced.vtu"), head + good.substr(data));
  EXPECT_EQ(read_mesh(dir.file("spaced.vtu")).n_cells(), 48);
  EXPECT_EQ(header_counts(dir.file("spaced.vtu")).cells, 48);
  // The Piece's counts as written that way are what the checks hold the arrays to.
  std::string wrong = head;
  wrong.replace(wrong.find("NumberOfCells = '48'"), 20, "NumberOfCells = '47'");
  spit(dir.file("wrong.vtu"), wrong + good.substr(data));
  const std::string what = test::input_error([&] { read_mesh(dir.file("wrong.vtu")); });
  EXPECT_NE(what.find("wrong.vtu: DataArray 'offsets' (appended at offset "), std::string::npos) << what;
  EXPECT_NE(what.find("it holds 384 bytes where 47 cells of 1 Int64 need 376"), std::string::npos) << what;
}

TEST(Readers, AnInlineBinaryArrayCutShortIsRefused) {
  // VTK's XML reader takes an inline base64 array shorter than its byte count without a word: a
  // .vtu with half its connectivity read with exit 0 and 81 degenerate cells, one with a third of
  // its field read as a wrong field. Written by VTK's own writer, then cut.
  test::TempDir dir;
  write_vtu(make_box(2, 2, 2, {0, 0, 0}, {1, 1, 1}, true), dir.file("box.vtu"));
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName(dir.file("box.vtu").c_str());
  reader->Update();
  for (bool compressed : {false, true}) {
    const std::string tag = compressed ? "z" : "raw";
    auto w = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
    w->SetInputData(reader->GetOutput());
    w->SetDataModeToBinary();
    if (!compressed) w->SetCompressorTypeToNone();
    w->SetFileName(dir.file(tag + ".vtu").c_str());
    w->Write();
    const std::string good = slurp(dir.file(tag + ".vtu"));
    ASSERT_NE(good.find("format=\"binary\""), std::string::npos);
    EXPECT_EQ(read_mesh(dir.file(tag + ".vtu")).n_cells(), read_mesh(dir.file("box.vtu")).n_cells()) << tag;
    // The connectivity's base64 text, cut to half.
    const std::size_t array = good.find("Name=\"connectivity\"");
    const std::size_t start = good.find_first_not_of(" \n", good.find('>', array) + 1);
    const std::size_t stop = good.find('<', start);
    const std::size_t length = good.find_last_not_of(" \n", stop - 1) + 1 - start;
    spit(dir.file(tag + "_cut.vtu"), good.substr(0, start + length / 2) + good.substr(start + length));
    const std::string what = test::input_error([&] { read_mesh(dir.file(tag + "_cut.vtu")); });
    EXPECT_NE(what.find(tag + "_cut.vtu: DataArray 'connectivity' (inline binary): "), std::string::npos) << what;
    EXPECT_NE(what.find("past the end of its data"), std::string::npos) << what;
  }
}

TEST(Readers, ParallelVtuPiecesAreMergedAtTheirInterface) {
  test::TempDir dir;
  auto half = [](double x0, double x1) {
    Mesh m = make_box(2, 4, 4, {x0, 0, 0}, {x1, 1, 1}, true);
    set_field(m, "f", [](const glm::dvec3& x) { return x.x + 2 * x.y; });
    return m;
  };
  write_vtu(half(0.0, 0.5), dir.file("a.vtu"));
  write_vtu(half(0.5, 1.0), dir.file("b.vtu"));
  spit(dir.file("box.pvtu"), R"(<?xml version="1.0"?>
<VTKFile type="PUnstructuredGrid" version="0.1" byte_order="LittleEndian" header_type="UInt64">
  <PUnstructuredGrid GhostLevel="0">
    <PPointData Scalars="f"><PDataArray type="Float64" Name="f"/></PPointData>
    <PPoints><PDataArray type="Float64" NumberOfComponents="3"/></PPoints>
    <Piece Source="a.vtu"/>
    <Piece Source="b.vtu"/>
  </PUnstructuredGrid>
</VTKFile>
)");
  const Mesh m = read_mesh(dir.file("box.pvtu"));
  const Mesh whole = make_box(4, 4, 4, glm::dvec3(0), glm::dvec3(1), true);
  EXPECT_EQ(m.n_points(), whole.n_points());  // 5 x 5 x 5, the 25 interface points once
  EXPECT_EQ(m.n_cells(), whole.n_cells());
  const FaceTopology topo = build_topology(m.view());
  EXPECT_EQ(topo.boundary.size(), build_topology(whole.view()).boundary.size());
  const auto& f = m.field("f").values;
  for (std::int64_t p = 0; p < m.n_points(); ++p) ASSERT_DOUBLE_EQ(f[p], m.points[3 * p] + 2 * m.points[3 * p + 1]);
  spit(dir.file("missing.pvtu"),
       slurp(dir.file("box.pvtu")).replace(slurp(dir.file("box.pvtu")).find("b.vtu"), 5, "c.vtu"));
  EXPECT_FALSE(read_error(dir.file("missing.pvtu")).empty());
}

// The isolated reader (io/isolated_read.hpp): what a reader does in its child process comes
// back to the caller as a mesh or an error, never as the caller's crash.
TEST(IsolatedRead, MovesTheMeshBackBitForBit) {
  Mesh m = make_box(3, 2, 2, glm::dvec3(-1), glm::dvec3(1), false);
  set_field(m, "s", [](const glm::dvec3& x) { return x.x * x.y + 0.1; });
  m.notes.push_back("a note");
  const Mesh back = read_isolated("mesh.vtu", "a reader", {}, [&] { return m; });
  EXPECT_EQ(back.points, m.points);
  EXPECT_EQ(back.connectivity, m.connectivity);
  EXPECT_EQ(back.offsets, m.offsets);
  EXPECT_EQ(back.types, m.types);
  ASSERT_EQ(back.fields.size(), 1u);
  EXPECT_EQ(back.fields[0].name, "s");
  EXPECT_EQ(back.fields[0].values, m.fields[0].values);
  EXPECT_EQ(back.notes, m.notes);
}

TEST(IsolatedRead, ErrorsCrashesAndExitsBecomeInputErrors) {
#if defined(__SANITIZE_ADDRESS__)
  const char* kCrashed = "bad.vtk: VTK's legacy reader crashed (signal ";  // AddressSanitizer's report ends in abort()
#else
  const char* kCrashed = "bad.vtk: VTK's legacy reader crashed (signal 11";
#endif
  auto message = [](const std::function<Mesh()>& read, const Isolation& iso = {}) -> std::string {
    try {
      read_isolated("bad.vtk", "VTK's legacy reader", iso, read);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(message([]() -> Mesh { throw InputError("bad.vtk: cell 3 is inverted"); }), "bad.vtk: cell 3 is inverted");
  EXPECT_NE(message([]() -> Mesh {
              std::raise(SIGSEGV);
              return {};
            }).find(kCrashed),
            std::string::npos);
  auto* handler = std::signal(SIGSEGV, SIG_IGN);  // a caller that ignores SIGSEGV: the crash still ends the child
  EXPECT_NE(message([]() -> Mesh {
              std::raise(SIGSEGV);
              return {};
            }).find(kCrashed),
            std::string::npos);
  std::signal(SIGSEGV, handler);
  EXPECT_NE(message([]() -> Mesh { std::exit(255); }).find("bad.vtk: VTK's legacy reader called exit()"),
            std::string::npos);
#if !defined(__SANITIZE_ADDRESS__)
  Isolation small;  // the child's address space is limited: a runaway allocation is refused
  small.memory_limit = 256u << 20;
  small.limit_source = "--max-memory";
  const std::string oom = message(
      []() -> Mesh {
        std::vector<double> v(std::size_t(1) << 30, 1.0);
        return {};
      },
      small);
  EXPECT_NE(oom.find("more memory than the 0.2 GiB allowed by --max-memory"), std::string::npos) << oom;
  // A library that calls exit() under the limit may have run out of memory: the message says both.
  const std::string exited = message([]() -> Mesh { std::exit(255); }, small);
  EXPECT_NE(exited.find("called exit() without a result; the file is malformed, or reading it needs more than the "
                        "0.2 GiB allowed by --max-memory"),
            std::string::npos)
      << exited;
#endif
}

TEST(IsolatedRead, TheHeaderIsCheckedAgainstTheMemoryLimitFirst) {
  test::TempDir dir;
  spit(dir.file("huge.vtk"),
       "# vtk DataFile Version 3.0\nx\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 2000000000 double\n");
  ReadOptions o;
  o.max_memory_gib = 4;
  EXPECT_NE(read_error(dir.file("huge.vtk"), o).find("its header declares 2000000000 points and 0 cells"),
            std::string::npos);
}

TEST(MemoryBudget, SizesInMessagesReadInTheirUnit) {
  EXPECT_EQ(format_bytes(3ull << 30), "3.0 GiB");
  EXPECT_EQ(format_bytes((1ull << 30) / 10), "0.1 GiB");
  EXPECT_EQ(format_bytes(2306867), "2.2 MiB");  // "0.0 GiB" said nothing
  EXPECT_EQ(format_bytes(0), "0.0 MiB");
}

namespace {

// A PLOT3D grid of n0 x n1 x n2 points (x = i, y = j, z = k), little-endian floats: written from C
// (no record markers, one grid) or from Fortran (records, a grid count, IBLANK).
std::string plot3d(int n0, int n1, int n2, bool fortran) {
  std::string out;
  const auto put = [&](auto v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); };
  const int n = n0 * n1 * n2;
  if (fortran) put(4), put(1), put(4), put(12);
  put(n0), put(n1), put(n2);
  if (fortran) put(12), put(n * 16);
  for (int axis = 0; axis < 3; ++axis)
    for (int k = 0; k < n2; ++k)
      for (int j = 0; j < n1; ++j)
        for (int i = 0; i < n0; ++i) put(static_cast<float>(axis == 0 ? i : axis == 1 ? j : k));
  if (fortran) {
    for (int p = 0; p < n; ++p) put(1);  // IBLANK: every point in use
    put(n * 16);
  }
  return out;
}

// Its solution (q) file in the same layout: the 4 properties, then density 1, momentum (i, 0, 0)
// and energy 3 per point.
std::string plot3d_q(int n0, int n1, int n2, bool fortran) {
  std::string out;
  const auto put = [&](auto v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); };
  const int n = n0 * n1 * n2;
  if (fortran) put(4), put(1), put(4), put(12);
  put(n0), put(n1), put(n2);
  if (fortran) put(12), put(16);
  for (float v : {0.5f, 0.0f, 1000.0f, 0.0f}) put(v);
  if (fortran) put(16), put(n * 20);
  for (int var = 0; var < 5; ++var)
    for (int p = 0; p < n; ++p) put(var == 0 ? 1.0f : var == 1 ? float(p % n0) : var == 4 ? 3.0f : 0.0f);
  if (fortran) put(n * 20);
  return out;
}

}  // namespace

TEST(Plot3d, ASolutionFileIsCheckedAgainstItsGridBeforeVtkReadsIt) {
  test::TempDir dir;
  for (bool fortran : {false, true}) {
    const std::string xyz = dir.file(fortran ? "fxyz.bin" : "cxyz.bin"), q = dir.file(fortran ? "fq.bin" : "cq.bin");
    spit(xyz, plot3d(4, 3, 2, fortran));
    const std::string good = plot3d_q(4, 3, 2, fortran);
    spit(q, good);
    const Mesh m = read_mesh(xyz);  // the q file found by its name
    ASSERT_NE(m.find_field("Density"), nullptr) << fortran;
    EXPECT_EQ(m.field("Density").values.size(), 24u);
    spit(q, good.substr(0, good.size() - 30));  // cut short
    EXPECT_NE(
        read_error(xyz).find(q + ": PLOT3D solution (q) file: truncated or corrupt: its 1 grid(s) of 5 variables need"),
        std::string::npos)
        << read_error(xyz);
    spit(q, plot3d_q(4, 3, 3, fortran));  // another grid's solution
    EXPECT_NE(read_error(xyz).find("grid 1's dimension 3 is 3, the grid file's is 2"), std::string::npos)
        << read_error(xyz);
  }
}

TEST(Plot3d, TheHeaderIsMatchedAsVtkDetectsItAndCorruptOnesAreRefusedFirst) {
  test::TempDir dir;
  for (bool fortran : {false, true}) {
    const std::string file = dir.file(fortran ? "f_xyz.bin" : "c_xyz.bin");
    spit(file, plot3d(4, 3, 2, fortran));
    const HeaderCounts h = header_counts(file);
    EXPECT_EQ(h.points, 24) << fortran;
    EXPECT_EQ(h.cells, 6) << fortran;
    EXPECT_EQ(read_mesh(file).n_cells(), 6) << fortran;
    // Cut short, and a dimension made huge: refused by the header check (no reader allocates it).
    const std::string bytes = plot3d(4, 3, 2, fortran);
    spit(file, bytes.substr(0, bytes.size() - 40));
    EXPECT_NE(read_error(file).find("PLOT3D grid (little-endian): truncated or corrupt"), std::string::npos)
        << read_error(file);
    std::string huge = bytes;
    const int big = 1 << 30;
    huge.replace(fortran ? 20 : 4, 4, reinterpret_cast<const char*>(&big), 4);
    spit(file, huge);
    EXPECT_NE(read_error(file).find("truncated or corrupt"), std::string::npos) << read_error(file);
    const int negative = -3;
    huge.replace(fortran ? 20 : 4, 4, reinterpret_cast<const char*>(&negative), 4);
    spit(file, huge);
    EXPECT_NE(read_error(file).find("truncated or corrupt"), std::string::npos) << read_error(file);
  }
}

TEST(VtkXml, AppendedDataThatLiesIsRefusedBeforeTheReaderRuns) {
  // A Piece whose point count disagrees with its arrays, an encoding VTK does not know: named
  // errors (VTK allocated what such headers claimed, up to the memory limit, or hung).
  test::TempDir dir;
  const Mesh m = make_box(2, 2, 2, glm::dvec3(0), glm::dvec3(1), true);
  write_vtu(m, dir.file("box.vtu"));
  const std::string good = slurp(dir.file("box.vtu"));
  std::string bad = good;
  const std::string points = "NumberOfPoints=\"" + std::to_string(m.n_points()) + "\"";
  ASSERT_NE(bad.find(points), std::string::npos);
  bad.replace(bad.find(points), points.size(), "NumberOfPoints=\"1000\"");
  spit(dir.file("count.vtu"), bad);
  EXPECT_NE(read_error(dir.file("count.vtu")).find("DataArray 'Points' (appended at offset"), std::string::npos)
      << read_error(dir.file("count.vtu"));
  EXPECT_NE(read_error(dir.file("count.vtu")).find("where 1000 points of 3 Float64 need 24000"), std::string::npos);
  bad = good;
  bad.replace(bad.find("encoding=\"base64\""), 17, "encoding=\"base32\"");
  spit(dir.file("enc.vtu"), bad);
  EXPECT_NE(read_error(dir.file("enc.vtu")).find("encoding 'base32' is neither raw nor base64"), std::string::npos);
  EXPECT_EQ(read_mesh(dir.file("box.vtu")).n_cells(), m.n_cells());
}
