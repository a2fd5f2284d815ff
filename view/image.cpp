#include "view/image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>

#include <png.h>

#include "base/error.hpp"

namespace cellproj {

Rgb8Image to_rgb8(const Image& img, const glm::dvec3& bg) {
  Rgb8Image out{img.width, img.height,
                std::vector<unsigned char>(static_cast<std::size_t>(img.width) * img.height * 3)};
  for (std::size_t p = 0; p < out.rgb.size() / 3; ++p) {
    const float* c = img.rgba.data() + 4 * p;
    for (int k = 0; k < 3; ++k) {
      const double v = std::clamp(c[k] + (1.0 - c[3]) * bg[k], 0.0, 1.0);
      out.rgb[3 * p + k] = static_cast<unsigned char>(std::lround(v * 255.0));
    }
  }
  return out;
}

void write_png(const Rgb8Image& img, const std::string& path) {
  DisplayImage display{img.width, img.height, std::vector<float>(static_cast<std::size_t>(img.width) * img.height * 4)};
  for (std::size_t p = 0; p < display.rgba.size() / 4; ++p) {
    for (int k = 0; k < 3; ++k) display.rgba[4 * p + k] = img.rgb[3 * p + k] / 255.0f;  // back to the same bytes
    display.rgba[4 * p + 3] = 1.0f;
  }
  write_png(display, 8, path);
}

DisplayImage to_display(const Image& img, const std::optional<glm::dvec3>& bg) {
  DisplayImage out{img.width, img.height, std::vector<float>(img.rgba.size())};
  for (std::size_t p = 0; p < out.rgba.size() / 4; ++p) {
    const float* c = img.rgba.data() + 4 * p;
    float* o = out.rgba.data() + 4 * p;
    const double a = std::clamp(static_cast<double>(c[3]), 0.0, 1.0);
    for (int k = 0; k < 3; ++k)
      o[k] = static_cast<float>(std::clamp(bg ? c[k] + (1.0 - a) * (*bg)[k] : a > 0.0 ? c[k] / a : 0.0, 0.0, 1.0));
    o[3] = bg ? 1.0f : static_cast<float>(a);
  }
  return out;
}

Image premultiplied(const DisplayImage& picture) {
  Image out(picture.width, picture.height);
  for (std::size_t p = 0; p < picture.rgba.size(); p += 4) {
    const float a = picture.rgba[p + 3];
    for (int k = 0; k < 3; ++k) out.rgba[p + k] = picture.rgba[p + k] * a;
    out.rgba[p + 3] = a;
  }
  return out;
}

namespace {

// libpng's writer or reader on `path`, opened, with its errors as InputErrors naming the file.
// (The caller sets libpng's error return, setjmp, in its own frame.)
struct PngFile {
  PngFile(const std::string& path, bool write) : writing(write) {
    file.reset(std::fopen(path.c_str(), write ? "wb" : "rb"));
    if (!file) throw InputError(where(path, write ? "cannot open for writing" : "cannot open"));
    png = write ? png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr)
                : png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
      release();  // no destructor runs for a constructor that throws
      throw InputError(where(path, "libpng could not start"));
    }
    png_init_io(png, file.get());
  }
  ~PngFile() { release(); }
  void release() {
    if (writing)
      png_destroy_write_struct(&png, &info);
    else
      png_destroy_read_struct(&png, &info, nullptr);
  }
  PngFile(const PngFile&) = delete;
  PngFile& operator=(const PngFile&) = delete;
  std::unique_ptr<FILE, int (*)(FILE*)> file{nullptr, &std::fclose};
  png_structp png = nullptr;
  png_infop info = nullptr;
  bool writing;
};

}  // namespace

void write_png(const DisplayImage& img, int bits, const std::string& path) {
  if (bits != 8 && bits != 16)
    throw InputError(where(path, "a PNG has 8 or 16 bits a sample, not " + std::to_string(bits)));
  bool opaque = true;
  for (std::size_t a = 3; a < img.rgba.size() && opaque; a += 4) opaque = img.rgba[a] == 1.0f;
  const int channels = opaque ? 3 : 4, bytes = bits / 8, max = (1 << bits) - 1;
  std::vector<unsigned char> row(static_cast<std::size_t>(img.width) * channels * bytes);
  PngFile f(path, true);
  if (setjmp(png_jmpbuf(f.png))) throw InputError(where(path, "libpng failed while writing"));
  png_set_IHDR(f.png, f.info, img.width, img.height, bits, opaque ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGBA,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(f.png, f.info);
  for (int j = 0; j < img.height; ++j) {
    for (int i = 0; i < img.width; ++i)
      for (int k = 0; k < channels; ++k) {
        const long v = std::lround(std::clamp(static_cast<double>(img.pixel(i, j)[k]), 0.0, 1.0) * max);
        unsigned char* out = row.data() + (static_cast<std::size_t>(i) * channels + k) * bytes;
        if (bytes == 2)
          out[0] = static_cast<unsigned char>(v >> 8), out[1] = static_cast<unsigned char>(v & 0xff);
        else
          out[0] = static_cast<unsigned char>(v);  // PNG's samples are big-endian
      }
    png_write_row(f.png, row.data());
  }
  png_write_end(f.png, nullptr);
}

DisplayImage read_png(const std::string& path, int* bits) {
  PngFile f(path, false);
  if (setjmp(png_jmpbuf(f.png))) throw InputError(where(path, "not a PNG libpng can read"));
  png_read_info(f.png, f.info);
  png_set_expand(f.png);  // palettes and low-bit gray to 8 bits, tRNS to alpha
  png_set_gray_to_rgb(f.png);
  png_set_add_alpha(f.png, 0xffff, PNG_FILLER_AFTER);
  png_read_update_info(f.png, f.info);
  const int depth = png_get_bit_depth(f.png, f.info), bytes = depth / 8;
  if (bits) *bits = depth;
  const int width = static_cast<int>(png_get_image_width(f.png, f.info)),
            height = static_cast<int>(png_get_image_height(f.png, f.info));
  if (width < 1 || height < 1 || width > 65536 || height > 65536 || (depth != 8 && depth != 16))
    throw InputError(where(path, "a PNG of an unexpected size or depth"));
  DisplayImage out{width, height, std::vector<float>(static_cast<std::size_t>(width) * height * 4)};
  std::vector<unsigned char> row(png_get_rowbytes(f.png, f.info));
  const double max = (1 << depth) - 1;
  for (int j = 0; j < height; ++j) {
    png_read_row(f.png, row.data(), nullptr);
    for (int i = 0; i < width * 4; ++i) {
      const unsigned char* v = row.data() + static_cast<std::size_t>(i) * bytes;
      out.rgba[static_cast<std::size_t>(j) * width * 4 + i] =
          static_cast<float>((bytes == 2 ? (v[0] << 8 | v[1]) : v[0]) / max);
    }
  }
  return out;
}

void write_npy(const Image& img, const std::string& path) {
  std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (" + std::to_string(img.height) + ", " +
                       std::to_string(img.width) + ", 4), }";
  const std::size_t total = 10 + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header.push_back('\n');
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError(where(path, "cannot open for writing"));
  const unsigned char magic[8] = {0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0};
  out.write(reinterpret_cast<const char*>(magic), 8);
  const std::uint16_t len = static_cast<std::uint16_t>(header.size());
  const unsigned char len_le[2] = {static_cast<unsigned char>(len & 0xff), static_cast<unsigned char>(len >> 8)};
  out.write(reinterpret_cast<const char*>(len_le), 2);
  out << header;
  out.write(reinterpret_cast<const char*>(img.rgba.data()),
            static_cast<std::streamsize>(img.rgba.size() * sizeof(float)));
  if (!out) throw InputError(where(path, "write failed"));
}

Image read_npy(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(where(path, "cannot open"));
  char magic[10];
  if (!in.read(magic, 10) || std::memcmp(magic, "\x93NUMPY", 6) != 0) throw InputError(where(path, "not a .npy file"));
  const std::size_t len = static_cast<unsigned char>(magic[8]) | (static_cast<unsigned char>(magic[9]) << 8);
  std::string header(len, '\0');
  in.read(header.data(), static_cast<std::streamsize>(len));
  if (header.find("'<f4'") == std::string::npos || header.find("False") == std::string::npos)
    throw InputError(where(path, "expected little-endian float32 in C order"));
  int h = 0, w = 0, c = 0;
  const auto at = header.find("'shape': (");
  if (at == std::string::npos || std::sscanf(header.c_str() + at + 10, "%d, %d, %d", &h, &w, &c) != 3 || c != 4)
    throw InputError(where(path, "expected shape (height, width, 4)"));
  Image img(w, h);
  if (!in.read(reinterpret_cast<char*>(img.rgba.data()), static_cast<std::streamsize>(img.rgba.size() * sizeof(float))))
    throw InputError(where(path, "truncated image data"));
  return img;
}

namespace {
void check_same_size(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw InputError("cannot compare images of different sizes: " + std::to_string(a.width) + "x" +
                     std::to_string(a.height) + " and " + std::to_string(b.width) + "x" + std::to_string(b.height));
}
}  // namespace

Image difference_image(const Image& a, const Image& b, double scale) {
  check_same_size(a, b);
  Image d(a.width, a.height);
  for (std::size_t p = 0; p < a.rgba.size(); p += 4) {
    for (int c = 0; c < 3; ++c)  // colour differences, plus the opacity difference in every channel
      d.rgba[p + c] =
          static_cast<float>(std::min(1.0, scale * std::max(std::abs(double(a.rgba[p + c]) - b.rgba[p + c]),
                                                            std::abs(double(a.rgba[p + 3]) - b.rgba[p + 3]))));
    d.rgba[p + 3] = 1.0f;
  }
  return d;
}

bool finite_pixels(const Image& image) {
  return std::all_of(image.rgba.begin(), image.rgba.end(), [](float v) { return std::isfinite(v); });
}

ImageDifference compare(const Image& a, const Image& b) {
  check_same_size(a, b);
  ImageDifference d;
  double sum = 0.0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) {
    const double e = std::abs(double(a.rgba[i]) - double(b.rgba[i]));
    sum += e * e;
    d.max_abs = std::max(d.max_abs, e);
  }
  d.rmse = a.rgba.empty() ? 0.0 : std::sqrt(sum / a.rgba.size());
  return d;
}

namespace {

// InputError unless k divides the image's sides.
void check_factor(const Image& image, int k) {
  if (k < 1 || image.width % k != 0 || image.height % k != 0)
    throw InputError("downsample: " + std::to_string(k) + " does not divide the image's " +
                     std::to_string(image.width) + "x" + std::to_string(image.height));
}

// One axis of a separable filter: per pixel, its samples along the axis and their weights.
using AxisWeights = std::vector<std::vector<std::pair<int, double>>>;

// The tent's: sample s weighs 1 - d for pixel i, d the distance of their centres in pixels (< 1),
// renormalized where the image's border cuts the tent.
AxisWeights tent_weights(int samples, int k) {
  AxisWeights w(static_cast<std::size_t>(samples / k));
  for (int i = 0; i < samples / k; ++i) {
    double sum = 0;
    for (int s = std::max(0, (i - 1) * k); s < std::min(samples, (i + 2) * k); ++s) {
      const double d = std::abs((s + 0.5) / k - (i + 0.5));
      if (d < 1.0) w[i].push_back({s, 1.0 - d}), sum += 1.0 - d;
    }
    for (auto& [s, v] : w[i]) v /= sum;
  }
  return w;
}

// `image` filtered along x (or y) by `w`: as many columns (rows) as `w` has pixels.
Image filter_axis(const Image& image, const AxisWeights& w, bool along_x) {
  const int n = static_cast<int>(w.size());
  Image out(along_x ? n : image.width, along_x ? image.height : n);
  for (int j = 0; j < out.height; ++j)
    for (int i = 0; i < out.width; ++i) {
      double sum[4] = {0, 0, 0, 0};
      for (const auto& [s, v] : w[along_x ? i : j]) {
        const float* p = along_x ? image.pixel(s, j) : image.pixel(i, s);
        for (int c = 0; c < 4; ++c) sum[c] += v * p[c];
      }
      for (int c = 0; c < 4; ++c) out.pixel(i, j)[c] = static_cast<float>(sum[c]);
    }
  return out;
}

}  // namespace

Image downsample(const Image& image, int k) {
  check_factor(image, k);
  Image out(image.width / k, image.height / k);
  const double inv = 1.0 / (double(k) * k);
  for (int j = 0; j < out.height; ++j)
    for (int i = 0; i < out.width; ++i) {
      double sum[4] = {0, 0, 0, 0};
      for (int b = 0; b < k; ++b)
        for (int a = 0; a < k; ++a) {
          const float* p = image.pixel(i * k + a, j * k + b);
          for (int c = 0; c < 4; ++c) sum[c] += p[c];
        }
      float* q = out.pixel(i, j);
      for (int c = 0; c < 4; ++c) q[c] = static_cast<float>(sum[c] * inv);
    }
  return out;
}

Image downsample(const Image& image, int k, SampleFilter filter) {
  if (filter == SampleFilter::box || k == 1) return downsample(image, k);
  check_factor(image, k);
  const Image rows = filter_axis(image, tent_weights(image.width, k), true);
  return filter_axis(rows, tent_weights(image.height, k), false);
}

}  // namespace cellproj
