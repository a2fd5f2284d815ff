#pragma once
// The face topology of a mesh with some cells split into tetrahedra (mesh/face_split), made from
// the unsplit mesh's topology: per view only the faces of the split cells and of the cells across
// them are redone, instead of matching every face of the mesh again.
#include "mesh/face_split.hpp"
#include "mesh/topology.hpp"

namespace cellproj {

// The topology of split.view, where split = split_cells(mesh, ...) and base = build_topology(mesh):
// the same face offsets, neighbours, boundary list, split quads and counts of shared and
// non-manifold faces as build_topology(split.view) (tested); the quad statistics are base's.
// Falls back to build_topology where a split cell has a non-manifold face or a repeated vertex.
FaceTopology split_topology(const MeshView& mesh, const FaceTopology& base, const SplitMesh& split);

}  // namespace cellproj
