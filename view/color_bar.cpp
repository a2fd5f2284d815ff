#include "view/color_bar.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <type_traits>

#include <glm/common.hpp>

#include "base/error.hpp"
#include "view/text.hpp"

namespace cellproj {
namespace {

// v to 4 significant digits, with what is below a millionth of the range's span shown as 0.
std::string label(double v, double span) {
  if (std::abs(v) < 1e-6 * std::abs(span)) v = 0.0;
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

// 1, 2 or 5 times a power of ten: the nice step nearest above `raw` (Heckbert, "Nice numbers for
// graph labels", Graphics Gems, 1990).
double nice_step(double raw) {
  const double decade = std::pow(10.0, std::floor(std::log10(raw))), f = raw / decade;
  return (f <= 1.0 ? 1.0 : f <= 2.0 ? 2.0 : f <= 5.0 ? 5.0 : 10.0) * decade;
}

}  // namespace

std::vector<BarTick> bar_ticks(const ColorBar& bar, int inner, double clearance) {
  const double span = bar.hi - bar.lo;
  const auto text = [&](double v) { return bar.log ? label(std::pow(10.0, v), 0.0) : label(v, span); };
  std::vector<BarTick> ticks{{0.0, text(bar.lo)}};
  if (!(span > 0)) return ticks;
  std::vector<double> values;  // in the bar's units (log10 of the values on a log bar)
  if (bar.log && span > 2.0) {
    const double step = std::max(1.0, std::ceil(span / std::max(1, inner)));  // every n-th decade
    for (double d = std::ceil(bar.lo / step) * step; d <= bar.hi; d += step) values.push_back(d);
  } else if (bar.log) {  // within a decade or two: 1, 2 and 5 times the decades
    for (double d = std::floor(bar.lo); d <= bar.hi; ++d)
      for (double m : {1.0, 2.0, 5.0}) values.push_back(d + std::log10(m));
  } else {
    const double step = nice_step(span / std::max(1, inner + 1));
    for (double v = std::ceil(bar.lo / step) * step; v <= bar.hi; v += step)
      values.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
  }
  for (double v : values) {
    const double at = (v - bar.lo) / span;
    if (at > clearance && at < 1.0 - clearance && static_cast<int>(ticks.size()) <= inner)
      ticks.push_back({at, text(v)});
  }
  ticks.push_back({1.0, text(bar.hi)});
  return ticks;
}

std::string default_font() {
#ifdef CELLPROJ_DEFAULT_FONT
  return CELLPROJ_DEFAULT_FONT;
#else
  return "";
#endif
}

glm::dvec3 text_color_for(const glm::dvec3& bg) {
  const double luminance = 0.2126 * bg.r + 0.7152 * bg.g + 0.0722 * bg.b;  // Rec. 709
  return glm::dvec3(luminance < 0.5 ? 1.0 : 0.0);
}

namespace {

// Where a legend's parts go in a picture `height` pixels tall: text size, labels, widths.
struct Layout {
  int pixels, margin, bar_w, gap, label_w, title_w;
  std::vector<std::string> title_lines;  // a long title's parenthesis on a line of its own
  std::vector<BarTick> ticks;            // the ends and nice values
  int width() const { return 2 * margin + std::max(bar_w + gap + label_w, title_w); }  // of a strip holding it
};
// The inner labels that would touch an end's label dropped: each label is centred on its tick and
// spans `extent` pixels along a bar `length` pixels long, and a `gap` must part two of them.
template <class Extent>
void drop_crowded(std::vector<BarTick>& ticks, double length, double gap, const Extent& extent) {
  if (ticks.size() < 3) return;
  const double lo = extent(ticks.front().text), hi = extent(ticks.back().text);
  std::vector<BarTick> kept{ticks.front()};
  for (std::size_t k = 1; k + 1 < ticks.size(); ++k) {
    const double own = extent(ticks[k].text);
    if (ticks[k].at * length >= (lo + own) / 2 + gap && (1.0 - ticks[k].at) * length >= (hi + own) / 2 + gap)
      kept.push_back(ticks[k]);
  }
  kept.push_back(ticks.back());
  ticks = std::move(kept);
}

// `length`: the bar's, in pixels; `spacing`: between labels along it, in text lines; `across`: a
// horizontal bar, whose labels stand side by side along it.
Layout layout(const ColorBar& bar, int height, Font& font, double length, double spacing, bool across = false) {
  Layout l;
  l.pixels = font.pixels();
  // As many inner ticks as fit `spacing` text lines apart, none nearer an end than a line and a half
  // (across the bar: than its label's width allows).
  l.ticks = bar_ticks(bar, std::clamp(static_cast<int>(length / (spacing * l.pixels)) - 1, 0, 8),
                      1.5 * l.pixels / std::max(1.0, length));
  if (across) drop_crowded(l.ticks, length, l.pixels / 2.0, [&](const std::string& t) { return font.width(t); });
  if (!bar.marks.empty()) {  // the marked values labelled instead of the nice ones between the ends
    l.ticks = {l.ticks.front(), l.ticks.back()};
    const double span = bar.hi - bar.lo;
    for (const BarMark& m : bar.marks)
      l.ticks.push_back({span > 0 ? std::clamp((m.value - bar.lo) / span, 0.0, 1.0) : 0.5,
                         bar.log ? label(std::pow(10.0, m.value), 0.0) : label(m.value, span)});
  }
  l.label_w = 0;
  for (const BarTick& t : l.ticks) l.label_w = std::max(l.label_w, font.width(t.text));
  l.margin = std::max(4, height / 40), l.bar_w = std::max(6, l.pixels), l.gap = std::max(3, l.pixels / 3);
  // A title much wider than the bar and its labels ("T [K] (maximum along each ray)") takes two
  // lines, broken before its parenthesis, so that the strip is not widened for it.
  l.title_lines = {bar.title};
  const std::size_t paren = bar.title.find(" (");
  if (paren != std::string::npos && font.width(bar.title) > 2 * (l.bar_w + l.gap + l.label_w))
    l.title_lines = {bar.title.substr(0, paren), bar.title.substr(paren + 1)};
  l.title_w = 0;
  for (const std::string& line : l.title_lines) l.title_w = std::max(l.title_w, font.width(line));
  return l;
}

// A one-pixel frame just outside the rectangle [x0, x1) x [y0, y1).
template <class Picture>
void outline(Picture& img, int x0, int y0, int x1, int y1, const glm::dvec3& c) {
  fill(img, x0 - 1, y0 - 1, x1 + 1, y0, c);
  fill(img, x0 - 1, y1, x1 + 1, y1 + 1, c);
  fill(img, x0 - 1, y0, x0, y1, c);
  fill(img, x1, y0, x1 + 1, y1, c);
}

template <class Picture>
void draw_bar(Picture& img, const ColorBar& bar) {
  if (bar.colors.empty()) return;
  Font font(bar.font.empty() ? default_font() : bar.font, text_pixels(img.height));
  const Layout l = layout(bar, img.height, font, 0.6 * img.height, 2.5);
  const int pixels = l.pixels, gap = l.gap;
  const int x1 = img.width - l.margin - l.label_w - gap, x0 = x1 - l.bar_w;
  const int lines = static_cast<int>(l.title_lines.size());
  const int top = l.margin + (1 + lines) * pixels, bottom = top + static_cast<int>(0.6 * img.height);
  const int n = static_cast<int>(bar.colors.size());
  for (int y = top; y < bottom && bar.gradient; ++y) {  // high values at the top
    const double t = 1.0 - (y - top + 0.5) / (bottom - top);
    fill(img, x0, y, x1, y + 1, bar.colors[std::clamp(static_cast<int>(t * n), 0, n - 1)]);
  }
  const double span = bar.hi - bar.lo;
  for (const BarMark& m : bar.marks) {  // a swatch across the bar at its value, outlined
    const double at = span > 0 ? std::clamp((m.value - bar.lo) / span, 0.0, 1.0) : 0.5;
    const int y = bottom - static_cast<int>(std::lround(at * (bottom - top))), h = std::max(2, pixels / 3);
    fill(img, x0 - 1, y - h - 1, x1 + 1, y + h + 1, bar.text);
    fill(img, x0, y - h, x1, y + h, m.color);
  }
  outline(img, x0, top, x1, bottom, bar.text);
  const int half = font.ascender() / 2;
  for (const BarTick& t : l.ticks) {
    const int y = bottom - static_cast<int>(std::lround(t.at * (bottom - top)));
    fill(img, x1, y, x1 + gap / 2 + 1, y + 1, bar.text);  // tick
    font.draw(img, x1 + gap, y + half, t.text, bar.text);
  }
  for (int k = 0; k < lines; ++k)
    font.draw(img, std::max(0, std::min(x0, img.width - l.margin - l.title_w)),
              top - pixels / 2 - 2 - (lines - 1 - k) * pixels, l.title_lines[k], bar.text);
}

// A horizontal bar across the strip of `strip` rows at the bottom of the image, 60% of the
// picture's width `width` long, low values on the left: the title above it, the labels below.
template <class Picture>
void draw_horizontal(Picture& img, const ColorBar& bar, int width, int strip) {
  Font font(bar.font.empty() ? default_font() : bar.font, text_pixels(img.height - strip));
  const int x0 = width / 5, x1 = x0 + static_cast<int>(0.6 * width);
  const Layout l = layout(bar, img.height - strip, font, x1 - x0, 6.0, /*across*/ true);
  const int pixels = l.pixels;
  const int top = img.height - strip + l.margin + pixels + pixels / 2, bottom = top + l.bar_w;
  const int n = static_cast<int>(bar.colors.size());
  for (int x = x0; x < x1 && bar.gradient; ++x)
    fill(img, x, top, x + 1, bottom,
         bar.colors[std::clamp(static_cast<int>((x - x0 + 0.5) / (x1 - x0) * n), 0, n - 1)]);
  const double span = bar.hi - bar.lo;
  for (const BarMark& m : bar.marks) {
    const int x = x0 + static_cast<int>(
                           std::lround((span > 0 ? std::clamp((m.value - bar.lo) / span, 0.0, 1.0) : 0.5) * (x1 - x0))),
              w = std::max(2, pixels / 3);
    fill(img, x - w - 1, top - 1, x + w + 1, bottom + 1, bar.text);
    fill(img, x - w, top, x + w, bottom, m.color);
  }
  outline(img, x0, top, x1, bottom, bar.text);
  for (const BarTick& t : l.ticks) {
    const int x = x0 + static_cast<int>(std::lround(t.at * (x1 - x0)));
    fill(img, x, bottom, x + 1, bottom + l.gap / 2 + 1, bar.text);  // tick
    font.draw(img, x - font.width(t.text) / 2, bottom + l.gap + font.ascender(), t.text, bar.text);
  }
  font.draw(img, x0, top - pixels / 2, bar.title, bar.text);
}

// The picture with a strip on its right (a horizontal bar: below it), `page` throughout, large
// enough for the legend, which is drawn there.
template <class Picture, class Sample>
Picture beside(const Picture& picture, const ColorBar& bar, const std::vector<Sample>& page) {
  Font font(bar.font.empty() ? default_font() : bar.font, text_pixels(picture.height));
  if (bar.horizontal) {
    const int strip = 2 * std::max(4, picture.height / 40) + 4 * font.pixels() + std::max(6, font.pixels());
    Picture out = grown(picture, 0, 0, page, strip);
    if (!bar.colors.empty()) draw_horizontal(out, bar, picture.width, strip);
    return out;
  }
  Picture out = grown(picture, layout(bar, picture.height, font, 0.6 * picture.height, 2.5).width(), 0, page);
  draw_bar(out, bar);
  return out;
}

}  // namespace

void draw_color_bar(Rgb8Image& image, const ColorBar& bar) { draw_bar(image, bar); }
void draw_color_bar(DisplayImage& image, const ColorBar& bar) { draw_bar(image, bar); }

Rgb8Image beside_legend(const Rgb8Image& picture, const ColorBar& bar, const glm::dvec3& page) {
  return beside(picture, bar, page_sample(page));
}
DisplayImage beside_legend(const DisplayImage& picture, const ColorBar& bar, const std::optional<glm::dvec3>& page) {
  return beside(picture, bar, page_sample(page));
}

}  // namespace cellproj
