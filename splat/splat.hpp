#pragma once
// EWA volume splatting of one cell (Zwicker, Pfister, van Baar and Gross 2001; MWSC section 6): the
// cell's Gaussian ellipsoid carries its optical depth, the integral of extinction over its volume;
// projected through the local affine map at its centre it is a 2D Gaussian in the image, which is
// convolved with the pre-filter and sampled at pixel centres, the opacity the exact exponential of
// the optical depth it spreads there.
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/mat2x2.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "composite/fragment.hpp"
#include "mesh/cell_type.hpp"
#include "mesh/geometry.hpp"
#include "optics/transfer_function.hpp"
#include "splat/ellipsoid.hpp"
#include "splat/small_cells.hpp"
#include "view/camera.hpp"
#include "view/raster.hpp"

namespace cellproj {

// What a cell's splat carries of the transfer function: the optical depth integral of kappa dV
// (area units: a length squared), and the colour weighted by extinction, integral of kappa C dV
// over it.
struct SplatOptics {
  double optical_depth = 0.0;
  glm::dvec3 color{0.0};
};
// Quadrature over the tetrahedra of for_each_fan_tet (those of cell_moments), the field linear on each: four points per
// tetrahedron (the degree-2 rule of Keast), so a transfer function linear over the cell's scalar
// range is integrated exactly. `scalar` per point, indexed by ids (null: zeros).
SplatOptics splat_optics(const std::int64_t* ids, CellType type, const RecentredPoints& points, const double* scalar,
                         const TransferFunction& tf);

// A splat in the image: optical depth tau(p) = peak exp(-(p - centre)^T conic (p - centre) / 2) at
// pixel position p, drawn where the exponent's argument is below `cutoff`.
struct Footprint {
  glm::dvec2 centre{0.0};
  glm::dmat2 covariance{1.0};  // pixels^2, pre-filter included
  glm::dmat2 conic{1.0};       // its inverse
  double peak = 0.0;           // the optical depth at the centre
  double total = 0.0;          // of tau over the image plane, in pixels (its integral)
  double cutoff = 0.0;         // of the squared Mahalanobis distance
  glm::dvec3 color{0.0};
  glm::dvec3 world{0.0};    // the centre in the (recentred) world
  double depth = 0.0;       // of the centre: the view depth, for back-to-front order among splats
  bool visible = false;     // false: the centre is at or behind the eye, or no optical depth
  bool behind_eye = false;  // perspective: the centre is at or behind the eye
  // The pixels of a width x height image whose centres may lie inside the cutoff: the ellipse's
  // bounding box (none when not visible).
  PixelBox pixels(int width, int height) const;
};
// The footprint of the ellipsoid `m` (recentred coordinates, as `rays`' camera) with `optics`, the
// footprint's covariance J Sigma J^T plus prefilter^2 I (J the ray-space Jacobian at the centre),
// its total kappa V |det J| (Zwicker et al. equation 21 with the 3D kernel's normalisation).
Footprint project_splat(const CellMoments& m, const SplatOptics& optics, const PixelRays& rays, double prefilter);

// Calls emit(i, j, rgb, alpha) for every pixel of a width x height image whose centre lies inside
// the footprint's cutoff, with the premultiplied light of the splat there: C (1 - exp(-tau)),
// 1 - exp(-tau). Returns how many.
template <class Emit>
std::int64_t rasterize_splat(const Footprint& f, int width, int height, Emit&& emit) {
  const PixelBox box = f.pixels(width, height);
  std::int64_t n = 0;
  const double a = f.conic[0][0], b = f.conic[1][0] + f.conic[0][1], c = f.conic[1][1];
  for (int j = box.j0; j <= box.j1; ++j) {
    const double dy = j + 0.5 - f.centre.y;
    for (int i = box.i0; i <= box.i1; ++i) {
      const double dx = i + 0.5 - f.centre.x;
      const double q = a * dx * dx + b * dx * dy + c * dy * dy;
      if (!(q <= f.cutoff)) continue;
      const double alpha = -std::expm1(-f.peak * std::exp(-0.5 * q));
      emit(i, j, f.color * alpha, alpha);
      ++n;
    }
  }
  return n;
}

// A splat drawn through a stencil (MWSC section 6): it adds light only at the pixels `open(i, j)`
// says no drawn polygon holds at its depth, as rasterize_splat elsewhere; counted in c (pixels
// drawn, and held by the stencil). Moving the held share onto the open pixels was measured and
// raised the error (bench/results/splat.txt), so held pixels get nothing.
template <class Open, class Emit>
void rasterize_splat_open(const Footprint& f, int width, int height, Open&& open, Emit&& emit, SplatCounters& c) {
  rasterize_splat(f, width, height, [&](int i, int j, const glm::dvec3& rgb, double alpha) {
    if (!open(i, j)) {
      ++c.masked_fragments;
      return;
    }
    ++c.splat_fragments;
    emit(i, j, rgb, alpha);
  });
}

// What every splat of a frame is made with: the recentred points and `rays` on the recentred
// camera, the field (null: zeros), the transfer function, the pre-filter in pixels.
struct SplatContext {
  const RecentredPoints& points;
  const double* scalar;
  const TransferFunction& tf;
  const PixelRays& rays;
  double prefilter;
};
// The footprint of the cell with point ids `ids` of `type`; not visible, and counted in c, when it
// has none (zero volume, inverted, centred behind the eye).
Footprint cell_splat(const SplatContext& frame, const std::int64_t* ids, CellType type, SplatCounters& c);
// Appends the footprint's fragments at the pixels `open(i, j)` allows (rasterize_splat_open) to
// out; counted in c.
template <class Open>
void append_fragments(const Footprint& f, int width, int height, Open&& open, FragmentBands& out, SplatCounters& c) {
  rasterize_splat_open(
      f, width, height, open,
      [&](int i, int j, const glm::dvec3& rgb, double a) { out.append(i, j, rgb.r, rgb.g, rgb.b, a); }, c);
}

}  // namespace cellproj
