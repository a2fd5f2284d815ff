#pragma once
// The settings of plane slicing (MWSC section 5; Yagel et al. 1996): how many planes, which family,
// how the light between two planes is integrated. Light enough for render/settings.hpp to hold.
#include "composite/backend.hpp"
#include "splat/splat_options.hpp"

namespace cellproj {

enum class SliceAxis {
  automatic,  // the axis-aligned stack (x, y or z) closest to the view direction, as the paper; the
              // view family where the camera is inside the mesh's box or the image's rays are too
              // slanted to the stack (slicing/slice_planes.hpp)
  view,       // planes perpendicular to the view direction, made per view
  x,
  y,
  z,
};

enum class SliceIntegral {
  sampled,        // each plane's scalar stands for the ray between it and the next: C(s), 1 - exp(-kappa(s) l)
  preintegrated,  // the ray between two planes integrated from the scalar at both ends (a lookup table)
};

struct SlicingOptions {
  int slices = 256;  // the spacing is the mesh's extent along the planes' normal over `slices`
  SliceAxis axis = SliceAxis::automatic;
  SliceIntegral integral = SliceIntegral::preintegrated;
  int table_size = 256;  // preintegrated: nodes per scalar axis of the table
  // software, or OpenGL (sampled only): the polygons drawn with per-vertex colour and opacity into
  // a float or an 8-bit framebuffer, as the paper's hardware path.
  Backend backend = Backend::software;
  SplatOptions splat;  // cells of small volume against the spacing: splatted on their nearest plane
};

// Throws InputError for fewer than 1 slice, a table size outside [2, 4096] or an OpenGL back end with
// the preintegrated integral, naming the option; ResourceError for OpenGL in a build without it.
void check_options(const SlicingOptions& options);

// The most slices a width x height image is given (docs/methods.md says why): 16 per pixel of its
// longer side.
int max_slices(int width, int height);
// Throws InputError when `slices` is more than max_slices(width, height), saying so.
void check_slices(int slices, int width, int height);

}  // namespace cellproj
