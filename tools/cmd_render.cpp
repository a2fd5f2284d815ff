// cellproj render SCENE.json
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <tuple>

#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "render/renderer.hpp"
#include "scene/camera_json.hpp"
#include "scene/names.hpp"
#include "scene/prepare.hpp"
#include "scene/scene_file.hpp"
#include "tools/commands.hpp"
#include "tools/memory_budget.hpp"
#include "tools/progress.hpp"
#include "tools/timing.hpp"

namespace cellproj {
namespace {

struct RenderArgs {
  std::string scene, png, npy, method = "pt-breakpoints", size, field, interpolation = "isoparametric", sort = "auto",
                               gaps = "auto", backend = "software", tetrahedralize = "problem", slice_axis = "auto",
                               slice_integral = "preintegrated", progressive, small_cells = "draw";
  int threads = 0, frames = 1, table_size = 256, slices = 256;
  std::vector<std::string> given;                     // the render settings given on the command line, by name
  double max_memory_gib = 0.0;                        // 0: the machine's available memory
  double splat_threshold = SplatOptions{}.threshold;  // NaN: the method's default
  double splat_prefilter = SplatOptions{}.prefilter;
  bool stats = false;
};

RenderSettings settings_from(const RenderArgs& a) {
  RenderSettings s;
  try {
    parse_render_method(a.method, s);
  } catch (const InputError& e) {
    throw InputError(std::string("--method: ") + e.what());
  }
  // Every option is checked, also those the chosen method does not use: a typo never passes silently.
  s.projection.sort = parse_sort_method(a.sort);
  s.projection.gaps = parse_gap_method(a.gaps);
  s.projection.table_size = a.table_size;
  s.projection.backend = parse_backend(a.backend);
  s.tetrahedralize = parse_tetrahedralize(a.tetrahedralize);
  s.interpolation = parse_cell_interpolation(a.interpolation);
  s.slicing.slices = a.slices;
  s.slicing.axis = parse_slice_axis(a.slice_axis);
  s.slicing.integral = parse_slice_integral(a.slice_integral);
  s.slicing.table_size = a.table_size;
  s.slicing.backend = s.projection.backend;
  s.projection.splat.small_cells = parse_small_cells(a.small_cells);
  s.projection.splat.threshold = a.splat_threshold;
  s.projection.splat.prefilter = a.splat_prefilter;
  s.slicing.splat = s.projection.splat;
  return s;
}

// "16,64,256": the plane counts of --progressive.
std::vector<int> parse_levels(const std::string& text) {
  std::vector<int> levels;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, comma - at);
    std::size_t used = 0;
    int n = 0;
    try {
      n = std::stoi(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (item.empty() || used != item.size())
      throw InputError("--progressive: '" + item + "' is not a number of slices (give counts like 16,64,256)");
    levels.push_back(n);
    at = comma + 1;
  }
  return levels;
}

// out.png -> out-64.png: where level `slices` of --progressive goes.
std::string level_path(const std::string& path, int slices) {
  if (path.empty()) return path;
  const std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + "-" + std::to_string(slices) + p.extension().string())).string();
}

// An option given for a renderer that does not read it is an error, not silently ignored.
void refuse_unused(const Renderer& renderer, const std::vector<std::string>& given) {
  const std::vector<std::string> used = renderer.settings_used();
  std::string list;
  for (const auto& u : used) list += (list.empty() ? "" : ", --") + u;
  for (const auto& g : given)
    if (std::find(used.begin(), used.end(), g) == used.end())
      throw InputError("--" + g + " does not apply to --method " + renderer.name() + ", which reads --" + list);
}

// The image into the PNG and the .npy asked for (either path may be empty), saying so with `what`.
void write_outputs(const Image& image, const glm::dvec3& background, const std::string& png, const std::string& npy,
                   const std::string& what) {
  if (!png.empty()) write_png(image, background, png);
  if (!npy.empty()) write_npy(image, npy);
  for (const std::string& out : {png, npy})
    if (!out.empty()) std::printf("wrote %s (%s)\n", out.c_str(), what.c_str());
  std::fflush(stdout);
}

int run_render(const RenderArgs& a) {
  const auto t_load = std::chrono::steady_clock::now();
  // The command line first (exit 2 on a bad value), then the scene (exit 1).
  const RenderSettings settings = usage([&] { return settings_from(a); });
  const std::unique_ptr<Renderer> renderer = usage([&] {
    auto r = make_renderer(settings);
    refuse_unused(*r, a.given);
    return r;
  });
  const std::vector<int> levels =
      a.progressive.empty() ? std::vector<int>{} : usage([&] { return parse_levels(a.progressive); });
  if (!levels.empty() && a.frames > 1) throw UsageError("--progressive renders one view: it does not go with --frames");
  int width = 0, height = 0;
  if (!a.size.empty()) usage([&] { parse_size(a.size, width, height); });
  Scene scene = load_scene(a.scene);
  if (width > 0) std::tie(scene.width, scene.height) = std::tie(width, height);
  if (!a.field.empty()) scene.field = a.field;
  scene.reader.max_memory_gib = a.max_memory_gib;
  if (settings.mode == RenderMode::slicing)
    for (int n : levels.empty() ? std::vector<int>{settings.slicing.slices} : levels)
      usage([&] { check_slices(n, scene.width, scene.height); });
  const ImageSize size{scene.width, scene.height};
  // Refuse what would not fit, before allocating it: from the file's header before reading it,
  // and again from the mesh as read.
  const auto size_text = std::to_string(scene.width) + "x" + std::to_string(scene.height);
  if (const HeaderCounts h = header_counts(scene.mesh); h.cells > 0)
    refuse_beyond_memory(
        estimate_mesh_bytes(h) + renderer->estimate_bytes({h.points, h.cells, h.cells}, size), a.max_memory_gib,
        "reading " + scene.mesh + " (" + std::to_string(h.cells) + " cells) and rendering " + size_text, a.scene);
  const PreparedScene prepared = prepare_scene(scene);
  for (const auto& w : prepared.warnings) std::fprintf(stderr, "cellproj: warning: %s\n", w.c_str());
  const double load_seconds = seconds_since(t_load);
  const Mesh& mesh = prepared.loaded.mesh;
  refuse_beyond_memory(renderer->estimate_bytes(size_of(mesh.view()), size), a.max_memory_gib,
                       "rendering " + size_text + " of " + std::to_string(mesh.n_cells()) + " cells", a.scene);

  std::string png = a.png;
  if (png.empty() && a.npy.empty()) png = std::filesystem::path(a.scene).stem().string() + ".png";
  for (const std::string& out : {png, a.npy}) {
    if (out.empty()) continue;
    const auto dir = std::filesystem::path(out).parent_path();
    if (!dir.empty()) std::filesystem::create_directories(dir);
  }

  const int threads = a.threads > 0 ? a.threads : tbb::info::default_concurrency();
  tbb::task_arena arena(threads);
  Image first;
  std::vector<double> frame_times;
  double prepare_seconds = 0.0, render_seconds = 0.0;
  RenderReport report;
  arena.execute([&] {
    const Volume volume(mesh.view(), {/*trusted: load_mesh validated it*/ true});
    const Field field = field_of(mesh, prepared.field);
    const auto t_prep = std::chrono::steady_clock::now();
    renderer->prepare(volume);
    prepare_seconds = seconds_since(t_prep);
    if (!levels.empty()) {  // each level written as soon as it is done, for the interactive user
      render_progressive(volume, field, prepared.tf, settings, prepared.camera, size, levels,
                         [&](std::size_t, int slices, const Image& img, const RenderReport& r) {
                           char what[96];
                           std::snprintf(what, sizeof what, "%dx%d, slicing, %d slices, %.3f s", scene.width,
                                         scene.height, slices, r.seconds);
                           write_outputs(img, scene.background, level_path(png, slices), level_path(a.npy, slices),
                                         what);
                           if (a.stats) {
                             nlohmann::json j = {{"method", a.method}, {"level_slices", slices}};
                             j.update(report_json(r));
                             std::fprintf(stderr, "%s\n", j.dump().c_str());
                           }
                           report = r;
                         });
      return;
    }
    for (int f = 0; f < a.frames; ++f) {
      const auto t_frame = std::chrono::steady_clock::now();
      ProgressBar bar(a.frames > 1 ? "frame " + std::to_string(f + 1) + "/" + std::to_string(a.frames) : "rendering");
      report = {};
      Image img = renderer->render(volume, field, prepared.tf, orbit(prepared.camera, f), size, &report,
                                   [&](double d) { bar(d); });
      render_seconds += report.seconds;
      frame_times.push_back(seconds_since(t_frame));  // preparation is reported on its own
      if (f == 0) first = std::move(img);
    }
  });
  for (const auto& w : report.warnings) std::fprintf(stderr, "cellproj: warning: %s\n", w.c_str());  // the last frame's
  if (!levels.empty()) return kExitOk;

  const double frame_seconds = median(frame_times);
  char what[128];
  std::snprintf(what, sizeof what, "%dx%d, %s, %.3f s per frame", scene.width, scene.height, a.method.c_str(),
                frame_seconds);
  write_outputs(first, scene.background, png, a.npy, what);

  if (a.stats) {
    nlohmann::json s = {{"method", a.method},
                        {"mesh", scene.mesh},
                        {"field", prepared.field},
                        {"cells", mesh.n_cells()},
                        {"width", scene.width},
                        {"height", scene.height},
                        {"threads", threads},
                        {"frames", a.frames},
                        {"load_seconds", load_seconds},
                        {"frame_seconds", frame_seconds},
                        {"min_frame_seconds", *std::min_element(frame_times.begin(), frame_times.end())},
                        {"max_frame_seconds", *std::max_element(frame_times.begin(), frame_times.end())},
                        {"prepare_seconds", prepare_seconds},
                        {"render_seconds", render_seconds / a.frames}};
    s.update(report_json(report));  // the last frame's
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
  // The render settings, by the names Renderer::settings_used() gives.
  std::vector<std::pair<std::string, CLI::Option*>> settings;
  settings.emplace_back(
      "method",
      cmd->add_option("--method", args->method,
                      "Rendering method: pt-breakpoints (default; exact for the canonical tetrahedra), pt-analytic, "
                      "pt-table, pt-linear (fastest), exact (the reference ray integrator), or slicing (cells cut on "
                      "parallel planes, no sort); see docs/methods.md"));
  settings.emplace_back("slices", cmd->add_option("--slices", args->slices,
                                                  "slicing: number of planes (default 256; at most 16 per pixel of "
                                                  "the image's longer side)"));
  settings.emplace_back("slice-axis", cmd->add_option("--slice-axis", args->slice_axis,
                                                      "slicing: the plane family, " + slice_axis_names() +
                                                          " (auto: the axis-aligned stack closest to the view)"));
  settings.emplace_back("slice-integral", cmd->add_option("--slice-integral", args->slice_integral,
                                                          "slicing: " + slice_integral_names() +
                                                              " (default: the segment between two planes looked up "
                                                              "from the scalar at both ends)"));
  settings.emplace_back("progressive",
                        cmd->add_option("--progressive", args->progressive,
                                        "slicing: render at each of these plane counts in turn, e.g. "
                                        "16,64,256, writing OUT-16.png, OUT-64.png, ... as each completes"));
  settings.emplace_back(
      "small-cells",
      cmd->add_option("--small-cells", args->small_cells,
                      "projection and slicing: what small cells get, " + small_cells_names() +
                          " (default draw; splat and skip need the software back end); docs/methods.md, Splatting"));
  settings.emplace_back("splat-threshold",
                        cmd->add_option("--splat-threshold", args->splat_threshold,
                                        "Which cells are small: projection, those covering fewer pixel centres "
                                        "(default 2); slicing, those of less volume than this times the spacing "
                                        "cubed (default 1)"));
  settings.emplace_back("splat-prefilter",
                        cmd->add_option("--splat-prefilter", args->splat_prefilter,
                                        "Standard deviation in pixels of the splats' anti-aliasing pre-filter "
                                        "(default 0.7; 0.3 to 4)"));
  settings.emplace_back("sort", cmd->add_option("--sort", args->sort,
                                                "Visibility sort for the projection methods: " + sort_method_names()));
  settings.emplace_back(
      "gaps",
      cmd->add_option("--gaps", args->gaps,
                      "How mpvo-abuffer finds the relations across gaps: " + gap_method_names() + " (as sortbench's)"));
  settings.emplace_back(
      "backend",
      cmd->add_option("--backend", args->backend,
                      "Where the projection methods and slicing rasterize: software (default), or for pt-linear, "
                      "pt-table and slicing with --slice-integral sampled opengl (OSMesa, float target), "
                      "opengl-8bit, opengl-8bit-dither"));
  settings.emplace_back(
      "tetrahedralize",
      cmd->add_option(
          "--tetrahedralize", args->tetrahedralize,
          "Which cells other than tetrahedra the projection methods split into tetrahedra: problem (default; "
          "per view, those with a folded non-planar face), all, or none (every cell whole)"));
  settings.emplace_back("table-size", cmd->add_option("--table-size", args->table_size,
                                                      "pt-table: nodes per axis of the opacity table; slicing: "
                                                      "of the preintegrated table (default 256)")
                                          ->check(CLI::Range(2, 8192)));
  settings.emplace_back(
      "interpolation",
      cmd->add_option(
             "--interpolation", args->interpolation,
             "Field inside hexahedra, wedges and pyramids for exact: isoparametric (default) or canonical-tets")
          ->check(CLI::IsMember({"isoparametric", "canonical-tets"})));
  cmd->add_option("--size", args->size, "Image size WxH, overriding the scene");
  cmd->add_option("--field", args->field, "Point field to render, overriding the scene");
  cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")->check(CLI::Range(1, 1024));
  cmd->add_option("--frames", args->frames,
                  "Render N frames, turning the camera 1 degree about its up axis each frame; "
                  "report the median frame time")
      ->check(CLI::Range(1, 100000));
  add_max_memory_option(*cmd, args->max_memory_gib, "Refuse renders");
  cmd->add_flag("--stats", args->stats, "Print one JSON line of timings on stderr");
  return [args, settings] {
    for (const auto& [name, option] : settings)
      if (option->count() > 0) args->given.push_back(name);
    return run_render(*args);
  };
}

}  // namespace cellproj
