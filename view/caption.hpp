#pragma once
// Text above the picture, in a strip of its own so that it never covers the data: a title
// centred, and a label at the left (a time series' time, "t = 1.50").
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "view/image.hpp"

namespace cellproj {

struct Caption {
  std::string title;     // centred; "" for none
  std::string label;     // at the left; "" for none
  glm::dvec3 text{1.0};  // text colour (view/color_bar.hpp: text_color_for)
  std::string font;      // a .ttf/.otf file; empty: default_font()
  bool empty() const { return title.empty() && label.empty(); }
};

// The picture grown by a strip above it, the `page` colour (a DisplayImage's: clear without one),
// holding the caption. InputError when the font cannot be loaded.
Rgb8Image above_caption(const Rgb8Image& picture, const Caption& caption, const glm::dvec3& page);
DisplayImage above_caption(const DisplayImage& picture, const Caption& caption, const std::optional<glm::dvec3>& page);

// `format` (printf's, with exactly one conversion of a double: %f, %e or %g with flags, width and
// precision, and %% for a percent sign) applied to `time`; InputError naming setting 'time-format'
// for any other format.
std::string time_label(const std::string& format, double time);

}  // namespace cellproj
