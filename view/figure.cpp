#include "view/figure.hpp"

#include "base/error.hpp"

namespace cellproj {

Rgb8Image figure_rgb8(const Image& image, const Figure& f) {
  if (!f.page) throw InputError("an 8-bit RGB figure (a movie's frame) has no alpha: it needs a background");
  Rgb8Image picture = to_rgb8(image, *f.page);
  if (f.annotations.any()) draw_annotations(picture, f.camera, f.annotations);
  const Rgb8Image rgb = above_caption(picture, f.caption, *f.page);
  return f.legend ? beside_legend(rgb, *f.legend, *f.page) : rgb;
}

DisplayImage figure_pixels(const Image& image, const Figure& f) {
  DisplayImage picture = to_display(image, f.page);
  if (f.annotations.any()) draw_annotations(picture, f.camera, f.annotations);
  const DisplayImage display = above_caption(picture, f.caption, f.page);
  return f.legend ? beside_legend(display, *f.legend, f.page) : display;
}

void write_figure(const Image& image, const Figure& f, const std::string& path) {
  if (f.bits != 8 && f.bits != 16)
    throw InputError("a PNG's bits must be 8 or 16 a sample, got " + std::to_string(f.bits));
  if (f.page && f.bits == 8) return write_png(figure_rgb8(image, f), path);  // the common picture, straight to 8 bits
  write_png(figure_pixels(image, f), f.bits, path);
}

}  // namespace cellproj
