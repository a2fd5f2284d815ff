#pragma once
// The choices of the visibility stage, as small enums a settings struct can hold without pulling
// in the sorters (their names: scene/names.hpp).
#include <cstdint>

namespace cellproj {

enum class SortMethod {
  centroid,      // by centroid depth, a radix sort: what common tools do; the baseline
  mpvo,          // Williams' MPVO: a relation across every shared face, then a topological sort
  mpvo_abuffer,  // MPVO plus the relations across the gaps of a non-convex mesh (software A-buffer)
  pairwise,      // Newell-Newell-Sancha for polyhedra: exact occlusion tests between all overlapping cells
  automatic,     // mpvo on a convex boundary, mpvo-abuffer otherwise
};

// How mpvo-abuffer finds the relations across gaps.
enum class GapMethod : std::uint8_t {
  automatic,  // overlaps; the A-buffer for a view where a visibility cycle holds a relation from them,
              // or where two of the faces pass through each other (which makes such a cycle)
  overlaps,   // from the boundary faces' overlaps in the image, per pair of faces (visibility/overlap_gaps.cpp)
  abuffer,    // from the software A-buffer at the pixel centres (visibility/abuffer.cpp)
};

// Which cells other than tetrahedra are split into their canonical tetrahedra before sorting.
enum class Tetrahedralize {
  problem,  // per view, only the cells a ray may cross more than twice (mesh/face_split; the default)
  all,      // every cell that is not a tetrahedron, once per mesh
  none,     // never: whole cells even where a ray crosses one twice (order and picture may be wrong there)
};

}  // namespace cellproj
