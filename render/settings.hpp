#pragma once
// What to render with: the mode (a renderer) and its settings, as named fields. Every field has
// the default a user gets from `cellproj render` without options.
#include "frame/projection_options.hpp"
#include "raycast/interpolation.hpp"
#include "raycast/iso_options.hpp"
#include "raycast/layer_options.hpp"
#include "raycast/reduction.hpp"
#include "slicing/slicing_options.hpp"
#include "view/image.hpp"
#include "visibility/methods.hpp"

namespace cellproj {

enum class RenderMode {
  projection,  // cell projection (frame/, projection/): `projection.method` picks the rung of the ladder
  exact,       // the reference ray integrator (raycast/)
  slicing,     // plane slicing (slicing/): cells cut on parallel planes, composited without a sort
  reduction,   // one value per ray (raycast/): maximum, minimum or mean intensity projection
  layers,      // the n-th crossings of an iso-value along each ray (raycast/iso_layers.hpp)
};

struct RenderSettings {
  RenderMode mode = RenderMode::projection;
  ProjectionOptions projection;                                        // method, back end, sort, gaps, table size
  Tetrahedralize tetrahedralize = Tetrahedralize::problem;             // projection: which cells are split
  CellInterpolation interpolation = CellInterpolation::isoparametric;  // exact: the field inside cells
  SlicingOptions slicing;                                              // slices, family, integral, table size
  RayReduction reduction = RayReduction::maximum;                      // reduction: which value of each ray
  LayerOptions layers;                                                 // layers: iso-value, layers, silhouettes
  IsoOptions iso;                                                      // exact: iso-surfaces with the volume
  // Anti-aliasing: each pixel the mean of ssaa x ssaa samples (a box filter), every method
  // rendering the image ssaa times larger on each side (render/renderer.cpp, Supersampled).
  int ssaa = 1;
  SampleFilter ssaa_filter = SampleFilter::box;  // how the samples become a pixel
};

struct ImageSize {
  int width = 512, height = 512;
};

}  // namespace cellproj
