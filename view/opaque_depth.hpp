#pragma once
// Opaque geometry a volume is drawn among, given as a depth buffer (a render window's): a ray is
// integrated only up to the nearest opaque surface, its last segment cut there, as the segments of
// a cell reaching behind the eye are cut at the eye. Exact for the model: the surface hides what
// lies behind it, and the volume in front of it is composited over it by the caller.
#include <cstddef>
#include <string>
#include <vector>

namespace cellproj {

struct OpaqueDepth {
  int width = 0, height = 0;
  // Per pixel (row 0 at the top, as Image): the view depth of the nearest opaque surface (camera.hpp's
  // z: along the view direction from the eye, or from the eye's plane in orthographic projection);
  // +infinity where there is none.
  std::vector<float> z;
  float at(int i, int j) const { return z[static_cast<std::size_t>(j) * static_cast<std::size_t>(width) + i]; }
};

// InputError (prefixed with `source`) unless `depth` is width x height and every value is positive
// or +infinity (NaN, zero and negative depths refused, naming the first such pixel).
void check_opaque_depth(const OpaqueDepth& depth, int width, int height, const std::string& source);

}  // namespace cellproj
