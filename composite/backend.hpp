#pragma once
// Where a rendering path (cell projection, slicing) rasterizes and composites: our software
// rasterizer into a float framebuffer, or OpenGL through OSMesa (composite/gl_compositor, built
// when OSMesa is found) into a float or an 8-bit framebuffer.
namespace cellproj {

enum class Backend {
  software,              // our rasterizer and a float framebuffer, every method (the default)
  opengl,                // OpenGL through OSMesa into a float framebuffer (Gouraud triangles)
  opengl_8bit,           // the same into 8-bit RGBA, as 1990s hardware
  opengl_8bit_dithered,  // 8-bit with alpha dithering (Williams, Frank and LaMar)
};
constexpr bool is_opengl(Backend backend) { return backend != Backend::software; }

// Whether this build has the OpenGL back ends (OSMesa was found when it was configured).
bool opengl_built();
// Throws ResourceError, saying why, for an OpenGL back end in a build without it.
void check_built(Backend backend);

}  // namespace cellproj
