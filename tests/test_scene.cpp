#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "base/error.hpp"
#include "io/read_mesh.hpp"
#include "io/write_mesh.hpp"
#include "render/settings_table.hpp"
#include "scene/prepare.hpp"
#include "scene/scene_file.hpp"
#include "test_util.hpp"
#include "tools/memory_budget.hpp"

using namespace cellproj;

namespace {

std::string scene_error(const std::string& path) {
  return test::input_error([&] { prepare_scene(load_scene(path)); });
}

}  // namespace

TEST(Scene, RelativeMeshPathAndErrorsNamingTheKey) {
  test::TempDir dir;
  Mesh m = make_box(2, 2, 2, glm::dvec3(0), glm::dvec3(1), true);
  set_field(m, "a", [](const glm::dvec3& x) { return x.x; });
  set_field(m, "b", [](const glm::dvec3& x) { return x.y; });
  write_vtu(m, dir.file("m.vtu"));
  auto write = [&](const std::string& text) {
    std::ofstream(dir.file("s.json")) << text;
    return dir.file("s.json");
  };
  const std::string tf = R"("transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]})";
  const Scene ok = load_scene(write(R"({"mesh": "m.vtu", "field": "b", )" + tf + "}"));
  EXPECT_EQ(ok.mesh, dir.file("m.vtu"));
  const PreparedScene p = prepare_scene(ok);
  EXPECT_EQ(p.field, "b");
  EXPECT_DOUBLE_EQ(p.field_max, 1.0);

  EXPECT_NE(scene_error(write(R"({"mesh": "m.vtu", )" + tf + "}"))
                .find("the mesh has several fields, choose one (setting 'field'): a, b"),
            std::string::npos);
  EXPECT_NE(scene_error(write(R"({"mesh": "m.vtu", "field": "c", )" + tf + "}")).find("the fields are: a, b"),
            std::string::npos);
  EXPECT_NE(scene_error(write(R"({"mesh": "m.vtu", "feild": "a", )" + tf + "}")).find("unknown key 'feild'"),
            std::string::npos);
  EXPECT_NE(scene_error(write(R"({"mesh": "m.vtu", "field": "a", "camera": {"eye": [0, 0, 1], "target": [0, 0, 1]}, )" +
                              tf + "}"))
                .find("eye and target are the same point"),
            std::string::npos);
  EXPECT_NE(
      scene_error(write(R"({"mesh": "m.vtu", "field": "a", "image": {"width": 0}, )" + tf + "}")).find("image.width"),
      std::string::npos);
  EXPECT_NE(scene_error(write(R"({"mesh": "m.vtu", "field": "a" )")).find("not valid JSON"), std::string::npos);
  EXPECT_NE(scene_error(write(R"({"mesh": "gone.vtu", "field": "a", )" + tf + "}")).find("gone.vtu: no such file"),
            std::string::npos);
}

TEST(MemoryBudget, CountsFromVtkXmlHeaders) {
  // The counts the --max-memory check uses before reading a file, against what reading finds.
  test::TempDir dir;
  Mesh m = make_box(3, 4, 5, glm::dvec3(0), glm::dvec3(1), true);
  set_field(m, "s", [](const glm::dvec3& x) { return x.x; });
  write_vtu(m, dir.file("box.vtu"));
  const HeaderCounts c = header_counts(dir.file("box.vtu"));
  EXPECT_EQ(c.points, m.n_points());
  EXPECT_EQ(c.cells, m.n_cells());
  EXPECT_EQ(header_counts(dir.file("missing.vtu")).cells, 0);
  const std::string vts = test::shared_data("nasa_bluntfin/bluntfin.vts");
  if (!std::filesystem::exists(vts)) GTEST_SKIP() << "no " << vts;
  const HeaderCounts b = header_counts(vts);  // WholeExtent="0 39 0 31 0 31", one piece
  EXPECT_EQ(b.points, 40 * 32 * 32);
  EXPECT_EQ(b.cells, 39 * 31 * 31);
  EXPECT_GT(estimate_mesh_bytes(b), 0u);
}

TEST(MemoryBudget, CountsFromLegacyDimensionsWithoutPoints) {
  // Structured points and rectilinear grids declare no POINTS or CELLS: their DIMENSIONS count, and
  // what reading finds agrees.
  test::TempDir dir;
  std::ofstream(dir.file("sp.vtk")) << "# vtk DataFile Version 3.0\nsp\nASCII\nDATASET STRUCTURED_POINTS\n"
                                       "DIMENSIONS 3 4 5\nORIGIN 0 0 0\nSPACING 1 1 1\n";
  const HeaderCounts c = header_counts(dir.file("sp.vtk"));
  EXPECT_EQ(c.points, 3 * 4 * 5);
  EXPECT_EQ(c.cells, 2 * 3 * 4);
  const Mesh m = read_mesh(dir.file("sp.vtk"));
  EXPECT_EQ(m.n_points(), c.points);
  EXPECT_EQ(m.n_cells(), c.cells);
  std::ofstream(dir.file("huge.vtk")) << "# vtk DataFile Version 3.0\nrg\nASCII\nDATASET RECTILINEAR_GRID\n"
                                         "DIMENSIONS 3000 3000 3000\nX_COORDINATES 3000 float\n";
  EXPECT_EQ(header_counts(dir.file("huge.vtk")).points, std::int64_t(27000000000));
}

namespace cellproj {
TEST(Scene, AScenePathTheFileSystemCannotLookUpIsAnInputError) {
  const std::string path = "/tmp/" + std::string(300, 's') + ".json";
  const std::string what = test::input_error([&] { load_scene(path); });
  EXPECT_NE(what.find(path + ": cannot be looked up (File name too long)"), std::string::npos) << what;
}
}  // namespace cellproj

// A scene's "render" block: any setting of the table, by name, what the scene renders with unless
// the command line says otherwise.
TEST(Scene, TheRenderBlockSetsAnySettingAsADefault) {
  test::TempDir dir;
  write_vtu(make_box(2, 2, 2, glm::dvec3(0), glm::dvec3(1), true), dir.file("m.vtu"));
  auto write = [&](const std::string& render) {
    std::ofstream(dir.file("s.json"))
        << R"({"mesh": "m.vtu", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]}, "render": )" +
               render + "}";
    return dir.file("s.json");
  };
  const Scene s = load_scene(write(R"({"method": "pt-table", "table_size": 64, "cull_transparent": false})"));
  RenderOptions o;
  EXPECT_TRUE(apply_scene_options(s, o).empty());
  EXPECT_TRUE(o.given.empty());  // the scene's defaults, not the user's words
  RenderSettings r = settings_from(o);
  EXPECT_EQ(r.projection.method, ProjectionMethod::pt_table);
  EXPECT_EQ(r.projection.table_size, 64);
  EXPECT_FALSE(r.projection.cull_transparent);

  RenderOptions cli;  // the command line wins, and a scene setting the method does not read is said
  set_option(cli, "method", "exact");
  const std::vector<std::string> warnings = apply_scene_options(s, cli);
  ASSERT_EQ(warnings.size(), 2u);  // the block's keys in JSON's order
  EXPECT_NE(warnings[0].find("render.cull_transparent does not apply to setting 'method' exact"), std::string::npos);
  EXPECT_NE(warnings[1].find("render.table_size does not apply to setting 'method' exact"), std::string::npos);
  EXPECT_EQ(settings_from(cli).mode, RenderMode::exact);
  EXPECT_NO_THROW(refuse_unused(settings_from(cli), cli.given));

  const auto refused = [&](const std::string& render) { return test::input_error([&] { load_scene(write(render)); }); };
  EXPECT_NE(refused(R"({"colour": "red"})").find("render.colour: 'colour' is not a render setting"), std::string::npos);
  EXPECT_NE(refused(R"({"table_size": 1})").find("render.table_size: setting 'table-size': expected an integer"),
            std::string::npos);
  EXPECT_NE(refused(R"({"iso": 0.5})").find("render.iso: give iso-surfaces in the scene's \"iso\" list"),
            std::string::npos);
  EXPECT_NE(refused(R"({"slices": [1, 2]})").find("expected a string, number or boolean"), std::string::npos);
  EXPECT_NE(refused(R"("exact")").find("expected an object of render settings"), std::string::npos);
}
