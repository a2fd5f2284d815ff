#include "slicing/slicing_options.hpp"

#include <algorithm>
#include <string>

#include "base/error.hpp"

namespace cellproj {

void check_options(const SlicingOptions& o) {
  if (o.slices < 1) throw InputError("setting 'slices' must be at least 1, not " + std::to_string(o.slices));
  if (o.table_size < 2 || o.table_size > 4096)
    throw InputError("setting 'table-size' for slicing must be in [2, 4096], not " + std::to_string(o.table_size));
  check_built(o.backend);
  if (is_opengl(o.backend) && o.integral == SliceIntegral::preintegrated)
    throw InputError(
        "the OpenGL back ends draw setting 'slice-integral' sampled (each polygon with its corners' colour and "
        "opacity); "
        "preintegrated slabs read two slices per pixel and run on setting 'backend' software");
  resolve(o.splat, o.backend);
}

int max_slices(int width, int height) { return 16 * std::max({width, height, 1}); }

void check_slices(int slices, int width, int height) {
  if (slices < 1) throw InputError("setting 'slices' must be at least 1, not " + std::to_string(slices));
  if (slices > max_slices(width, height))
    throw InputError("setting 'slices' " + std::to_string(slices) + " is more than a " + std::to_string(width) + "x" +
                     std::to_string(height) + " image can use: at most " + std::to_string(max_slices(width, height)) +
                     " (16 per pixel of its longer side; docs/methods.md, Slicing)");
}

}  // namespace cellproj
