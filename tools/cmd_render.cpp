// cellproj render SCENE.json
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <tuple>

#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "base/file_status.hpp"
#include "mesh/clip.hpp"
#include "mesh/time_series.hpp"
#include "render/names.hpp"
#include "render/playback.hpp"
#include "render/renderer.hpp"
#include "render/settings_table.hpp"
#include "scene/camera_json.hpp"
#include "scene/prepare.hpp"
#include "scene/report_json.hpp"
#include "scene/scene_file.hpp"
#include "tools/commands.hpp"
#include "tools/frame_loops.hpp"
#include "tools/frame_output.hpp"
#include "tools/memory_budget.hpp"
#include "tools/mesh_options.hpp"
#include "tools/progress.hpp"
#include "tools/render_distributed.hpp"
#include "tools/render_input.hpp"
#include "tools/render_volumes.hpp"
#include "tools/terminal_text.hpp"
#include "tools/timing.hpp"
#include "view/camera_moves.hpp"

namespace cellproj {
namespace {

// --stats: one JSON line on stderr (docs/cli.md lists the keys).
void print_stats(const FrameJob& job, const FrameLoop& run, double load_seconds, int threads) {
  const RenderArgs& a = job.args;
  const Input& input = job.input;
  const Scene& scene = input.scene;
  const PreparedScene& prepared = input.prepared;
  const std::vector<double>& frame_times = run.frame_times;
  nlohmann::json s = {{"method", job.renderer.name()},
                      {"mesh", scene.mesh},
                      {"field", prepared.field},
                      {"cells", input.player ? input.player->cells().n_cells() : prepared.loaded.mesh.n_cells()},
                      {"width", scene.width},
                      {"height", scene.height},
                      {"threads", threads},
                      {"frames", a.frames},
                      {"load_seconds", load_seconds},
                      {"frame_seconds", median(frame_times)},
                      {"min_frame_seconds", *std::min_element(frame_times.begin(), frame_times.end())},
                      {"max_frame_seconds", *std::max_element(frame_times.begin(), frame_times.end())},
                      {"prepare_seconds", run.prepare_seconds},
                      {"render_seconds", run.render_seconds / a.frames}};
  if (!prepared.opacity_field.empty()) s["opacity_field"] = prepared.opacity_field;
  s["settings"] = settings_json(job.settings);
  s.update(report_json(run.report));  // the last frame's
  if (!scene.clip.empty()) {
    const ClipReport& c = input.player ? run.series_clipped : input.clipped;
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
              {"volumes", run.playback.volumes},
              {"prefetch", !a.no_prefetch},
              {"series_make_seconds", run.playback.make_seconds},
              {"series_wait_seconds", run.playback.wait_seconds}});
  }
  s["peak_rss_mib"] = peak_rss_mib();  // a movie's frames are not held: this does not grow with --frames
  std::fprintf(stderr, "%s\n", s.dump().c_str());
}

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
      if (scene_read->volumes.size() > 1 && !option_given(a.options, "method")) {
        set_option(a.options, "method", "exact");
        a.options.given.pop_back();  // the scene's default, not the user's word
      }
      for (const std::string& w : apply_scene_options(*scene_read, a.options)) warn(w);
    } catch (const InputError&) {
      if (const std::string m = option_text(a.options, "method"); m == "layers" || m == "exact") throw;
    }
  if (!a.animate.empty()) {  // --animate T0:T1:N renders N frames
    if (a.frames != 1) throw UsageError("--animate T0:T1:FRAMES gives the number of frames: drop --frames");
    a.frames = static_cast<int>(usage([&] { return animation_times(a.animate); }).size());
  }
  // The command line first (exit 2 on a bad value), then the scene (exit 1).
  const RenderSettings settings = usage([&] { return settings_from(a.options); });
  const std::unique_ptr<Renderer> renderer = usage([&] {
    auto r = make_renderer(settings);
    refuse_unused(settings, a.options.given);
    return r;
  });
  const std::string method = renderer->name();
  const std::vector<int> levels =
      a.progressive.empty() ? std::vector<int>{} : usage([&] { return parse_int_list("progressive", a.progressive); });
  if (!levels.empty() && settings.mode != RenderMode::slicing)
    throw UsageError("--progressive does not apply to --method " + method + ": it renders slicing's levels");
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
  if (!std::isfinite(a.orbit))
    throw UsageError("--orbit: expected a finite angle in degrees, got " + std::to_string(a.orbit));
  if (a.orbit != 0.0 && a.frames < 2) throw UsageError("--orbit turns the camera over --frames N (N >= 2)");
  if (a.time_label) usage([&] { return time_label(a.time_format, 0.0); });  // the format, before any file is read
  const Input input = load_input(a, *renderer, settings, levels, std::move(scene_read));
  if (a.time_label && !input.player)
    throw UsageError("--time-label labels a time series' frames, and " + a.input +
                     " is not one (a .pvd, a numbered pattern, or an Exodus file with --time or --animate)");
  if (input.partition || world.size > 1) return render_distributed(a, input, settings, world);
  const Scene& scene = input.scene;
  const PreparedScene& prepared = input.prepared;
  for (const auto& w : prepared.warnings) warn(w);
  usage([&] { refuse_iso_on_log_scale(settings, prepared.log_scale); });
  if (const PointField* f = prepared.loaded.mesh.find_field(prepared.field);
      f && f->per_cell && (!settings.iso.surfaces.empty() || settings.mode == RenderMode::layers))
    warn(prepared.field +
         " is cell data drawn constant over each cell: its iso-surfaces are the faces between cells whose values "
         "straddle the iso-value, a staircase of the cells; setting 'cell-data' points averages it to the points for "
         "a smooth surface");
  const double load_seconds = seconds_since(t_load);

  FrameWriter writer(paths, png_format(a, scene, bounds(prepared.loaded.mesh)),
                     a.legend ? std::optional<ColorBar>(legend_of(a, prepared, settings, scene)) : std::nullopt,
                     movie_options(a));
  const FrameJob job{a, input, *renderer, settings, writer};
  const int threads = a.threads > 0 ? a.threads : tbb::info::default_concurrency();
  FrameLoop run;
  tbb::task_arena(threads).execute([&] {
    run = input.player ? play_series_frames(job) : !levels.empty() ? progressive_levels(job, levels) : mesh_frames(job);
  });
  for (const auto& w : run.report.warnings) warn(w);  // the last frame's
  if (!levels.empty()) return kExitOk;

  char what[128];
  std::snprintf(what, sizeof what, "%dx%d, %s, %.3f s per frame", scene.width, scene.height, method.c_str(),
                median(run.frame_times));
  writer.finish(what);

  if (a.stats) print_stats(job, run, load_seconds, threads);
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
                  "Picture to write, by its name: a PNG (default: INPUT's name with .png, in the current folder), "
                  "an OpenEXR .exr (float RGBA, premultiplied), or a movie of every frame (.mp4: H.264, .gif); with "
                  "--frames, a pattern such as out/frame_%04d.png writes a file a frame");
  cmd->add_option("--fps", args->fps, "A movie's frames per second (default 24)")->check(CLI::Range(0.01, 240.0));
  cmd->add_option("--npy", args->npy,
                  "Also write the premultiplied float RGBA image as .npy (H, W, 4); a pattern as for -o");
  add_reader_options(*cmd, args->reader);
  const std::vector<CLI::Option*> look = add_look_options(*cmd, args->look);
  cmd->add_option("--view", args->view,
                  "Frame the mesh from a named view, replacing the scene's camera: " + view_names() +
                      " (ParaView's: +x looks along +x)");
  // The camera moves, one option a row of their table (view/camera_moves.hpp), made in its order
  // on the scene's camera or --view's.
  std::vector<std::pair<const CameraMoveRow*, CLI::Option*>> moves;
  for (const CameraMoveRow& row : camera_moves()) {
    const std::string name = "--" + std::string(row.name), value = row.value;
    CLI::Option* option = value.empty() ? cmd->add_flag(name, row.help) : cmd->add_option(name, row.help);
    if (value.empty()) option->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    if (value == "[DEG]") option->expected(0, 1);
    if (!value.empty()) option->type_name(value);
    moves.emplace_back(&row, option);
  }
  cmd->add_option("--background", args->background,
                  "Background colour: R,G,B in [0, 1], #rrggbb, black or white; none: a transparent PNG (straight "
                  "alpha) for slides and compositing tools");
  cmd->add_option("--png-bits", args->png_bits, "Bits a sample of the PNG: 8 (default) or 16")
      ->check(CLI::IsMember({8, 16}));
  cmd->add_flag("--legend", args->legend, "Draw the colour legend (field name and range) on the PNG");
  cmd->add_option("--legend-orientation", args->legend_orientation,
                  "The legend's bar: vertical (default, in a strip on the right) or horizontal (in a strip below); "
                  "implies --legend")
      ->check(CLI::IsMember({"vertical", "horizontal"}));
  cmd->add_option("--legend-title", args->legend_title,
                  "The legend's title instead of the field's name (a reduction's \"maximum along each ray\" is "
                  "kept); implies --legend");
  cmd->add_option("--legend-unit", args->legend_unit,
                  "The field's unit, after the legend's title in brackets: \"temperature [K]\"; implies --legend");
  cmd->add_flag("--outline", args->outline, "Draw the mesh's bounding box over the picture, as ParaView's outline");
  cmd->add_flag("--axes", args->axes,
                "Draw an axes triad in the picture's lower-left corner (x red, y green, z blue), as ParaView's "
                "orientation axes");
  cmd->add_option("--title", args->title, "A title above the picture, in a strip of its own (the PNG grows)");
  cmd->add_flag("--time-label", args->time_label,
                "A time series: label each frame with its time above the picture (\"t = 1.50\")");
  cmd->add_option("--time-format", args->time_format,
                  "With --time-label: printf's format of the time, one %f, %e or %g (default \"t = %.2f\")");
  cmd->add_option("--orbit", args->orbit,
                  "Turn the camera this many degrees about its up axis over --frames N (a turntable: 360)");
  // The render settings, one option a row of the table (render/settings_table.hpp): --NAME is
  // setting NAME, its help the row's with its choices and default.
  auto texts = std::make_shared<std::map<std::string, std::vector<std::string>>>();
  for (const SettingRow& row : render_settings()) {
    std::vector<std::string>& text = (*texts)[row.name];
    CLI::Option* option = cmd->add_option("--" + std::string(row.name), text, setting_help(row))->type_name("TEXT");
    if (row.repeatable)
      option->allow_extra_args(false);
    else
      option->expected(1);
  }
  cmd->add_option("--progressive", args->progressive,
                  "slicing: render at each of these plane counts in turn, e.g. 16,64,256, writing OUT-16.png, "
                  "OUT-64.png, ... as each completes");
  cmd->add_option("--size", args->size, "Image size WxH, overriding the scene");
  cmd->add_option("--field", args->field,
                  "Point field to render, overriding the scene; of a vector or tensor one scalar: NAME:x (y, z, N, "
                  "xx ... for a tensor), NAME_X, NAME:magnitude, NAME:von_mises (NAME alone: its magnitude)");
  add_log_options(*cmd, args->log, args->log_floor);
  add_opacity_field_option(*cmd, args->look.opacity_field);
  cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")->check(CLI::Range(1, kMaxThreads));
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
  CLI::Option* cell_data = cmd->get_option("--cell-data");
  CLI::Option* time_format = cmd->get_option("--time-format");
  const std::vector<CLI::Option*> legend_parts = {cmd->get_option("--legend-orientation"),
                                                  cmd->get_option("--legend-title"), cmd->get_option("--legend-unit")};
  return [args, texts, look, moves, cell_data, time_format, legend_parts] {
    args->cell_data_given = cell_data->count() > 0;
    if (time_format->count() > 0) args->time_label = true;
    for (CLI::Option* part : legend_parts)
      if (part->count() > 0) args->legend = true;
    for (const auto& [row, option] : moves) {
      if (option->count() == 0) continue;
      const std::vector<std::string> given = option->results();
      if (*row->value == '\0' || given.empty())  // a switch, or --perspective alone
        args->camera_moves.emplace_back(row->name, "");
      else
        for (const std::string& text : given) args->camera_moves.emplace_back(row->name, text);
    }
    for (const SettingRow& row : render_settings())  // in the table's order, each use of a repeatable one
      for (const std::string& text : (*texts)[row.name]) usage([&] { set_option(args->options, row.name, text); });
    for (CLI::Option* option : look)
      if (option->count() > 0) args->look_given.push_back(option->get_name().substr(2));
    return run_render(*args);
  };
}

}  // namespace cellproj
