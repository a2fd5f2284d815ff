#include "tools/render_volumes.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <nlohmann/json.hpp>

#include <glm/common.hpp>

#include "base/error.hpp"
#include "render/names.hpp"
#include "render/volume_set.hpp"
#include "scene/camera_json.hpp"
#include "scene/prepare.hpp"
#include "scene/report_json.hpp"
#include "scene/volume_scene.hpp"
#include "tools/commands.hpp"
#include "tools/frame_output.hpp"
#include "tools/memory_budget.hpp"
#include "tools/progress.hpp"
#include "tools/terminal_text.hpp"
#include "tools/timing.hpp"

namespace cellproj {

void check_volume_scene(const RenderArgs& a, const Scene& scene) {
  const std::string what = a.input + " has " + std::to_string(scene.volumes.size()) + " volumes";
  const auto given = [&](const char* name) { return option_given(a.options, name); };
  const std::string method = option_text(a.options, "method");
  if (method != "exact")
    throw UsageError("--method " + method + " draws one mesh; " + what +
                     ", drawn together by --method exact (the default for such a scene): cells of overlapping "
                     "meshes cannot be ordered as whole cells");
  if (given("iso")) throw UsageError("--iso: " + what + ": give each volume's iso-surfaces in its \"iso\" list");
  if (given("interpolation") && option_text(a.options, "interpolation") != "canonical-tets")
    throw UsageError("--interpolation " + option_text(a.options, "interpolation") + ": " + what +
                     ", whose fields are drawn linear in each canonical tetrahedron (canonical-tets)");
  if (!a.field.empty()) throw UsageError("--field: " + what + ": give each volume's \"field\" in the scene");
  if (!a.look_given.empty() || a.legend)
    throw UsageError(std::string(a.legend ? "--legend" : "--colormap") + ": " + what +
                     ", each with its own transfer function: edit them in the scene");
  if (a.time || !a.animate.empty()) throw UsageError("--time and --animate: " + what + "; time series take one mesh");
  if (!a.progressive.empty()) throw UsageError("--progressive is a slicing option; " + what);
}

int render_volume_scene(const RenderArgs& a, Scene scene, const RenderSettings& settings) {
  const auto t_load = std::chrono::steady_clock::now();
  if (!a.size.empty()) usage([&] { parse_size(a.size, scene.width, scene.height); });
  if (a.background == "none")
    scene.transparent = true;
  else if (!a.background.empty())
    scene.background = usage([&] { return parse_color(a.background, "--background"); }), scene.transparent = false;
  if (!a.view.empty()) usage([&] { return view_camera(a.view, {0, 0, 0}, {1, 1, 1}, 1.0); });  // the name, now
  apply_view_and_clip(a, scene);
  const FramePaths paths = usage([&] { return frame_paths(a.png, a.npy, a.input, a.frames); });
  make_output_folders(paths);
  if (a.orbit != 0.0 && a.frames < 2) throw UsageError("--orbit turns the camera over --frames N (N >= 2)");
  const ImageSize size{scene.width, scene.height};

  // Refuse what would not fit before reading: every volume's header.
  std::uint64_t mesh_bytes = 0;
  std::vector<VolumeSize> sizes;
  for (const SceneVolume& v : scene.volumes)
    if (const HeaderCounts h = header_counts(v.mesh); h.cells > 0) {
      mesh_bytes += estimate_mesh_bytes(h);
      sizes.push_back({h.points, h.cells, h.cells});
    }
  const std::string size_text = std::to_string(scene.width) + "x" + std::to_string(scene.height);
  refuse_beyond_memory(mesh_bytes + estimate_volumes_bytes(sizes, size, settings.ssaa), a.max_memory_gib,
                       "reading " + std::to_string(scene.volumes.size()) + " volumes and rendering " + size_text,
                       a.input);
  const bool volume_given = option_given(a.options, "volume");
  const VolumeScene volumes(
      scene,
      [&](const SceneVolume& v) {
        ReadOptions reader = v.reader;
        reader.max_memory_gib = a.max_memory_gib;
        return read_with_progress(v.mesh, reader);
      },
      volume_given ? std::optional<bool>(settings.iso.volume) : std::nullopt);
  for (const auto& w : volumes.warnings()) warn(w);
  const PreparedVolumes& prepared = volumes.prepared();
  std::int64_t cells = 0;
  for (const VolumeEntry& e : volumes.entries()) cells += e.volume->mesh().n_cells;

  const int threads = a.threads > 0 ? a.threads : tbb::info::default_concurrency();
  tbb::task_arena arena(threads);
  std::vector<double> frame_times;
  double render_seconds = 0.0;
  RenderReport report;
  std::pair<glm::dvec3, glm::dvec3> box{glm::dvec3(HUGE_VAL), glm::dvec3(-HUGE_VAL)};  // every volume's, for --outline
  for (const VolumeEntry& e : volumes.entries()) {
    const auto [lo, hi] = bounds(e.volume->mesh());
    box = {glm::min(box.first, lo), glm::max(box.second, hi)};
  }
  FrameWriter writer(paths, png_format(a, scene, box), std::nullopt, movie_options(a));
  const double load_seconds = seconds_since(t_load);
  arena.execute([&] {
    ProgressBar bar("rendering");
    for (int f = 0; f < a.frames; ++f) {
      const auto t_frame = std::chrono::steady_clock::now();
      if (a.frames > 1) bar.relabel("frame " + std::to_string(f + 1) + "/" + std::to_string(a.frames));
      report = {};
      const double degrees = a.orbit != 0.0 ? f * a.orbit / a.frames : f;
      const Camera camera = orbit(prepared.camera, degrees, prepared.turn_axis);
      Image img = render_volumes(volumes.entries(), settings, camera, size, &report,
                                 [&](double d) { bar((f + d) / a.frames); });
      render_seconds += report.seconds;
      frame_times.push_back(seconds_since(t_frame));
      char what[128];
      std::snprintf(what, sizeof what, "frame %d/%d, %dx%d, %zu volumes, exact, %.3f s", f + 1, a.frames, scene.width,
                    scene.height, volumes.entries().size(), report.seconds);
      if (paths.sequence) bar.clear();
      writer.frame(f, std::move(img), what, std::nullopt, camera);
    }
  });
  for (const auto& w : report.warnings) warn(w);
  const double frame_seconds = median(frame_times);
  char what[128];
  std::snprintf(what, sizeof what, "%dx%d, %zu volumes, exact, %.3f s per frame", scene.width, scene.height,
                scene.volumes.size(), frame_seconds);
  writer.finish(what);
  if (a.stats) {
    nlohmann::json meshes = nlohmann::json::array();
    for (std::size_t k = 0; k < prepared.volumes.size(); ++k)
      meshes.push_back({{"mesh", scene.volumes[k].mesh},
                        {"field", prepared.volumes[k].field},
                        {"cells", prepared.volumes[k].loaded.mesh.n_cells()},
                        {"clip_cells_cut", volumes.clipped()[k].cut},
                        {"clip_cells_dropped", volumes.clipped()[k].dropped}});
    nlohmann::json s = {{"method", "exact"},
                        {"meshes", meshes},
                        {"cells", cells},
                        {"width", scene.width},
                        {"height", scene.height},
                        {"threads", threads},
                        {"frames", a.frames},
                        {"load_seconds", load_seconds},
                        {"frame_seconds", frame_seconds},
                        {"render_seconds", render_seconds / a.frames},
                        {"settings", settings_json(settings)}};
    s.update(report_json(report));
    std::fprintf(stderr, "%s\n", s.dump().c_str());
  }
  return kExitOk;
}

}  // namespace cellproj
