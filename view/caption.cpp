#include "view/caption.hpp"

#include <cstdio>
#include <regex>

#include "view/color_bar.hpp"
#include "view/text.hpp"

namespace cellproj {
namespace {

// The strip's height for a picture this tall: a line of text and a margin above and below it.
int strip_height(int height) { return text_pixels(height) * 2; }

template <class Picture, class Sample>
Picture above(const Picture& picture, const Caption& caption, const std::vector<Sample>& page) {
  if (caption.empty()) return picture;
  Font font(caption.font.empty() ? default_font() : caption.font, text_pixels(picture.height));
  Picture out = grown(picture, 0, strip_height(picture.height), page);
  const int baseline = font.pixels() / 2 + font.ascender(), margin = std::max(4, picture.height / 40);
  if (!caption.label.empty()) font.draw(out, margin, baseline, caption.label, caption.text);
  if (!caption.title.empty())
    font.draw(out, std::max(0, (out.width - font.width(caption.title)) / 2), baseline, caption.title, caption.text);
  return out;
}

}  // namespace

Rgb8Image above_caption(const Rgb8Image& picture, const Caption& caption, const glm::dvec3& page) {
  return above(picture, caption, page_sample(page));
}
DisplayImage above_caption(const DisplayImage& picture, const Caption& caption, const std::optional<glm::dvec3>& page) {
  return above(picture, caption, page_sample(page));
}

std::string time_label(const std::string& format, double time) {
  // Text, %% and one double's conversion: nothing printf could read past its one argument.
  static const std::regex one_double("([^%]|%%)*%[-+ #0]*[0-9]{0,3}(\\.[0-9]{0,3})?[fFeEgG]([^%]|%%)*");
  if (!std::regex_match(format, one_double))
    throw InputError("setting 'time-format': expected text with one %f, %e or %g (e.g. \"t = %.2f s\"), got '" +
                     format + "'");
  char text[256];
  std::snprintf(text, sizeof text, format.c_str(), time);
  return text;
}

}  // namespace cellproj
