#include "window_image.h"

#include <algorithm>
#include <cmath>

#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

namespace cellproj::vtk {

WindowImage::WindowImage() = default;
WindowImage::~WindowImage() = default;

void WindowImage::Draw(vtkRenderer* ren, const cellproj::Image& image) {
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!window) return;
  const int width = image.width, height = image.height;
  this->Pixels.resize(4 * static_cast<std::size_t>(width) * height);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const float* p = image.pixel(i, height - 1 - j);
      unsigned short* q = &this->Pixels[4 * (static_cast<std::size_t>(j) * width + i)];
      for (int c = 0; c < 4; ++c)
        q[c] = static_cast<unsigned short>(std::lround(std::clamp(p[c], 0.0f, 1.0f) * 65535.0f));
    }
  this->Texture->SetContext(window);
  this->Texture->SetMinificationFilter(vtkTextureObject::Nearest);
  this->Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  this->Texture->Create2DFromRaw(width, height, 4, VTK_UNSIGNED_SHORT, this->Pixels.data());
  if (!this->Quad) {
    std::string fs = vtkOpenGLRenderUtilities::GetFullScreenQuadFragmentShaderTemplate();
    vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Decl", "uniform sampler2D source;");
    vtkShaderProgram::Substitute(fs, "//VTK::FSQ::Impl", "gl_FragData[0] = texture2D(source, texCoord);");
    this->Quad = std::make_unique<vtkOpenGLQuadHelper>(window, nullptr, fs.c_str(), "");
  } else {
    window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglEnableDisable depth_test(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglDepthMask depth_mask(state);
  vtkOpenGLState::ScopedglBlendFuncSeparate blend_func(state);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied "over"
  this->Texture->Activate();
  this->Quad->Program->SetUniformi("source", this->Texture->GetTextureUnit());
  this->Quad->Render();
  this->Texture->Deactivate();
}

void WindowImage::ReleaseGraphicsResources(vtkWindow* window) {
  this->Texture->ReleaseGraphicsResources(window);
  this->Quad.reset();
}

}  // namespace cellproj::vtk
