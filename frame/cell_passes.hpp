#pragma once
// The passes of a frame over its cells that need no visibility order (internal to
// projection_renderer.cpp): which cells are small, which image rows each reaches, how many pixels
// each box holds.
#include <cstdint>
#include <vector>

#include "base/huge_pages.hpp"
#include "mesh/mesh.hpp"
#include "splat/small_cells.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"
#include "view/screen.hpp"

namespace cellproj {

// Which cells of the frame are small: their projection covers fewer than `threshold` pixel
// centres (MWSC section 6, Williams et al.'s software scan conversion), counted in `counters`;
// with `rows`, also the rows each cell reaches (cell_rows), in the same pass over the cells'
// vertices.
std::vector<std::uint8_t> small_cells(const MeshView& cells, const ScreenPoints& screen, const PixelRays& rays,
                                      double threshold, SplatCounters& counters, FrameBuffer<RowRange>* rows);

// The rows each cell reaches (cell_rows) alone: small_cells' pass where nothing reads which cells
// are small before they are drawn (count_small_after then counts them).
void cell_reach(const MeshView& cells, const ScreenPoints& screen, const PixelRays& rays, FrameBuffer<RowRange>& rows);

// small_cells' counts for a threshold of at most one pixel centre, after the cells were drawn: a
// cell whose `drew` is set added a fragment, so covers a centre; the others are tested. (The
// fan's rule and the test's may differ on a centre on a cell's outline to rounding.)
void count_small_after(const MeshView& cells, const ScreenPoints& screen, const PixelRays& rays, double threshold,
                       const std::uint8_t* drew, SplatCounters& counters);

// Pixels under each cell's image bounding box (clamped to the image); a cell reaching behind a
// perspective eye has no image box and is ray cast over the whole image (an orthographic one only
// over its box).
std::vector<float> cell_footprints(const MeshView& cells, const ScreenPoints& screen, const PixelRays& rays);

}  // namespace cellproj
