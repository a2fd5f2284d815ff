// cellproj generate KIND -o FILE
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "base/error.hpp"
#include "io/series_files.hpp"
#include "io/write_mesh.hpp"
#include "mesh/generate.hpp"
#include "tools/commands.hpp"

namespace cellproj {
namespace {

// A time series of `steps` key frames at times 0, 1, ...: the mesh's field times a wave travelling
// along x, 1 + 0.5 sin(4x - 2 pi k / steps). `out` is a pattern with one %d (mesh_%04d.vtu), or a
// .pvd written with its key frames NAME_0000.vtu, ... beside it. Returns the files written.
std::vector<std::string> write_series(Mesh m, const std::string& out, int steps, bool binary) {
  const bool pvd = std::filesystem::path(out).extension() == ".pvd";
  if (!pvd && !is_series_path(out))
    throw InputError("--steps: -o must be a .pvd collection or a file pattern with one %d (mesh_%04d.vtu)");
  const std::string pattern =
      pvd ? (std::filesystem::path(out).parent_path() / (std::filesystem::path(out).stem().string() + "_%04d.vtu"))
                .string()
          : out;
  check_file_pattern(pattern);  // given to printf: one %d and no other %
  const std::vector<double> base = m.fields.at(0).values;
  std::vector<std::string> files;
  std::string collection = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (int k = 0; k < steps; ++k) {
    for (std::int64_t p = 0; p < m.n_points(); ++p)
      m.fields[0].values[p] = base[p] * (1.0 + 0.5 * std::sin(4.0 * m.points[3 * p] - 2.0 * M_PI * k / steps));
    char file[4096];
    std::snprintf(file, sizeof file, pattern.c_str(), k);
    write_mesh(m, file, binary);
    files.push_back(file);
    collection += "  <DataSet timestep=\"" + std::to_string(k) + "\" part=\"0\" file=\"" +
                  std::filesystem::path(file).filename().string() + "\"/>\n";
  }
  if (pvd) {
    std::ofstream f(out);
    f << collection << "</Collection>\n</VTKFile>\n";
    if (!f) throw InputError(where(out, "write failed"));
    files.push_back(out);
  }
  return files;
}

// The mesh's field as cell data: each cell the mean of its vertices' values (a finite-volume
// solver's cell averages, for trying --cell-data).
Mesh as_cell_data(Mesh m) {
  for (const PointField& f : m.fields) {
    PointField c{f.name, {}, "generated, the mean over each cell", f.components};
    for (std::int64_t cell = 0; cell < m.n_cells(); ++cell)
      for (int k = 0; k < f.components; ++k) {
        double sum = 0;
        for (std::int64_t i = m.offsets[cell]; i < m.offsets[cell + 1]; ++i) sum += f.tuple(m.connectivity[i])[k];
        c.values.push_back(sum / static_cast<double>(m.offsets[cell + 1] - m.offsets[cell]));
      }
    m.cell_fields.push_back(std::move(c));
  }
  m.fields.clear();
  return m;
}

}  // namespace

Action add_generate(CLI::App& app) {
  struct Args {
    std::string kind, out;
    int n = 16, steps = 1;
    bool binary = false, cell_data = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("generate", "Write a synthetic mesh made by cellproj (" + generated_kinds() + ")");
  cmd->add_option("kind", args->kind, "box | box-tets | swirl | swirl-tets | mixed | graded | graded-tets")->required();
  cmd->add_option("-n,--resolution", args->n, "Cells per axis (swirl: 3n x n x n; graded: 2n x 2n x 2n)")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("-o,--output", args->out,
                  "Output mesh: .vtu, .vtk (legacy), .exo (Exodus II), or for tetrahedra .node (TetGen) or .off")
      ->required();
  cmd->add_flag("--binary", args->binary, ".vtk: binary instead of ASCII");
  cmd->add_flag("--cell-data", args->cell_data,
                "Write the field as cell data (each cell the mean of its vertices), as a finite-volume solver would");
  cmd->add_option("--steps", args->steps,
                  "Write a time series of this many key frames (times 0, 1, ...), the field times a wave travelling "
                  "along x: -o a .pvd (its files beside it) or a pattern such as out/mesh_%04d.vtu")
      ->check(CLI::Range(1, 100000));
  return [args] {
    Mesh m = usage([&] { return generate(args->kind, args->n); });  // an unknown kind: exit 2
    if (args->cell_data && args->steps > 1) throw UsageError("--cell-data writes one mesh: give it without --steps");
    if (args->cell_data) m = as_cell_data(std::move(m));
    if (args->steps > 1) {
      const std::vector<std::string> files = write_series(m, args->out, args->steps, args->binary);
      std::printf("wrote %s ... %s (%d key frames of %lld points, %lld cells)\n", files.front().c_str(),
                  files.back().c_str(), args->steps, static_cast<long long>(m.n_points()),
                  static_cast<long long>(m.n_cells()));
      return kExitOk;
    }
    write_mesh(m, args->out, args->binary);
    std::printf("wrote %s (%lld points, %lld cells)\n", args->out.c_str(), static_cast<long long>(m.n_points()),
                static_cast<long long>(m.n_cells()));
    return kExitOk;
  };
}

}  // namespace cellproj
