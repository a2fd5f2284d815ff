#pragma once
// A float RGBA image (premultiplied, without background) and its output: PNG for people, .npy for
// comparisons. Row 0 is the top row.
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "base/huge_pages.hpp"

namespace cellproj {

struct Image {
  int width = 0, height = 0;
  FrameBuffer<float> rgba;  // 4 floats per pixel, row-major from the top

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0.0f) {}
  float* pixel(int i, int j) { return rgba.data() + (static_cast<std::size_t>(j) * width + i) * 4; }
  const float* pixel(int i, int j) const { return rgba.data() + (static_cast<std::size_t>(j) * width + i) * 4; }
};

// Image rows begin <= j < end: the rows a call draws (an image tile's, or all).
struct RowRange {
  int begin = 0, end = 0;
  bool empty() const { return end <= begin; }
};

// The picture for people: 8-bit RGB, row-major from the top.
struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  // 3 bytes per pixel
  unsigned char* pixel(int i, int j) { return rgb.data() + (static_cast<std::size_t>(j) * width + i) * 3; }
};
// colour + (1 - alpha) * background, clamped to [0, 1], rounded to 8 bits.
Rgb8Image to_rgb8(const Image& image, const glm::dvec3& background);
// Throws InputError if unwritable.
void write_png(const Rgb8Image& image, const std::string& path);
inline void write_png(const Image& image, const glm::dvec3& background, const std::string& path) {
  write_png(to_rgb8(image, background), path);
}
// A picture for people before it is quantized: straight (not premultiplied) RGBA in [0, 1], row-major
// from the top; composited over a background, its alpha is 1 everywhere.
struct DisplayImage {
  int width = 0, height = 0;
  std::vector<float> rgba;  // 4 floats per pixel
  float* pixel(int i, int j) { return rgba.data() + (static_cast<std::size_t>(j) * width + i) * 4; }
  const float* pixel(int i, int j) const { return rgba.data() + (static_cast<std::size_t>(j) * width + i) * 4; }
};
// The render over `background`, or without one its colour un-premultiplied (colour / alpha where
// alpha > 0, black where nothing was drawn), for slides and compositing tools.
DisplayImage to_display(const Image& image, const std::optional<glm::dvec3>& background);
// The picture's colour multiplied by its alpha again: a figure as compositing tools take it (EXR).
Image premultiplied(const DisplayImage& picture);
// A PNG of `bits` (8 or 16) per sample: RGB when the picture is opaque everywhere, RGBA otherwise.
// Throws InputError if unwritable.
void write_png(const DisplayImage& image, int bits, const std::string& path);
// A PNG read back (8 or 16 bits, gray, RGB or RGBA; for tests and tools), samples scaled to [0, 1];
// InputError naming the file if it is not one.
DisplayImage read_png(const std::string& path, int* bits = nullptr);

// float32, shape (height, width, 4), little-endian, C order.
void write_npy(const Image& image, const std::string& path);
Image read_npy(const std::string& path);

struct ImageDifference {
  double rmse = 0.0;     // over all channels of all pixels
  double max_abs = 0.0;  // largest channel difference
};
ImageDifference compare(const Image& a, const Image& b);
// Whether every channel of every pixel is finite: what every renderer's output must be
// (CELLPROJ_DCHECK in render/renderer.cpp).
bool finite_pixels(const Image& image);
// The image box-filtered down by k in each direction: each pixel the mean of a k x k block (the
// anti-aliased reference of an image rendered at k times the resolution). Throws InputError
// unless k >= 1 divides both sides.
Image downsample(const Image& image, int k);
// How a supersampled frame becomes its pixels: the mean of each pixel's k x k samples (box), or
// the samples within a pixel of its centre weighted by a tent, 1 - |d| on each axis (d in pixels;
// smoother edges, a touch softer), renormalized at the image's border.
enum class SampleFilter { box, tent };
Image downsample(const Image& image, int k, SampleFilter filter);
// |a - b| per pixel times `scale`, clamped to 1, opaque: each colour channel shows the larger of
// its own difference and the opacity difference (for looking at where two methods disagree).
Image difference_image(const Image& a, const Image& b, double scale);

}  // namespace cellproj
