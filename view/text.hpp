#pragma once
// What the legend and the caption share (internal to view/, not installed): a FreeType face, text
// and rectangles blended onto a picture, and a picture grown by a strip of page colour.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include <ft2build.h>
#include FT_FREETYPE_H
#include <glm/common.hpp>

#include "base/error.hpp"
#include "view/image.hpp"

namespace cellproj {

// Colour c over pixel (x, y) with coverage a: in 8 bits, or (straight alpha) in floats, where the
// pixel's opacity grows by the coverage.
inline void blend(Rgb8Image& img, int x, int y, const glm::dvec3& c, double a) {
  unsigned char* p = img.pixel(x, y);
  for (int k = 0; k < 3; ++k) p[k] = static_cast<unsigned char>(std::lround(p[k] * (1 - a) + 255 * c[k] * a));
}
inline void blend(DisplayImage& img, int x, int y, const glm::dvec3& c, double a) {
  float* p = img.pixel(x, y);
  const double alpha = a + p[3] * (1 - a);
  for (int k = 0; k < 3; ++k) p[k] = alpha > 0 ? static_cast<float>((c[k] * a + p[k] * p[3] * (1 - a)) / alpha) : 0.0f;
  p[3] = static_cast<float>(alpha);
}

// One FreeType face at one pixel size, released with it.
class Font {
 public:
  Font(const std::string& path, int pixels) {
    if (path.empty())
      throw InputError(
          "text on the picture: no font was found when cellproj was built; install fonts-dejavu-core and rebuild");
    if (FT_Init_FreeType(&library_)) throw InputError("text on the picture: FreeType could not start");
    if (FT_New_Face(library_, path.c_str(), 0, &face_)) {
      FT_Done_FreeType(library_);
      throw InputError(where(path, "FreeType cannot load this font"));
    }
    FT_Set_Pixel_Sizes(face_, 0, static_cast<FT_UInt>(pixels));
    pixels_ = pixels;
  }
  ~Font() {
    FT_Done_Face(face_);
    FT_Done_FreeType(library_);
  }
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  int pixels() const { return pixels_; }
  int ascender() const { return static_cast<int>(face_->size->metrics.ascender >> 6); }
  int width(const std::string& text) {
    int w = 0;
    for (unsigned char c : text)
      if (!FT_Load_Char(face_, c, FT_LOAD_DEFAULT)) w += static_cast<int>(face_->glyph->advance.x >> 6);
    return w;
  }
  // Blends `text` in `color` with its baseline at y, starting at x, by each glyph's coverage.
  template <class Picture>
  void draw(Picture& img, int x, int y, const std::string& text, const glm::dvec3& color) {
    for (unsigned char c : text) {
      if (FT_Load_Char(face_, c, FT_LOAD_RENDER)) continue;
      const FT_GlyphSlot g = face_->glyph;
      for (unsigned r = 0; r < g->bitmap.rows; ++r)
        for (unsigned q = 0; q < g->bitmap.width; ++q) {
          const int px = x + g->bitmap_left + static_cast<int>(q), py = y - g->bitmap_top + static_cast<int>(r);
          if (px < 0 || py < 0 || px >= img.width || py >= img.height) continue;
          blend(img, px, py, color, g->bitmap.buffer[r * g->bitmap.pitch + q] / 255.0);
        }
      x += static_cast<int>(g->advance.x >> 6);
    }
  }

 private:
  FT_Library library_ = nullptr;
  FT_Face face_ = nullptr;
  int pixels_ = 0;
};

template <class Picture>
void fill(Picture& img, int x0, int y0, int x1, int y1, const glm::dvec3& c) {
  for (int y = std::max(0, y0); y < std::min(img.height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(img.width, x1); ++x) blend(img, x, y, glm::clamp(c, 0.0, 1.0), 1.0);
}

// Text size for a picture `height` pixels tall.
inline int text_pixels(int height) { return std::clamp(height / 32, 9, 48); }

// A picture's samples, whichever kind it is.
template <class Picture>
auto& samples_of(Picture& p) {
  if constexpr (std::is_same_v<std::remove_const_t<Picture>, Rgb8Image>)
    return p.rgb;
  else
    return p.rgba;
}

// One pixel of page colour: 8-bit RGB, or straight-alpha floats (clear without a colour).
inline std::vector<unsigned char> page_sample(const glm::dvec3& page) {
  std::vector<unsigned char> p(3);
  for (int k = 0; k < 3; ++k) p[k] = static_cast<unsigned char>(std::lround(std::clamp(page[k], 0.0, 1.0) * 255));
  return p;
}
inline std::vector<float> page_sample(const std::optional<glm::dvec3>& page) {
  const glm::dvec3 c = page ? glm::clamp(*page, 0.0, 1.0) : glm::dvec3(0.0);
  return {float(c.r), float(c.g), float(c.b), page ? 1.0f : 0.0f};
}

// The picture with `right` columns on its right, `top` rows above it and `bottom` below it of
// `page` (a pixel's worth of samples).
template <class Picture, class Sample>
Picture grown(const Picture& picture, int right, int top, const std::vector<Sample>& page, int bottom = 0) {
  const std::size_t n = page.size();
  Picture out;
  out.width = picture.width + right, out.height = picture.height + top + bottom;
  auto& to = samples_of(out);
  const auto& from = samples_of(picture);
  to.resize(static_cast<std::size_t>(out.width) * out.height * n);
  for (int j = 0; j < out.height; ++j) {
    Sample* row = to.data() + static_cast<std::size_t>(j) * out.width * n;
    const int source = j - top;  // the picture's row, or none in the strips above and below it
    const bool strip = source < 0 || source >= picture.height;
    for (int i = 0; i < out.width; ++i)
      if (strip || i >= picture.width) std::copy(page.begin(), page.end(), row + i * n);
    if (!strip) std::copy_n(from.data() + static_cast<std::size_t>(source) * picture.width * n, picture.width * n, row);
  }
  return out;
}

}  // namespace cellproj
