#pragma once
// The settings of splatting small cells (MWSC section 6): which cells count as small, and what is
// done with them. Light enough for the projection and slicing settings to hold.
#include <limits>

#include "composite/backend.hpp"

namespace cellproj {

enum class SmallCells {
  splat,  // small cells are drawn by their EWA splat instead of their polygons
  draw,   // every cell by its polygons, however small (the default: docs/methods.md, "Splatting small cells")
  skip,   // small cells are not drawn at all (to see what they carry)
};

struct SplatOptions {
  SmallCells small_cells = SmallCells::draw;
  // The rule's parameter; NaN: the method's default. Cell projection: a cell is small when its
  // projection covers fewer than `threshold` pixel centres. Slicing: when its volume is less than
  // `threshold` times the cube of the slice spacing.
  double threshold = std::numeric_limits<double>::quiet_NaN();
  // Standard deviation, in pixels, of the Gaussian pre-filter every footprint is convolved with
  // (Zwicker et al.'s low-pass filter): the splats' sum is anti-aliased, and sampled at pixel
  // centres it keeps the splat's total light (to 1e-4 from 0.7 pixels on).
  double prefilter = 0.7;
};

// The defaults docs/methods.md measures.
constexpr double kDefaultPixelThreshold = 1.0;   // cell projection: pixel centres covered
constexpr double kDefaultVolumeThreshold = 1.0;  // slicing: cell volume over spacing^3

// The mode that runs with `backend`, checked: throws InputError for splat or skip with an OpenGL
// back end, a negative or non-finite threshold, or a pre-filter outside [0.3, 4] pixels.
SmallCells resolve(const SplatOptions& options, Backend backend);
// The threshold that runs: the option, or the method's default.
inline double threshold_or(const SplatOptions& options, double method_default) {
  return options.threshold == options.threshold ? options.threshold : method_default;
}

}  // namespace cellproj
