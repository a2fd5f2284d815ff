// Seams: blocks of a multi-block grid written into one file with their interface points repeated
// (../shared/data: AngularSector, Blunt Fin) meet along pairs of boundary faces at the same place,
// a zero-thickness "boundary" inside the mesh. Matched by position, such a pair is one shared face:
// a ray crosses it from one cell into the other, so the order needs the face's relation, not an
// A-buffer gap, and the mesh may well be convex.
#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "mesh/face_match.hpp"
#include "mesh/geometry.hpp"
#include "mesh/topology.hpp"

namespace cellproj {
namespace {

// A boundary face that touches a point repeated elsewhere: its key over the points' first ids.
struct Open {
  FaceKey key;
  std::int64_t cf, cell;
};

}  // namespace

void glue_seams(const MeshView& m, FaceTopology& t) {
  auto ids_of = [&](std::int64_t cf, std::int64_t ids[4]) {
    const std::int64_t c = t.cell_of(cf);
    const FaceDef& face = cell_def(m.type(c)).face[cf - t.face_offsets[c]];
    for (int i = 0; i < face.size; ++i) ids[i] = m.cell(c)[face.v[i]];
    return static_cast<int>(face.size);
  };
  // The boundary's points at the same place as another: each group is named by its lowest id.
  std::vector<std::int64_t> pts;
  for (const std::int64_t cf : t.boundary) {
    std::int64_t ids[4];
    const int n = ids_of(cf, ids);
    pts.insert(pts.end(), ids, ids + n);
  }
  std::sort(pts.begin(), pts.end());  // each point once
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  const PointGroups groups = coincident_points(m, pts);
  std::unordered_map<std::int64_t, std::int64_t> first_id;  // only the points of groups of two or more
  for (std::size_t g = 0; g + 1 < groups.start.size(); ++g)
    for (std::int64_t k = groups.start[g]; k < groups.start[g + 1]; ++k)
      first_id[groups.ids[k]] = groups.ids[groups.start[g]];
  if (first_id.empty()) return;

  std::vector<Open> open;
  for (const std::int64_t cf : t.boundary) {
    std::int64_t ids[4];
    const int n = ids_of(cf, ids);
    bool repeated = false;
    for (int i = 0; i < n; ++i)
      if (const auto it = first_id.find(ids[i]); it != first_id.end()) ids[i] = it->second, repeated = true;
    if (repeated) open.push_back({face_key_of(ids, n), cf, t.cell_of(cf)});
  }
  std::sort(open.begin(), open.end(),
            [](const Open& a, const Open& b) { return std::tie(a.key, a.cf) < std::tie(b.key, b.cf); });
  auto normal = [&](std::int64_t cf) {
    std::int64_t ids[4];
    const int n = ids_of(cf, ids);
    glm::dvec3 p[4];
    for (int i = 0; i < n; ++i) p[i] = m.point(ids[i]);
    return newell_normal(p, n);
  };
  // Two faces at one place are a seam when their cells lie on opposite sides of it (overlapping
  // cells are not glued) and no third face is there too.
  auto opposite = [&](std::int64_t a, std::int64_t b) {  // cell faces
    return t.cell_of(a) != t.cell_of(b) && glm::dot(normal(a), normal(b)) < 0;
  };
  auto glue = [&](const Open& a, const Open& b) {
    t.neighbor[a.cf] = b.cell, t.neighbor[b.cf] = a.cell;
    t.seam.push_back(a.cf), t.seam.push_back(b.cf);
  };
  std::int64_t glued = 0;
  for (std::size_t s = 0, e; s < open.size(); s = e) {
    for (e = s + 1; e < open.size() && open[e].key == open[s].key;) ++e;
    if (e - s == 2 && opposite(open[s].cf, open[s + 1].cf)) glue(open[s], open[s + 1]), ++glued;
  }
  t.shared_faces += glued;
  // A quad across from two triangles (the cell there split into tetrahedra by the same diagonal).
  std::vector<std::int64_t> quad_or_tri;
  for (const Open& o : open)
    if (t.neighbor[o.cf] == kBoundary) quad_or_tri.push_back(o.cf);
  auto same = [&](std::int64_t p) {
    const auto it = first_id.find(p);
    return it == first_id.end() ? p : it->second;
  };
  const std::size_t before = t.split_faces.size();
  glued += match_quads_to_triangles(m, t, quad_or_tri, same, opposite);
  for (std::size_t k = before; k < t.split_faces.size(); ++k)
    t.seam.insert(t.seam.end(), t.split_faces[k].begin(), t.split_faces[k].end());
  t.seam_faces += glued;
  t.boundary.erase(std::remove_if(t.boundary.begin(), t.boundary.end(),
                                  [&](std::int64_t cf) { return t.neighbor[cf] != kBoundary; }),
                   t.boundary.end());
}

}  // namespace cellproj
