// cellproj render SCENE.json
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <tuple>

#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "base/file_status.hpp"
#include "grid/clip.hpp"
#include "grid/time_series.hpp"
#include "render/playback.hpp"
#include "render/renderer.hpp"
#include "scene/camera_json.hpp"
#include "scene/names.hpp"
#include "scene/prepare.hpp"
#include "scene/render_options.hpp"
#include "scene/scene_file.hpp"
#include "tools/commands.hpp"
#include "tools/memory_budget.hpp"
#include "tools/mesh_options.hpp"
#include "tools/frame_output.hpp"
#include "tools/progress.hpp"
#include "tools/render_distributed.hpp"
#include "tools/render_input.hpp"
#include "tools/render_volumes.hpp"
#include "tools/timing.hpp"

namespace cellproj {
namespace {

int run_render(const RenderArgs& given) {
  const auto t_load = std::chrono::steady_clock::now();
  RenderArgs a = given;
  // A scene's render options (its "layers" block, its "iso" list) where the command line gives none.
  // (A scene that does not load is reported when it is loaded, after the command line's checks,
  // unless the method needs its options first.)
  // The scene read here is the one rendered: load_input does not read it again.
  std::optional<Scene> scene_read;
  if (is_scene_file(a.input) && path_is_file(a.input)) try {
      scene_read = load_scene(a.input);
      // Several volumes are drawn by the exact renderer (render/volume_set.hpp): its default there.
      const bool method_given =
          std::find(a.options.given.begin(), a.options.given.end(), "method") != a.options.given.end();
      if (scene_read->volumes.size() > 1 && !method_given) a.options.method = "exact";
      for (const std::string& w : apply_scene_options(*scene_read, a.options))
        std::fprintf(stderr, "cellproj: warning: %s\n", w.c_str());
    } catch (const InputError&) {
      if (a.options.method == "layers" || a.options.method == "exact") throw;
    }
  if (!a.animate.empty()) {  // --animate T0:T1:N renders N frames
    if (a.frames != 1) throw UsageError("--animate T0:T1:FRAMES gives the number of frames: drop --frames");
    a.frames = static_cast<int>(usage([&] { return animation_times(a.animate); }).size());
  }
  // The command line first (exit 2 on a bad value), then the scene (exit 1).
  const RenderSettings settings = usage([&] { return settings_from(a.options); });
  const std::unique_ptr<Renderer> renderer = usage([&] {
    auto r = make_renderer(settings);
    refuse_unused(*r, a.options.given);
    return r;
  });
  const std::vector<int> levels =
      a.progressive.empty() ? std::vector<int>{} : usage([&] { return parse_int_list("progressive", a.progressive); });
  if (!levels.empty() && a.frames > 1) throw UsageError("--progressive renders one view: it does not go with --frames");
  if (!levels.empty() && (a.time || !a.animate.empty()))
    throw UsageError("--progressive renders one mesh: it does not go with --time or --animate");
  const Communicator world = Communicator::world();
  if (scene_read && scene_read->volumes.size() > 1) {
    check_volume_scene(a, *scene_read);
    if (world.size > 1) throw UsageError(a.input + " has several volumes: render it in one process, not over MPI");
    return render_volume_scene(a, std::move(*scene_read), settings);
  }
  if (is_distributed(a, world)) check_distributed(a, settings);
  const FramePaths paths = usage([&] { return frame_paths(a.png, a.npy, a.input, a.frames); });
  make_output_folders(paths);
  if (!std::isfinite(a.orbit)) throw UsageError("--orbit: expected a finite angle in degrees, got " + std::to_string(a.orbit));
  if (a.orbit != 0.0 && a.frames < 2) throw UsageError("--orbit turns the camera over --frames N (N >= 2)");
  const Input input = load_input(a, *renderer, settings, levels, std::move(scene_read));
  if (input.partition || world.size > 1) return render_distributed(a, input, settings, world);
  const Scene& scene = input.scene;
  const PreparedScene& prepared = input.prepared;
  for (const auto& w : prepared.warnings) std::fprintf(stderr, "cellproj: warning: %s\n", w.c_str());
  const double load_seconds = seconds_since(t_load);
  const Mesh& mesh = prepared.loaded.mesh;
  const ImageSize size{scene.width, scene.height};
  const ColorBar legend = color_bar(prepared, scene.background);
  const auto write = [&](const Image& img, const std::string& png, const std::string& npy, const std::string& what) {
    write_outputs(img, scene.background, a.legend ? &legend : nullptr, png, npy, what);
  };
  const auto frame_what = [&](int f, double seconds) {
    char what[128];
    std::snprintf(what, sizeof what, "frame %d/%d, %dx%d, %s, %.3f s", f + 1, a.frames, scene.width, scene.height,
                  a.options.method.c_str(), seconds);
    return std::string(what);
  };

  const int threads = a.threads > 0 ? a.threads : tbb::info::default_concurrency();
  tbb::task_arena arena(threads);
  Image first;
  std::vector<double> frame_times;
  double prepare_seconds = 0.0, render_seconds = 0.0;
  RenderReport report;
  PlaybackStats playback;
  ClipReport series_clipped;  // a time series is clipped as it plays
  arena.execute([&] {
    // --orbit D: a turntable of D degrees over the frames; without it a playback (--animate) keeps
    // its camera, and a timing run (--frames) turns a degree per frame.
    const auto degrees = [&](int f) { return a.orbit != 0.0 ? f * a.orbit / a.frames : a.animate.empty() ? f : 0.0; };
    if (input.player) {  // a time series: frame f at times[f], the next one made while f renders
      auto t_frame = std::chrono::steady_clock::now();
      std::unique_ptr<ProgressBar> bar;
      playback = play_series(
          *input.player, input.first, input.times, !a.no_prefetch, *renderer, prepared.tf,
          [&](int f) { return orbit(prepared.camera, degrees(f)); }, size,
          [&](int f, Image&& img, const RenderReport& r) {
            report = r;
            render_seconds += r.seconds;
            frame_times.push_back(seconds_since(t_frame));
            t_frame = std::chrono::steady_clock::now();
            char what[64];
            std::snprintf(what, sizeof what, ", time %g", input.times[f]);
            if (paths.sequence)
              write(img, paths.png_of(f), paths.npy_of(f), frame_what(f, r.seconds) + what);
            else if (f == 0)
              first = std::move(img);
          },
          [&](int f) -> Progress {
            bar = std::make_unique<ProgressBar>(a.frames > 1 ? "frame " + std::to_string(f + 1) + "/" +
                                                                   std::to_string(a.frames)
                                                             : "rendering");
            return [&bar](double d) { (*bar)(d); };
          },
          scene.clip, &series_clipped);
      return;
    }
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
                           write(img, level_path(paths.png, slices), level_path(paths.npy, slices), what);
                           if (a.stats) {
                             nlohmann::json j = {{"method", a.options.method}, {"level_slices", slices}};
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
      Image img = renderer->render(volume, field, prepared.tf, orbit(prepared.camera, degrees(f)), size, &report,
                                   [&](double d) { bar(d); });
      render_seconds += report.seconds;
      frame_times.push_back(seconds_since(t_frame));  // preparation is reported on its own
      if (paths.sequence)
        write(img, paths.png_of(f), paths.npy_of(f), frame_what(f, report.seconds));
      else if (f == 0)
        first = std::move(img);
    }
  });
  for (const auto& w : report.warnings) std::fprintf(stderr, "cellproj: warning: %s\n", w.c_str());  // the last frame's
  if (!levels.empty()) return kExitOk;

  const double frame_seconds = median(frame_times);
  if (!paths.sequence) {
    char what[128];
    std::snprintf(what, sizeof what, "%dx%d, %s, %.3f s per frame", scene.width, scene.height, a.options.method.c_str(),
                  frame_seconds);
    write(first, paths.png, paths.npy, what);
  }

  if (a.stats) {
    nlohmann::json s = {{"method", a.options.method},
                        {"mesh", scene.mesh},
                        {"field", prepared.field},
                        {"cells", input.player ? input.player->cells().n_cells() : mesh.n_cells()},
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
    if (!scene.clip.empty()) {
      const ClipReport& c = input.player ? series_clipped : input.clipped;
      s.update({{"clip_planes", scene.clip.size()},
                {"clip_cells_whole", c.kept_whole},
                {"clip_cells_cut", c.cut},
                {"clip_cells_dropped", c.dropped},
                {"clip_tetrahedra", c.tetrahedra}});
    }
    if (input.player) {  // how much of making the frames the background thread hid behind the renders
      const SeriesPlayer& p = *input.player;
      s.update({{"key_frames", p.series().frames.size()},
                {"key_frames_read", p.key_frames_read()},
                {"key_frame_read_seconds", p.read_seconds()},
                {"points_move", p.points_move()},
                {"volumes", playback.volumes},
                {"prefetch", !a.no_prefetch},
                {"series_make_seconds", playback.make_seconds},
                {"series_wait_seconds", playback.wait_seconds},
                {"peak_rss_mib", peak_rss_mib()}});
    }
    std::fprintf(stderr, "%s\n", s.dump().c_str());
  }
  return kExitOk;
}

}  // namespace

Action add_render(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand(
      "render", "Render a scene file, or a mesh with a default scene, to a PNG (and/or a float .npy)");
  cmd->add_option("input", args->input,
                  "Scene file (.json, see docs/scene.md), or a mesh file (any format `info` reads) rendered with the "
                  "scene `cellproj scene MESH` writes")
      ->required();
  cmd->add_option("-o,--output", args->png,
                  "PNG to write (default: INPUT's name with .png, in the current folder); with --frames, a pattern "
                  "such as out/frame_%04d.png writes every frame");
  cmd->add_option("--npy", args->npy,
                  "Also write the premultiplied float RGBA image as .npy (H, W, 4); a pattern as for -o");
  add_reader_options(*cmd, args->reader);
  const std::vector<CLI::Option*> look = add_look_options(*cmd, args->look);
  cmd->add_option("--view", args->view,
                  "Frame the mesh from a named view, replacing the scene's camera: " + view_names() +
                      " (ParaView's: +x looks along +x)");
  cmd->add_option("--background", args->background, "Background colour: R,G,B in [0, 1], #rrggbb, black or white");
  cmd->add_flag("--legend", args->legend, "Draw the colour legend (field name and range) on the PNG");
  cmd->add_option("--orbit", args->orbit,
                  "Turn the camera this many degrees about its up axis over --frames N (a turntable: 360)");
  // The render settings, by the names Renderer::settings_used() gives: option --NAME is setting NAME.
  std::vector<std::pair<std::string, CLI::Option*>> settings;
  const auto setting = [&](const std::string& name, auto& value, const std::string& help) {
    CLI::Option* option = cmd->add_option("--" + name, value, help);
    settings.emplace_back(name, option);
    return option;
  };
  setting("method", args->options.method,
          "Rendering method: pt-breakpoints (default; exact for the canonical tetrahedra), pt-analytic, "
          "pt-table, pt-linear (fastest), exact (the reference ray integrator), slicing (cells cut on "
          "parallel planes, no sort), mip, minip, average (one value per ray), or layers (the n-th "
          "crossings of --iso along each ray); see docs/methods.md");
  setting("iso", args->options.iso,
          "Iso-surfaces, repeatable, V:R,G,B,A (A the opacity seen head-on, "
          "default 1; without a colour the colour map's at V): with --method "
          "exact, drawn with the volume; with layers, the one iso-value V or "
          "V:R,G,B whose crossings it draws")
      ->allow_extra_args(false);
  setting("volume", args->options.volume,
          "exact with --iso: draw the volume between the surfaces, on "
          "(default) or off");
  setting("iso-mode", args->options.iso_mode,
          "exact with --iso: " + iso_mode_names() +
              " (ordered, the default: exact order along each ray; "
              "blend2: the volume, then surfaces over it in submission "
              "order; oit3, oit4: libMini's order-independent passes)");
  setting("iso-opacity", args->options.iso_opacity,
          "exact with --iso: " + iso_opacity_names() +
              " (spectrum: a thin layer's 1 - exp(-c d / |cos t|); "
              "spectrum-fit: libMini's cosine-power fit)");
  setting("layer", args->options.layer,
          "layers: which crossings of V to draw, 1 the nearest: N, or "
          "increasing N1,N2,... blended (default 1)");
  setting("layer-weights", args->options.layer_weights,
          "layers: one weight per --layer, blended as their weighted mean where the "
          "ray reaches them (default equal)");
  setting("silhouettes", args->options.silhouettes,
          "layers: draw where the view grazes a layer: " + silhouettes_names() +
              " (visible: the front layer, black; hidden: layers "
              "behind it up to the deepest --layer, grey)");
  setting("silhouette-epsilon", args->options.silhouette_epsilon,
          "layers: a silhouette where |view . normal| is below this (default 0.2)");
  setting("slices", args->options.slices,
          "slicing: number of planes (default 256; at most 16 per pixel of "
          "the image's longer side)");
  setting("slice-axis", args->options.slice_axis,
          "slicing: the plane family, " + slice_axis_names() + " (auto: the axis-aligned stack closest to the view)");
  setting("slice-integral", args->options.slice_integral,
          "slicing: " + slice_integral_names() +
              " (default: the segment between two planes looked up "
              "from the scalar at both ends)");
  setting("progressive", args->progressive,
          "slicing: render at each of these plane counts in turn, e.g. "
          "16,64,256, writing OUT-16.png, OUT-64.png, ... as each completes");
  setting("small-cells", args->options.small_cells,
          "projection and slicing: what small cells get, " + small_cells_names() +
              " (default draw; splat and skip need the software back end); docs/methods.md, Splatting");
  setting("splat-threshold", args->options.splat_threshold,
          "Which cells are small: projection, those covering fewer pixel centres "
          "(default 1: those covering none); slicing, those of less volume than this times the spacing "
          "cubed (default 1)");
  setting("splat-prefilter", args->options.splat_prefilter,
          "Standard deviation in pixels of the splats' anti-aliasing pre-filter "
          "(default 0.7; 0.3 to 4)");
  setting("cull-transparent", args->options.cull_transparent,
          "projection methods: leave out the cells whose scalar range has extinction 0 "
          "throughout, on (default: the same picture, less work) or off");
  setting("compositing", args->options.compositing,
          "software projection: tiles (default: image tiles each drawing the cells that reach it, in order, "
          "no fragment stored) or stream (fragments buffered by batch, blended in order); the same picture");
  setting("early-termination", args->options.early_termination,
          "software projection with --compositing tiles: on composites each tile front to back, closing a pixel "
          "once within 1e-6 of opaque and leaving out the cells behind closed pixels (faster on opaque "
          "scenes; the picture within 2e-6 of off, not the same bits), or off (default)");
  setting("tile-orders", args->options.tile_orders,
          "software projection with --compositing tiles: on has each image tile order its own cells by the "
          "face relations among them where those are the whole order (mpvo on a convex mesh), with no serial "
          "sort of the whole mesh before the tiles; off sorts every cell once; auto (default): on from " +
              std::to_string(kTileOrdersFromThreads) + " threads; the same picture");
  setting("whole-cells", args->options.whole_cells,
          "software pt-linear and pt-table on hexahedra, wedges and pyramids: layers (the thick-vertex "
          "formula at every pixel from the cell's front and back faces), polygons (the image-plane "
          "subdivision Gouraud-shaded, as the OpenGL back ends draw them) or auto (default: layers for cells "
          "whose image box spans at most 256 pixels, polygons for larger ones)");
  setting("tile-rows", args->options.tile_rows,
          "software projection with --compositing tiles: rows per image tile (default 0: about 4 tiles per thread, "
          "16 to 64 rows)");
  setting("sort", args->options.sort, "Visibility sort for the projection methods: " + sort_method_names());
  setting("gaps", args->options.gaps,
          "How mpvo-abuffer finds the relations across gaps: " + gap_method_names() + " (as sortbench's)");
  setting("backend", args->options.backend,
          "Where the projection methods and slicing rasterize: software (default), or for pt-linear, "
          "pt-table and slicing with --slice-integral sampled opengl (OSMesa, float target), "
          "opengl-8bit, opengl-8bit-dither");
  setting("tetrahedralize", args->options.tetrahedralize,
          "Which cells other than tetrahedra the projection methods split into tetrahedra: problem (default; "
          "per view, those with a folded non-planar face), all, or none (every cell whole)");
  setting("table-size", args->options.table_size,
          "pt-table: nodes per axis of the opacity table; slicing: "
          "of the preintegrated table (default 256)")
      ->check(CLI::Range(2, 8192));
  setting("interpolation", args->options.interpolation,
          "Field inside hexahedra, wedges and pyramids for exact: isoparametric (default) or canonical-tets")
      ->check(CLI::IsMember({"isoparametric", "canonical-tets"}));
  cmd->add_option("--size", args->size, "Image size WxH, overriding the scene");
  cmd->add_option("--field", args->field, "Point field to render, overriding the scene");
  cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")->check(CLI::Range(1, 1024));
  cmd->add_option(
         "--frames", args->frames,
         "Render N frames: a turntable with --orbit and a pattern in -o, else a timing run turning the camera 1 "
         "degree per frame (the median frame time in --stats)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--clip", args->clip,
                  "A clipping plane x,y,z,nx,ny,nz (a point and the normal), repeatable, replacing the scene's: "
                  "keeps the side the normal points away from (ParaView's Clip); cut cells are clipped exactly, "
                  "for every method")
      ->allow_extra_args(false);
  cmd->add_option("--time", args->time,
                  "A time series (the input's mesh a .pvd, a numbered pattern mesh_%04d.vtu, or an Exodus file with "
                  "time steps): render the field interpolated linearly between the key frames around T");
  cmd->add_option("--animate", args->animate,
                  "A time series played: FRAMES frames from time T0 to T1 (T0:T1:FRAMES), written to a pattern in -o "
                  "(out/%04d.png); with --orbit the camera turns meanwhile");
  cmd->add_flag("--no-prefetch", args->no_prefetch,
                "Time series: make each frame in turn instead of on a background thread while the previous renders "
                "(to measure what the thread hides)");
  add_max_memory_option(*cmd, args->max_memory_gib, "Refuse renders");
  cmd->add_flag("--stats", args->stats, "Print one JSON line of timings on stderr");
  return [args, settings, look] {
    for (const auto& [name, option] : settings)
      if (option->count() > 0) args->options.given.push_back(name);
    for (CLI::Option* option : look)
      if (option->count() > 0) args->look_given.push_back(option->get_name().substr(2));
    return run_render(*args);
  };
}

}  // namespace cellproj
