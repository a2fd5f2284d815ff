// `cellproj info` on every dataset in ../shared/data: the counts of its README and PROVENANCE notes,
// and every known defect reported (none is a crash).
#include <filesystem>
#include <map>

#include <gtest/gtest.h>

#include "io/read_mesh.hpp"
#include "mesh/topology.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

struct Expected {
  const char* file;
  const char* zone;
  std::int64_t points, tetra, hexahedron, wedge, pyramid;
  std::int64_t boundary_faces;  // -1: not stated by the data's notes
  int convex;                   // 1 yes, 0 no, -1 not checked
  std::int64_t degenerate, inverted, duplicates;
};

// From shared/data/README.md and the PROVENANCE.md files.
const Expected kData[] = {
    {"nasa_bluntfin/bluntfinxyz.bin", "", 40960, 0, 37479, 0, 0, 6758, 0, 0, 0, 39},
    {"nasa_bluntfin/bluntfin.vts", "", 40960, 0, 37479, 0, 0, 6758, 0, 0, 0, 39},
    {"nasa_bluntfin/bluntfin_hex.vtu", "", 40960, 0, 37479, 0, 0, 6758, 0, 0, 0, 39},
    {"nasa_bluntfin/bluntfin_tets.vtu", "", 40960, 187395, 0, 0, 0, 13516, 0, 77, 0, 39},
    {"nasa_combustion_chamber/combxyz.bin", "", 47025, 0, 43008, 0, 0, 7808, 0, 0, 0, 0},
    {"nasa_combustion_chamber/comb.vts", "", 47025, 0, 43008, 0, 0, 7808, 0, 0, 0, 0},
    {"nasa_combustion_chamber/comb_hex.vtu", "", 47025, 0, 43008, 0, 0, 7808, 0, 0, 0, 0},
    {"nasa_combustion_chamber/comb_tets.vtu", "", 47025, 215040, 0, 0, 0, 15616, 0, 0, 2, 0},
    // CFX writes its wedges with the other orientation: every one is re-oriented.
    {"cgns_heating_coil/heating_coil_fluid.vtu", "", 29826, 59193, 0, 33476, 558, 10258, 0, 0, 33476, -1},
    {"cgns_heating_coil/HeatingCoil.cgns.gz", "FluidZone", 29826, 59193, 0, 33476, 558, 10258, 0, 0, 33476, -1},
    {"cgns_heating_coil/heating_coil_solid.vtu", "", 4394, 17908, 0, 0, 0, 4558, 0, 0, 0, -1},
    {"cgns_static_mixer/static_mixer.vtu", "", 2786, 13761, 0, 0, 0, -1, 0, 0, -1, -1},
    {"cgns_static_mixer/StaticMixer.cgns.gz", "", 2786, 13761, 0, 0, 0, -1, 0, 0, -1, -1},
    {"exodus_disk_out_ref/disk_out_ref.ex2", "", 8499, 0, 7472, 0, 0, -1, 0, 0, -1, -1},
    {"exodus_disk_out_ref/disk_out_ref.vtu", "", 8499, 0, 7472, 0, 0, -1, 0, 0, -1, -1},
    {"vtkdata_can/can.vtu", "", 6724, 0, 4800, 0, 0, -1, 0, 0, -1, -1},
    {"vtkdata_can/can_point_scalars.vtu", "", 6724, 0, 4800, 0, 0, -1, 0, 0, -1, -1},
    {"vtkdata_hexa/hexa.vtk", "", 12167, 0, 10648, 0, 0, -1, 1, 0, 0, 0},
    {"vtkdata_hexa/hexa.vtu", "", 12167, 0, 10648, 0, 0, -1, 1, 0, 0, 0},
    {"vtkdata_post_tets/post.vtk", "", 2288, 8750, 0, 0, 0, -1, 0, -1, -1, 88},
    {"vtkdata_post_tets/post_tets.vtu", "", 2288, 8750, 0, 0, 0, -1, 0, -1, -1, 88},
    {"vtkdata_tetramesh/tetraMesh.vtk", "", 55, 160, 0, 0, 0, -1, 1, 0, 80, 0},
    {"vtkdata_tetramesh/tetramesh.vtu", "", 55, 160, 0, 0, 0, -1, 1, 0, 80, 0},
    {"vtkdata_angular_sector/AngularSector.vtk", "", 10141, 0, 7632, 0, 144, -1, 0, -1, -1, 1014},
    {"vtkdata_angular_sector/angular_sector.vtu", "", 10141, 0, 7632, 0, 144, -1, 0, -1, -1, 1014},
    {"vtkdata_notch_stress/notch_stress_fixed.vtk", "", 3537, 0, 2188, 4, 0, -1, 0, -1, -1, -1},
    {"vtkdata_notch_stress/notch_stress.vtu", "", 3537, 0, 2188, 4, 0, -1, 0, -1, -1, -1},
    {"vtk_small_cell_samples/uGridEx.vtk", "", 27, 2, 2, 0, 0, -1, 0, -1, -1, -1},
    {"vtk_small_cell_samples/elements.vtu", "", 112, 2, 2, 2, 2, -1, 0, -1, -1, -1},  // the voxel is a hexahedron
    {"vtk_small_cell_samples/Tetrahedron.vtu", "", 35, 96, 0, 0, 0, -1, 1, 0, 0, 0},
    {"vtk_small_cell_samples/Wedge.vtu", "", 27, 0, 0, 16, 0, -1, 1, 0, 0, 0},
};

class SharedData : public ::testing::TestWithParam<Expected> {};

}  // namespace

TEST_P(SharedData, CountsAndDefects) {
  const Expected& e = GetParam();
  const std::string path = test::shared_data(e.file);
  if (!std::filesystem::exists(test::shared_data(""))) GTEST_SKIP() << "no ../shared/data beside this clone";
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  ReadOptions o;
  o.zone = e.zone;
  o.cell_data.reset();  // the file's points, its cell data kept per cell
  const LoadedMesh l = load_mesh(path, o);
  std::map<CellType, std::int64_t> n;
  for (auto t : l.mesh.types) ++n[static_cast<CellType>(t)];
  EXPECT_EQ(l.mesh.n_points(), e.points);
  EXPECT_EQ(n[CellType::Tetra], e.tetra);
  EXPECT_EQ(n[CellType::Hexahedron], e.hexahedron);
  EXPECT_EQ(n[CellType::Wedge], e.wedge);
  EXPECT_EQ(n[CellType::Pyramid], e.pyramid);
  const FaceTopology t = build_topology(l.mesh.view());
  if (e.boundary_faces >= 0) EXPECT_EQ(static_cast<std::int64_t>(t.boundary.size()), e.boundary_faces);
  if (e.convex >= 0) EXPECT_EQ(boundary_convexity(l.mesh.view(), t).convex, e.convex == 1);
  if (e.degenerate >= 0) EXPECT_EQ(l.report.degenerate_cells, e.degenerate);
  if (e.inverted >= 0) EXPECT_EQ(l.report.inverted_cells, e.inverted);
  if (e.duplicates >= 0) EXPECT_EQ(l.report.duplicate_points, e.duplicates);
  EXPECT_EQ(t.nonmanifold_faces, 0);
}

INSTANTIATE_TEST_SUITE_P(Datasets, SharedData, ::testing::ValuesIn(kData), [](const auto& info) {
  std::string name = info.param.file;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

TEST(SharedDataDefects, ConstantAndCellFieldsAreReported) {
  if (!std::filesystem::exists(test::shared_data(""))) GTEST_SKIP() << "no ../shared/data beside this clone";
  const Mesh comb = read_mesh(test::shared_data("nasa_combustion_chamber/combxyz.bin"));
  const auto& e = comb.field("StagnationEnergy").values;
  EXPECT_TRUE(std::all_of(e.begin(), e.end(), [](double v) { return v == 0.0; }));
  EXPECT_EQ(comb.find_field("Pressure"), nullptr);  // meaningless from zero energy: omitted, with a note
  Mesh can = read_mesh(test::shared_data("vtkdata_can/can.vtu"));
  ASSERT_EQ(can.cell_fields.size(), 1u);
  EXPECT_EQ(can.cell_fields[0].name, "EQPS");
  apply_cell_data(can, CellData::points);
  ASSERT_NE(can.find_field("EQPS"), nullptr);
  EXPECT_NE(can.field("EQPS").origin.find("volume-weighted"), std::string::npos);
}
