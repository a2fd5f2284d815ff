#include "distributed/brick_renderer.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>

#include "composite/fragment.hpp"
#include "composite/partial_image.hpp"
#include "distributed/binary_swap.hpp"
#include "mesh/field_choice.hpp"
#include "partition/brick_order.hpp"

namespace cellproj {

const char* const kRankStatNames[10] = {"bricks",         "cells",
                                        "load_seconds",   "sort_seconds",
                                        "render_seconds", "render_cpu_seconds",
                                        "wait_seconds",   "composite_seconds",
                                        "bytes_sent",     "bytes_received"};

std::vector<double> RankStats::values() const {
  return {double(bricks),     double(cells), load_seconds,      sort_seconds,       render_seconds,
          render_cpu_seconds, wait_seconds,  composite_seconds, double(bytes_sent), double(bytes_received)};
}

void check_distributable(const RenderSettings& settings) {
  const char* why = settings.mode == RenderMode::reduction ? "takes one value of each whole ray"
                    : settings.mode == RenderMode::layers  ? "counts crossings along each whole ray"
                    : !settings.iso.surfaces.empty() && settings.iso.mode != IsoMode::ordered
                        ? "blends iso-surfaces out of depth order (use setting 'iso-mode' ordered)"
                    : settings.ssaa > 1
                        ? "is anti-aliased (setting 'ssaa'), which the bricks' composite does not do yet"
                        : nullptr;
  if (why)
    throw InputError(std::string("a distributed render composites the bricks' pictures in depth order, and this "
                                 "method ") +
                     why + ": render it in one process, from the mesh");
}

struct BrickRenderer::Brick {
  Mesh mesh;
  std::unique_ptr<Volume> volume;
};

namespace {
double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
// The CPU seconds of every thread of this process: the work a rank did, whatever the time the
// machine gave it (ranks oversubscribed on few cores take turns).
double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}
}  // namespace

BrickRenderer::~BrickRenderer() = default;

void BrickRenderer::load(const std::function<Mesh(int brick)>& make) {
  const auto t = std::chrono::steady_clock::now();
  roots_ = rank_subtrees(tree_, comm_.size);
  subtree_ = roots_[comm_.rank];
  owner_.assign(static_cast<std::size_t>(tree_.bricks()), -1);
  for (int r = 0; r < comm_.size; ++r)
    if (roots_[r] >= 0)
      for (int b : bricks_under(tree_, roots_[r])) owner_[b] = r;
  bricks_.resize(static_cast<std::size_t>(tree_.bricks()));
  agree(comm_, [&] {
    if (subtree_ < 0) return;
    for (int b : bricks_under(tree_, subtree_)) {
      Mesh mesh = make(b);
      if (mesh.n_cells() == 0) continue;
      select_field(mesh, field_);  // made from a vector if need be, or an error naming the brick's file and its fields
      if (!opacity_field_.empty()) select_field(mesh, opacity_field_);
      auto brick = std::make_unique<Brick>();
      brick->mesh = std::move(mesh);
      brick->volume = std::make_unique<Volume>(brick->mesh.view(), VolumeOptions{true});
      bricks_[b] = std::move(brick);
    }
  });
  load_seconds_ = since(t);
}

BrickRenderer::BrickRenderer(const Communicator& comm, const PartitionIndex& index, const std::string& field,
                             const ReadOptions& reader)
    : comm_(comm), tree_(index.tree), field_(field) {
  load([&](int b) {
    const std::string path = index.brick_path(b);
    if (path.empty()) return Mesh{};
    LoadedMesh loaded = load_mesh(path, reader);
    if (loaded.mesh.n_cells() != index.bricks[b].cells)
      throw InputError(where(path, "brick " + std::to_string(b) + " has " + std::to_string(loaded.mesh.n_cells()) +
                                       " cells where " + index.path + " lists " +
                                       std::to_string(index.bricks[b].cells)));
    return std::move(loaded.mesh);
  });
}

BrickRenderer::BrickRenderer(const Communicator& comm, const Mesh& mesh, const std::string& field,
                             const std::string& cost_model, const std::string& opacity_field)
    : comm_(comm), field_(field), opacity_field_(opacity_field) {
  tree_ = build_kd_tree(mesh.view(), cell_costs(mesh.view(), 1024, cost_model == "cells"), comm.size);
  const std::vector<std::vector<std::int64_t>> cells = cells_of_bricks(mesh.view(), tree_);
  load([&](int b) { return extract_brick(mesh, tree_, b, cells[b]); });
}

Image BrickRenderer::render(const RenderSettings& settings, const TransferFunction& tf, const Camera& camera,
                            ImageSize size, RankStats* stats, RenderReport* report) const {
  check_distributable(settings);
  const std::unique_ptr<Renderer> renderer = make_renderer(settings);
  RankStats st;
  st.load_seconds = load_seconds_;
  Image mine(size.width, size.height);
  const auto t = std::chrono::steady_clock::now();
  const double cpu = process_cpu_seconds();
  agree(comm_, [&] {
    if (subtree_ < 0) return;
    for (int b : back_to_front(tree_, camera, subtree_)) {  // this rank's bricks, farthest first
      if (!bricks_[b]) continue;
      const Brick& brick = *bricks_[b];
      RenderReport r;
      const Image img =
          renderer->render(*brick.volume, field_of(brick.mesh, field_, opacity_field_), tf, camera, size, &r);
      for (std::size_t k = 0; k < mine.rgba.size(); k += 4) over(&mine.rgba[k], &img.rgba[k]);
      for (const auto& [phase, s] : r.phase_seconds)
        if (phase == "sort") st.sort_seconds += s;
      ++st.bricks;
      st.cells += brick.mesh.n_cells();
      if (report)  // each warning once, whichever brick gave it
        for (const std::string& w : r.warnings)
          if (std::find(report->warnings.begin(), report->warnings.end(), w) == report->warnings.end())
            report->warnings.push_back(w);
    }
    st.render_seconds = since(t);
    st.render_cpu_seconds = process_cpu_seconds() - cpu;
  });
  st.wait_seconds = since(t) - st.render_seconds;  // for the slowest rank, in agree()
  // The ranks in depth order: each subtree's bricks are contiguous in the whole tree's order.
  std::vector<int> order;
  for (int b : back_to_front(tree_, camera))
    if (std::find(order.begin(), order.end(), owner_[b]) == order.end()) order.push_back(owner_[b]);
  for (int r = 0; r < comm_.size; ++r)
    if (roots_[r] < 0) order.push_back(r);  // idle ranks: empty images, anywhere in the order
  const TrafficStats traffic = composite_binary_swap(comm_, mine, covered_box(mine), order);
  st.composite_seconds = traffic.seconds;
  st.bytes_sent = traffic.bytes_sent;
  st.bytes_received = traffic.bytes_received;
  if (stats) *stats = st;
  return mine;
}

}  // namespace cellproj
