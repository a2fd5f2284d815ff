#include "partition/partition_index.hpp"

#include "mesh/field_choice.hpp"
#include "optics/auto_opacity.hpp"
#include "view/camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "base/file_status.hpp"
#include "io/write_mesh.hpp"

namespace cellproj {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kIndexName = "partition.json";

json box_json(const KdBox& b) { return {{"lo", {b.lo.x, b.lo.y, b.lo.z}}, {"hi", {b.hi.x, b.hi.y, b.hi.z}}}; }

KdBox box_of(const json& j, const std::string& what) {
  KdBox b;
  for (int k = 0; k < 3; ++k) {
    b.lo[k] = j.at("lo").at(k).get<double>();
    b.hi[k] = j.at("hi").at(k).get<double>();
    if (!std::isfinite(b.lo[k]) || !std::isfinite(b.hi[k]) || b.lo[k] > b.hi[k])
      throw InputError(what + ": box with lo > hi or a non-finite corner");
  }
  return b;
}

// Each node reached once from the root, each brick's leaf once, children after their parent.
void check_tree(const KdTree& tree, const std::string& path) {
  const int n = static_cast<int>(tree.nodes.size());
  std::vector<int> seen(n, 0);
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const int k = stack.back();
    stack.pop_back();
    if (k < 0 || k >= n || seen[k]++)
      throw InputError(
          where(path, "the k-d tree is not a tree (node " + std::to_string(k) + " out of range or reached twice)"));
    const KdNode& node = tree.nodes[k];
    if (node.leaf()) {
      if (node.brick < 0 || node.brick >= tree.bricks() || tree.leaf_of[node.brick] != k)
        throw InputError(where(path, "k-d tree node " + std::to_string(k) + " names brick " +
                                         std::to_string(node.brick) + ", which is not its brick"));
      continue;
    }
    if (node.axis > 2 || !std::isfinite(node.plane))
      throw InputError(
          where(path, "k-d tree node " + std::to_string(k) + ": axis must be 0, 1 or 2 and the plane finite"));
    stack.push_back(node.children[0]);
    stack.push_back(node.children[1]);
  }
  for (int k = 0; k < n; ++k)
    if (!seen[k]) throw InputError(where(path, "k-d tree node " + std::to_string(k) + " is not reached from the root"));
}

}  // namespace

std::string PartitionIndex::brick_path(int brick) const {
  const std::string& f = bricks.at(brick).file;
  return f.empty() ? f : (fs::path(path).parent_path() / f).string();
}

bool is_partition_index(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return fs::is_regular_file(fs::path(path) / kIndexName, ec);
  return fs::path(path).filename() == kIndexName;
}

PartitionIndex read_partition_index(const std::string& given) {
  std::error_code ec;
  const std::string path = fs::is_directory(given, ec) ? (fs::path(given) / kIndexName).string() : given;
  std::ifstream in(path);
  if (!in) throw InputError(where(path, "cannot open the partition index"));
  PartitionIndex index;
  index.path = path;
  try {
    const json j = json::parse(in);
    if (j.value("cellproj_partition", 0) != 1)
      throw InputError("not a cellproj partition index (\"cellproj_partition\": 1 missing)");
    index.source = j.at("source").get<std::string>();
    index.cells = j.at("cells").get<std::int64_t>();
    index.cost_model = j.value("cost_model", "projected");
    for (const json& f : j.at("fields")) {
      index.fields.push_back(
          {f.at("name").get<std::string>(), f.at("min").get<double>(), f.at("max").get<double>(), {}});
      for (const json& p : f.value("auto_extinction", json::array()))
        index.fields.back().auto_extinction.push_back({p.at(0).get<double>(), p.at(1).get<double>()});
    }
    for (const json& b : j.at("bricks")) {
      BrickEntry e{b.at("file").get<std::string>(), b.at("cells").get<std::int64_t>(),
                   b.at("points").get<std::int64_t>(), b.at("cost").get<double>()};
      if (e.cells < 0 || e.points < 0 || (e.cells > 0) == e.file.empty() || e.file.find('/') != std::string::npos)
        throw InputError("brick " + std::to_string(index.bricks.size()) +
                         ": a file (in the index's folder) for a brick with cells, none for an empty one");
      index.bricks.push_back(e);
    }
    index.tree.leaf_of.assign(index.bricks.size(), -1);
    for (const json& n : j.at("tree")) {
      KdNode node;
      node.box = box_of(n.at("box"), "k-d tree node " + std::to_string(index.tree.nodes.size()));
      node.cost = n.value("cost", 0.0);
      if (n.contains("brick")) {
        node.brick = n.at("brick").get<int>();
        if (node.brick < 0 || node.brick >= static_cast<int>(index.bricks.size()) ||
            index.tree.leaf_of[node.brick] >= 0)
          throw InputError("k-d tree leaf " + std::to_string(index.tree.nodes.size()) + " names brick " +
                           std::to_string(node.brick) + ": out of range or named twice");
        index.tree.leaf_of[node.brick] = static_cast<int>(index.tree.nodes.size());
      } else {
        node.axis = n.at("axis").get<int>();
        node.plane = n.at("plane").get<double>();
        node.children[0] = n.at("children").at(0).get<int>();
        node.children[1] = n.at("children").at(1).get<int>();
        if (node.axis < 0) throw InputError("k-d tree node " + std::to_string(index.tree.nodes.size()) + ": axis < 0");
      }
      index.tree.nodes.push_back(node);
    }
  } catch (const json::exception& e) {
    throw InputError(where(path, std::string("malformed partition index: ") + e.what()));
  } catch (const InputError& e) {
    throw InputError(where(path, e.what()));
  }
  if (index.tree.nodes.empty() || index.bricks.empty()) throw InputError(where(path, "the index lists no bricks"));
  for (std::size_t b = 0; b < index.bricks.size(); ++b)
    if (index.tree.leaf_of[b] < 0)
      throw InputError(where(path, "brick " + std::to_string(b) + " is in no leaf of the k-d tree"));
  check_tree(index.tree, path);
  for (KdNode& node : index.tree.nodes)
    for (int c : node.children)
      if (c >= 0) index.tree.nodes[c].parent = static_cast<int>(&node - index.tree.nodes.data());
  return index;
}

void write_partition_index(const PartitionIndex& index, const std::string& path) {
  json bricks = json::array(), tree = json::array(), fields = json::array();
  for (const BrickEntry& b : index.bricks)
    bricks.push_back({{"file", b.file}, {"cells", b.cells}, {"points", b.points}, {"cost", b.cost}});
  for (const KdNode& n : index.tree.nodes) {
    json j = {{"box", box_json(n.box)}, {"cost", n.cost}};
    if (n.leaf())
      j["brick"] = n.brick;
    else
      j.update({{"axis", n.axis}, {"plane", n.plane}, {"children", {n.children[0], n.children[1]}}});
    tree.push_back(j);
  }
  for (const FieldRange& f : index.fields) {
    json points = json::array();
    for (const ExtinctionPoint& p : f.auto_extinction) points.push_back({p.s, p.kappa});
    fields.push_back({{"name", f.name}, {"min", f.min}, {"max", f.max}, {"auto_extinction", points}});
  }
  const json j = {{"cellproj_partition", 1},
                  {"source", index.source},
                  {"cells", index.cells},
                  {"cost_model", index.cost_model},
                  {"bounds", box_json(index.tree.nodes.at(0).box)},
                  {"fields", fields},
                  {"bricks", bricks},
                  {"tree", tree}};
  std::ofstream out(path);
  out << j.dump(1) << "\n";
  if (!out) throw InputError(where(path, "cannot write the partition index"));
}

LoadedMesh extent_mesh(const PartitionIndex& index) {
  LoadedMesh m;
  m.mesh.source = index.path;
  const KdBox& b = index.tree.nodes.at(0).box;
  m.mesh.points = {b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z};
  for (const FieldRange& f : index.fields) m.mesh.fields.push_back({f.name, {f.min, f.max}, "the partition's range"});
  return m;
}

PartitionIndex partition_mesh(const Mesh& mesh, int bricks, const std::string& dir, const std::string& cost_model,
                              int image_side, PartitionReport* report) {
  if (cost_model != "projected" && cost_model != "cells")
    throw InputError("setting 'cost' must be projected or cells, not '" + cost_model + "'");
  create_folders(dir);
  const MeshView view = mesh.view();
  PartitionIndex index;
  index.path = (fs::path(dir) / kIndexName).string();
  index.source = mesh.source;
  index.cells = mesh.n_cells();
  index.cost_model = cost_model;
  const std::vector<double> costs = cell_costs(view, image_side, cost_model == "cells");
  index.tree = build_kd_tree(view, costs, bricks);
  for (const PointField& f : mesh.fields) {  // a vector's range is its magnitude's
    const std::vector<double> v = shown_values(f);
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    index.fields.push_back({f.name, v.empty() ? 0.0 : *lo, v.empty() ? 0.0 : *hi,
                            auto_extinction(view, v.data(), kDefaultFrom, kDefaultUp)});
  }
  std::vector<std::vector<std::int64_t>> cells = cells_of_bricks(view, index.tree);
  PartitionReport total;
  for (int b = 0; b < bricks; ++b) {
    ClipReport r;
    const Mesh brick = extract_brick(mesh, index.tree, b, cells[b], &r);
    std::vector<std::int64_t>().swap(cells[b]);  // one brick in memory at a time
    total.clipped.kept_whole += r.kept_whole, total.clipped.cut += r.cut, total.clipped.dropped += r.dropped;
    total.clipped.tetrahedra += r.tetrahedra;
    total.peak_brick_cells = std::max(total.peak_brick_cells, brick.n_cells());
    BrickEntry e{"", brick.n_cells(), brick.n_points(), index.tree.nodes[index.tree.leaf_of[b]].cost};
    if (brick.n_cells() > 0) {
      char name[32];
      std::snprintf(name, sizeof name, "brick_%04d.vtu", b);
      e.file = name;
      write_vtu(brick, (fs::path(dir) / name).string());
    }
    index.bricks.push_back(e);
  }
  write_partition_index(index, index.path);
  if (report) *report = total;
  return index;
}

}  // namespace cellproj
