#pragma once
// What the OpenGL back ends draw: triangles given by their corners (composite/gl_compositor).
#include <cstdint>

namespace cellproj {

// A corner of a triangle for the OpenGL back end: pixel position, colour and opacity (pt-linear:
// Gouraud; pt-table: opacity 1, to be modulated by the 2D alpha texture at u, v in [0, 1]), and
// where it reads the dither noise (screen position in noise tiles, shifted per cell).
struct GLCorner {
  float x, y, u, v, r, g, b, a, nu, nv;
};
constexpr int kDitherTile = 64;  // pixels per side of the dither noise tile

// A whole-pixel shift of the noise tile for one layer (a cell, a slice), from a 64-bit mix of its
// key: each layer over a pixel reads another noise value, so the rounding errors cancel.
struct DitherShift {
  float u, v;
  explicit DitherShift(std::uint64_t key) {
    std::uint64_t h = key * 0x9E3779B97F4A7C15ull;
    h ^= h >> 29;
    u = static_cast<float>(h % kDitherTile), v = static_cast<float>((h >> 16) % kDitherTile);
  }
};

}  // namespace cellproj
