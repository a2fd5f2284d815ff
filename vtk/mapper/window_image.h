// A mapper's picture blended into the render window, pixel for pixel: each of its pixels onto the
// viewport's pixel (nearest, no resampling: vtkRayCastImageDisplayHelper insets its texture by
// half a texel, which blurs and widens the picture by a pixel), premultiplied "over" what the
// window holds, without the depth test (the picture is already cut at the opaque geometry).
#ifndef window_image_h
#define window_image_h

#include <memory>
#include <vector>

#include "view/image.hpp"
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
  // The picture (premultiplied float RGBA, row 0 at the top) as the viewport's pixels.
  void Draw(vtkRenderer* ren, const cellproj::Image& image);
  void ReleaseGraphicsResources(vtkWindow* window);

 private:
  vtkNew<vtkTextureObject> Texture;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  std::vector<unsigned short> Pixels;  // the picture in 16 bits, rows from the bottom (OpenGL's)
};

}  // namespace cellproj::vtk

#endif
