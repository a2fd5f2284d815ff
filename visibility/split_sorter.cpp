#include "visibility/split_sorter.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

#include "mesh/split_topology.hpp"

namespace cellproj {

Viewpoint viewpoint(const Camera& camera, const glm::dvec3& centre) {
  const Camera c = recentred(camera, centre);
  Viewpoint v;
  v.perspective = c.projection == Projection::Perspective;
  v.eye = c.eye;
  v.dir = glm::normalize(c.target - c.eye);
  return v;
}

std::shared_ptr<SortableMesh> sortable_mesh(const MeshView& mesh, const std::vector<char>* which,
                                            std::shared_ptr<const RecentredPoints> points,
                                            std::shared_ptr<const BoundaryHull> hull, const SortableMesh* whole) {
  if (!which) whole = nullptr;  // nothing to patch
  if (whole) hull = whole->boundary_hull;
  auto s = std::make_shared<SortableMesh>();
  if (which) {
    s->split = split_cells(mesh, *which);
    s->cells = s->split.view;
  } else {
    s->cells = mesh;
  }
  s->topology = whole ? split_topology(mesh, whole->topology, s->split) : build_topology(s->cells);
  s->boundary_hull = hull ? std::move(hull) : std::make_shared<const BoundaryHull>(s->cells, s->topology);
  s->hull = boundary_convexity(s->cells, s->topology, *s->boundary_hull);
  s->sorter =
      std::make_unique<VisibilitySorter>(s->cells, s->topology, s->hull, std::move(points),
                                         whole ? whole->sorter.get() : nullptr, whole ? &s->split.parent : nullptr);
  return s;
}

SplittingSorter::SplittingSorter(const MeshView& mesh, Tetrahedralize mode)
    : mesh_(mesh), mode_(mode), points_(std::make_shared<const RecentredPoints>(recentre(mesh))) {
  const bool mixed = std::any_of(mesh.types, mesh.types + mesh.n_cells,
                                 [](std::uint8_t t) { return t != static_cast<std::uint8_t>(CellType::Tetra); });
  if (!mixed) mode_ = Tetrahedralize::none;  // nothing to split
  if (mixed && mode_ != Tetrahedralize::all) folds_ = std::make_unique<const CellFolds>(mesh, points_);
  // A mesh whose cells are never split per view (all tetrahedra, none split, or all split once)
  // sorts one prepared mesh in every view: made now, as the volume's preparation, not in the first
  // frame's sort. Per-view splits stay lazy: a single view pays for its own split only.
  if (mode_ != Tetrahedralize::problem) base_mesh();
}

const SortableMesh& SplittingSorter::base() const { return *base_mesh(); }

std::shared_ptr<const SortableMesh> SplittingSorter::base_mesh() const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!base_) {                   // made when first needed: sorted when no cell needs splitting, patched by each split
    const std::vector<char> all;  // empty: every cell that is not a tetrahedron
    base_ = sortable_mesh(mesh_, mode_ == Tetrahedralize::all ? &all : nullptr, points_, hull_);
    if (!hull_) hull_ = base_->boundary_hull;
  }
  return base_;
}

SplittingSorter::~SplittingSorter() = default;

std::shared_ptr<const SortableMesh> SplittingSorter::split_for(const std::vector<char>& problem) const {
  std::shared_ptr<const SortableMesh> whole;
  std::shared_ptr<const BoundaryHull> hull;
  bool first_split;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (last_ && last_->problem == problem) return last_;
    whole = base_, hull = hull_, first_split = !last_;
  }
  // Each split patches the unsplit mesh's topology and sorter (mesh/split_topology), made once,
  // when a second split is needed: a single view pays for its own split only, as from scratch.
  if (!whole && !first_split) whole = base_mesh();
  auto s = sortable_mesh(mesh_, &problem, points_, hull, whole.get());
  s->problem = problem;
  std::lock_guard<std::mutex> lock(mutex_);
  last_ = s;
  if (!hull_) hull_ = s->boundary_hull;
  return s;
}

ViewOrder SplittingSorter::sort(SortMethod method, const SortView& view, ViewRelations* relations) const {
  ViewOrder out;
  if (mode_ == Tetrahedralize::all) {
    out.mesh = base_mesh();
    out.sorted = out.mesh->sorter->sort(method, view, relations);
    return out;
  }
  check_camera(view.camera, "sort view");
  std::vector<char> problem = folds_
                                  ? folds_->problem_cells(viewpoint(view.camera, points_->centre), &out.problem_cells)
                                  : std::vector<char>(static_cast<std::size_t>(mesh_.n_cells), 0);
  if (mode_ == Tetrahedralize::none || out.problem_cells == 0) {
    out.mesh = base_mesh();
    // Relations only where no cell folds: whole cells a ray may cross more than twice (none mode)
    // make MPVO's order depend on which of its linear extensions is taken (and a split mesh has
    // split quads, which relate through lists).
    out.sorted = out.mesh->sorter->sort(method, view, out.problem_cells == 0 ? relations : nullptr);
  } else {
    out.mesh = split_for(problem);
    out.sorted = out.mesh->sorter->sort(method, view);
  }
  if (mode_ == Tetrahedralize::none) return out;
  // Whole cells left in a visibility cycle (warped faces can make one without folding): split them
  // too and sort again, once.
  std::int64_t more = 0;
  for (const VisibilityCycle& cycle : out.sorted.stats.cycles)
    for (const std::int64_t c : cycle.cells)
      if (out.mesh->cells.type(c) != CellType::Tetra && !problem[out.mesh->parent(c)])
        problem[out.mesh->parent(c)] = 1, ++more;
  if (more == 0) return out;
  const double first_seconds = out.sorted.stats.seconds;
  out.cycle_splits = more;
  out.mesh = split_for(problem);
  out.sorted = out.mesh->sorter->sort(method, view);
  out.sorted.stats.seconds += first_seconds;
  return out;
}

}  // namespace cellproj
