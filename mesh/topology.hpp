#pragma once
// Face topology: which cells share a face (a quad matched by its four vertices, a triangle by its
// three), the boundary faces, non-planar quadrilaterals, and whether the boundary is convex.
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"

namespace cellproj {

constexpr std::int64_t kBoundary = -1;     // no cell across this face
constexpr std::int64_t kNonManifold = -2;  // more than two cells share this face
// A quadrilateral face across which a neighbour was split into tetrahedra: its two canonical
// triangles (mesh/tetrahedralize) are faces of two cells, listed in FaceTopology::split_faces.
constexpr std::int64_t kSplitFace = -3;

struct FaceTopology {
  // Cell c's faces are the "cell faces" [face_offsets[c], face_offsets[c+1]), in the order of its
  // CellDef; neighbor[cf] is the cell across cell face cf, kBoundary or kNonManifold.
  std::vector<std::int64_t> face_offsets;
  std::vector<std::int64_t> neighbor;
  std::vector<std::int64_t> boundary;  // the cell faces with no cell across them
  // Quads matched to the two triangles of their canonical split: (quad's cell face, the triangles'
  // cell faces). The triangles' neighbor is the quad's cell; the quad's is kSplitFace.
  std::vector<std::array<std::int64_t, 3>> split_faces;
  // Seams glued by glue_seams: the cell faces matched by position, not by ids (both sides listed).
  std::vector<std::int64_t> seam;
  std::int64_t seam_faces = 0;         // shared faces among those (counted once)
  std::int64_t shared_faces = 0;       // faces (counted once) between exactly two cells
  std::int64_t nonmanifold_faces = 0;  // faces (counted once) used by three or more cells
  std::int64_t first_nonmanifold_cell = -1;
  std::int64_t nonplanar_faces = 0;        // quads (counted once) warped beyond kNonPlanarRelative
  double max_nonplanarity = 0.0;           // largest distance between a quad's diagonals (world units)
  double max_relative_nonplanarity = 0.0;  // the same over the quad's mean diagonal length

  std::int64_t cell_of(std::int64_t cell_face) const;  // the cell a cell face belongs to
};

// A face's vertex ids in increasing order, what faces are matched by; a triangle's 4th is max().
using FaceKey = std::array<std::int64_t, 4>;
inline FaceKey face_key_of(const std::int64_t* ids, int n) {
  FaceKey k{0, 0, 0, std::numeric_limits<std::int64_t>::max()};
  for (int i = 0; i < n; ++i) {  // insertion sort of 3 or 4
    int j = i;
    for (; j > 0 && k[j - 1] > ids[i]; --j) k[j] = k[j - 1];
    k[j] = ids[i];
  }
  return k;
}

// A quad is non-planar when its diagonals pass further apart than this share of their length.
constexpr double kNonPlanarRelative = 1e-6;

// O(F) after a counting sort of the faces by their lowest vertex; parallel over buckets. Then
// glue_seams.
FaceTopology build_topology(const MeshView& mesh);

// Glues the seams among t's boundary faces: blocks stored with their interface points repeated
// leave pairs of boundary faces at the same place. Two boundary faces whose vertices have the same
// coordinates (bit-identical), whose cells lie on opposite sides and that no third face shares
// become a shared face; so does a quad with the two triangles of its diagonal from the lowest id.
// O(b log b) in the boundary faces; nothing changes when no two boundary points coincide.
void glue_seams(const MeshView& mesh, FaceTopology& t);

struct HullReport {
  bool convex = false;
  std::int64_t boundary_faces_off_hull = 0;  // boundary faces not on a supporting plane of the hull
  double off_hull_area_share = 0.0;
  std::vector<char> off_hull;  // per FaceTopology::boundary entry: 1 when that face is not on the hull
};

// The convex hull of a mesh's boundary points (CGAL's 3D convex hull), for telling the boundary
// faces on it from those off it. The same for a mesh and any mesh made from it by splitting cells
// (a split adds no boundary point), so it is made once per mesh.
class BoundaryHull {
 public:
  BoundaryHull(const MeshView& mesh, const FaceTopology& topo);
  bool empty() const { return vertex_.empty(); }  // no boundary, or a flat one
  // Whether the face through p[0..n) with unit normal dir lies on a supporting plane of the hull,
  // within 1e-6 of the bounding-box diagonal (thinner concavities are invisible), on either side.
  // up and down: hull vertices to start the climbs from (the last answer's, for nearby faces).
  bool supports(const glm::dvec3& dir, const glm::dvec3* p, int n, int& up, int& down) const;

 private:
  double support(const glm::dvec3& n, int& v) const;  // max n . x over the hull, climbing from vertex v
  std::vector<glm::dvec3> vertex_;
  std::vector<std::vector<int>> adjacent_;
  double tol_ = 0.0;
};

// The boundary is convex when every boundary face lies on the convex hull of the mesh (a face on
// a supporting plane of the hull).
HullReport boundary_convexity(const MeshView& mesh, const FaceTopology& topo);
HullReport boundary_convexity(const MeshView& mesh, const FaceTopology& topo, const BoundaryHull& hull);

}  // namespace cellproj
