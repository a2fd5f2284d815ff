#pragma once
// A projected tetrahedron's fan (MWSC section 2: three or four triangles around the thick vertex)
// evaluated over its whole pixel box at once, in SIMD lanes: no per-row edge search. A row's
// pixels are those between its crossings of the outline; each takes the fan triangle whose wedge
// around the thick vertex holds it (each wedge is under 180 degrees, the thick vertex inside the
// outline; the choice near a shared spoke does not matter, the quantities are continuous across
// it) and that triangle's planes.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "optics/opacity_table.hpp"
#include "projection/projected_tet.hpp"
#include "projection/segment_batch.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"

namespace cellproj {

constexpr int kFanQuantities = 5;  // the most per-pixel quantities interpolated (pt-table's)

// An affine function of the pixel centre, relative to the box's first centre: c + gx x + gy y.
struct Plane {
  double c, gx, gy;
};

// A triangle's planes of the quantities, one array per coefficient (quantity m's plane is c[m] +
// gx[m] x + gy[m] y): computed four quantities at a time.
struct QuantityPlanes {
  double c[kFanQuantities], gx[kFanQuantities], gy[kFanQuantities];
};

// The fan's edge functions and its quantities' planes per triangle ("sector" a: thick vertex,
// hull[a], hull[a + 1]). Only the first `sectors` triangles and `quantities` quantities are set (a
// fan is made per tetrahedron: not zero-filling the rest is a tenth of fan_planes).
struct FanPlanes {
  int sectors = 0, quantities = 0;
  // pt-linear: the four quantities opacity and colour become the pixel's opacity clamped to
  // [0, 1] and its colour clamped to >= 0 times it (premultiplied).
  bool linear_opacity = false;
  Plane outline[4];     // edge hull[a] -> hull[a + 1], positive inside
  double inv_gx[4];     // 1 / outline[a].gx (0 for a flat edge: the row is all in or all out)
  Plane spoke[4];       // edge thick -> hull[k], positive on triangle k's side
  double left_out[4];   // -1e300 for a triangle of no area to rounding (never chosen), else 0
  QuantityPlanes q[4];  // zero for a triangle left out
};

// The planes of the fan of pt whose box's first pixel centre is (x0, y0); quantity m has value
// thick[m] at the thick vertex and hull[k][m] at hull corner k. Empty (sectors = 0) if pt is, or
// its outline has no area to rounding. `quantities` is 4 or 5 (thick and each hull row hold at least 4).
FanPlanes fan_planes(const ProjectedTet& pt, double x0, double y0, int quantities, const double* thick,
                     const double (*hull)[kFanQuantities]);

// Per row r of rows [row0, row0 + rows) of a box `width` pixels wide (rows from the box's first):
// the pixels first[r] <= i <= last[r] whose centres lie between the row's crossings of the
// outline's edges (within the box), and their quantities. Row r's pixel i is at r * stride + i.
// A centre on the outline to rounding may be drawn by both tetrahedra sharing the edge, or by
// neither: for a fan with no face edge-on (ProjectedTet::edge_on) the tetrahedron is zero thick
// there, so that adds or loses nothing (view/raster.hpp's rule, which gives such a centre to one
// triangle, costs more than the fan saves).
struct FanPixels {
  int stride = 0;
  std::vector<int> first, last;
  std::vector<double> q;  // quantity m of pixel p at m * size + p
  std::size_t size = 0;
  const double* quantity(int m) const { return q.data() + static_cast<std::size_t>(m) * size; }
};
void fan_pixels(const FanPlanes& f, int row0, int rows, int width, FanPixels& out);

// pt-linear's fan (linear_opacity) composited "over" onto the image, whose pixel (i0, j0) is the
// box's first: rows [row0, row0 + rows) of the box, `width` pixels wide, each pixel's opacity and
// premultiplied colour as fan_pixels gives them. The same bits as composite/fragment.hpp's over()
// of those values. Returns the number of fragments composited, those adding nothing (opacity and
// colour 0, which leave the image as it was) not counted.
// `lanes`: `pairs`, two pixels at a time, each one's four quantities in half of a vector, where
// the processor has AVX-512 (else `quantities`; pt-linear's and the exact rungs' fans); `quantities`, one pixel at a
// time with its four quantities in a vector, where the processor has AVX2 (else `pixels`); `pixels`, four pixels at a
// time (portable). The same bits.
enum class FanLanes { pairs, quantities, pixels };
std::int64_t fan_composite_over(const FanPlanes& f, Image& image, int i0, int j0, int row0, int rows, int width,
                                FanLanes lanes = FanLanes::pairs);

// The exact rungs' fan (its planes the ends' quantities, affine_ends: front and back 1/z and s/z in
// perspective, depth and scalar in orthographic): the pixels of rows [row0, row0 + rows) of its box
// appended to a batch with their segments' lengths, end scalars clamped to [smin, smax] and end
// extinctions from `piece`, as segment_ends gives them (the same bits): no pass over stored
// quantities. The box's first pixel is (i0, j0) in the image, `rays` the frame's.
struct FanSegments {
  const PixelRays& rays;
  int i0, j0, row0, rows, width;
  double smin, smax;
  LinearPiece piece;
};
// `lanes` as fan_composite_over's (the same bits either way).
void fan_segments(const FanPlanes& f, const FanSegments& at, SegmentBatch& out, FanLanes lanes = FanLanes::pairs);

// pt-table's fan (its five quantities kappa_avg, thickness and colour) composited "over" onto the
// image as fan_composite_over's: each pixel's opacity from `table`, its colour clamped to >= 0
// times it; the same bits as fan_pixels' values through the table and composite/fragment.hpp's
// over(). Returns the fragments composited, those adding nothing not counted. `lanes` as
// fan_composite_over's, `pairs` as `quantities` (the same bits either way).
std::int64_t fan_composite_table(const FanPlanes& f, const OpacityTable& table, Image& image, int i0, int j0, int row0,
                                 int rows, int width, FanLanes lanes = FanLanes::quantities);

}  // namespace cellproj
