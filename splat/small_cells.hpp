#pragma once
// Which cells are small (MWSC section 6): those whose projection covers few pixel centres (cell
// projection, Williams et al.'s software scan conversion, per view) or whose volume is small
// against the slice spacing (slicing, per slice stack); and what their splats did, for --stats.
#include <cstdint>

#include "view/screen.hpp"

namespace cellproj {

// The pixel centres of a width x height image the convex hull of the cell's n projected vertices
// covers, by the coverage rule of view/raster.hpp, counted up to `limit` (a count of `limit` means
// at least that many). -1 when a vertex is at or behind the eye (or its plane: behind_eye).
int covered_pixels(const ScreenVertex* const* v, int n, int width, int height, int limit);

struct SplatCounters {
  std::int64_t small_cells = 0;         // cells the rule called small in this frame
  std::int64_t covering_no_pixel = 0;   // of the cells, those whose projection covers no pixel centre
  std::int64_t splats = 0;              // small cells drawn by a splat
  std::int64_t splat_fragments = 0;     // their pixels
  std::int64_t masked_fragments = 0;    // splat pixels the stencil held (a drawn cell, or the slice, was there)
  std::int64_t refused_degenerate = 0;  // small cells of zero volume: no splat
  std::int64_t refused_inverted = 0;    // small cells turned inside out: no splat
  std::int64_t behind_eye = 0;          // splats centred at or behind the eye
  void add(const SplatCounters& o);
};
// Each counter with its report key (render/report.hpp), in one place: f(key, value).
template <class F>
void each_counter(const SplatCounters& c, F&& f) {
  f("small_cells", c.small_cells), f("cells_covering_no_pixel", c.covering_no_pixel), f("splats", c.splats);
  f("splat_fragments", c.splat_fragments), f("splat_fragments_masked", c.masked_fragments);
  f("splats_refused_degenerate", c.refused_degenerate), f("splats_refused_inverted", c.refused_inverted);
  f("splats_behind_eye", c.behind_eye);
}

}  // namespace cellproj
