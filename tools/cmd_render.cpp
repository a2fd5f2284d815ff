// cellproj render SCENE.json
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>

#include <nlohmann/json.hpp>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include "grid/error.hpp"
#include "optics/transfer_function.hpp"
#include "parallel/projection_renderer.hpp"
#include "raycast/reference_renderer.hpp"
#include "grid/tetrahedralize.hpp"
#include "tools/commands.hpp"
#include "tools/memory_budget.hpp"
#include "tools/timing.hpp"
#include "tools/progress.hpp"
#include "tools/scene.hpp"
#include "tools/scene_setup.hpp"

namespace cellproj {
namespace {

struct RenderArgs {
  std::string scene, png, npy, method = "pt-breakpoints", size, field, interpolation = "isoparametric", sort = "auto", gaps = "auto",
              backend = "software", tetrahedralize = "problem";
  int threads = 0, frames = 1, table_size = 256;
  bool interpolation_given = false;  // --interpolation on the command line (it applies to exact only)
  bool tetrahedralize_given = false;  // --tetrahedralize (the projection methods only)
  double max_memory_gib = 0.0;  // 0: the machine's available memory
  bool stats = false;
};

nlohmann::json projection_stats_json(const ProjectionStats& p) {
  nlohmann::json phases = nlohmann::json::object();
  for (const auto& [name, sec] : p.phase_seconds) phases[name] = sec;
  const auto& c = p.counters;
  nlohmann::json j = {{"sort", name_of(p.sort.method)},
          {"tetrahedralize", name_of(p.tetrahedralize)},
          {"cells_projected", p.cells},
          {"tets", p.tets},
          {"problem_cells", p.problem_cells},
          {"cells_split", p.cells_split},
          {"cycle_splits", p.cycle_splits},
          {"polyhedra", c.polyhedra},
          {"polygons", c.polygons},
          {"subdivisions_looked_up", c.subdivisions_looked_up},
          {"class1_tets", c.class1},
          {"class2_tets", c.class2},
          {"empty_tets", c.empty},
          {"behind_eye_tets", c.behind_eye},
          {"fragments", c.fragments},
          {"breakpoint_cells", c.breakpoint_cells},
          {"direct_cells", c.direct_cells},
          {"face_relations", p.sort.face_relations},
          {"gap_relations", p.sort.gap_relations},
          {"gaps_from", p.sort.method == SortMethod::mpvo_abuffer ? nlohmann::json(name_of(p.sort.gaps_from))
                                                                   : nlohmann::json(nullptr)},
          {"gap_pair_tests", p.sort.gap_pair_tests},
          {"abuffer_runs", p.sort.abuffer_runs},
          {"cycles", p.sort.cycles.size()},
          {"phase_seconds", phases}};
  if (!p.gl_renderer.empty()) j["gl_renderer"] = p.gl_renderer;
  return j;
}

int run_render(const RenderArgs& a) {
  const auto t_load = std::chrono::steady_clock::now();
  Scene scene = load_scene(a.scene);
  if (!a.size.empty()) parse_size(a.size, scene.width, scene.height);
  if (!a.field.empty()) scene.field = a.field;
  const bool exact = a.method == "exact";
  ProjectionOptions projection;
  if (!exact) {
    try {
      projection.method = projection_method_from_name(a.method);
    } catch (const InputError&) {
      throw InputError("--method: unknown method '" + a.method + "' (known: exact, " + projection_method_names() + ")");
    }
  }
  // Every option is checked, also those the chosen method does not use: a typo never passes silently.
  projection.sort = sort_method_from_name(a.sort);
  projection.gaps = gap_method_from_name(a.gaps);
  projection.table_size = a.table_size;
  projection.backend = projection_backend_from_name(a.backend);
  const Tetrahedralize tetrahedralize = tetrahedralize_from_name(a.tetrahedralize);
  if (!exact && a.interpolation_given)
    throw InputError("--interpolation chooses the field inside cells for --method exact; the projection methods "
                     "interpolate linearly along each ray segment through a cell");
  if (exact && a.tetrahedralize_given)
    throw InputError("--tetrahedralize chooses the cells the projection methods split; --method exact traces every "
                     "cell whole (--interpolation chooses its field)");
  if (exact && projection.backend != ProjectionBackend::software)
    throw InputError("--backend " + a.backend + " draws the projection methods; --method exact is a ray integrator on the CPU");
  const CellInterpolation interpolation = cell_interpolation_from_name(a.interpolation);
  // Refuse what would not fit, before allocating it: from the file's header before reading it,
  // and again from the mesh as read.
  const auto size_text = std::to_string(scene.width) + "x" + std::to_string(scene.height);
  if (const HeaderCounts h = vtk_xml_header_counts(scene.mesh); h.cells > 0)
    refuse_beyond_memory(
        estimate_mesh_bytes(h) + estimate_render_bytes({scene.width, scene.height, h.points, h.cells, h.cells, exact}),
        a.max_memory_gib, "reading " + scene.mesh + " (" + std::to_string(h.cells) + " cells) and rendering " + size_text,
        a.scene);
  const PreparedScene prepared = prepare_scene(scene);
  for (const auto& w : prepared.warnings) std::fprintf(stderr, "cellproj: warning: %s\n", w.c_str());
  const double load_seconds = seconds_since(t_load);
  {
    const Mesh& m = prepared.loaded.mesh;
    std::int64_t tets = 0;
    for (std::int64_t c = 0; c < m.n_cells(); ++c) tets += m.types[c] == static_cast<std::uint8_t>(CellType::Tetra) ? 1 : kMaxTetsPerCell;
    refuse_beyond_memory(estimate_render_bytes({scene.width, scene.height, m.n_points(), m.n_cells(), tets, exact}),
                         a.max_memory_gib, "rendering " + size_text + " of " + std::to_string(m.n_cells()) + " cells", a.scene);
  }

  const int threads = a.threads > 0 ? a.threads : tbb::info::default_concurrency();
  tbb::task_arena arena(threads);
  Image first;
  std::vector<double> frame_times;
  double prepare_seconds = 0.0, trace_seconds = 0.0;
  ExactStats st;
  ProjectionStats pst;
  arena.execute([&] {
    const auto t_prep = std::chrono::steady_clock::now();
    const MeshView view = prepared.loaded.mesh.view(prepared.field);
    std::unique_ptr<ExactRenderer> exact_renderer;
    std::unique_ptr<ProjectionRenderer> projector;
    if (exact) exact_renderer = std::make_unique<ExactRenderer>(view, interpolation);
    else projector = std::make_unique<ProjectionRenderer>(view, tetrahedralize);
    prepare_seconds = seconds_since(t_prep);
    for (int f = 0; f < a.frames; ++f) {
      const auto t_frame = std::chrono::steady_clock::now();
      ProgressBar bar(a.frames > 1 ? "frame " + std::to_string(f + 1) + "/" + std::to_string(a.frames) : "rendering");
      const Camera camera = orbit(prepared.camera, f);
      Image img = exact ? exact_renderer->render(prepared.tf, camera, scene.width, scene.height, &st, [&](double d) { bar(d); })
                        : projector->render(prepared.tf, camera, scene.width, scene.height, projection, &pst);
      trace_seconds += exact ? st.trace_seconds : pst.seconds;
      frame_times.push_back(seconds_since(t_frame));  // preparation is reported on its own
      if (f == 0) first = std::move(img);
    }
  });
  // The software back end ray casts the tetrahedra reaching behind the eye; OpenGL cannot draw them,
  // nor can whole cells be projected there.
  if (!exact && pst.counters.behind_eye > 0 &&
      (projection.backend != ProjectionBackend::software || tetrahedralize == Tetrahedralize::none))
    std::fprintf(stderr,
                 "cellproj: warning: %lld cells reach behind the eye and were not drawn (the camera is inside or too "
                 "close to the mesh); use --backend software with --tetrahedralize problem or all, which ray casts them\n",
                 static_cast<long long>(pst.counters.behind_eye));
  if (!exact && tetrahedralize == Tetrahedralize::none && pst.problem_cells > 0)
    std::fprintf(stderr,
                 "cellproj: warning: %lld cells have a face folded in this view and were projected whole "
                 "(--tetrahedralize none): the order and the picture may be wrong there\n",
                 static_cast<long long>(pst.problem_cells));

  if (!exact && !pst.sort.cycles.empty()) {  // the last frame's
    long long cells = 0;
    for (const VisibilityCycle& c : pst.sort.cycles) cells += c.size;
    std::fprintf(stderr,
                 "cellproj: warning: the visibility sort met %zu visibility cycle%s (%lld cells) and broke each at one "
                 "relation: those cells have no back-to-front order (cells that overlap, or warped faces), so the picture "
                 "may be wrong where they cover each other; --method exact is exact there, and `cellproj info "
                 "--overlaps` tells whether cells overlap\n",
                 pst.sort.cycles.size(), pst.sort.cycles.size() == 1 ? "" : "s", cells);
  }

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
                        {"backend", exact ? "" : a.backend},
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
                        {"render_seconds", trace_seconds / a.frames}};
    if (exact) {
      s["segments"] = st.segments;
      s["interpolation"] = name_of(interpolation);
      s["newton_failures"] = st.newton_failures;
    } else {
      s.update(projection_stats_json(pst));  // the last frame's
    }
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
  cmd->add_option("--method", args->method,
                  "Rendering method: pt-breakpoints (default; exact for the canonical tetrahedra), pt-analytic, "
                  "pt-table, pt-linear (fastest), or exact (the reference ray integrator); see docs/methods.md");
  cmd->add_option("--sort", args->sort, "Visibility sort for the projection methods: " + sort_method_names());
  cmd->add_option("--gaps", args->gaps,
                  "How mpvo-abuffer finds the relations across gaps: " + gap_method_names() + " (as sortbench's)");
  cmd->add_option("--backend", args->backend,
                  "Where the projection methods rasterize: software (default), or for pt-linear and pt-table "
                  "opengl (OSMesa, float target), opengl-8bit, opengl-8bit-dither");
  CLI::Option* tetrahedralize = cmd->add_option("--tetrahedralize", args->tetrahedralize,
                  "Which cells other than tetrahedra the projection methods split into tetrahedra: problem (default; "
                  "per view, those with a folded non-planar face), all, or none (every cell whole)");
  cmd->add_option("--table-size", args->table_size, "pt-table: nodes per axis of the opacity table (default 256)")
      ->check(CLI::Range(2, 8192));
  CLI::Option* interpolation = cmd->add_option("--interpolation", args->interpolation,
                  "Field inside hexahedra, wedges and pyramids for exact: isoparametric (default) or canonical-tets")
      ->check(CLI::IsMember({"isoparametric", "canonical-tets"}));
  cmd->add_option("--size", args->size, "Image size WxH, overriding the scene");
  cmd->add_option("--field", args->field, "Point field to render, overriding the scene");
  cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")->check(CLI::Range(1, 1024));
  cmd->add_option("--frames", args->frames, "Render N frames, turning the camera 1 degree about its up axis each frame; "
                                            "report the median frame time")->check(CLI::Range(1, 100000));
  cmd->add_option("--max-memory", args->max_memory_gib,
                  "Refuse renders estimated to need more than this many GiB (default: the memory available now)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--stats", args->stats, "Print one JSON line of timings on stderr");
  return [args, interpolation, tetrahedralize] {
    args->interpolation_given = interpolation->count() > 0;
    args->tetrahedralize_given = tetrahedralize->count() > 0;
    return run_render(*args);
  };
}

}  // namespace cellproj
