#pragma once
// Every point of a mesh in the image once per frame: pixel x, y (the coverage rule's coordinates),
// view depth z and the scalar, through the same PixelRays (on the recentred camera) that the
// A-buffer and the exact renderer's tracer use, so all three place a vertex on the same bits.
#include <cstdint>
#include <vector>

#include "base/huge_pages.hpp"
#include "base/recentred_points.hpp"
#include "view/camera.hpp"

namespace cellproj {

// A point (a cell's vertex) in the image: pixel position x, y, view depth z, scalar s.
struct ScreenVertex {
  double x, y, z, s;
};

// One 32-byte record per point, since a tetrahedron gathers all four values of each of its vertices.
// Written afresh every frame (34 MB for a million points: beyond malloc's mapping threshold, so
// mapped anew each time; huge_pages.hpp).
struct ScreenPoints {
  FrameBuffer<ScreenVertex> v;
  std::int64_t behind_eye = 0;  // points with z <= 0, at or behind the eye (or its plane)
};
// `rays` must be built on recentred(camera, points.centre). Parallel over points (oneTBB, in the
// caller's task arena); `scalar` may be null (zeros).
ScreenPoints project_points(const RecentredPoints& points, const double* scalar, const PixelRays& rays);

}  // namespace cellproj
