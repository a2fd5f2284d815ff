#pragma once
// Internal to mesh/: matching a quad with the two triangles of its split, shared by
// build_topology (faces matched by their ids) and glue_seams (by their points' positions).
#include <cstdint>
#include <functional>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/topology.hpp"

namespace cellproj {

// Among the cell faces `open` (still kBoundary in t): a quad whose two triangles of the diagonal
// from its lowest id (split_quad, on its own ids) are, by key, open triangles of other cells, each
// the only open face with that key, is shared with both when `accept(quad, triangle)` holds for
// each (neighbor: the quad kSplitFace, the triangles the quad's cell; listed in t.split_faces).
// `same(p)` names point p as faces are matched (p itself, or the first point at its place).
// Returns how many quads were matched.
std::int64_t match_quads_to_triangles(const MeshView& m, FaceTopology& t, const std::vector<std::int64_t>& open,
                                      const std::function<std::int64_t(std::int64_t)>& same,
                                      const std::function<bool(std::int64_t, std::int64_t)>& accept);

}  // namespace cellproj
