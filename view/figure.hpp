#pragma once
// A picture as a figure to publish: the image over its page colour (or transparent), a caption
// above it and the colour legend beside it, neither covering the data, written as a PNG of 8 or
// 16 bits a sample. What the command line's and Python's PNGs (and movie frames and EXRs: media/)
// are made of.
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "view/annotations.hpp"
#include "view/caption.hpp"
#include "view/color_bar.hpp"
#include "view/image.hpp"

namespace cellproj {

struct Figure {
  std::optional<glm::dvec3> page = glm::dvec3(0.0);  // the background; none: transparent (straight alpha)
  int bits = 8;                                      // 8 or 16 a sample
  Caption caption;                                   // above the picture, when not empty
  std::optional<ColorBar> legend;                    // beside it, when given
  Annotations annotations;                           // over the picture, drawn through `camera`
  Camera camera;                                     // the picture's (for the annotations)
};

// The figure's pixels in 8 bits over its page (a movie's frame; InputError for a transparent
// figure), or in float: straight alpha, opaque over a page. InputError for a font that cannot be
// loaded.
Rgb8Image figure_rgb8(const Image& image, const Figure& figure);
DisplayImage figure_pixels(const Image& image, const Figure& figure);
// InputError for bits other than 8 or 16, a font that cannot be loaded, a file that cannot be written.
void write_figure(const Image& image, const Figure& figure, const std::string& path);

}  // namespace cellproj
