// cellproj info MESH
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include <nlohmann/json.hpp>

#include "io/read_mesh.hpp"
#include "io/series_files.hpp"
#include "mesh/cell_order.hpp"
#include "mesh/field_choice.hpp"
#include "mesh/overlaps.hpp"
#include "mesh/topology.hpp"
#include "partition/partition_index.hpp"
#include "scene/prepare.hpp"
#include "tools/commands.hpp"
#include "tools/mesh_options.hpp"

namespace cellproj {
namespace {

struct InfoArgs {
  std::string mesh;
  ReadOptions reader;
  bool json = false, overlaps = false;
};

nlohmann::json describe(const LoadedMesh& loaded, double seconds_read) {
  const Mesh& m = loaded.mesh;
  const MeshView view = m.view();
  const auto t0 = std::chrono::steady_clock::now();
  const FaceTopology topo = build_topology(view);
  const double seconds_topology = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const HullReport hull = boundary_convexity(view, topo);

  std::map<std::string, std::int64_t> by_type = {{"tetra", 0}, {"hexahedron", 0}, {"wedge", 0}, {"pyramid", 0}};
  for (auto t : m.types) ++by_type[cell_name(static_cast<CellType>(t))];
  const auto [lo, hi] = bounds(m);
  nlohmann::json fields = nlohmann::json::object(), constant = nlohmann::json::array(),
                 nonfinite = nlohmann::json::object(), components = nlohmann::json::object();
  nlohmann::json association = nlohmann::json::object();
  for (const auto* list : {&m.fields, &m.cell_fields})
    for (const auto& f : *list) {
      association[f.name] = list == &m.fields ? "point" : "cell";
      double fmin = std::numeric_limits<double>::infinity(), fmax = -fmin;
      std::int64_t bad = 0;
      // A vector's or tensor's range is its magnitude's, as a picture of the field alone shows it.
      const std::vector<double> values = shown_values(f);
      components[f.name] = f.components;
      for (double v : values) {
        if (!std::isfinite(v)) {
          ++bad;
          continue;
        }
        fmin = std::min(fmin, v);
        fmax = std::max(fmax, v);
      }
      fields[f.name] = bad == static_cast<std::int64_t>(values.size()) ? nlohmann::json::array({nullptr, nullptr})
                                                                       : nlohmann::json::array({fmin, fmax});
      if (bad) nonfinite[f.name] = bad;
      if (fmin == fmax) constant.push_back(f.name);
    }
  nlohmann::json origins = nlohmann::json::object();
  for (const auto* list : {&m.fields, &m.cell_fields})
    for (const auto& f : *list) origins[f.name] = f.origin;
  return {{"file", m.source},
          {"points", m.n_points()},
          {"cells", m.n_cells()},
          {"cells_by_type", by_type},
          {"bounds", {lo.x, hi.x, lo.y, hi.y, lo.z, hi.z}},
          {"fields", fields},
          {"field_origins", origins},
          {"field_components", components},
          {"field_association", association},
          {"constant_fields", constant},
          {"nonfinite_values", nonfinite},
          {"boundary_faces", static_cast<std::int64_t>(topo.boundary.size())},
          {"shared_faces", topo.shared_faces},
          {"seam_faces", topo.seam_faces},
          {"nonmanifold_faces", topo.nonmanifold_faces},
          {"convex", hull.convex},
          {"boundary_faces_off_hull", hull.boundary_faces_off_hull},
          {"boundary_area_off_hull", hull.off_hull_area_share},
          {"nonplanar_faces", topo.nonplanar_faces},
          {"max_nonplanarity", topo.max_nonplanarity},
          {"max_relative_nonplanarity", topo.max_relative_nonplanarity},
          {"degenerate_cells", loaded.report.degenerate_cells},
          {"inverted_cells", loaded.report.inverted_cells},
          {"duplicate_points", loaded.report.duplicate_points},
          {"cell_numbering_spread", numbering_spread(view)},
          {"notes", m.notes},
          {"read_seconds", seconds_read},
          {"topology_seconds", seconds_topology}};
}

void print_text(const nlohmann::json& j) {
  if (const auto& s = j["series"]; !s.is_null())
    std::printf(
        "%s: a time series of %lld key frames, times %s to %s (render --time T or --animate); the "
        "first key frame:\n",
        s["source"].get<std::string>().c_str(), s["key_frames"].get<long long>(), s["times"].front().dump().c_str(),
        s["times"].back().dump().c_str());
  std::printf("%s\n", j["file"].get<std::string>().c_str());
  std::printf("  points %lld, cells %lld:", j["points"].get<long long>(), j["cells"].get<long long>());
  for (const auto& [k, v] : j["cells_by_type"].items())
    if (v.get<long long>()) std::printf(" %s %lld", k.c_str(), v.get<long long>());
  const auto& b = j["bounds"];
  std::printf("\n  bounds x [%g, %g]  y [%g, %g]  z [%g, %g]\n", b[0].get<double>(), b[1].get<double>(),
              b[2].get<double>(), b[3].get<double>(), b[4].get<double>(), b[5].get<double>());
  std::printf("  fields:%s\n", j["fields"].empty() ? " (none)" : "");
  for (const auto& [k, v] : j["fields"].items()) {
    const int nc = j["field_components"][k].get<int>();
    const std::string parts =
        nc == 1 ? ""
                : "; " + std::to_string(nc) + " components, pick " + component_words(nc) + "; range of the magnitude";
    const std::string cells =
        j["field_association"][k] == "cell" ? "; rendered constant over each cell, --cell-data points averages it" : "";
    std::printf("    %-28s [%s, %s]  (%s%s%s)\n", k.c_str(), v[0].dump().c_str(), v[1].dump().c_str(),
                j["field_origins"][k].get<std::string>().c_str(), parts.c_str(), cells.c_str());
  }
  std::printf("  boundary faces %lld, shared faces %lld", j["boundary_faces"].get<long long>(),
              j["shared_faces"].get<long long>());
  if (j["seam_faces"].get<long long>())
    std::printf(" (%lld of them seams: faces at repeated points, matched by position)",
                j["seam_faces"].get<long long>());
  std::printf("; boundary %s", j["convex"].get<bool>() ? "convex" : "NOT convex");
  if (!j["convex"].get<bool>())
    std::printf(" (%lld boundary faces, %.1f%% of the boundary area, off the convex hull)",
                j["boundary_faces_off_hull"].get<long long>(), 100 * j["boundary_area_off_hull"].get<double>());
  std::printf("\n  non-planar quadrilateral faces %lld (largest warp %g, %.3g of the face's size)\n",
              j["nonplanar_faces"].get<long long>(), j["max_nonplanarity"].get<double>(),
              j["max_relative_nonplanarity"].get<double>());
  std::printf(
      "  degenerate cells %lld, inverted cells %lld (re-oriented), duplicate points %lld, non-manifold faces %lld\n",
      j["degenerate_cells"].get<long long>(), j["inverted_cells"].get<long long>(),
      j["duplicate_points"].get<long long>(), j["nonmanifold_faces"].get<long long>());
  const double spread = j["cell_numbering_spread"].get<double>();
  std::printf("  cell numbering: consecutive cells %.3g cell radii apart%s\n", spread,
              spread > kLocalSpread ? " (scattered: the renderers draw a copy renumbered along a Z-order curve)" : "");
  for (const auto& c : j["constant_fields"])
    std::printf("  note: field '%s' is constant\n", c.get<std::string>().c_str());
  for (const auto& [k, v] : j["nonfinite_values"].items())
    std::printf("  WARNING: field '%s' has %lld non-finite values: it cannot be rendered\n", k.c_str(),
                v.get<long long>());
  for (const auto& n : j["notes"]) std::printf("  note: %s\n", n.get<std::string>().c_str());
  if (!j["overlapping_cell_pairs"].is_null()) {
    if (const auto pairs = j["overlapping_cell_pairs"].get<long long>())
      std::printf(
          "  WARNING: cells overlap in %lld pair%s (first: cells %lld and %lld): no back-to-front order of "
          "whole cells is right there, so the projection methods are not; --method exact is\n",
          pairs, pairs == 1 ? "" : "s", j["first_overlapping_cells"][0].get<long long>(),
          j["first_overlapping_cells"][1].get<long long>());
    else
      std::printf("  overlapping cells: none\n");
  }
}

// A time series' key frames (a .pvd, a numbered pattern, an Exodus file with several time steps),
// or null; `described` becomes the key frame described below them (the first).
nlohmann::json series_of(const InfoArgs& a, std::string& described) {
  std::string format = a.reader.format;
  if (format.empty()) try {
      format = format_for(a.mesh);
    } catch (const InputError&) {  // load_mesh says what is wrong with the name
    }
  if (!is_series_path(a.mesh) && format != "exodus") return nullptr;
  TimeSeries s;
  try {
    s = list_series(a.mesh, a.reader);
  } catch (const InputError&) {
    if (is_series_path(a.mesh)) throw;
    return nullptr;  // an Exodus file that cannot be listed: reading it says why (memory first)
  }
  if (!is_series_path(a.mesh) && s.frames.size() < 2) return nullptr;
  nlohmann::json times = nlohmann::json::array(), files = nlohmann::json::array();
  for (const KeyFrame& f : s.frames) times.push_back(f.time), files.push_back(f.path);
  if (is_series_path(a.mesh)) described = s.frames.front().path;
  return {{"source", s.source}, {"key_frames", s.frames.size()}, {"times", times}, {"files", files}};
}

// A partition index (`cellproj partition`): its bricks, their cells, costs and boxes, without
// reading the bricks.
int partition_info(const InfoArgs& a) {
  const PartitionIndex index = read_partition_index(a.mesh);
  nlohmann::json bricks = nlohmann::json::array(), fields = nlohmann::json::object();
  double hi = 0.0, sum = 0.0;
  std::int64_t cells = 0;
  for (int b = 0; b < static_cast<int>(index.bricks.size()); ++b) {
    const BrickEntry& e = index.bricks[b];
    const KdBox& box = index.tree.nodes[index.tree.leaf_of[b]].box;
    bricks.push_back({{"file", e.file},
                      {"cells", e.cells},
                      {"points", e.points},
                      {"cost", e.cost},
                      {"lo", {box.lo.x, box.lo.y, box.lo.z}},
                      {"hi", {box.hi.x, box.hi.y, box.hi.z}}});
    hi = std::max(hi, e.cost), sum += e.cost, cells += e.cells;
  }
  for (const FieldRange& f : index.fields) fields[f.name] = {f.min, f.max};
  const nlohmann::json j = {{"partition", index.path},
                            {"source", index.source},
                            {"source_cells", index.cells},
                            {"brick_cells", cells},
                            {"cost_model", index.cost_model},
                            {"cost_imbalance", sum > 0 ? hi * index.bricks.size() / sum : 1.0},
                            {"fields", fields},
                            {"bricks", bricks}};
  if (a.json) {
    std::printf("%s\n", j.dump().c_str());
    return kExitOk;
  }
  std::printf(
      "%s\n  partition of %s: %lld cells into %zu bricks (%lld cells once cut), cost model %s, cost max/mean %.3f\n",
      index.path.c_str(), index.source.c_str(), static_cast<long long>(index.cells), index.bricks.size(),
      static_cast<long long>(cells), index.cost_model.c_str(), j["cost_imbalance"].get<double>());
  for (const FieldRange& f : index.fields) std::printf("  field %-28s [%.17g, %.17g]\n", f.name.c_str(), f.min, f.max);
  for (const auto& b : bricks)
    std::printf("  %-16s %9lld cells  cost %.4g  box [%g, %g] x [%g, %g] x [%g, %g]\n",
                b["file"].get<std::string>().empty() ? "(no cells)" : b["file"].get<std::string>().c_str(),
                static_cast<long long>(b["cells"].get<std::int64_t>()), b["cost"].get<double>(),
                b["lo"][0].get<double>(), b["hi"][0].get<double>(), b["lo"][1].get<double>(), b["hi"][1].get<double>(),
                b["lo"][2].get<double>(), b["hi"][2].get<double>());
  return kExitOk;
}

int run_info(const InfoArgs& a) {
  if (is_partition_index(a.mesh)) return partition_info(a);
  const auto t0 = std::chrono::steady_clock::now();
  std::string described = a.mesh;
  const nlohmann::json series = series_of(a, described);
  const LoadedMesh loaded = load_mesh(described, a.reader);
  const double read = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  nlohmann::json j = describe(loaded, read);
  j["series"] = series;
  j["overlapping_cell_pairs"] = nullptr;
  if (a.overlaps) {
    const auto t1 = std::chrono::steady_clock::now();
    const OverlapReport o = overlapping_cells(loaded.mesh.view());
    j["overlapping_cell_pairs"] = o.cell_pairs;
    j["first_overlapping_cells"] =
        o.cell_pairs ? nlohmann::json::array({o.first_a, o.first_b}) : nlohmann::json(nullptr);
    j["overlap_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  }
  if (a.json)
    std::printf("%s\n", j.dump().c_str());
  else
    print_text(j);
  return kExitOk;
}

}  // namespace

Action add_info(CLI::App& app) {
  auto args = std::make_shared<InfoArgs>();
  CLI::App* cmd = app.add_subcommand("info", "Describe a mesh: cells, bounds, fields, boundary, defects");
  cmd->add_option("mesh", args->mesh,
                  "Mesh file (.vtu .pvtu .vts .vtk .exo/.ex2/.e .cgns[.gz] PLOT3D .node/.ele .off .xyzs .vtp)")
      ->required();
  args->reader.cell_data.reset();  // cell data listed as it is, its counts the file's
  add_reader_options(*cmd, args->reader);
  add_max_memory_option(*cmd, args->reader.max_memory_gib, "Refuse meshes");
  cmd->add_flag("--json", args->json, "Print one JSON object instead of text");
  cmd->add_flag("--overlaps", args->overlaps,
                "Also look for cells whose interiors overlap (over their tetrahedra; seconds per million cells)");
  return [args] { return run_info(*args); };
}

}  // namespace cellproj
