#pragma once
// The paper's hardware path (MWSC sections 2 and 5) through OpenGL in software (OSMesa, Mesa's
// llvmpipe), for cell projection and slicing: triangles drawn in visibility order with Gouraud colour, opacity either
// interpolated (pt-linear) or read from the 2D alpha texture at (kappa_avg, l) (pt-table), and
// blended back to front. Targets: float32, or 8-bit RGBA as the 1990s hardware had, optionally with
// alpha dithering (Williams, Frank and LaMar) so that many faint layers do not round away.
#include <memory>
#include <string>
#include <vector>

#include "composite/backend.hpp"
#include "composite/gl_corner.hpp"
#include "optics/opacity_table.hpp"
#include "view/image.hpp"

namespace cellproj {

enum class GLTarget {
  float32,         // a float RGBA framebuffer: the same picture as the software back end
  rgba8,           // 8 bits per channel: faint layers are lost to rounding
  rgba8_dithered,  // 8 bits, each fragment's value offset by a fixed pseudo-random +-1/2 step first
};

// The framebuffer of an OpenGL back end.
constexpr GLTarget gl_target(Backend backend) {
  return backend == Backend::opengl        ? GLTarget::float32
         : backend == Backend::opengl_8bit ? GLTarget::rgba8
                                           : GLTarget::rgba8_dithered;
}

// One OpenGL context (OSMesa) with its framebuffer; every call must come from the same thread.
class GLCompositor {
 public:
  // Throws ResourceError when OSMesa cannot make the context.
  GLCompositor(int width, int height, GLTarget target);
  ~GLCompositor();
  GLCompositor(const GLCompositor&) = delete;
  GLCompositor& operator=(const GLCompositor&) = delete;

  // Clears the framebuffer; `table` is the 2D alpha texture (pt-table) or null (pt-linear).
  void begin(const OpacityTable* table);
  // Draws triangles (3 corners each), in the order given.
  void draw(const std::vector<GLCorner>& corners);
  // The framebuffer as a premultiplied float image, row 0 at the top.
  Image finish();
  std::string renderer() const;  // the GL_RENDERER string

 private:
  struct Context;
  std::unique_ptr<Context> gl_;
};

}  // namespace cellproj
