// Writes the fuzzers' seed corpora: small generated files of every format, one folder per harness
// (OUT/vtu, OUT/vtk, ...), so that fuzzing starts from valid structure. Usage: fuzz_seeds OUT
#include <vtk_cgns.h>  // VTK's copy of the CGNS library, the one its reader uses
#include VTK_CGNS(cgnslib.h)

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/write_mesh.hpp"
#include "mesh/generate.hpp"
#include "tests/legacy_samples.hpp"

namespace fs = std::filesystem;
using namespace cellproj;

namespace {

// An unstructured CGNS zone through the CGNS library VTK reads with: TETRA_4 or HEXA_8 (the
// corner order of both is VTK's), with the first field at the vertices.
void write_cgns(const Mesh& m, const std::string& path) {
  int fn = 0, base = 0, zone = 0, coord = 0, section = 0, sol = 0, field = 0;
  if (cg_open(path.c_str(), CG_MODE_WRITE, &fn) != CG_OK) throw std::runtime_error(cg_get_error());
  cg_base_write(fn, "Base", 3, 3, &base);
  const cgsize_t size[3] = {m.n_points(), m.n_cells(), 0};
  cg_zone_write(fn, base, "Zone", size, CGNS_ENUMV(Unstructured), &zone);
  const char* names[3] = {"CoordinateX", "CoordinateY", "CoordinateZ"};
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> x;
    for (std::int64_t p = 0; p < m.n_points(); ++p) x.push_back(m.points[3 * p + axis]);
    cg_coord_write(fn, base, zone, CGNS_ENUMV(RealDouble), names[axis], x.data(), &coord);
  }
  std::vector<cgsize_t> conn;
  for (auto id : m.connectivity) conn.push_back(id + 1);  // CGNS numbers from 1
  const bool tets = m.types.front() == static_cast<std::uint8_t>(CellType::Tetra);
  cg_section_write(fn, base, zone, "Cells", tets ? CGNS_ENUMV(TETRA_4) : CGNS_ENUMV(HEXA_8), 1, m.n_cells(), 0,
                   conn.data(), &section);
  cg_sol_write(fn, base, zone, "Solution", CGNS_ENUMV(Vertex), &sol);
  cg_field_write(fn, base, zone, sol, CGNS_ENUMV(RealDouble), m.fields.front().name.c_str(),
                 m.fields.front().values.data(), &field);
  if (cg_close(fn) != CG_OK) throw std::runtime_error(cg_get_error());
}

// A PLOT3D multi-grid whole file with Fortran record markers: one 3x3x3 block, float32, a twist.
void write_plot3d(const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  auto record = [&](const void* data, std::int32_t bytes) {
    out.write(reinterpret_cast<const char*>(&bytes), 4);
    out.write(static_cast<const char*>(data), bytes);
    out.write(reinterpret_cast<const char*>(&bytes), 4);
  };
  const std::int32_t blocks = 1, dims[3] = {3, 3, 3};
  record(&blocks, 4);
  record(dims, 12);
  std::vector<float> xyz(3 * 27);
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const int p = i + 3 * (j + 3 * k);
        xyz[p] = float(i) + 0.1f * float(k);
        xyz[27 + p] = float(j) - 0.1f * float(k);
        xyz[54 + p] = float(k);
      }
  record(xyz.data(), static_cast<std::int32_t>(xyz.size() * 4));
}

void concat(const std::vector<std::string>& parts, const std::string& path) {  // TetGen: .node NUL .ele
  std::ofstream out(path, std::ios::binary);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    std::ifstream in(parts[i], std::ios::binary);
    out << in.rdbuf();
    if (i + 1 < parts.size()) out.put('\0');
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_seeds OUT\n");
    return 2;
  }
  const fs::path out = argv[1];
  for (const char* d : {"vtu", "vtk", "exodus", "cgns", "plot3d", "tetgen", "off", "points", "scene"})
    fs::create_directories(out / d);
  const Mesh tets = generate("box-tets", 1), box = generate("box", 2), mixed = generate("mixed", 2);
  write_mesh(tets, (out / "vtu/box-tets.vtu").string());
  write_mesh(mixed, (out / "vtu/mixed.vtu").string());
  write_mesh(tets, (out / "vtk/box-tets-ascii.vtk").string());
  write_mesh(mixed, (out / "vtk/mixed-ascii.vtk").string());
  write_mesh(mixed, (out / "vtk/mixed-binary.vtk").string(), true);
  // Legacy structured grids (read without VTK's metadata pass) and the attribute blocks the
  // dataset walk checks in POINT_DATA and CELL_DATA, which cellproj's writer does not write.
  std::ofstream(out / "vtk/structured-ascii.vtk") << test::kStructuredGridNamedField << R"(VECTORS v float
0 0 1 0 1 0 1 0 0 0 0 1 0 1 0 1 0 0 0 0 1 1 1 1
COLOR_SCALARS c 2
0 1 0 1 0 1 0 1 0 1 0 1 0 1 0 1
CELL_DATA 1
FIELD FieldData 1
heat 1 1 double
2.5
LOOKUP_TABLE t 1
0 0 0 1
)";
  {
    std::ofstream sg(out / "vtk/structured-binary.vtk", std::ios::binary);
    sg << "# vtk DataFile Version 3.0\nsg\nBINARY\nDATASET STRUCTURED_GRID\nDIMENSIONS 2 2 2\nPOINTS 8 float\n";
    auto big_endian = [&](const void* p, int n) {  // legacy binary values are big-endian
      const auto* b = static_cast<const unsigned char*>(p);
      for (int k = n - 1; k >= 0; --k) sg.put(static_cast<char>(b[k]));
    };
    for (int k = 0; k < 8; ++k)
      for (int a = 0; a < 3; ++a) {
        const float x = static_cast<float>((k >> a) & 1);
        big_endian(&x, 4);
      }
    sg << "\nPOINT_DATA 8\nSCALARS s float 1\nLOOKUP_TABLE default\n";
    for (int k = 0; k < 8; ++k) {
      const float x = static_cast<float>(k);
      big_endian(&x, 4);
    }
    sg << "\nCELL_DATA 1\nFIELD FieldData 1\nheat 1 1 double\n";
    const double h = 2.5;
    big_endian(&h, 8);
    sg << "\n";
  }
  // A rectilinear grid (its axes' coordinates checked against DIMENSIONS) and structured points.
  std::ofstream(out / "vtk/rectilinear-ascii.vtk") << R"(# vtk DataFile Version 3.0
rg
ASCII
DATASET RECTILINEAR_GRID
DIMENSIONS 3 2 2
X_COORDINATES 3 float
0 0.5 1
Y_COORDINATES 2 float
0 1
Z_COORDINATES 2 double
0 1
POINT_DATA 12
SCALARS s float 1
LOOKUP_TABLE default
0 1 2 3 4 5 6 7 8 9 10 11
)";
  std::ofstream(out / "vtk/points-ascii.vtk") << R"(# vtk DataFile Version 3.0
sp
ASCII
DATASET STRUCTURED_POINTS
DIMENSIONS 2 2 3
ORIGIN 0 0 0
SPACING 1 1 0.5
POINT_DATA 12
SCALARS s float 1
LOOKUP_TABLE default
0 1 2 3 4 5 6 7 8 9 10 11
)";
  write_mesh(mixed, (out / "exodus/mixed.exo").string());
  write_cgns(tets, (out / "cgns/box-tets.cgns").string());
  write_cgns(box, (out / "cgns/box.cgns").string());
  write_plot3d((out / "plot3d/twisted.xyz").string());
  const fs::path tmp = out / "tetgen/tmp";
  write_mesh(tets, tmp.string() + ".node");
  concat({tmp.string() + ".node", tmp.string() + ".ele"}, (out / "tetgen/box-tets").string());
  fs::remove(tmp.string() + ".node");
  fs::remove(tmp.string() + ".ele");
  write_mesh(tets, (out / "off/box-tets.off").string());
  {
    std::ofstream pts(out / "points/cloud.xyzs");
    for (int i = 0; i < 12; ++i) pts << (i % 3) << ' ' << (i / 3 % 2) << ' ' << (i * 7 % 5) * 0.25 << ' ' << i << '\n';
  }
  std::ofstream(out / "scene/basic.json")
      << R"({"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 1, 1]], "extinction": [[0, 1]]}})";
  std::ofstream(out / "scene/full.json") << R"({"mesh": "box.vtu", "field": "scalar", "reader": {"format": "vtk-xml"},
  "transfer_function": {"color": [[0.0, 0.1, 0.2, 0.55], [0.5, 0.95, 0.85, 0.35], [1.1, 1.0, 0.95, 0.85]],
                        "extinction": [[0.0, 0.4], [0.45, 2.0], [1.1, 30.0]]},
  "camera": {"projection": "perspective", "eye": [1.6, -2.6, 2.2], "target": [0, 0, 0], "up": [0, 0, 1], "fov_y": 32},
  "image": {"width": 64, "height": 48, "background": [0.04, 0.04, 0.06]}})";
  std::ofstream(out / "scene/ortho.json")
      << R"({"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 0, 0], [1, 0, 0, 1]], "extinction": [[0, 0], [1, 5]]},
  "camera": {"projection": "orthographic", "eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "height": 4}})";
  std::ofstream(out / "scene/volumes.json")
      << R"({"volumes": [{"mesh": "box.vtu", "transfer_function": {"color": [[0, 1, 0.5, 0]], "extinction": [[0, 1]]}},
  {"mesh": "box.vtu", "field": "scalar", "volume": false, "transfer_function": {"color": [[0, 0, 0, 1]], "extinction": [[0, 2]]},
   "iso": [{"value": 0.5, "color": [1, 0, 0], "opacity": 0.4}]}], "iso_mode": "oit4",
  "clip": [{"point": [0, 0, 0.1], "normal": [0, 0.2, 1]}], "image": {"width": 32, "height": 24}})";
  std::printf("wrote seeds to %s\n", out.c_str());
  return 0;
}
