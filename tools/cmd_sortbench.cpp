// cellproj sortbench MESH... : every sort from N views over a sphere, timed, optionally checked
// against the order oracle.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include <tbb/info.h>
#include <tbb/task_arena.h>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "io/read_mesh.hpp"
#include "raycast/order_oracle.hpp"
#include "render/names.hpp"
#include "scene/prepare.hpp"
#include "scene/scene_file.hpp"
#include "tools/commands.hpp"
#include "tools/timing.hpp"
#include "visibility/sort.hpp"
#include "visibility/split_sorter.hpp"

namespace cellproj {
namespace {

struct SortbenchArgs {
  std::vector<std::string> meshes;
  std::string sorts = "centroid,mpvo,mpvo-abuffer,pairwise", size = "512x512", projection = "ortho", csv,
              tetrahedralize = "problem", gaps = "auto";
  int views = 8, threads = 0;
  bool check = false, json = false, abuffer_every_pixel = false;
  std::int64_t pairwise_limit = 50000;
  ReadOptions reader;
};

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

// The benchmark's views of a mesh: n directions over a sphere, each framing its bounding box.
std::vector<Camera> sphere_views(const Mesh& mesh, Projection projection, int n, double aspect) {
  const auto [lo, hi] = bounds(mesh);
  std::vector<Camera> cameras;
  for (const glm::dvec3& d : sphere_directions(n))
    cameras.push_back(frame_box(lo, hi, projection, d, up_for(d), aspect));
  return cameras;
}

// One (mesh, sort, projection) row over the given views.
nlohmann::json bench_row(const std::string& mesh_name, const Mesh& mesh, const SplittingSorter& sorter,
                         const CellRayTracer* tracer, SortMethod method, const std::vector<Camera>& cameras, int w,
                         int h, bool abuffer_every_pixel, GapMethod gaps) {
  const int views = static_cast<int>(cameras.size());
  const Projection projection = cameras.front().projection;
  std::vector<double> times;
  std::map<std::string, std::vector<double>> phases;
  std::int64_t face = 0, gap = 0, pair = 0, cycles = 0, violations = 0, violating_pixels = 0, overlapping_pixels = 0,
               violating_clear = 0, problem = 0, split = 0;
  std::int64_t fragments = 0, runs = 0, crossings = 0, pair_tests = 0, abuffer_views = 0;
  std::vector<double> split_times;
  std::string ran;
  for (const Camera& camera : cameras) {
    const auto t0 = std::chrono::steady_clock::now();
    SortView view{camera, w, h};
    view.abuffer_every_pixel = abuffer_every_pixel;
    view.gaps = gaps;
    const ViewOrder v = sorter.sort(method, view);
    const SortResult& r = v.sorted;
    split_times.push_back(std::max(0.0, seconds_since(t0) - r.stats.seconds));  // finding and splitting problem cells
    problem += v.problem_cells, split += v.mesh->split.cells_split;
    ran = name_of(r.stats.method);
    times.push_back(r.stats.seconds);
    std::map<std::string, double> in_view;  // a phase run twice (mpvo-abuffer asking the A-buffer) counts once, summed
    for (const auto& [phase, s] : r.stats.phase_seconds) in_view[phase] += s;
    for (const auto& [phase, s] : in_view) phases[phase].push_back(s);
    face += r.stats.face_relations, gap += r.stats.gap_relations, pair += r.stats.pair_relations;
    cycles += static_cast<std::int64_t>(r.stats.cycles.size());
    fragments += r.stats.abuffer_fragments, runs += r.stats.abuffer_runs, crossings += r.stats.abuffer_crossings;
    pair_tests += r.stats.gap_pair_tests, abuffer_views += r.stats.gaps_from == GapMethod::abuffer;
    if (tracer) {
      // The oracle traces the cells the order lists: the mesh, or its cells split for this view.
      std::unique_ptr<CellRayTracer> split_tracer;
      if (v.mesh->cells.connectivity != mesh.view().connectivity)
        split_tracer = std::make_unique<CellRayTracer>(v.mesh->cells);
      const OrderCheck k =
          check_order(split_tracer ? *split_tracer : *tracer, v.mesh->cells.n_cells, r.order, camera, w, h);
      if (k.missing_cells || k.repeated_cells)
        throw InternalError(std::string(name_of(method)) + " dropped or repeated cells");  // a bug, exit 3
      violations += k.violations, violating_pixels += k.violating_pixels, overlapping_pixels += k.overlapping_pixels;
      violating_clear += k.violating_pixels_without_overlap;
    }
  }
  nlohmann::json phase_json = nlohmann::json::object();
  for (const auto& [phase, s] : phases) phase_json[phase] = median(s);
  const double med = median(times);
  return {{"mesh", mesh_name},
          {"sort", name_of(method)},
          {"ran", ran},
          {"projection", projection == Projection::Perspective ? "persp" : "ortho"},
          {"views", views},
          {"width", w},
          {"height", h},
          {"cells", mesh.n_cells()},
          {"median_seconds", med},
          {"min_seconds", *std::min_element(times.begin(), times.end())},
          {"max_seconds", *std::max_element(times.begin(), times.end())},
          {"phase_seconds", phase_json},
          {"cells_per_second", med > 0 ? mesh.n_cells() / med : 0.0},
          {"face_relations", face / views},
          {"gap_relations", gap / views},
          {"pair_relations", pair / views},
          {"abuffer_every_pixel", abuffer_every_pixel},
          {"gaps", name_of(gaps)},
          {"gap_pair_tests", pair_tests / views},
          {"abuffer_views", abuffer_views},
          {"abuffer_fragments", fragments / views},
          {"abuffer_runs", runs / views},
          {"abuffer_crossings", crossings},
          {"cycles", cycles},
          {"tetrahedralize", name_of(sorter.mode())},
          {"problem_cells", problem / views},
          {"cells_split", split / views},
          {"split_seconds", median(split_times)},
          {"violations", tracer ? nlohmann::json(violations) : nlohmann::json(nullptr)},
          {"violating_pixels", tracer ? nlohmann::json(violating_pixels) : nlohmann::json(nullptr)},
          {"overlapping_pixels", tracer ? nlohmann::json(overlapping_pixels) : nlohmann::json(nullptr)},
          {"violating_pixels_without_overlap", tracer ? nlohmann::json(violating_clear) : nlohmann::json(nullptr)}};
}

std::string cell(const nlohmann::json& v) {
  if (v.is_null()) return "-";
  char b[64];
  if (v.is_number_float())
    std::snprintf(b, sizeof b, "%.4g", v.get<double>());
  else
    return v.is_string() ? v.get<std::string>() : v.dump();
  return b;
}

// One row as the text table's two lines.
void print_row(const nlohmann::json& row, bool checked, bool every_pixel) {
  std::printf(
      "  %-13s %-5s median %9.5f s (min %.5f, max %.5f)  %10.3g cells/s  relations: faces %lld, gaps %lld, pairs %lld  "
      "cycles %lld",
      cell(row["sort"]).c_str(), cell(row["projection"]).c_str(), row["median_seconds"].get<double>(),
      row["min_seconds"].get<double>(), row["max_seconds"].get<double>(), row["cells_per_second"].get<double>(),
      row["face_relations"].get<long long>(), row["gap_relations"].get<long long>(),
      row["pair_relations"].get<long long>(), row["cycles"].get<long long>());
  if (row["problem_cells"].get<long long>() > 0)
    std::printf("  problem cells %lld (split %lld, %.5f s)", row["problem_cells"].get<long long>(),
                row["cells_split"].get<long long>(), row["split_seconds"].get<double>());
  if (row["gap_pair_tests"].get<long long>() > 0)
    std::printf("  overlaps: %lld face pairs tested", row["gap_pair_tests"].get<long long>());
  if (row["abuffer_views"].get<long long>() > 0)
    std::printf("  A-buffer in %lld views: %lld runs, %lld pixels%s", row["abuffer_views"].get<long long>(),
                row["abuffer_runs"].get<long long>(), row["abuffer_fragments"].get<long long>(),
                every_pixel ? " (every pixel ordered)" : "");
  if (checked)
    std::printf("  violations %s (%s pixels, %s of them where no cells overlap; cells overlap on %s)",
                cell(row["violations"]).c_str(), cell(row["violating_pixels"]).c_str(),
                cell(row["violating_pixels_without_overlap"]).c_str(), cell(row["overlapping_pixels"]).c_str());
  std::printf("\n    phases:");
  for (const auto& [phase, s] : row["phase_seconds"].items()) std::printf(" %s %.5f s", phase.c_str(), s.get<double>());
  std::printf("\n");
}

int run_sortbench(const SortbenchArgs& a) {
  int w = 0, h = 0;
  usage([&] { parse_size(a.size, w, h); });
  std::vector<SortMethod> methods;
  for (const auto& s : split(a.sorts)) methods.push_back(usage([&] { return parse_sort_method(s); }));
  if (methods.empty()) throw UsageError("--sorts: no sort named; known: " + sort_method_names());
  const Tetrahedralize tetrahedralize = usage([&] { return parse_tetrahedralize(a.tetrahedralize); });
  const GapMethod gaps = usage([&] { return parse_gap_method(a.gaps); });
  std::vector<Projection> projections;
  if (a.projection == "ortho" || a.projection == "both") projections.push_back(Projection::Orthographic);
  if (a.projection == "persp" || a.projection == "both") projections.push_back(Projection::Perspective);

  static const char* kColumns[] = {"mesh",
                                   "sort",
                                   "projection",
                                   "views",
                                   "cells",
                                   "median_seconds",
                                   "min_seconds",
                                   "max_seconds",
                                   "cells_per_second",
                                   "face_relations",
                                   "gap_relations",
                                   "pair_relations",
                                   "cycles",
                                   "tetrahedralize",
                                   "problem_cells",
                                   "cells_split",
                                   "abuffer_every_pixel",
                                   "gaps",
                                   "gap_pair_tests",
                                   "abuffer_views",
                                   "abuffer_fragments",
                                   "abuffer_runs",
                                   "abuffer_crossings",
                                   "violations",
                                   "violating_pixels",
                                   "overlapping_pixels",
                                   "violating_pixels_without_overlap"};
  const char* const last = kColumns[std::size(kColumns) - 1];
  std::ofstream csv;
  if (!a.csv.empty()) {
    csv.open(a.csv);
    if (!csv) throw InputError(where(a.csv, "cannot write the CSV file"));
    for (const char* c : kColumns) csv << c << (c == last ? "\n" : ",");
  }
  const int threads = a.threads > 0 ? a.threads : tbb::info::default_concurrency();
  tbb::task_arena arena(threads);
  arena.execute([&] {
    for (const std::string& path : a.meshes) {
      const auto t0 = std::chrono::steady_clock::now();
      LoadedMesh loaded = load_mesh(path, a.reader);
      const Mesh& mesh = loaded.mesh;
      const double load_seconds = seconds_since(t0);
      const auto t1 = std::chrono::steady_clock::now();
      const SplittingSorter sorter(mesh.view(), tetrahedralize);
      const bool convex = sorter.base().hull.convex;
      const double prepare_seconds = seconds_since(t1);
      std::unique_ptr<CellRayTracer> tracer;
      if (a.check) tracer = std::make_unique<CellRayTracer>(mesh.view());
      std::vector<std::vector<Camera>> views;  // per projection, shared by every sort
      for (Projection projection : projections) views.push_back(sphere_views(mesh, projection, a.views, double(w) / h));
      if (!a.json)
        std::printf("%s: %lld cells, boundary %s; read %.3f s, topology and sort preparation %.3f s; %d views, %dx%d\n",
                    path.c_str(), static_cast<long long>(mesh.n_cells()), convex ? "convex" : "not convex",
                    load_seconds, prepare_seconds, a.views, w, h);
      for (SortMethod method : methods) {
        if (method == SortMethod::pairwise && mesh.n_cells() > a.pairwise_limit) {
          if (!a.json)
            std::printf("  pairwise skipped: %lld cells is above --pairwise-limit %lld (it is O(n^2))\n",
                        static_cast<long long>(mesh.n_cells()), static_cast<long long>(a.pairwise_limit));
          continue;
        }
        for (const auto& cameras : views) {
          nlohmann::json row =
              bench_row(path, mesh, sorter, tracer.get(), method, cameras, w, h, a.abuffer_every_pixel, gaps);
          row["threads"] = threads;
          if (a.json)
            std::printf("%s\n", row.dump().c_str());
          else
            print_row(row, a.check, a.abuffer_every_pixel);
          if (csv.is_open())
            for (const char* c : kColumns) csv << cell(row[c]) << (c == last ? "\n" : ",");
          std::fflush(stdout);
        }
      }
    }
  });
  return kExitOk;
}

}  // namespace

Action add_sortbench(CLI::App& app) {
  auto args = std::make_shared<SortbenchArgs>();
  CLI::App* cmd =
      app.add_subcommand("sortbench", "Time the visibility sorts from views spread over a sphere, and check them");
  cmd->add_option("meshes", args->meshes, "Mesh files (any format `info` reads)")->required();
  cmd->add_option("--sorts", args->sorts, "Comma-separated sorts: " + sort_method_names())->capture_default_str();
  cmd->add_option("--views", args->views, "Viewpoints, spread evenly over a sphere around the mesh")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  cmd->add_option("--size", args->size, "Image size WxH (the A-buffer samples its pixel centres)")
      ->capture_default_str();
  cmd->add_option("--projection", args->projection, "ortho, persp or both")
      ->check(CLI::IsMember({"ortho", "persp", "both"}))
      ->capture_default_str();
  cmd->add_option("--tetrahedralize", args->tetrahedralize,
                  "Cells other than tetrahedra split into tetrahedra: problem (per view, those a ray may cross more "
                  "than twice), all, or none")
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Worker threads for the sorts' parallel phases (default: all cores)")
      ->check(CLI::Range(1, kMaxThreads));
  add_max_memory_option(*cmd, args->reader.max_memory_gib, "Refuse meshes");
  cmd->add_flag("--check", args->check, "Count order violations with the ray-traced oracle (slow)");
  cmd->add_flag("--abuffer-every-pixel", args->abuffer_every_pixel,
                "mpvo-abuffer samples every boundary face off the hull and orders each pixel's list (the reference "
                "the sweep is measured against: the same relations, slower)");
  cmd->add_option("--gaps", args->gaps,
                  "How mpvo-abuffer finds the relations across gaps: " + gap_method_names() +
                      " (auto: overlaps, and the A-buffer for a view where a visibility cycle holds one of their "
                      "relations)")
      ->capture_default_str();
  cmd->add_option("--csv", args->csv, "Also write the rows to this CSV file");
  cmd->add_flag("--json", args->json, "One JSON object per line per (mesh, sort, projection) instead of the table");
  cmd->add_option("--pairwise-limit", args->pairwise_limit, "Skip pairwise on meshes with more cells than this")
      ->capture_default_str();
  return [args] { return run_sortbench(*args); };
}

}  // namespace cellproj
