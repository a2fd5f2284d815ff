// cellproj partition MESH --bricks N -o DIR
#include <cstdio>

#include <nlohmann/json.hpp>

#include "partition/partition_index.hpp"
#include "tools/commands.hpp"
#include "tools/memory_budget.hpp"
#include "tools/mesh_options.hpp"
#include "tools/progress.hpp"
#include "tools/timing.hpp"

namespace cellproj {

Action add_partition(CLI::App& app) {
  struct Args {
    std::string mesh, out, cost = "projected";
    int bricks = 0, image_side = 1024;
    ReadOptions reader;
    bool stats = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "partition",
      "Cut a mesh into k-d bricks for `mpirun -np P cellproj render DIR` (docs/parallel.md): one .vtu per brick "
      "and DIR/partition.json");
  cmd->add_option("mesh", args->mesh, "Mesh file (any format `info` reads)")->required();
  cmd->add_option("--bricks", args->bricks, "Number of bricks (a multiple of the ranks balances best)")
      ->required()
      ->check(CLI::Range(1, 65536));
  cmd->add_option("-o,--output", args->out, "Folder to write the bricks and partition.json into")->required();
  cmd->add_option("--cost", args->cost,
                  "What the bricks balance: projected (default: each cell's tetrahedra and their mean projected "
                  "area in pixels, --image-size across the mesh) or cells (the tetrahedra alone)")
      ->check(CLI::IsMember({"projected", "cells"}));
  cmd->add_option("--image-size", args->image_side,
                  "projected: the pixels across the mesh's diagonal in the renders to balance (default 1024)")
      ->check(CLI::Range(16, 65536));
  add_reader_options(*cmd, args->reader);
  add_max_memory_option(*cmd, args->reader.max_memory_gib, "Refuse meshes whose partitioning is");
  cmd->add_flag("--stats", args->stats, "Print one JSON line: seconds, cells cut, peak memory");
  return [args] {
    const auto t = std::chrono::steady_clock::now();
    // The mesh, and at most one brick as large as the mesh with its cut cells' pieces and the cells'
    // brick lists: twice the mesh, from the header before reading it.
    if (const HeaderCounts h = header_counts(args->mesh); h.cells > 0)
      refuse_beyond_memory(2 * estimate_mesh_bytes(h), args->reader.max_memory_gib,
                           "partitioning " + std::to_string(h.cells) + " cells (the mesh and one brick)", args->mesh,
                           "partition on a machine with more memory, or cut the mesh first");
    const LoadedMesh loaded = read_with_progress(args->mesh, args->reader);
    const double read_mib = peak_rss_mib();
    PartitionReport r;
    const PartitionIndex index = partition_mesh(loaded.mesh, args->bricks, args->out, args->cost, args->image_side, &r);
    std::printf("wrote %s (%d bricks of %lld cells: %lld cut by the planes into %lld tetrahedra)\n", index.path.c_str(),
                args->bricks, static_cast<long long>(loaded.mesh.n_cells()), static_cast<long long>(r.clipped.cut),
                static_cast<long long>(r.clipped.tetrahedra));
    if (args->stats) {
      double lo = 1e300, hi = 0, sum = 0;
      for (const BrickEntry& b : index.bricks) lo = std::min(lo, b.cost), hi = std::max(hi, b.cost), sum += b.cost;
      const nlohmann::json s = {{"mesh", args->mesh},
                                {"bricks", args->bricks},
                                {"cells", loaded.mesh.n_cells()},
                                {"cells_cut", r.clipped.cut},
                                {"tetrahedra_from_cut_cells", r.clipped.tetrahedra},
                                {"largest_brick_cells", r.peak_brick_cells},
                                {"cost_imbalance", hi / (sum / args->bricks)},
                                {"seconds", seconds_since(t)},
                                {"peak_rss_after_read_mib", read_mib},
                                {"peak_rss_mib", peak_rss_mib()}};
      std::fprintf(stderr, "%s\n", s.dump().c_str());
    }
    return kExitOk;
  };
}

}  // namespace cellproj
