#include "view/annotations.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "view/color_bar.hpp"
#include "view/text.hpp"

namespace cellproj {
namespace {

// A line from a to b (pixel coordinates), one pixel wide, each step's two nearest pixels across it
// covered by their share (Wu's antialiased line).
template <class Picture>
void line(Picture& img, glm::dvec2 a, glm::dvec2 b, const glm::dvec3& color) {
  const glm::dvec2 d = b - a;
  const int steps = static_cast<int>(std::ceil(std::max(std::abs(d.x), std::abs(d.y))));
  const bool steep = std::abs(d.y) > std::abs(d.x);
  for (int k = 0; k <= steps; ++k) {
    const glm::dvec2 p = a + d * (steps ? double(k) / steps : 0.0) - 0.5;  // pixel centres at +0.5
    const double across = steep ? p.x : p.y, f = across - std::floor(across);
    for (int side = 0; side < 2; ++side) {
      const int x = steep ? static_cast<int>(std::floor(p.x)) + side : static_cast<int>(std::lround(p.x));
      const int y = steep ? static_cast<int>(std::lround(p.y)) : static_cast<int>(std::floor(p.y)) + side;
      if (x >= 0 && y >= 0 && x < img.width && y < img.height) blend(img, x, y, color, side ? f : 1.0 - f);
    }
  }
}

template <class Picture>
void draw(Picture& img, const Camera& camera, const Annotations& a) {
  const PixelRays rays(camera, img.width, img.height);
  if (a.outline) {
    glm::dvec3 corner[8];
    for (int k = 0; k < 8; ++k) corner[k] = {k & 1 ? a.hi.x : a.lo.x, k & 2 ? a.hi.y : a.lo.y, k & 4 ? a.hi.z : a.lo.z};
    for (int k = 0; k < 8; ++k)
      for (int bit : {1, 2, 4})
        if (!(k & bit)) {  // the edge from corner k along one axis
          double ax = 0, ay = 0, az = 0, bx = 0, by = 0, bz = 0;
          rays.project(corner[k], ax, ay, az);
          rays.project(corner[k | bit], bx, by, bz);
          if (az > 0 && bz > 0) line(img, {ax, ay}, {bx, by}, a.color);  // not behind a perspective eye
        }
  }
  if (a.axes) {  // each world axis's direction in the picture at the view's target, a tenth of its height long
    Font font(a.font.empty() ? default_font() : a.font, text_pixels(img.height));
    const double length = 0.1 * img.height, margin = std::max(4, img.height / 40) + font.pixels();
    const glm::dvec2 origin{margin + length, img.height - margin - length};
    double tx = 0, ty = 0, tz = 0;
    rays.project(camera.target, tx, ty, tz);
    const double step = 0.01 * glm::length(camera.target - camera.eye);
    // The picture's length of `step` across the view: an axis along the view is foreshortened to a point.
    double rx = 0, ry = 0, rz = 0;
    rays.project(camera.target + step * glm::normalize(glm::cross(camera.target - camera.eye, camera.up)), rx, ry, rz);
    const double across = std::hypot(rx - tx, ry - ty);
    const char* names[] = {"x", "y", "z"};
    const glm::dvec3 colors[] = {{0.9, 0.2, 0.2}, {0.2, 0.8, 0.3}, {0.3, 0.5, 1.0}};
    for (int k = 0; k < 3; ++k) {
      glm::dvec3 e(0.0);
      e[k] = step;
      double x = 0, y = 0, z = 0;
      rays.project(camera.target + e, x, y, z);
      const glm::dvec2 d = glm::dvec2{x - tx, y - ty} * (across > 0 ? length / across : 0.0);
      line(img, origin, origin + d, colors[k]);
      font.draw(img, static_cast<int>(origin.x + 1.15 * d.x) - font.width(names[k]) / 2,
                static_cast<int>(origin.y + 1.15 * d.y) + font.ascender() / 2, names[k], colors[k]);
    }
  }
}

}  // namespace

void draw_annotations(Rgb8Image& picture, const Camera& camera, const Annotations& a) { draw(picture, camera, a); }
void draw_annotations(DisplayImage& picture, const Camera& camera, const Annotations& a) { draw(picture, camera, a); }

}  // namespace cellproj
