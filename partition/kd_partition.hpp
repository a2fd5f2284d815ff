#pragma once
// Bricks for distributed rendering (MWSC section 7, SDVR): a k-d decomposition of the mesh into N
// boxes balanced by estimated rendering cost, and each brick's cells clipped to its box, so that
// the bricks are convex and disjoint and composite exactly in the k-d tree's order from the eye.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/clip.hpp"
#include "mesh/mesh.hpp"

namespace cellproj {

struct KdBox {
  glm::dvec3 lo{0.0}, hi{0.0};
};

struct KdNode {
  int axis = -1;               // 0, 1, 2; -1 for a leaf
  double plane = 0.0;          // children[0] holds x[axis] <= plane, children[1] x[axis] >= plane
  int children[2] = {-1, -1};  // node indices
  int parent = -1;             // -1 for the root
  int brick = -1;              // a leaf's brick number (0 .. bricks-1, left to right)
  KdBox box;                   // the root's is the mesh's bounds
  double cost = 0.0;           // the estimated cost of the cells whose centroid lies in it
  bool leaf() const { return axis < 0; }
};

struct KdTree {
  std::vector<KdNode> nodes;  // nodes[0] is the root
  std::vector<int> leaf_of;   // brick -> its node
  int bricks() const { return static_cast<int>(leaf_of.size()); }
};

// A cell's estimated rendering cost, in fragments: 40 per canonical tetrahedron (setting up its
// projection costs about what 40 fragments do in pt-linear) plus the fragments of its tetrahedra, their
// mean projected area in pixels when the mesh's diagonal spans `image_side` pixels (a convex body's
// mean projection over all views is a quarter of its surface: Cauchy's formula). `cells_only`: the
// canonical tetrahedra alone (a plain cell count, weighted by cell type).
std::vector<double> cell_costs(const MeshView& mesh, int image_side = 512, bool cells_only = false);

// The k-d tree of `bricks` leaves: each node splits its cells' centroids across the longest extent
// of their box, at the plane that gives each side cost in proportion to its number of leaves
// (floor(n/2) and ceil(n/2)). InputError for bricks < 1 or an empty mesh.
KdTree build_kd_tree(const MeshView& mesh, const std::vector<double>& costs, int bricks);

// For each brick, the cells that reach into its box (a cell crossing a plane is listed on both sides).
std::vector<std::vector<std::int64_t>> cells_of_bricks(const MeshView& mesh, const KdTree& tree);

// The planes that bound a brick: those of the splits on the path from the root to its leaf.
std::vector<ClipPlane> brick_planes(const KdTree& tree, int brick);

// Brick `brick`: `cells` of `mesh` (cells_of_bricks) clipped to its box (clip_mesh: a cut cell
// becomes the clipped pieces of its canonical tetrahedra, the field linear in each).
Mesh extract_brick(const Mesh& mesh, const KdTree& tree, int brick, const std::vector<std::int64_t>& cells,
                   ClipReport* report = nullptr);

// The subtrees `ranks` processes render: the tree cut into at most `ranks` subtrees by splitting the
// costliest splittable one until there are enough; entry r is rank r's subtree root, or -1 for a
// rank left idle (more ranks than bricks). A subtree's bricks are contiguous in every view order.
std::vector<int> rank_subtrees(const KdTree& tree, int ranks);
// The bricks of the subtree at `node`, left to right.
std::vector<int> bricks_under(const KdTree& tree, int node);

}  // namespace cellproj
