#include <algorithm>
#include <climits>
#include <cstring>
#include <limits>
#include <unordered_map>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "base/error.hpp"
#include "base/timing.hpp"
#include "mesh/cell_type.hpp"
#include "mesh/tetrahedralize.hpp"
#include "visibility/image_faces.hpp"

namespace cellproj {
namespace {

// A face's normal (outward for the cell listing it in this order) and a point of its plane.
// Triangles take their normal from the vertices in increasing id and their centroid, so both cells
// of a face get the same plane; quads take Newell's normal through their lowest-id vertex, since
// they may be warped.
void face_plane(const VisibilitySorter::Prepared& p, const std::int64_t* ids, int n, glm::dvec3& normal,
                glm::dvec3& point) {
  glm::dvec3 x[4];
  for (int k = 0; k < n; ++k) x[k] = p.point(ids[k]);
  if (n != 3) {
    // Newell's normal of a quad is the sum of its two triangles' (either split), and the lowest id
    // lies on both triangles of the canonical split: where both triangles put the viewpoint on one
    // side, this plane does too.
    normal = newell_normal(x, n);
    point = x[std::min_element(ids, ids + n) - ids];
    return;
  }
  point = glm::dvec3(0.0);
  for (int k = 0; k < 3; ++k) point += x[k] / 3.0;
  std::int64_t s[3] = {ids[0], ids[1], ids[2]};
  const bool flip = sort_triangle_ids(s);
  normal = glm::cross(p.point(s[1]) - p.point(s[0]), p.point(s[2]) - p.point(s[0]));
  if (flip) normal = -normal;
}

// mpvo: the face relations, then the topological sort.
std::vector<std::int64_t> mpvo_order(const VisibilitySorter::Prepared& p, const ViewFrame& v, SortStats& stats,
                                     PhaseClock& clock) {
  FaceOrder faces = face_relations(p, v);
  stats.face_relations = faces.relations;
  clock.lap("face_relations");
  std::vector<std::int64_t> order = topological_order(p, v, faces, {}, stats);
  clock.lap("topological_sort");
  return order;
}

// What mpvo-abuffer reports having found the gaps with on a convex boundary, where none can be.
GapMethod gaps_on_convex(const SortView& view) {
  const GapMethod gaps_by = view.abuffer_every_pixel ? GapMethod::abuffer : view.gaps;
  return gaps_by == GapMethod::abuffer ? GapMethod::abuffer : GapMethod::overlaps;
}

// mpvo-abuffer: the face relations, and the relations across gaps from the faces' overlaps, found
// side by side (they are independent; the topological sort needs both). A view where two faces
// pass through each other, or where a visibility cycle holds a relation from the overlaps, takes
// the A-buffer's relations instead (GapMethod::automatic), over the faces already projected.
std::vector<std::int64_t> mpvo_with_gaps(const VisibilitySorter::Prepared& p, const ViewFrame& v, const SortView& view,
                                         SortStats& stats, PhaseClock& clock) {
  const GapMethod gaps_by = view.abuffer_every_pixel ? GapMethod::abuffer : view.gaps;
  if (p.boundary_tri.empty()) {  // a convex boundary: no face can bound a gap
    stats.gaps_from = gaps_on_convex(view);
    return mpvo_order(p, v, stats, clock);
  }
  FaceOrder faces;
  auto find_face_relations = [&] {
    faces = face_relations(p, v);
    stats.face_relations = faces.relations;
  };
  ProjectedFaces in_image;  // the off-hull faces as the view sees them
  if (gaps_by == GapMethod::abuffer) {
    find_face_relations();
    clock.lap("face_relations");
    in_image = project_faces(p, v, view, !view.abuffer_every_pixel);  // timed with the A-buffer
  } else {
    Relations gaps;
    double face_seconds = 0, overlap_seconds = 0;
    auto timed = [](double& seconds, auto&& work) {
      const auto t = std::chrono::steady_clock::now();
      work();
      seconds = seconds_since(t);
    };
    tbb::parallel_invoke([&] { timed(face_seconds, find_face_relations); },
                         [&] {
                           timed(overlap_seconds, [&] {
                             in_image = project_faces(p, v, view, true);
                             gaps = overlap_gap_relations(p, in_image, view, stats, gaps_by == GapMethod::automatic);
                           });
                         });
    clock.add("face_relations", face_seconds), clock.add("overlaps", overlap_seconds), clock.restart();
    // A cycle across a gap may be one that no pixel centre sees: then ask the pixel centres.
    if (gaps_by == GapMethod::overlaps || stats.gap_face_crossings == 0) {
      std::vector<std::int64_t> order = topological_order(p, v, faces, {&gaps}, stats, &gaps);
      clock.lap("topological_sort");
      stats.gaps_from = GapMethod::overlaps;
      const bool cycle_across_gap =
          std::any_of(stats.cycles.begin(), stats.cycles.end(), [](const VisibilityCycle& c) { return c.across_gap; });
      if (gaps_by == GapMethod::overlaps || !cycle_across_gap) return order;
      stats.cycles.clear();
      find_face_relations();  // the sort consumed their in-counts
      clock.lap("face_relations");
    }
  }
  const Relations gaps = gap_relations(p, in_image, view, stats);
  clock.lap("abuffer");
  std::vector<std::int64_t> order = topological_order(p, v, faces, {&gaps}, stats, &gaps);
  clock.lap("topological_sort");
  stats.gaps_from = GapMethod::abuffer;
  return order;
}

}  // namespace

VisibilitySorter::VisibilitySorter(const MeshView& mesh, const FaceTopology& topo, const HullReport& hull,
                                   std::shared_ptr<const RecentredPoints> points, const VisibilitySorter* whole,
                                   const std::vector<std::int64_t>* parent)
    : p_(std::make_unique<Prepared>()) {
  Prepared& p = *p_;
  p.mesh = mesh;
  p.topo = &topo;
  p.convex = hull.convex;
  p.points = points ? std::move(points) : std::make_shared<const RecentredPoints>(recentre(mesh));

  reserve_in_huge_pages(p.centroid, static_cast<std::size_t>(mesh.n_cells));
  p.centroid.resize(static_cast<std::size_t>(mesh.n_cells));
  const auto cells = tbb::blocked_range<std::int64_t>(0, mesh.n_cells, 4096);
  tbb::parallel_for(cells, [&](const tbb::blocked_range<std::int64_t>& r) {
    for (std::int64_t c = r.begin(); c < r.end(); ++c) {
      glm::dvec3 s(0.0);
      for (int k = 0; k < mesh.cell_size(c); ++k) s += p.point(mesh.cell(c)[k]);
      p.centroid[c] = s / double(mesh.cell_size(c));
    }
  });

  if (mesh.n_cells > INT32_MAX) throw InputError(where(mesh.source, "more than 2^31 cells: too many for one sorter"));
  const auto& fo = topo.face_offsets;
  reserve_in_huge_pages(p.across, topo.neighbor.size());
  p.across.assign(topo.neighbor.size(), -1);
  auto face_ids = [&](std::int64_t c, std::int64_t cf, std::int64_t ids[4]) {
    const FaceDef& f = cell_def(mesh.type(c)).face[cf - fo[c]];
    for (int k = 0; k < f.size; ++k) ids[k] = mesh.cell(c)[f.v[k]];
    return static_cast<int>(f.size);
  };
  // Whether cell c makes the shared face cf (each is made once: by the lower id, or from the
  // triangle's side of a split quad), and m's face back towards c (-1 for a split quad).
  auto makes = [&](std::int64_t c, std::int64_t cf, std::int64_t& back) {
    const std::int64_t m = topo.neighbor[cf];
    if (m < 0) return false;  // boundary, non-manifold, or a quad whose triangles make the relations
    back = -1;
    for (std::int64_t g = fo[m]; g < fo[m + 1]; ++g)
      if (topo.neighbor[g] == c) back = g;
    return !(back >= 0 && m < c);
  };
  // Counted per cell, then filled in parallel at each cell's offset (the same order as serially).
  std::vector<std::int64_t> first;
  reserve_in_huge_pages(first, static_cast<std::size_t>(mesh.n_cells) + 1);
  first.assign(static_cast<std::size_t>(mesh.n_cells) + 1, 0);
  tbb::parallel_for(cells, [&](const tbb::blocked_range<std::int64_t>& r) {
    for (std::int64_t c = r.begin(); c < r.end(); ++c) {
      std::int64_t back;
      for (std::int64_t cf = fo[c]; cf < fo[c + 1]; ++cf) first[c + 1] += makes(c, cf, back);
    }
  });
  for (std::int64_t c = 0; c < mesh.n_cells; ++c) first[c + 1] += first[c];
  const std::size_t n_shared = static_cast<std::size_t>(first.back());
  // A face between two cells the mesh `whole` has too (a split mesh's cells that stayed whole: the
  // same type as their parent) has the same ids, maker and points there: its plane is copied.
  auto plane_from_whole = [&](std::int64_t c, std::int64_t m, std::size_t at) {
    if (!whole) return false;
    const Prepared& w = *whole->p_;
    const std::int64_t pc = (*parent)[c], pm = (*parent)[m];
    if (w.mesh.types[pc] != mesh.types[c] || w.mesh.types[pm] != mesh.types[m]) return false;
    for (std::int64_t k = w.face_start[pc]; k < w.face_start[pc + 1]; ++k)
      if (w.face_b[k] == pm && w.local_a[k] == p.local_a[at]) {
        p.normal[at] = w.normal[k], p.offset[at] = w.offset[k];
        return true;
      }
    return false;
  };
  for (auto* a : {&p.face_a, &p.face_b}) reserve_in_huge_pages(*a, n_shared), a->resize(n_shared);
  p.local_a.resize(n_shared), p.local_b.resize(n_shared);
  reserve_in_huge_pages(p.normal, n_shared), reserve_in_huge_pages(p.offset, n_shared);
  p.normal.resize(n_shared), p.offset.resize(n_shared);
  tbb::parallel_for(cells, [&](const tbb::blocked_range<std::int64_t>& r) {
    for (std::int64_t c = r.begin(); c < r.end(); ++c) {
      std::int64_t at = first[c], back, ids[4];
      for (std::int64_t cf = fo[c]; cf < fo[c + 1]; ++cf) {
        if (!makes(c, cf, back)) continue;
        const std::int64_t m = topo.neighbor[cf];
        // back < 0: c's triangle is half of m's quad (kSplitFace), made from the triangle's side only
        p.across[cf] = static_cast<std::int32_t>(m);
        if (back >= 0) p.across[back] = static_cast<std::int32_t>(c);  // written by this face's maker only
        p.face_a[at] = static_cast<std::int32_t>(c);
        p.face_b[at] = static_cast<std::int32_t>(m);
        p.local_a[at] = static_cast<std::uint8_t>(cf - fo[c]);
        p.local_b[at] = back >= 0 ? static_cast<std::uint8_t>(back - fo[m]) : kNoLocalFace;
        if (!plane_from_whole(c, m, at)) {
          glm::dvec3 normal, point;
          face_plane(p, ids, face_ids(c, cf, ids), normal, point);
          const double len = glm::length(normal);
          if (len > 0) normal /= len;
          p.normal[at] = normal;
          p.offset[at] = glm::dot(normal, point);
        }
        ++at;
      }
    }
  });
  // Boundary faces off the convex hull: only they can bound a gap (a ray leaving through a hull
  // face never comes back), so only they go into the A-buffer.
  const bool know_hull = hull.off_hull.size() == topo.boundary.size();
  std::unordered_map<std::int64_t, std::uint32_t> local;  // a point's index in boundary_point
  auto local_id = [&](std::int64_t id) {
    const auto [it, added] = local.try_emplace(id, static_cast<std::uint32_t>(p.boundary_point.size()));
    if (added) p.boundary_point.push_back(id);
    return it->second;
  };
  for (std::size_t b = 0; b < topo.boundary.size(); ++b) {
    if (know_hull && !hull.off_hull[b]) continue;
    const std::int64_t cf = topo.boundary[b], c = topo.cell_of(cf);
    std::int64_t ids[4];
    const int n = face_ids(c, cf, ids);
    std::int64_t tri[2][3];
    if (n == 3)
      std::copy(ids, ids + 3, tri[0]);
    else
      split_quad(ids, tri);
    for (int t = 0; t < (n == 3 ? 1 : 2); ++t) {
      p.boundary_cell.push_back(c);
      p.boundary_tri.push_back({local_id(tri[t][0]), local_id(tri[t][1]), local_id(tri[t][2])});
    }
  }
  for (std::size_t f = 0; f < n_shared; ++f)
    if (p.local_b[f] == kNoLocalFace) p.split_faces.push_back(static_cast<std::int32_t>(f));
  p.face_start = std::move(first);
  p.all_tetrahedra = std::all_of(mesh.types, mesh.types + mesh.n_cells,
                                 [](std::uint8_t t) { return t == static_cast<std::uint8_t>(CellType::Tetra); });
}

bool VisibilitySorter::Prepared::face_triangle(std::size_t f, std::int64_t tri[3]) const {
  const std::int64_t c = face_a[f];
  const FaceDef& face = cell_def(mesh.type(c)).face[local_a[f]];
  if (face.size != 3) return false;
  for (int k = 0; k < 3; ++k) tri[k] = mesh.cell(c)[face.v[k]];
  if (sort_triangle_ids(tri)) std::swap(tri[1], tri[2]);  // as face_plane turns the normal
  return true;
}

VisibilitySorter::~VisibilitySorter() = default;
VisibilitySorter::VisibilitySorter(VisibilitySorter&&) noexcept = default;
std::int64_t VisibilitySorter::cells() const { return p_->mesh.n_cells; }

namespace {

// Whether the tetrahedra are Delaunay: across every shared face, the far vertex of face_b's cell
// is not inside face_a's circumsphere (on it is allowed: a box's cubes split in six). Parallel.
bool locally_delaunay(const VisibilitySorter::Prepared& p) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto point = [&](std::int64_t id) {
    const glm::dvec3 x = p.point(id);
    return K::Point_3(x.x, x.y, x.z);
  };
  const FaceDef* faces = cell_def(CellType::Tetra).face;
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, p.face_a.size(), 4096), true,
      [&](const tbb::blocked_range<std::size_t>& r, bool ok) {
        for (std::size_t f = r.begin(); ok && f < r.end(); ++f) {
          const std::int64_t *a = p.mesh.cell(p.face_a[f]), *b = p.mesh.cell(p.face_b[f]);
          const FaceDef& shared = faces[p.local_b[f]];
          const int far = 6 - shared.v[0] - shared.v[1] - shared.v[2];  // local vertices 0..3 sum to 6
          const K::Point_3 x0 = point(a[0]), x1 = point(a[1]), x2 = point(a[2]), x3 = point(a[3]);
          ok = CGAL::orientation(x0, x1, x2, x3) != CGAL::COPLANAR &&
               CGAL::side_of_bounded_sphere(x0, x1, x2, x3, point(b[far])) != CGAL::ON_BOUNDED_SIDE;
        }
        return ok;
      },
      [](bool x, bool y) { return x && y; });
}

}  // namespace

bool VisibilitySorter::acyclic() const {
  std::call_once(p_->acyclic_checked, [&] { p_->acyclic = p_->convex && p_->all_tetrahedra && locally_delaunay(*p_); });
  return p_->acyclic;
}

bool VisibilitySorter::convex_boundary() const { return p_->convex; }

ViewFrame view_frame(const VisibilitySorter::Prepared& p, const SortView& view) {
  ViewFrame v;
  v.camera = recentred(view.camera, p.points->centre);
  v.perspective = view.camera.projection == Projection::Perspective;
  v.eye = v.camera.eye;
  v.dir = glm::normalize(v.camera.target - v.camera.eye);
  v.eye_scale = glm::length(v.eye) + p.points->half_diagonal;
  return v;
}

SortResult VisibilitySorter::sort(SortMethod method, const SortView& view, ViewRelations* relations) const {
  check_camera(view.camera, "sort view");
  const auto start = std::chrono::steady_clock::now();
  const Prepared& p = *p_;
  if (method == SortMethod::automatic) method = p.convex ? SortMethod::mpvo : SortMethod::mpvo_abuffer;
  SortResult r;
  r.stats.method = method;
  PhaseClock clock(r.stats);
  const ViewFrame v = view_frame(p, view);
  // (mpvo-abuffer on a convex boundary is mpvo: mpvo_with_gaps)
  const bool faces_alone = method == SortMethod::mpvo || (method == SortMethod::mpvo_abuffer && p.boundary_tri.empty());
  if (relations && faces_alone && p.convex && p.split_faces.empty()) {
    if (method == SortMethod::mpvo_abuffer) r.stats.gaps_from = gaps_on_convex(view);
    FaceOrder faces = face_relations(p, v, true);
    r.stats.face_relations = faces.relations;
    relations->ahead = std::move(faces.ahead), relations->behind = std::move(faces.behind);
    relations->across = p.across.data(), relations->face_offsets = p.topo->face_offsets.data();
    relations->tetrahedra = p.all_tetrahedra;
    r.relations_only = true;
    clock.lap("face_relations");
    r.stats.seconds = seconds_since(start);
    return r;
  }
  switch (method) {
    case SortMethod::centroid:
      r.order = centroid_order(p, v);
      clock.lap("radix_sort");
      break;
    case SortMethod::mpvo: r.order = mpvo_order(p, v, r.stats, clock); break;
    case SortMethod::mpvo_abuffer: r.order = mpvo_with_gaps(p, v, view, r.stats, clock); break;
    case SortMethod::pairwise: {
      const Relations pairs = pairwise_relations(p, v, view, r.stats);
      clock.lap("occlusion_tests");
      FaceOrder none;
      r.order = topological_order(p, v, none, {&pairs}, r.stats);
      clock.lap("topological_sort");
      break;
    }
    case SortMethod::automatic: break;
  }
  r.stats.seconds = seconds_since(start);
  return r;
}

std::int64_t Relations::build(std::int64_t n, std::vector<std::pair<std::int64_t, std::int64_t>>& pairs) {
  // A counting sort by `from` (O(n + pairs)), then each cell's short list sorted and deduplicated.
  start.assign(static_cast<std::size_t>(n + 1), 0);
  for (const auto& e : pairs) ++start[e.first + 1];
  for (std::int64_t c = 0; c < n; ++c) start[c + 1] += start[c];
  to.resize(pairs.size());
  for (const auto& e : pairs) to[start[e.first]++] = e.second;  // start[c] ends as c's end
  std::int64_t kept = 0, begin = 0;
  for (std::int64_t c = 0; c < n; ++c) {
    const std::int64_t end = start[c];
    std::sort(to.begin() + begin, to.begin() + end);
    start[c] = kept;
    for (std::int64_t k = begin; k < end; ++k)
      if (k == begin || to[k] != to[k - 1]) to[kept++] = to[k];
    begin = end;
  }
  start[n] = kept;
  to.resize(static_cast<std::size_t>(kept));
  return kept;
}

std::vector<std::int64_t> centroid_order(const VisibilitySorter::Prepared& p, const ViewFrame& v) {
  const std::size_t n = p.centroid.size();
  // Float keys made sortable as unsigned integers, inverted so the farthest comes first.
  std::vector<std::uint32_t> key(n), key2(n), idx(n), idx2(n);
  for (std::size_t c = 0; c < n; ++c) {
    const float f = static_cast<float>(v.far_key(p.centroid[c]));
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    u = (u & 0x80000000u) ? ~u : (u | 0x80000000u);
    key[c] = ~u;
    idx[c] = static_cast<std::uint32_t>(c);
  }
  for (int shift = 0; shift < 32; shift += 11) {  // three stable passes of 11 bits
    std::uint32_t count[2049] = {};
    for (std::size_t c = 0; c < n; ++c) ++count[((key[c] >> shift) & 2047u) + 1];
    for (int b = 0; b < 2048; ++b) count[b + 1] += count[b];
    for (std::size_t c = 0; c < n; ++c) {
      const std::uint32_t at = count[(key[c] >> shift) & 2047u]++;
      key2[at] = key[c];
      idx2[at] = idx[c];
    }
    key.swap(key2);
    idx.swap(idx2);
  }
  return std::vector<std::int64_t>(idx.begin(), idx.end());
}

}  // namespace cellproj
