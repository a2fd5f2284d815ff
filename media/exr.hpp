#pragma once
// OpenEXR images for compositing tools: 32-bit float R, G, B and A, colour premultiplied by alpha
// (EXR's convention, and the renderer's own), row 0 at the top, ZIP-compressed (lossless).
#include <string>

#include "view/image.hpp"

namespace cellproj {

// Whether a path names an EXR (.exr, any case): where the front ends write one instead of a PNG.
bool names_exr(const std::string& path);
// InputError naming the file if it cannot be written, or for an image with no pixel.
void write_exr(const Image& premultiplied, const std::string& path);
// An EXR read back: its R, G, B and A (missing colour channels 0, a missing A 1) as floats.
// InputError naming the file if it is not one.
Image read_exr(const std::string& path);

}  // namespace cellproj
