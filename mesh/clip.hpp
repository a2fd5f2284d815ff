#pragma once
// Clipping a mesh by planes, exactly: the cells wholly on the kept side stay as they are, those
// the plane cuts become the clipped pieces of their canonical tetrahedra, each piece split into
// tetrahedra by the canonical rule (so neighbours stay conforming), the point fields interpolated
// linearly along the cut edges (exact for the field linear in each tetrahedron). Every method then
// draws the clipped mesh.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"

namespace cellproj {

// Keeps the half-space n . (x - point) <= 0, the side the normal points away from (ParaView's
// Clip filter with its default Invert).
struct ClipPlane {
  glm::dvec3 point{0.0}, normal{0.0, 0.0, 1.0};
};

struct ClipReport {
  std::int64_t kept_whole = 0;  // cells wholly on the kept side of every plane
  std::int64_t dropped = 0;     // cells wholly on the other side of a plane
  std::int64_t cut = 0;         // cells a plane cut, replaced by tetrahedra
  std::int64_t tetrahedra = 0;  // the tetrahedra they became
};

// InputError "setting 'clip': ..." for a non-finite point or a zero or non-finite normal.
void check(const ClipPlane& plane);

// How each point of a clipped mesh is made from the points of the mesh clipped: its value of any
// point field is the sum of weight * value over its sources (one source of weight 1 for a point
// kept, the ends of cut edges for a new one). A time series whose points do not move is clipped
// once, and each frame's field mapped through this.
struct ClipWeights {
  std::vector<std::int64_t> start{0};  // per clipped point, its range of source and weight
  std::vector<std::int64_t> source;
  std::vector<double> weight;
  std::int64_t size() const { return static_cast<std::int64_t>(start.size()) - 1; }
  std::vector<double> apply(const std::vector<double>& field) const;  // one value per clipped point
};

// The part of `mesh` on the kept side of every plane. Points on a plane are kept; pieces of zero
// volume are dropped; points no cell uses any more are removed. `weights`, when given, receives how
// the clipped points are made from mesh's.
Mesh clip_mesh(const Mesh& mesh, const std::vector<ClipPlane>& planes, ClipReport* report = nullptr,
               ClipWeights* weights = nullptr);
// The same, InputError naming `source` when nothing of the mesh is on the kept side (a picture of
// one mesh: nothing would show).
Mesh clip_mesh_kept(const Mesh& mesh, const std::vector<ClipPlane>& planes, const std::string& source,
                    ClipReport* report = nullptr);

}  // namespace cellproj
