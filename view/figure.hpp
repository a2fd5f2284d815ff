#pragma once
// A picture as a figure to publish: the image over its page colour (or transparent), a caption
// above it and the colour legend beside it, neither covering the data, written as a PNG of 8 or
// 16 bits a sample. What the command line's and Python's PNGs are made of.
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

// InputError for bits other than 8 or 16, a font that cannot be loaded, a file that cannot be written.
void write_figure(const Image& image, const Figure& figure, const std::string& path);

}  // namespace cellproj
