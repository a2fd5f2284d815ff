#include "tools/render_input.hpp"

#include "mesh/field_choice.hpp"
#include "optics/auto_opacity.hpp"

#include <tuple>

#include "base/error.hpp"
#include "render/playback.hpp"
#include "scene/camera_json.hpp"
#include "tools/commands.hpp"
#include "tools/memory_budget.hpp"
#include "tools/mesh_options.hpp"
#include "tools/progress.hpp"

namespace cellproj {

void apply_view_and_clip(const RenderArgs& a, Scene& scene) {
  if (!a.view.empty()) {
    scene.camera.reset(), scene.camera_moves = {};
    scene.view = a.view;
  }
  for (const auto& move : a.camera_moves) usage([&] { set_camera_move(scene.camera_moves, move.first, move.second); });
  if (!a.clip.empty()) {
    scene.clip.clear();
    for (const std::string& c : a.clip) scene.clip.push_back(usage([&] { return parse_clip_plane(c); }));
  }
}

Input load_input(const RenderArgs& a, const Renderer& renderer, const RenderSettings& settings,
                 const std::vector<int>& levels, std::optional<Scene> given_scene) {
  int width = 0, height = 0;
  if (!a.size.empty()) usage([&] { parse_size(a.size, width, height); });
  const bool scene_file = is_scene_file(a.input);
  if (scene_file && !a.look_given.empty() && a.look_given != std::vector<std::string>{"colormap"})
    throw UsageError("--opacity and --depth make the extinction of a mesh rendered without a scene; " + a.input +
                     " is a scene file: edit its transfer_function");
  std::optional<glm::dvec3> background;  // --background none: transparent
  if (!a.background.empty() && a.background != "none")
    background = usage([&] { return parse_color(a.background, "--background"); });
  if (!a.view.empty()) usage([&] { return view_camera(a.view, {0, 0, 0}, {1, 1, 1}, 1.0); });  // the name, now

  Scene scene;
  if (scene_file) {
    scene = given_scene ? std::move(*given_scene) : load_scene(a.input);
    if (a.cell_data_given) scene.reader.cell_data = a.reader.cell_data;
    if (!a.look_given.empty()) {  // --colormap: the scene's colours replaced by the map over the field's range
      usage([&] { return colormap(a.look.colormap, 0, 1); });
      scene.transfer_function.erase("color");
      scene.transfer_function["color_preset"] = {{"name", a.look.colormap}};
    }
  } else {
    scene.source = a.input;
    scene.mesh = a.input;
    scene.reader = a.reader;
  }
  if (!a.field.empty()) scene.field = a.field;
  if (!a.look.opacity_field.empty()) scene.opacity_field = a.look.opacity_field;
  if (a.log) scene.log_scale = true;
  if (a.log_floor) scene.log_floor = a.log_floor;
  if (width > 0) std::tie(scene.width, scene.height) = std::tie(width, height);
  scene.reader.max_memory_gib = a.max_memory_gib;
  if (background) scene.background = *background, scene.transparent = false;
  if (a.background == "none") scene.transparent = true;
  if (settings.mode == RenderMode::slicing)
    for (int n : levels.empty() ? std::vector<int>{settings.slicing.slices} : levels)
      usage([&] { check_slices(n, scene.width, scene.height); });
  // Refuse what would not fit, before allocating it: from the file's header before reading it,
  // and again from the mesh as read.
  const ImageSize size{scene.width, scene.height};
  const auto size_text = std::to_string(scene.width) + "x" + std::to_string(scene.height);
  // A time series: the key frames listed (no mesh read), and the first frame made.
  std::unique_ptr<SeriesPlayer> player;
  std::vector<double> times;
  const bool series = is_series_path(scene.mesh) || a.time || !a.animate.empty();
  std::string first_file = scene.mesh;
  if (series) {
    if (a.time && !a.animate.empty()) throw UsageError("--time renders one frame and --animate many: give one");
    TimeSeries listed = list_series(scene.mesh, scene.reader);
    first_file = listed.frames.front().path;
    times = !a.animate.empty() ? usage([&] { return animation_times(a.animate); })
                               : std::vector<double>(a.frames, a.time ? *a.time : listed.frames.front().time);
    for (double t : {times.front(), times.back()}) locate(listed, t);  // in range, before any read
    player = std::make_unique<SeriesPlayer>(std::move(listed), scene_field(scene), key_frame_reader(scene.reader));
  }
  // A partition index: each rank reads its bricks later; the scene is prepared from the whole mesh's extent.
  std::optional<PartitionIndex> partition;
  if (is_partition_index(scene.mesh)) {
    if (series) throw UsageError(scene.mesh + " is a partition index: --time and --animate need a time series");
    if (!scene.opacity_field.empty())
      throw InputError(where(scene.mesh, "an opacity field of its own is drawn from one mesh, not a partition yet"));
    partition = read_partition_index(scene.mesh);
  } else if (const HeaderCounts h = header_counts(first_file); h.cells > 0)
    refuse_beyond_memory(
        estimate_mesh_bytes(h) * (series ? 2 : 1) + renderer.estimate_bytes({h.points, h.cells, h.cells}, size),
        a.max_memory_gib,
        "reading " + first_file + " (" + std::to_string(h.cells) + " cells" + (series ? ", two key frames" : "") +
            ") and rendering " + size_text,
        a.input);
  // A series' colours and framing come from its first key frame whatever the time rendered, so that
  // --time T and --animate give the same picture at T.
  SeriesFrame first;
  LoadedMesh loaded = player      ? first_key_frame(*player, scene)
                      : partition ? extent_mesh(*partition)
                                  : read_with_progress(scene.mesh, scene.reader);
  if (player) first = player->frame_at(times.front());
  if (!scene_file) {
    QuickLook look = a.look;
    if (player) {  // the scalar the player plays, its log in its name
      look.field = scene.field;
    } else {
      look.field = a.field;
      look.log = a.log, look.log_floor = a.log_floor;
    }
    std::tie(look.width, look.height) = std::tie(scene.width, scene.height);
    const glm::dvec3 bg = scene.background;
    const bool transparent = scene.transparent;
    scene = usage([&] {
      // Opacity auto looks at the cells: a series' are the player's (with its first key frame's
      // points and field), and a partition keeps auto's extinction for its bricks.
      std::vector<ExtinctionPoint> played;
      const std::vector<ExtinctionPoint>* known = nullptr;
      if (player && look.opacity == "auto") {
        MeshView cells = player->cells().view();
        cells.points = PointArray(loaded.mesh.points.data()), cells.n_points = loaded.mesh.n_points();
        played = auto_extinction(cells, loaded.mesh.fields.front().values.data(), kDefaultFrom, kDefaultUp);
        known = &played;
      }
      if (partition && !look.log)
        for (const FieldRange& f : partition->fields)
          if (f.name == choose_field(loaded.mesh, look.field).field && !f.auto_extinction.empty())
            known = &f.auto_extinction;
      return scene_from_json(quick_scene(loaded, a.input, a.reader, look, "", known), a.input, "");
    });
    scene.reader.max_memory_gib = a.max_memory_gib;
    scene.background = bg, scene.transparent = transparent;
  }
  apply_view_and_clip(a, scene);
  if (!scene.clip.empty() && partition)
    throw UsageError(
        "clipping planes do not go with a partition index yet: clip the mesh in memory (mpirun with the "
        "mesh itself) or before partitioning it");
  PreparedScene prepared = prepare_scene(scene, std::move(loaded));
  ClipReport clipped;
  if (!scene.clip.empty() && !player) {  // after the scene is prepared: colours and framing are the whole mesh's
    // (a time series is clipped frame by frame as it plays: render/playback.hpp)
    prepared.loaded.mesh = clip_mesh_kept(prepared.loaded.mesh, scene.clip, a.input, &clipped);
  }
  const MeshView cells = player ? player->view(first) : prepared.loaded.mesh.view();
  refuse_beyond_memory(renderer.estimate_bytes(size_of(cells), size), a.max_memory_gib,
                       "rendering " + size_text + " of " + std::to_string(cells.n_cells) + " cells", a.input);
  return {std::move(scene), std::move(prepared), std::move(player), std::move(first), std::move(times),
          clipped,          std::move(partition)};
}

}  // namespace cellproj
