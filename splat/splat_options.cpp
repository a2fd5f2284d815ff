#include "splat/splat_options.hpp"

#include <cmath>
#include <string>

#include "base/error.hpp"

namespace cellproj {

SmallCells resolve(const SplatOptions& o, Backend backend) {
  if (!std::isnan(o.threshold) && !(o.threshold >= 0.0 && std::isfinite(o.threshold)))
    throw InputError("setting 'splat-threshold' must be a finite number >= 0, not " + std::to_string(o.threshold));
  if (!(o.prefilter >= 0.3 && o.prefilter <= 4.0))
    throw InputError("the splats' pre-filter must be 0.3 to 4 pixels, not " + std::to_string(o.prefilter) +
                     " (below 0.3 the footprints alias at pixel centres)");
  if (o.small_cells != SmallCells::draw && is_opengl(backend))
    throw InputError(std::string("setting 'small-cells' ") + (o.small_cells == SmallCells::splat ? "splat" : "skip") +
                     " needs the software back end: the OpenGL back ends draw every cell (setting 'small-cells' draw)");
  return o.small_cells;
}

}  // namespace cellproj
