// cellproj render SCENE.json
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>

#include <nlohmann/json.hpp>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include "grid/error.hpp"
#include "optics/transfer_function.hpp"
#include "raycast/reference_renderer.hpp"
#include "tools/commands.hpp"
#include "tools/timing.hpp"
#include "tools/progress.hpp"
#include "tools/scene.hpp"
#include "tools/scene_setup.hpp"

namespace cellproj {
namespace {

struct RenderArgs {
  std::string scene, png, npy, method = "exact", size, field, interpolation = "isoparametric";
  int threads = 0, frames = 1;
  bool stats = false;
};

int run_render(const RenderArgs& a) {
  const auto t_load = std::chrono::steady_clock::now();
  Scene scene = load_scene(a.scene);
  if (!a.size.empty()) parse_size(a.size, scene.width, scene.height);
  if (!a.field.empty()) scene.field = a.field;
  if (a.method != "exact")
    throw InputError("--method: unknown method '" + a.method + "'; available: exact (the projection methods come with the projection stage)");
  const CellInterpolation interpolation = cell_interpolation_from_name(a.interpolation);
  const PreparedScene prepared = prepare_scene(scene);
  for (const auto& w : prepared.warnings) std::fprintf(stderr, "cellproj: warning: %s\n", w.c_str());
  const double load_seconds = seconds_since(t_load);

  const int threads = a.threads > 0 ? a.threads : tbb::info::default_concurrency();
  tbb::task_arena arena(threads);
  Image first;
  std::vector<double> frame_times;
  double prepare_seconds = 0.0, trace_seconds = 0.0;
  ExactStats st;
  arena.execute([&] {
    const auto t_prep = std::chrono::steady_clock::now();
    const ExactRenderer renderer(prepared.loaded.mesh.view(prepared.field), interpolation);
    prepare_seconds = seconds_since(t_prep);
    for (int f = 0; f < a.frames; ++f) {
      const auto t_frame = std::chrono::steady_clock::now();
      ProgressBar bar(a.frames > 1 ? "frame " + std::to_string(f + 1) + "/" + std::to_string(a.frames) : "rendering");
      Image img = renderer.render(prepared.tf, orbit(prepared.camera, f), scene.width, scene.height, &st,
                                  [&](double d) { bar(d); });
      trace_seconds += st.trace_seconds;
      frame_times.push_back(seconds_since(t_frame) + (f == 0 ? prepare_seconds : 0.0));
      if (f == 0) first = std::move(img);
    }
  });

  std::string png = a.png;
  if (png.empty() && a.npy.empty()) png = std::filesystem::path(a.scene).stem().string() + ".png";
  for (const std::string& out : {png, a.npy}) {
    if (out.empty()) continue;
    const auto dir = std::filesystem::path(out).parent_path();
    if (!dir.empty()) std::filesystem::create_directories(dir);
  }
  if (!png.empty()) write_png(first, scene.background, png);
  if (!a.npy.empty()) write_npy(first, a.npy);
  const double frame_seconds = median(frame_times);
  for (const std::string& out : {png, a.npy})
    if (!out.empty()) std::printf("wrote %s (%dx%d, %s, %.3f s per frame)\n", out.c_str(), scene.width, scene.height, a.method.c_str(), frame_seconds);

  if (a.stats) {
    nlohmann::json s = {{"method", a.method},
                        {"mesh", scene.mesh},
                        {"field", prepared.field},
                        {"cells", prepared.loaded.mesh.n_cells()},
                        {"width", scene.width},
                        {"height", scene.height},
                        {"threads", threads},
                        {"frames", a.frames},
                        {"load_seconds", load_seconds},
                        {"frame_seconds", frame_seconds},
                        {"min_frame_seconds", *std::min_element(frame_times.begin(), frame_times.end())},
                        {"max_frame_seconds", *std::max_element(frame_times.begin(), frame_times.end())},
                        {"prepare_seconds", prepare_seconds},
                        {"trace_seconds", trace_seconds / a.frames},
                        {"segments", st.segments},
                        {"interpolation", name_of(interpolation)},
                        {"newton_failures", st.newton_failures}};
    std::fprintf(stderr, "%s\n", s.dump().c_str());
  }
  return kExitOk;
}

}  // namespace

Action add_render(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene file to a PNG (and/or a float .npy)");
  cmd->add_option("scene", args->scene, "Scene file (JSON, see docs/scene.md)")->required();
  cmd->add_option("-o,--output", args->png, "PNG to write (default: SCENE's name with .png, in the current folder)");
  cmd->add_option("--npy", args->npy, "Also write the premultiplied float RGBA image as .npy (H, W, 4)");
  cmd->add_option("--method", args->method, "Rendering method: exact (the reference ray integrator)");
  cmd->add_option("--interpolation", args->interpolation,
                  "Field inside hexahedra, wedges and pyramids for exact: isoparametric (default) or canonical-tets")
      ->check(CLI::IsMember({"isoparametric", "canonical-tets"}));
  cmd->add_option("--size", args->size, "Image size WxH, overriding the scene");
  cmd->add_option("--field", args->field, "Point field to render, overriding the scene");
  cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")->check(CLI::Range(1, 1024));
  cmd->add_option("--frames", args->frames, "Render N frames, turning the camera 1 degree about its up axis each frame; "
                                            "report the median frame time")->check(CLI::Range(1, 100000));
  cmd->add_flag("--stats", args->stats, "Print one JSON line of timings on stderr");
  return [args] { return run_render(*args); };
}

}  // namespace cellproj
