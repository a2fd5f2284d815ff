#pragma once
// A partitioned mesh on disk (`cellproj partition`): one .vtu per brick and the index
// DIR/partition.json naming the brick files, their boxes and costs, the k-d tree, and the whole
// mesh's bounds and field ranges (so each rank frames and colours the picture as one process would,
// having read only its own bricks).
#include <cstdint>
#include <string>
#include <vector>

#include "io/read_mesh.hpp"
#include "mesh/clip.hpp"
#include "optics/transfer_function.hpp"
#include "partition/kd_partition.hpp"

namespace cellproj {

struct BrickEntry {
  std::string file;  // relative to the index's folder; "" for a brick with no cells
  std::int64_t cells = 0, points = 0;
  double cost = 0.0;
};

struct FieldRange {
  std::string name;
  double min = 0.0, max = 0.0;
  // opacity auto's extinction for the field (a vector's magnitude), found from the whole mesh when
  // it was partitioned (optics/auto_opacity.hpp), so that its bricks render the mesh's default look.
  std::vector<ExtinctionPoint> auto_extinction;
};

struct PartitionIndex {
  std::string path;    // the index file, for messages
  std::string source;  // the mesh partitioned
  std::int64_t cells = 0;
  std::string cost_model;  // "projected" or "cells" (cell_costs)
  KdTree tree;
  std::vector<BrickEntry> bricks;
  std::vector<FieldRange> fields;
  std::string brick_path(int brick) const;  // the file of a brick, as a path to open
};

// A directory holding partition.json, or a file named partition.json.
bool is_partition_index(const std::string& path);
// InputError naming the file for anything malformed (a tree that is not one, a brick listed twice).
PartitionIndex read_partition_index(const std::string& path);
void write_partition_index(const PartitionIndex& index, const std::string& path);

// The whole mesh's extent as a mesh without cells: its box's two corners and, per field, the field's
// range, so that prepare_scene gives the camera and colours of the whole mesh.
LoadedMesh extent_mesh(const PartitionIndex& index);

struct PartitionReport {
  ClipReport clipped;  // summed over the bricks
  std::int64_t peak_brick_cells = 0;
};

// `mesh` cut into `bricks` bricks written as DIR/brick_NNNN.vtu with DIR/partition.json; one brick
// in memory at a time. `cost_model`: "projected" or "cells".
// `image_side`: the pixels across the mesh's diagonal in the renders to balance (cell_costs).
PartitionIndex partition_mesh(const Mesh& mesh, int bricks, const std::string& dir, const std::string& cost_model,
                              int image_side = 1024, PartitionReport* report = nullptr);

}  // namespace cellproj
