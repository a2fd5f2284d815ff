#pragma once
// Exact traversal of the rays through pixel centres: for every pixel, the segments of the ray in
// each cell, front to back. Cells other than tetrahedra are traversed through their canonical
// tetrahedralization (mesh/tetrahedralize.hpp), inside which the field is linear.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

#include "mesh/geometry.hpp"
#include "mesh/mesh.hpp"
#include "mesh/tetrahedralize.hpp"
#include "view/camera.hpp"

namespace cellproj {

struct RaySegment {
  double t0, t1;      // world distance along the ray (from the eye, or the eye plane if orthographic)
  double s0, s1;      // the scalar at the segment's front and back ends
  std::int64_t cell;  // the mesh cell it crosses
  std::uint32_t tet;  // the tracer's tetrahedron it crosses (CellRayTracer::gradient)
};

class CellRayTracer {
 public:
  // Copies the points (recentred on the bounding box, so huge offsets lose no precision); drops
  // zero-volume tetrahedra and orients the rest positively. The field comes with each trace.
  explicit CellRayTracer(const MeshView& mesh);

  // Calls visit(i, j, ray, segments, n) for every pixel with the segments sorted front to back; the
  // ray is in the recentred frame of points(). The segments' s0, s1 interpolate the point field
  // `scalar` (zeros when null). Pixels are visited concurrently from the calling task arena's
  // threads, each pixel once.
  using Visitor = std::function<void(int i, int j, const Ray& ray, const RaySegment* segments, std::size_t n)>;
  void trace(const Camera& camera, int width, int height, const double* scalar, const Visitor& visit,
             const std::function<void(double done)>& progress = {}) const;

  // One view's rays through the tetrahedra, binned by image tile: trace() tile by tile, for callers
  // that walk several tracers' segments of the same pixels together (raycast/volume_union.hpp).
  class View {
   public:
    static constexpr int kTile = 16;  // tiles of kTile x kTile pixels
    View(const CellRayTracer& tracer, const Camera& camera, int width, int height);
    int tiles() const { return tiles_x_ * tiles_y_; }
    // lists[p] and rays[p] (p = (j - tile's j0) * kTile + i - tile's i0, kTile * kTile of each): the
    // segments of pixel p's ray sorted front to back, and the ray in the tracer's recentred frame.
    void tile_segments(int tile, const double* scalar, std::vector<RaySegment>* lists, Ray* rays) const;
    // f(i, j, p) for the image's pixels in `tile`.
    template <class F>
    void for_each_pixel(int tile, F&& f) const {
      const int i0 = (tile % tiles_x_) * kTile, j0 = (tile / tiles_x_) * kTile;
      for (int j = j0; j < std::min(j0 + kTile, height_); ++j)
        for (int i = i0; i < std::min(i0 + kTile, width_); ++i) f(i, j, (j - j0) * kTile + (i - i0));
    }

   private:
    struct PixelBox {
      int x0, x1, y0, y1;  // inclusive pixel ranges; empty when x0 > x1
    };
    const CellRayTracer* tracer_;
    PixelRays rays_;
    int width_, height_, tiles_x_, tiles_y_;
    std::vector<PixelBox> box_;          // per tetrahedron
    std::vector<std::int64_t> start_;    // per tile, into binned_
    std::vector<std::uint32_t> binned_;  // tetrahedra by tile
  };

  // The gradient of the point field `scalar` in tetrahedron `tet` (a RaySegment's), constant there.
  glm::dvec3 gradient(std::uint32_t tet, const double* scalar) const;

  // The point field `scalar` interpolated linearly in tetrahedron `tet` at x (recentred, as the rays).
  double value(std::uint32_t tet, const double* scalar, const glm::dvec3& x) const;

  // Per point, the volume-weighted mean of the gradients of the tetrahedra around it: a smooth
  // normal field for shading surfaces of the piecewise-linear field.
  std::vector<glm::dvec3> point_gradients(const double* scalar) const;
  // point_gradients interpolated linearly in tetrahedron `tet` at x (recentred, as the rays).
  glm::dvec3 interpolate(const std::vector<glm::dvec3>& per_point, std::uint32_t tet, const glm::dvec3& x) const;

  // The unit normal of the face of tetrahedron `tet` nearest x (recentred, as the rays): where x is
  // on the tetrahedron's boundary, the face it lies on. Oriented outwards.
  glm::dvec3 face_normal(std::uint32_t tet, const glm::dvec3& x) const;

  std::int64_t tetrahedra() const { return static_cast<std::int64_t>(tets_.size()); }
  std::int64_t dropped_degenerate() const { return dropped_; }
  const double* points() const { return points_.xyz.data(); }  // recentred on the bounding box

 private:
  RecentredPoints points_;
  std::vector<Tet> tets_;             // positively oriented
  std::vector<std::int64_t> parent_;  // the mesh cell of each tetrahedron
  std::int64_t dropped_ = 0;
};

}  // namespace cellproj
