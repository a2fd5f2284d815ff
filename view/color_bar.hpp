#pragma once
// A colour legend on the picture: the transfer function's colour bar with the field's name and
// value range, its text set in a TrueType font through FreeType (Debian's fonts-dejavu-core).
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "view/image.hpp"

namespace cellproj {

// A value the picture draws in a colour of its own (an iso-surface, a layer), marked on the bar.
struct BarMark {
  double value;  // in the bar's units
  glm::dvec3 color;
};

struct ColorBar {
  std::vector<glm::dvec3> colors;  // from the low end of the range to the high end, evenly spaced
  bool gradient = true;            // the colours drawn; false: the picture has none of them (iso-surfaces alone)
  std::vector<BarMark> marks;      // swatches beside the bar at their values, labelled
  bool horizontal = false;         // beside_legend: a strip below the picture, the bar across it
  double lo = 0, hi = 1;           // the values at the ends
  bool log = false;                // lo and hi are log10 of the values: labels show 10^lo ... 10^hi
  std::string title;               // the field's name
  glm::dvec3 text{1.0};            // colour of text, ticks and outline
  std::string font;                // a .ttf/.otf file; empty: default_font()
};

// A legend's title: the field's (or the caller's) name with its unit in brackets, "T [K]"; the
// name alone without a unit.
inline std::string legend_title(const std::string& name, const std::string& unit) {
  return unit.empty() ? name : name + " [" + unit + "]";
}

// A labelled tick of the bar: where along it (0 at the low end, 1 at the high end) and its text.
struct BarTick {
  double at;
  std::string text;
};
// The ends of the range and, between them, at most `inner` values at nice steps (1, 2 or 5 times a
// power of ten; on a log bar the decades, and 2 and 5 times them where few decades fit), none
// closer to an end than `clearance` of the bar.
std::vector<BarTick> bar_ticks(const ColorBar& bar, int inner, double clearance);

// The font found when cellproj was built (DejaVu Sans), or "" when none was.
std::string default_font();
// A text colour that reads on `background`: white on dark, black on light.
glm::dvec3 text_color_for(const glm::dvec3& background);

// Draws the bar on the right of the image, 60% of its height, with the title above it and the
// low, middle and high values beside it. Throws InputError when the font cannot be loaded.
void draw_color_bar(Rgb8Image& image, const ColorBar& bar);
void draw_color_bar(DisplayImage& image, const ColorBar& bar);  // opaque over a transparent picture

// The picture widened by a strip on its right that holds the legend (or, for a horizontal bar,
// lengthened by one below it), so that the legend never covers the picture: the strip is the
// `page` colour (a DisplayImage's: clear without one).
Rgb8Image beside_legend(const Rgb8Image& picture, const ColorBar& bar, const glm::dvec3& page);
DisplayImage beside_legend(const DisplayImage& picture, const ColorBar& bar, const std::optional<glm::dvec3>& page);

}  // namespace cellproj
