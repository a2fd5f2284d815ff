#pragma once
// The slices of a frame as images and their compositing (internal to slicing/): each slice's
// polygons scan converted into the scalar at the pixel centres they cover, then the slabs between
// neighbouring slices composited back to front, pixel by pixel.
#include <cstdint>
#include <limits>
#include <vector>

#include "optics/transfer_function.hpp"
#include "slicing/boundary_crossings.hpp"
#include "slicing/preintegration.hpp"
#include "slicing/slice_cut.hpp"
#include "slicing/slicing_options.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"

namespace cellproj {

constexpr float kEmpty = std::numeric_limits<float>::quiet_NaN();  // a pixel no polygon of the slice covers

// One slice scan converted: the scalar at each pixel centre it covers, and the box of those pixels.
struct SliceImage {
  std::vector<float> s;
  double height = 0.0;                 // of its plane
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // covered pixels lie in [x0, x1) x [y0, y1)
  bool covers(int i, int j) const { return i >= x0 && i < x1 && j >= y0 && j < y1; }
  float at(int i, int j, int width) const { return covers(i, j) ? s[static_cast<std::size_t>(j) * width + i] : kEmpty; }
  void clear(int width) {
    for (int j = y0; j < y1; ++j) std::fill_n(s.begin() + static_cast<std::ptrdiff_t>(j) * width + x0, x1 - x0, kEmpty);
    x0 = y0 = x1 = y1 = 0;
  }
};

// A plane's polygons: those the previous level kept, or its entries of every block of cells.
struct PlanePolygons {
  const SlicePolygons* kept = nullptr;
  const CutBlocks* blocks = nullptr;
  std::size_t index = 0;  // in each block
  template <class F>
  void for_each(F&& f) const {
    if (kept) return f(*kept);
    for (const auto& block : *blocks) f(block[index]);
  }
};

struct ScanCounts {
  std::int64_t fragments = 0, overlapping_fragments = 0, polygons = 0, clipped_polygons = 0;
};
// A plane's polygons, fanned from their first vertex, into its scalar image (the coverage rule of
// view/raster.hpp: neighbouring polygons, whose shared edges have the same bits, cover each centre
// on them once), the scalar interpolated perspective-correctly (s w / w); counted.
void scan_convert(const PlanePolygons& plane, int width, int height, SliceImage& out, ScanCounts& counts);

// The light of a constant scalar over `length`: C (1 - exp(-kappa l)), 1 - exp(-kappa l).
void constant_light(const TransferFunction& tf, double s, double length, float rgba[4]);

// What one frame composites from: the ray length between neighbouring planes at each pixel (the
// spacing over the cosine of the ray with the normal, per pixel: slanted and perspective rays cross
// farther), and the preintegrated table's layer for it.
struct PixelLengths {
  std::vector<float> length, layer;
  double lo = 0.0, hi = 0.0;
  std::int64_t along = 0;  // rays within 0.06 degrees of the planes, or turning away from the eye's side
};
PixelLengths pixel_lengths(const PixelRays& rays, const glm::dvec3& normal, double spacing);

// Composites the slabs between neighbouring planes onto the image, back to front: for the planes
// of `slices` in order, the slab behind each (between it and the one before, `behind` for the
// first), and, when `front` is a height (not NaN), the slab from the last plane to that height.
// Where both planes of a slab cover the pixel, the slab is either two half-spacing samples, each
// plane's scalar held constant (sampled), or the preintegrated segment between the two scalars.
// Where only one does, the ray crosses the boundary inside the slab: the inside part, from the
// covering plane to the boundary crossing (half the slab when none is known), with that scalar.
struct SplatLayer;
struct Compositor {
  const TransferFunction& tf;
  const SlicingOptions& options;
  const PixelLengths& lengths;
  const PreintegratedTable* table;
  const BoundaryCrossings& boundary;
  double eye_height;  // the eye's height along the normal (infinity for an orthographic axis stack)
  int width, height;

  // `splats` (empty, or one per slice, null where none): each plane's splat layer, composited over
  // the slab behind that plane.
  void operator()(Image& image, const SliceImage& behind, const std::vector<const SliceImage*>& slices,
                  const std::vector<const SplatLayer*>& splats, double front) const;

  // The slabs of pixel (i, j).
  void pixel(Image& image, int i, int j, const SliceImage& behind, const std::vector<const SliceImage*>& slices,
             const std::vector<const SplatLayer*>& splats, double front_height) const;
};

}  // namespace cellproj
