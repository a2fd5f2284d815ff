// A mapper's picture blended into the render window, pixel for pixel: each of its pixels onto the
// viewport's pixel (nearest, no resampling: vtkRayCastImageDisplayHelper insets its texture by
// half a texel, which blurs and widens the picture by a pixel), premultiplied "over" what the
// window holds, without the depth test (the picture is already cut at the opaque geometry).
#ifndef window_image_h
#define window_image_h

#include <memory>

#include "vtkNew.h"
#include "vtkTextureObject.h"

class vtkOpenGLQuadHelper;
class vtkRenderer;
class vtkWindow;

namespace cellproj::vtk {

class WindowImage {
 public:
  WindowImage();
  ~WindowImage();
  // rgba: width x height pixels of 4 premultiplied 16-bit values, rows from the bottom.
  void Draw(vtkRenderer* ren, const unsigned short* rgba, int width, int height);
  void ReleaseGraphicsResources(vtkWindow* window);

 private:
  vtkNew<vtkTextureObject> Texture;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
};

}  // namespace cellproj::vtk

#endif
