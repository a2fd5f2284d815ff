#pragma once
// A distributed frame (MWSC section 7, SDVR): each rank renders the bricks of its k-d subtree, each
// brick with the ordinary renderer (any method, its own sort inside the brick), composites them in
// the tree's order into one sub-image, and the ranks' sub-images are composited by binary swap.
// Not a Renderer: a rank holds only its bricks, never the whole Volume the interface takes.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "distributed/communicator.hpp"
#include "partition/kd_partition.hpp"
#include "partition/partition_index.hpp"
#include "render/renderer.hpp"

namespace cellproj {

// What one rank did in a frame (--stats prints every rank's, and the imbalance).
struct RankStats {
  int bricks = 0;
  std::int64_t cells = 0;
  double load_seconds = 0, sort_seconds = 0, render_seconds = 0, composite_seconds = 0;
  double render_cpu_seconds = 0;  // the work: CPU seconds of the rank's threads while rendering
  double wait_seconds = 0;        // after rendering, until every rank has rendered
  std::uint64_t bytes_sent = 0, bytes_received = 0;
  std::vector<double> values() const;  // in the order of kRankStatNames
};
extern const char* const kRankStatNames[10];

// InputError for settings whose pictures do not composite with "over" brick by brick: one value per
// ray (mip, minip, average), the n-th crossings along the whole ray (layers), iso-surfaces blended
// out of order (iso modes other than ordered).
void check_distributable(const RenderSettings& settings);

class BrickRenderer {
 public:
  // This rank's bricks read from the index's files (each read isolated and validated; a missing or
  // corrupt file is an error naming rank and file on every rank).
  BrickRenderer(const Communicator& comm, const PartitionIndex& index, const std::string& field,
                const ReadOptions& reader);
  // Or cut from `mesh`, which every rank holds, into one brick per rank (the k-d tree built here);
  // `opacity_field`: the extinction's own field (Field::opacity), none when empty.
  BrickRenderer(const Communicator& comm, const Mesh& mesh, const std::string& field, const std::string& cost_model,
                const std::string& opacity_field = "");
  ~BrickRenderer();

  // The picture on rank 0 (other ranks: an image of no meaning), each brick drawn by
  // make_renderer(settings). Collective: every rank calls it. InputError unless check_distributable.
  Image render(const RenderSettings& settings, const TransferFunction& tf, const Camera& camera, ImageSize size,
               RankStats* stats = nullptr, RenderReport* report = nullptr) const;

  const KdTree& tree() const { return tree_; }
  int subtree() const { return subtree_; }  // this rank's subtree root, -1 when idle

 private:
  struct Brick;
  void load(const std::function<Mesh(int brick)>& make);
  Communicator comm_;
  KdTree tree_;
  std::vector<int> roots_;  // each rank's subtree
  std::vector<int> owner_;  // each brick's rank
  int subtree_ = -1;
  std::string field_, opacity_field_;
  std::vector<std::unique_ptr<Brick>> bricks_;  // by brick number; null where another rank's or empty
  double load_seconds_ = 0.0;
};

}  // namespace cellproj
