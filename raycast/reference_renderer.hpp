#pragma once
// The exact reference renderer: every pixel's ray is traced through the cells and each segment is
// integrated exactly for the piecewise-linear transfer function (optics/segment_integral.hpp),
// front to back. Every other method is measured against it.
#include <cstdint>
#include <functional>

#include "grid/mesh.hpp"
#include "optics/transfer_function.hpp"
#include "raycast/cell_ray_tracer.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"

namespace cellproj {

struct ExactStats {
  double trace_seconds = 0.0;   // traversal and integration of one frame
  std::int64_t segments = 0;    // ray-cell segments integrated
};

// Prepared once per mesh and field, then renders any number of frames. Threads: those of the task
// arena it is called from (oneTBB); the image splits into tiles among them.
class ExactRenderer {
 public:
  explicit ExactRenderer(const MeshView& mesh) : tracer_(mesh) {}
  Image render(const TransferFunction& tf, const Camera& camera, int width, int height, ExactStats* stats = nullptr,
               const std::function<void(double)>& progress = {}) const;
  const CellRayTracer& tracer() const { return tracer_; }

 private:
  CellRayTracer tracer_;
};

}  // namespace cellproj
