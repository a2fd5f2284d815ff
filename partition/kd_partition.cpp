#include "partition/kd_partition.hpp"

#include <algorithm>
#include <numeric>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "mesh/geometry.hpp"
#include "mesh/tetrahedralize.hpp"

namespace cellproj {
namespace {

KdBox cell_box(const MeshView& mesh, std::int64_t c) {
  const std::int64_t* ids = mesh.cell(c);
  KdBox b{mesh.point(ids[0]), mesh.point(ids[0])};
  for (int k = 1; k < mesh.cell_size(c); ++k) {
    b.lo = glm::min(b.lo, mesh.point(ids[k]));
    b.hi = glm::max(b.hi, mesh.point(ids[k]));
  }
  return b;
}

// The box of the mesh's points ({0, 0} without points).
KdBox points_box(const MeshView& mesh) {
  if (mesh.n_points == 0) return {};
  KdBox b{mesh.point(0), mesh.point(0)};
  for (std::int64_t p = 1; p < mesh.n_points; ++p)
    b.lo = glm::min(b.lo, mesh.point(p)), b.hi = glm::max(b.hi, mesh.point(p));
  return b;
}

class TreeBuilder {
 public:
  TreeBuilder(const MeshView& mesh, const std::vector<double>& costs) : costs_(costs) {
    centroids_.resize(static_cast<std::size_t>(mesh.n_cells));
    for (std::int64_t c = 0; c < mesh.n_cells; ++c) centroids_[c] = cell_centroid(mesh, c);
  }

  // Makes the node of `leaves` leaves over cells [begin, end) of ids_, returning its index.
  int build(KdTree& tree, const KdBox& box, std::int64_t* begin, std::int64_t* end, int leaves) {
    const int index = static_cast<int>(tree.nodes.size());
    tree.nodes.emplace_back();
    tree.nodes[index].box = box;
    double total = 0.0;
    for (const std::int64_t* c = begin; c != end; ++c) total += costs_[*c];
    tree.nodes[index].cost = total;
    if (leaves == 1) {
      tree.nodes[index].brick = tree.bricks();
      tree.leaf_of.push_back(index);
      return index;
    }
    // Across the longest extent of the centroids (of the box when there are none).
    KdBox extent = box;
    if (begin != end) {
      extent = {centroids_[*begin], centroids_[*begin]};
      for (const std::int64_t* c = begin; c != end; ++c)
        extent.lo = glm::min(extent.lo, centroids_[*c]), extent.hi = glm::max(extent.hi, centroids_[*c]);
    }
    const glm::dvec3 size = extent.hi - extent.lo;
    const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
    std::sort(begin, end, [&](std::int64_t a, std::int64_t b) { return centroids_[a][axis] < centroids_[b][axis]; });
    const int left_leaves = leaves / 2;
    const double target = total * left_leaves / leaves;
    std::int64_t* split = begin;
    for (double sum = 0.0; split != end && sum + costs_[*split] / 2 < target; ++split) sum += costs_[*split];
    double plane = 0.5 * (box.lo[axis] + box.hi[axis]);
    if (begin != end) {
      const double before = split == begin ? centroids_[*begin][axis] : centroids_[*(split - 1)][axis];
      const double after = split == end ? centroids_[*(end - 1)][axis] : centroids_[*split][axis];
      plane = std::clamp(0.5 * (before + after), box.lo[axis], box.hi[axis]);
    }
    tree.nodes[index].axis = axis;
    tree.nodes[index].plane = plane;
    KdBox left = box, right = box;
    left.hi[axis] = plane;
    right.lo[axis] = plane;
    const int l = build(tree, left, begin, split, left_leaves);
    const int r = build(tree, right, split, end, leaves - left_leaves);
    tree.nodes[index].children[0] = l;
    tree.nodes[index].children[1] = r;
    tree.nodes[l].parent = tree.nodes[r].parent = index;
    return index;
  }

 private:
  const std::vector<double>& costs_;
  std::vector<glm::dvec3> centroids_;
};

void collect_bricks(const KdTree& tree, int node, std::vector<int>& out) {
  const KdNode& n = tree.nodes[node];
  if (n.leaf()) {
    out.push_back(n.brick);
    return;
  }
  collect_bricks(tree, n.children[0], out);
  collect_bricks(tree, n.children[1], out);
}

// A tetrahedron's setup (points, sort, projection) in fragments' worth: about 1 microsecond against 26
// nanoseconds per fragment of pt-linear, on one thread (bench/mpi.sh: the load-balance rows).
constexpr double kTetCost = 40.0;

}  // namespace

std::vector<double> cell_costs(const MeshView& mesh, int image_side, bool cells_only) {
  std::vector<double> costs(static_cast<std::size_t>(mesh.n_cells));
  const KdBox all = points_box(mesh);
  const double diagonal = glm::length(all.hi - all.lo);
  const double pixel = diagonal > 0 ? diagonal / image_side : 1.0;
  Tet tets[kMaxTetsPerCell];
  for (std::int64_t c = 0; c < mesh.n_cells; ++c) {
    const int n = canonical_tetrahedra(mesh, c, tets);
    costs[c] = kTetCost * n;
    if (cells_only) continue;
    double area = 0.0;  // of the tetrahedra's faces, in pixels
    for (int t = 0; t < n; ++t)
      for (int f = 0; f < 4; ++f) {
        const glm::dvec3 a = mesh.point(tets[t][f]), b = mesh.point(tets[t][(f + 1) % 4]),
                         d = mesh.point(tets[t][(f + 2) % 4]);
        area += 0.5 * glm::length(glm::cross(b - a, d - a)) / (pixel * pixel);
      }
    costs[c] += area / 4;  // Cauchy: a convex body's mean projected area is a quarter of its surface
  }
  return costs;
}

KdTree build_kd_tree(const MeshView& mesh, const std::vector<double>& costs, int bricks) {
  if (bricks < 1) throw InputError(where(mesh.source, "the number of bricks must be at least 1"));
  if (mesh.n_cells == 0) throw InputError(where(mesh.source, "the mesh has no cells to partition"));
  if (static_cast<std::int64_t>(costs.size()) != mesh.n_cells)
    throw InternalError("build_kd_tree: one cost per cell expected");
  const KdBox box = points_box(mesh);
  std::vector<std::int64_t> ids(static_cast<std::size_t>(mesh.n_cells));
  std::iota(ids.begin(), ids.end(), std::int64_t{0});
  KdTree tree;
  TreeBuilder(mesh, costs).build(tree, box, ids.data(), ids.data() + ids.size(), bricks);
  return tree;
}

std::vector<std::vector<std::int64_t>> cells_of_bricks(const MeshView& mesh, const KdTree& tree) {
  std::vector<std::vector<std::int64_t>> cells(static_cast<std::size_t>(tree.bricks()));
  std::vector<int> stack;
  for (std::int64_t c = 0; c < mesh.n_cells; ++c) {
    const KdBox b = cell_box(mesh, c);
    stack.assign(1, 0);
    while (!stack.empty()) {
      const KdNode& n = tree.nodes[stack.back()];
      stack.pop_back();
      if (n.leaf()) {
        cells[n.brick].push_back(c);
        continue;
      }
      // A cell touching the plane from one side only stays on that side, whole.
      const bool left = b.lo[n.axis] < n.plane || b.hi[n.axis] <= n.plane;
      const bool right = b.hi[n.axis] > n.plane;
      if (left) stack.push_back(n.children[0]);
      if (right) stack.push_back(n.children[1]);
    }
  }
  return cells;
}

std::vector<ClipPlane> brick_planes(const KdTree& tree, int brick) {
  std::vector<ClipPlane> planes;
  for (int node = tree.leaf_of.at(brick); tree.nodes[node].parent >= 0; node = tree.nodes[node].parent) {
    const KdNode& n = tree.nodes[tree.nodes[node].parent];
    const bool left = n.children[0] == node;
    // children[0] keeps x <= plane: the normal +e points away from it (clip_mesh keeps n . (x - p) <= 0).
    glm::dvec3 point(0.0), normal(0.0);
    point[n.axis] = n.plane;
    normal[n.axis] = left ? 1.0 : -1.0;
    planes.push_back({point, normal});
  }
  return planes;
}

Mesh extract_brick(const Mesh& mesh, const KdTree& tree, int brick, const std::vector<std::int64_t>& cells,
                   ClipReport* report) {
  const MeshView view = mesh.view();
  Mesh sub;
  sub.source = mesh.source + ", brick " + std::to_string(brick);
  // The points keep their relative order: the canonical split (a hexahedron's diagonals from its
  // lowest-index vertex) is the same in the brick as in the whole mesh, and so is the field.
  std::vector<std::int64_t> new_id(static_cast<std::size_t>(mesh.n_points()), -1);
  for (std::int64_t c : cells)
    for (int k = 0; k < view.cell_size(c); ++k) new_id[view.cell(c)[k]] = 0;
  std::vector<std::int64_t> old_id;
  for (std::int64_t p = 0; p < mesh.n_points(); ++p)
    if (new_id[p] == 0) {
      new_id[p] = static_cast<std::int64_t>(old_id.size());
      old_id.push_back(p);
    }
  sub.points.reserve(old_id.size() * 3);
  for (std::int64_t p : old_id) sub.points.insert(sub.points.end(), &mesh.points[3 * p], &mesh.points[3 * p] + 3);
  for (const PointField& f : mesh.fields) sub.fields.push_back(gather(f, old_id));
  std::int64_t ids[8];  // the most points a cell type has (a hexahedron)
  for (std::int64_t c : cells) {
    for (int k = 0; k < view.cell_size(c); ++k) ids[k] = new_id[view.cell(c)[k]];
    sub.add_cell(view.type(c), ids);
  }
  ClipReport r;
  Mesh clipped = clip_mesh(sub, brick_planes(tree, brick), &r);
  clipped.source = sub.source;
  if (report) *report = r;
  return clipped;
}

std::vector<int> bricks_under(const KdTree& tree, int node) {
  std::vector<int> out;
  collect_bricks(tree, node, out);
  return out;
}

std::vector<int> rank_subtrees(const KdTree& tree, int ranks) {
  std::vector<int> roots{0};
  while (static_cast<int>(roots.size()) < ranks) {
    int best = -1;
    for (int k = 0; k < static_cast<int>(roots.size()); ++k)
      if (!tree.nodes[roots[k]].leaf() && (best < 0 || tree.nodes[roots[k]].cost > tree.nodes[roots[best]].cost))
        best = k;
    if (best < 0) break;  // every subtree is one brick: the other ranks stay idle
    const KdNode& n = tree.nodes[roots[best]];
    roots[best] = n.children[0];
    roots.insert(roots.begin() + best + 1, n.children[1]);  // left to right, as the bricks
  }
  roots.resize(static_cast<std::size_t>(ranks), -1);
  return roots;
}

}  // namespace cellproj
