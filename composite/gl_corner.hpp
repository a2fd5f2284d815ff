#pragma once
// What the OpenGL back ends draw: triangles given by their corners (composite/gl_compositor).
namespace cellproj {

// A corner of a triangle for the OpenGL back end: pixel position, colour and opacity (pt-linear:
// Gouraud; pt-table: opacity 1, to be modulated by the 2D alpha texture at u, v in [0, 1]), and
// where it reads the dither noise (screen position in noise tiles, shifted per cell).
struct GLCorner {
  float x, y, u, v, r, g, b, a, nu, nv;
};
constexpr int kDitherTile = 64;  // pixels per side of the dither noise tile

}  // namespace cellproj
