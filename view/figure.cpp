#include "view/figure.hpp"

#include "base/error.hpp"

namespace cellproj {

void write_figure(const Image& image, const Figure& f, const std::string& path) {
  if (f.bits != 8 && f.bits != 16)
    throw InputError("a PNG's bits must be 8 or 16 a sample, got " + std::to_string(f.bits));
  if (f.page && f.bits == 8) {  // the common picture, straight to 8 bits
    Rgb8Image picture = to_rgb8(image, *f.page);
    if (f.annotations.any()) draw_annotations(picture, f.camera, f.annotations);
    const Rgb8Image rgb = above_caption(picture, f.caption, *f.page);
    return write_png(f.legend ? beside_legend(rgb, *f.legend, *f.page) : rgb, path);
  }
  DisplayImage picture = to_display(image, f.page);
  if (f.annotations.any()) draw_annotations(picture, f.camera, f.annotations);
  const DisplayImage display = above_caption(picture, f.caption, f.page);
  write_png(f.legend ? beside_legend(display, *f.legend, f.page) : display, f.bits, path);
}

}  // namespace cellproj
