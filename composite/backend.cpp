#include "composite/backend.hpp"

namespace cellproj {

#ifdef CELLPROJ_HAVE_OPENGL
bool opengl_built() { return true; }
#else
bool opengl_built() { return false; }
#endif

}  // namespace cellproj
