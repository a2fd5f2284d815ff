#pragma once
// The order oracle: traces the ray through every pixel centre (the exact renderer's traversal),
// lists the cells it crosses front to back, and counts the pairs a back-to-front order puts the
// wrong way round. Segments shorter than 1e-10 of their distance from the eye are contacts at an
// edge or a vertex, not crossings, and are not counted.
#include <cstdint>
#include <vector>

#include "raycast/cell_ray_tracer.hpp"

namespace cellproj {

struct OrderCheck {
  std::int64_t violations = 0;        // pairs of cells on one ray composited in the wrong order
  std::int64_t violating_pixels = 0;  // pixels with at least one such pair
  std::int64_t missing_cells = 0;     // cells absent from the order (each one an error)
  std::int64_t repeated_cells = 0;    // cells listed more than once
  // Pixels whose ray is inside two cells at once over more than a contact (overlapping cells:
  // inverted or intersecting ones). No back-to-front order of whole cells is right there.
  std::int64_t overlapping_pixels = 0;
  std::int64_t violating_pixels_without_overlap = 0;  // where the order, not the mesh, is wrong
  std::int64_t pixels = 0, pixels_covered = 0;
  std::int64_t first_pixel_i = -1, first_pixel_j = -1;  // a violating pixel, for messages
};

// `order` lists cell ids back to front. Threads: the calling task arena's.
OrderCheck check_order(const CellRayTracer& tracer, std::int64_t n_cells, const std::vector<std::int64_t>& order,
                       const Camera& camera, int width, int height);

}  // namespace cellproj
