#include "composite/gl_compositor.hpp"

#include <random>

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include "base/error.hpp"

namespace cellproj {

namespace {
// A square RGBA float texture on the active texture unit.
void upload_texture(GLuint texture, int n, const float* rgba, GLint filter, GLint wrap) {
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, n, n, 0, GL_RGBA, GL_FLOAT, rgba);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
  glEnable(GL_TEXTURE_2D);
}
}  // namespace

struct GLCompositor::Context {
  OSMesaContext ctx = nullptr;
  int width = 0, height = 0;
  GLTarget target = GLTarget::float32;
  std::vector<float> color32;
  std::vector<unsigned char> color8;
  GLuint textures[2] = {0, 0};  // the alpha table, the dither noise

  void make_current() {
    const bool f = target == GLTarget::float32;
    if (!OSMesaMakeCurrent(ctx, f ? static_cast<void*>(color32.data()) : static_cast<void*>(color8.data()),
                           f ? GL_FLOAT : GL_UNSIGNED_BYTE, width, height))
      throw ResourceError("OSMesa: cannot bind a " + std::string(f ? "float" : "8-bit") + " framebuffer");
    OSMesaPixelStore(OSMESA_Y_UP, 0);  // row 0 at the top, as Image
  }
};

GLCompositor::GLCompositor(int width, int height, GLTarget target) : gl_(std::make_unique<Context>()) {
  gl_->width = width, gl_->height = height, gl_->target = target;
  gl_->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
  if (!gl_->ctx) throw ResourceError("OSMesa: cannot create an OpenGL context");
  if (target == GLTarget::float32)
    gl_->color32.assign(static_cast<std::size_t>(width) * height * 4, 0.0f);
  else
    gl_->color8.assign(static_cast<std::size_t>(width) * height * 4, 0);
  gl_->make_current();
  glGenTextures(2, gl_->textures);
}

GLCompositor::~GLCompositor() {
  if (gl_->ctx) OSMesaDestroyContext(gl_->ctx);
}

std::string GLCompositor::renderer() const {
  gl_->make_current();
  return reinterpret_cast<const char*>(glGetString(GL_RENDERER));
}

void GLCompositor::begin(const OpacityTable* table) {
  gl_->make_current();
  glViewport(0, 0, gl_->width, gl_->height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, gl_->width, gl_->height, 0, -1, 1);  // our pixel coordinates: x right, y down
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_DITHER);
  glShadeModel(GL_SMOOTH);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_BLEND);
  // Back-to-front "over" on premultiplied colour: pt-table's fragment is (C a, a) from the texture;
  // pt-linear's is (C, a) interpolated, premultiplied by the blend.
  if (table)
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  else
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);

  glActiveTexture(GL_TEXTURE0);
  if (table) {  // the 2D alpha texture, every channel alpha, modulating (C, 1)
    const int n = table->size();
    std::vector<float> rgba(static_cast<std::size_t>(n) * n * 4);
    for (std::size_t k = 0; k < rgba.size(); ++k) rgba[k] = table->data()[k / 4];
    upload_texture(gl_->textures[0], n, rgba.data(), GL_LINEAR, GL_CLAMP_TO_EDGE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  } else {
    glDisable(GL_TEXTURE_2D);
  }

  glActiveTexture(GL_TEXTURE1);
  if (gl_->target == GLTarget::rgba8_dithered) {
    // Williams, Frank and LaMar's fix for 8-bit targets: add noise of +-1/2 step before the
    // framebuffer rounds, so that on average faint layers add up instead of rounding to nothing.
    // A fixed noise tile (deterministic), repeated over the screen and shifted per cell (GLCorner),
    // added signed: each layer of a pixel reads another noise value, so rounding errors cancel.
    constexpr int kTile = kDitherTile;
    std::vector<float> noise(kTile * kTile * 4);
    std::mt19937 rng(20261123);
    std::uniform_real_distribution<float> u(-0.5f / 255, 0.5f / 255);
    for (float& x : noise) x = 0.5f + u(rng);
    upload_texture(gl_->textures[1], kTile, noise.data(), GL_NEAREST, GL_REPEAT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_ADD_SIGNED);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_ADD_SIGNED);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_PREVIOUS);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_TEXTURE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_PREVIOUS);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, GL_TEXTURE);
  } else {
    glDisable(GL_TEXTURE_2D);
  }
  glActiveTexture(GL_TEXTURE0);
}

void GLCompositor::draw(const std::vector<GLCorner>& corners) {
  if (corners.empty()) return;
  const GLsizei stride = sizeof(GLCorner);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, stride, &corners[0].x);
  glColorPointer(4, GL_FLOAT, stride, &corners[0].r);
  glClientActiveTexture(GL_TEXTURE0);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(2, GL_FLOAT, stride, &corners[0].u);
  glClientActiveTexture(GL_TEXTURE1);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glTexCoordPointer(2, GL_FLOAT, stride, &corners[0].nu);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(corners.size()));
}

Image GLCompositor::finish() {
  glFinish();
  Image img(gl_->width, gl_->height);
  if (gl_->target == GLTarget::float32)
    img.rgba.assign(gl_->color32.begin(), gl_->color32.end());
  else
    for (std::size_t k = 0; k < img.rgba.size(); ++k) img.rgba[k] = gl_->color8[k] / 255.0f;
  return img;
}

}  // namespace cellproj
