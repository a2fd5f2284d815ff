#pragma once
// Several volumes in one picture (a scene's "volumes": a fluid and a solid, two solvers' outputs),
// possibly intersecting, each with its mesh, field, transfer function and iso-surfaces, on the exact
// renderer's rays. Per pixel the rays of every volume are merged along t, so the picture is exact
// for the model however the volumes overlap: where two or more overlap, their extinctions add and
// each emits its own kappa C (optics/segment_integral.hpp, integrate_overlap_reference); the
// iso-surfaces of all volumes are composited in the mode asked for (raycast/iso_options.hpp).
#include <cstdint>
#include <functional>
#include <vector>

#include "optics/transfer_function.hpp"
#include "raycast/cell_ray_tracer.hpp"
#include "raycast/iso_options.hpp"
#include "raycast/iso_surfaces.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"

namespace cellproj {

// One volume of a scene of several: what its mesh, field and transfer function are, and what of it
// is drawn. The pointers must outlive the render call.
struct VolumePart {
  const CellRayTracer* tracer = nullptr;
  const double* scalar = nullptr;  // one value per point of the tracer's mesh
  std::int64_t n_points = 0;
  const TransferFunction* tf = nullptr;
  std::vector<IsoSurface> surfaces;
  bool volume = true;  // the transfer function's volume, else its iso-surfaces alone
};

// The picture of the parts (premultiplied RGBA without background). Surfaces are ordered by depth
// across all parts; in blend2 they are sent part by part, each in cell order. The volume is the
// field linear in each canonical tetrahedron (as --interpolation canonical-tets).
Image render_volume_union(const std::vector<VolumePart>& parts, IsoMode mode, IsoOpacity opacity, const Camera& camera,
                          int width, int height, IsoStats* stats = nullptr,
                          const std::function<void(double)>& progress = {});

}  // namespace cellproj
