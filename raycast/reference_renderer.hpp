#pragma once
// The exact reference renderer: every pixel's ray is traced through the cells and each segment is
// integrated exactly for the piecewise-linear transfer function (optics/segment_integral.hpp),
// front to back. Every other method is measured against it.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "mesh/cell_order.hpp"
#include "mesh/mesh.hpp"
#include "optics/transfer_function.hpp"
#include "raycast/cell_ray_tracer.hpp"
#include "raycast/interpolation.hpp"
#include "raycast/isoparametric.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"
#include "view/opaque_depth.hpp"

namespace cellproj {

struct ExactStats {
  double trace_seconds = 0.0;        // traversal and integration of one frame
  std::int64_t segments = 0;         // ray-tetrahedron segments integrated
  std::int64_t newton_failures = 0;  // isoparametric points that fell back to the linear value
};
// Each counter the report shows, with its key (render/report.hpp): f(key, value).
template <class F>
void each_counter(const ExactStats& s, F&& f) {
  f("segments", s.segments), f("newton_failures", s.newton_failures);
}

// Prepared once per mesh (its canonical tetrahedra and, for the other cells, their shape; the
// cells renumbered along a Z-order curve where the mesh's numbering scatters them, LocalCells),
// then renders any number of frames of any point field. Threads: those of the task arena it is called
// from (oneTBB); the image splits into tiles among them.
class ExactRenderer {
 public:
  explicit ExactRenderer(const MeshView& mesh);
  // One frame of the point field `scalar` (n_points values). With `opacity` (n_points values) the
  // colour comes from `scalar` and the extinction from `opacity` (optics/two_fields.hpp), both
  // linear over the canonical tetrahedra whatever `interpolation` says.
  Image render(const double* scalar, const TransferFunction& tf, const Camera& camera, int width, int height,
               CellInterpolation interpolation = CellInterpolation::isoparametric, ExactStats* stats = nullptr,
               const std::function<void(double)>& progress = {}, const double* opacity = nullptr,
               const OpaqueDepth* opaque = nullptr) const;
  const CellRayTracer& tracer() const { return tracer_; }  // (over local_cells(): cell ids are its)
  const LocalCells& local_cells() const { return local_; }

 private:
  LocalCells local_;  // the cells the tracer holds, renumbered or as given
  CellRayTracer tracer_;
  std::int64_t n_points_ = 0;
  std::unique_ptr<IsoparametricField> iso_;  // null when every cell is a tetrahedron
};

}  // namespace cellproj
