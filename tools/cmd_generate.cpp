// cellproj generate KIND -o FILE
#include <cstdio>
#include <filesystem>

#include "base/error.hpp"
#include "grid/generate.hpp"
#include "grid/write_mesh.hpp"
#include "tools/commands.hpp"

namespace cellproj {

Action add_generate(CLI::App& app) {
  struct Args {
    std::string kind, out;
    int n = 16;
    bool binary = false;
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
  return [args] {
    const Mesh m = generate(args->kind, args->n);
    write_mesh(m, args->out, args->binary);
    std::printf("wrote %s (%lld points, %lld cells)\n", args->out.c_str(), static_cast<long long>(m.n_points()),
                static_cast<long long>(m.n_cells()));
    return kExitOk;
  };
}

}  // namespace cellproj
