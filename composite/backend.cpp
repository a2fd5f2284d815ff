#include "composite/backend.hpp"

#include "base/error.hpp"

namespace cellproj {

#ifdef CELLPROJ_HAVE_OPENGL
bool opengl_built() { return true; }
#else
bool opengl_built() { return false; }
#endif

void check_built(Backend backend) {
  if (is_opengl(backend) && !opengl_built())
    throw ResourceError(
        "the OpenGL back ends were not built (OSMesa, libosmesa6-dev, was not found when cellproj was "
        "configured); use the software back end");
}

}  // namespace cellproj
