#include "tools/render_distributed.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <nlohmann/json.hpp>

#include "distributed/brick_renderer.hpp"
#include "render/names.hpp"
#include "render/volume.hpp"
#include "scene/camera_json.hpp"
#include "scene/prepare.hpp"
#include "scene/report_json.hpp"
#include "tools/commands.hpp"
#include "tools/frame_loops.hpp"
#include "tools/frame_output.hpp"
#include "tools/terminal_text.hpp"
#include "tools/timing.hpp"

namespace cellproj {

bool is_distributed(const RenderArgs& a, const Communicator& world) {
  return world.size > 1 || is_partition_index(a.input);
}

void check_distributed(const RenderArgs& a, const RenderSettings& settings) {
  usage([&] { check_distributable(settings); });
  if (!a.progressive.empty() || a.time || !a.animate.empty())
    throw UsageError(
        "a distributed render (mpirun, or a partition index) renders one mesh: --progressive, --time and "
        "--animate do not go with it yet");
}

int render_distributed(const RenderArgs& a, const Input& input, const RenderSettings& settings,
                       const Communicator& world) {
  check_distributed(a, settings);
  const auto t_start = std::chrono::steady_clock::now();
  const Scene& scene = input.scene;
  const PreparedScene& prepared = input.prepared;
  if (world.rank == 0)
    for (const auto& w : prepared.warnings) warn(w);
  const int threads = a.threads > 0 ? a.threads : tbb::info::default_concurrency();
  tbb::task_arena arena(threads);
  RankStats stats;
  RenderReport report;
  std::vector<double> frame_times;
  const FramePaths paths = frame_paths(a.png, a.npy, a.input, a.frames);
  make_output_folders(paths);
  // Rank 0 writes: the other ranks' writer holds nothing and opens nothing.
  std::optional<FrameWriter> writer;
  if (world.rank == 0)
    writer.emplace(paths, png_format(a, scene, bounds(prepared.loaded.mesh)),
                   a.legend ? std::optional<ColorBar>(legend_of(a, prepared, settings, scene)) : std::nullopt,
                   movie_options(a));
  const std::string ranks = std::to_string(world.size) + (world.size > 1 ? " ranks" : " rank");
  arena.execute([&] {
    // A partition index: each rank reads its own bricks; a mesh: every rank holds it and cuts its brick.
    const BrickRenderer bricks = input.partition ? BrickRenderer(world, *input.partition, prepared.field, scene.reader)
                                                 : BrickRenderer(world, prepared.loaded.mesh, prepared.field,
                                                                 "projected", prepared.opacity_field);
    // Frames as a single process makes them: a turntable with --orbit, else a degree a frame.
    for (int f = 0; f < a.frames; ++f) {
      const auto t_frame = std::chrono::steady_clock::now();
      const Camera camera = frame_camera(a, prepared, f);
      Image image = bricks.render(settings, prepared.tf, camera, {scene.width, scene.height}, &stats, &report);
      frame_times.push_back(seconds_since(t_frame));
      if (world.rank != 0) continue;
      char what[160];
      std::snprintf(what, sizeof what, "frame %d/%d, %dx%d, %s, %s, %.3f s", f + 1, a.frames, scene.width, scene.height,
                    option_text(a.options, "method").c_str(), ranks.c_str(), frame_times.back());
      writer->frame(f, std::move(image), what, std::nullopt, camera);
    }
  });
  const std::vector<double> all = gather_to_root(world, stats.values());
  if (world.rank != 0) return kExitOk;
  for (const auto& w : report.warnings) warn(w);
  char what[160];
  std::snprintf(what, sizeof what, "%dx%d, %s, %s, %.3f s per frame", scene.width, scene.height,
                option_text(a.options, "method").c_str(), ranks.c_str(), median(frame_times));
  writer->finish(what);
  if (a.stats) {
    constexpr std::size_t n = std::size(kRankStatNames);
    nlohmann::json ranks = nlohmann::json::array();
    double slowest = -1, sum = 0;
    int slowest_rank = 0;
    for (int r = 0; r < world.size; ++r) {
      nlohmann::json j = {{"rank", r}};
      for (std::size_t k = 0; k < n; ++k) j[kRankStatNames[k]] = all[r * n + k];
      const double render = all[r * n + 5];  // render_cpu_seconds: the work, not the turns on shared cores
      sum += render;
      if (render > slowest) slowest = render, slowest_rank = r;
      ranks.push_back(j);
    }
    nlohmann::json s = {{"method", option_text(a.options, "method")},
                        {"settings", settings_json(settings)},
                        {"mesh", scene.mesh},
                        {"field", prepared.field},
                        {"width", scene.width},
                        {"height", scene.height},
                        {"ranks", world.size},
                        {"bricks", input.partition ? input.partition->bricks.size() : std::size_t(world.size)},
                        {"threads_per_rank", threads},
                        {"frames", a.frames},
                        {"frame_seconds", median(frame_times)},  // on rank 0, composite and all
                        {"seconds", seconds_since(t_start)},
                        {"slowest_rank", slowest_rank},
                        {"imbalance", sum > 0 ? slowest / (sum / world.size) : 1.0},  // of render_cpu_seconds
                        {"per_rank", ranks}};
    if (!prepared.opacity_field.empty()) s["opacity_field"] = prepared.opacity_field;
    std::fprintf(stderr, "%s\n", s.dump().c_str());
  }
  return kExitOk;
}

}  // namespace cellproj
