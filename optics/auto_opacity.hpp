#pragma once
// The extinction a mesh gets before anyone chooses one (`--opacity`): named shapes over the field's
// range, and `auto`, which looks at the field and the picture first. Its shape comes from the
// field's histogram over the mesh's volume: a value that fills much of the volume (a freestream,
// a far field) is nearly transparent and extinction rises away from it on either side, so a
// feature at the low end shows as well as one at the high end. Its scale comes from the optical
// depth that shape gives the mesh seen from the default view (the extinction integrated over each
// cell, which needs no order): the scale that leaves the most of the mesh's footprint neither an
// opaque slab (alpha above 0.95) nor an invisible haze (below 0.05). It depends on the mesh and
// the field alone, not on the camera of the picture: a turntable, a camera move or an MPI rank
// sees one transfer function, and a partition index keeps it for its bricks.
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/mesh.hpp"
#include "optics/transfer_function.hpp"

namespace cellproj {

// The opacities by name, for messages: "auto, ramp, reverse, flat, sigmoid, geometric".
std::string opacity_names();

// The relative extinction (largest 1) of a named shape over [lo, hi]: ramp (0 at lo rising linearly
// to 1 at hi, as ParaView's default), reverse, flat, sigmoid (a smooth step at the middle of the
// range), geometric (rising a hundredfold over the range, for features at the high end of a field
// spanning decades). Empty for another name.
std::vector<ExtinctionPoint> opacity_shape(const std::string& name, double lo, double hi);

// `auto`'s shape for `field` (one value per point of `mesh`) over [lo, hi], and what it found.
struct AutoShape {
  std::vector<ExtinctionPoint> points;          // relative extinction, largest 1
  double background_lo = 0, background_hi = 0;  // the dominant values (background_lo > hi: none)
  double background_share = 0;                  // of the mesh's volume
};
AutoShape auto_shape(const MeshView& mesh, const double* field, double lo, double hi);

// The extinction scale (per unit of length) at which `shape` (relative, over the field's values)
// leaves the largest share of the mesh's footprint, seen orthographically from direction `from`
// (towards the eye) with `up`, with alpha in (0.05, 0.95); and that share as estimated. Falls back
// to 20 optical depths across the mesh's diagonal where the shape gives no depth at all.
struct FootprintScale {
  double kappa = 0;
  double share = 0;  // of the footprint's bins, estimated from the integrated extinction
};
FootprintScale footprint_scale(const MeshView& mesh, const double* field, const std::vector<ExtinctionPoint>& shape,
                               const glm::dvec3& from, const glm::dvec3& up);

// auto's extinction for `field` (one value per point), per unit of length: the shape over the
// field's range times the footprint's scale from `from` (view/camera.hpp's default view).
std::vector<ExtinctionPoint> auto_extinction(const MeshView& mesh, const double* field, const glm::dvec3& from,
                                             const glm::dvec3& up);

}  // namespace cellproj
