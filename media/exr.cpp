#include "media/exr.hpp"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

#include <exception>

#include "base/error.hpp"
#include "base/file_status.hpp"

namespace cellproj {
namespace {

// The image's four floats a pixel as EXR slices: R, G, B, A interleaved, `origin` its data window's corner.
Imf::FrameBuffer slices(float* rgba, int width, const Imath::V2i& origin) {
  const std::size_t x = 4 * sizeof(float), y = x * static_cast<std::size_t>(width);
  char* base = reinterpret_cast<char*>(rgba) - (origin.x * x + origin.y * y);
  Imf::FrameBuffer buffer;
  const char* names[] = {"R", "G", "B", "A"};
  for (int c = 0; c < 4; ++c)
    buffer.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), x, y, 1, 1, c == 3 ? 1.0 : 0.0));
  return buffer;
}

}  // namespace

bool names_exr(const std::string& path) { return lower_extension(path) == ".exr"; }

void write_exr(const Image& image, const std::string& path) {
  if (image.width <= 0 || image.height <= 0) throw InputError(where(path, "an EXR needs an image with pixels"));
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const char* c : {"R", "G", "B", "A"}) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    Imf::OutputFile file(path.c_str(), header);
    Image copy = image;  // OpenEXR's slices take a non-const base
    file.setFrameBuffer(slices(copy.rgba.data(), image.width, {0, 0}));
    file.writePixels(image.height);
  } catch (const std::exception& e) {
    throw InputError(where(path, std::string("cannot write the EXR: ") + e.what()));
  }
}

Image read_exr(const std::string& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
    if (width <= 0 || height <= 0 || static_cast<long long>(width) * height > (1LL << 28))
      throw InputError(where(path, "an EXR of " + std::to_string(width) + "x" + std::to_string(height) +
                                       " pixels is not an image cellproj reads back"));
    Image image(width, height);
    file.setFrameBuffer(slices(image.rgba.data(), width, window.min));
    file.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(where(path, std::string("not a readable EXR: ") + e.what()));
  }
}

}  // namespace cellproj
