// A projected tetrahedron's fan over its pixel box (tet_fan.hpp) against the triangle rasterizer
// it replaces for small tetrahedra: the same pixels, the same interpolated quantities.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include <gtest/gtest.h>

#include "composite/fragment.hpp"
#include "projection/projected_tet.hpp"
#include "projection/tet_fan.hpp"
#include "view/raster.hpp"

using namespace cellproj;

namespace {

constexpr int kW = 64, kH = 48;

// Quantity 0 is 1 at the thick vertex and 0 on the outline (the thick vertex's weight); the others
// are arbitrary corner values.
struct Corners {
  double thick[kFanQuantities];
  double hull[4][kFanQuantities];
};

Corners corner_values(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-2.0, 3.0);
  Corners c{};
  c.thick[0] = 1.0;
  for (int m = 1; m < kFanQuantities; ++m) c.thick[m] = u(rng);
  for (auto& h : c.hull) {
    h[0] = 0.0;
    for (int m = 1; m < kFanQuantities; ++m) h[m] = u(rng);
  }
  return c;
}

// The fan of pt over its pixel box (as project_fan draws it), from row row0 of the box on.
struct DrawnFan {
  PixelBox box;
  FanPixels f;
  int width() const { return box.i1 - box.i0 + 1; }
  int height() const { return box.j1 - box.j0 + 1; }
  double at(int m, int r, int i) const { return f.quantity(m)[static_cast<std::size_t>(r) * f.stride + i]; }
};
// The pixel box of pt's outline, as project_fan takes it.
PixelBox fan_box(const ProjectedTet& pt) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (int k = 0; k < pt.hull_size; ++k)
    x0 = std::min(x0, pt.hull[k].x), x1 = std::max(x1, pt.hull[k].x), y0 = std::min(y0, pt.hull[k].y),
    y1 = std::max(y1, pt.hull[k].y);
  return PixelBox({x0, y0}, {x1, y1}, {x0, y0}, kW, kH);
}

DrawnFan draw_fan(const ProjectedTet& pt, const Corners& c, int row0 = 0) {
  DrawnFan d{fan_box(pt), {}};
  if (d.box.empty()) return d;
  const FanPlanes planes = fan_planes(pt, d.box.i0 + 0.5, d.box.j0 + 0.5, kFanQuantities, c.thick, c.hull);
  EXPECT_EQ(planes.sectors, pt.hull_size);
  fan_pixels(planes, row0, d.height() - row0, d.width(), d.f);
  return d;
}

// Compares the fan with the triangles (thick, hull[a], hull[a + 1]) rasterized one by one.
void expect_fan_matches_triangles(const ProjectedTet& pt, const Corners& c) {
  ASSERT_GT(pt.hull_size, 0);
  const DrawnFan d = draw_fan(pt, c);
  const PixelBox& box = d.box;
  if (box.empty()) return;
  const int bw = d.width(), bh = d.height();
  const FanPixels& f = d.f;
  // Which triangle covers each pixel of the box (-1: none), and its interpolated quantities.
  std::vector<int> owner(static_cast<std::size_t>(bw * bh), -1);
  std::vector<double> want(static_cast<std::size_t>(bw * bh) * kFanQuantities);
  const int n = pt.hull_size;
  for (int a = 0; a < n; ++a) {
    const ThickVertex &t = pt.thick, &p = pt.hull[a], &q = pt.hull[(a + 1) % n];
    rasterize_triangle_weights(
        {t.x, t.y}, {p.x, p.y}, {q.x, q.y}, kW, kH, [&](int i, int j, double wt, double wp, double wq) {
          const std::size_t k = static_cast<std::size_t>((j - box.j0) * bw + (i - box.i0));
          EXPECT_EQ(owner[k], -1) << "pixel " << i << "," << j << " covered twice";
          owner[k] = a;
          for (int m = 0; m < kFanQuantities; ++m)
            want[k * kFanQuantities + m] = wt * c.thick[m] + wp * c.hull[a][m] + wq * c.hull[(a + 1) % n][m];
        });
  }
  for (int r = 0; r < bh; ++r) {
    for (int i = 0; i < bw; ++i) {
      const std::size_t k = static_cast<std::size_t>(r * bw + i);
      const bool in_fan = f.first[r] <= i && i <= f.last[r];
      if (owner[k] >= 0 && !in_fan) {
        // Only a centre on the outline, to rounding, may be left to the tetrahedron across it:
        // there the thick vertex's weight is 0 (nothing of a thickness to draw).
        EXPECT_NEAR(want[k * kFanQuantities], 0.0, 1e-9)
            << "pixel " << box.i0 + i << "," << box.j0 + r << " left out of the fan";
      } else if (owner[k] >= 0) {
        for (int m = 0; m < kFanQuantities; ++m)
          EXPECT_NEAR(d.at(m, r, i), want[k * kFanQuantities + m], 1e-9)
              << "quantity " << m << " at " << box.i0 + i << "," << box.j0 + r;
      } else if (in_fan) {
        // And only such a centre may be in the fan and in no triangle.
        EXPECT_NEAR(d.at(0, r, i), 0.0, 1e-9) << "pixel " << box.i0 + i << "," << box.j0 + r;
      }
    }
  }
}

ProjectedTet projected(const ScreenVertex v[4]) { return project_tet(v, false); }

// Projects v (orthographic), expects an outline of hull_size corners and the fan to match.
ProjectedTet expect_projected_fan_matches(const ScreenVertex v[4], int hull_size, const Corners& c) {
  const ProjectedTet pt = projected(v);
  EXPECT_EQ(pt.hull_size, hull_size);
  if (pt.hull_size == hull_size) expect_fan_matches_triangles(pt, c);
  return pt;
}

}  // namespace

TEST(TetFan, RandomTetrahedraMatchTheirTriangles) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> x(1.0, kW - 1.0), y(1.0, kH - 1.0), z(1.0, 5.0);
  int classes[5] = {};
  for (int t = 0; t < 400; ++t) {
    // Mostly small tetrahedra (a few pixels across), some spanning the image, some slivers.
    const double cx = x(rng), cy = y(rng), span = t % 4 == 0 ? 30.0 : t % 4 == 1 ? 0.8 : 6.0;
    std::uniform_real_distribution<double> d(-span, span);
    ScreenVertex v[4];
    for (auto& p : v) p = {cx + d(rng), cy + (t % 8 == 3 ? 0.01 : 1.0) * d(rng), z(rng), 0.0};
    const ProjectedTet pt = projected(v);
    ++classes[pt.hull_size];
    if (pt.hull_size == 0) continue;
    SCOPED_TRACE("tetrahedron " + std::to_string(t));
    expect_fan_matches_triangles(pt, corner_values(rng));
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(classes[3], 50);
  EXPECT_GT(classes[4], 50);
}

TEST(TetFan, ThickVertexOnAPixelCentreIsDrawnOnce) {
  std::mt19937 rng(3);
  // Class 1, the inner vertex exactly on the centre of pixel (10, 10), corners on centres too.
  const ScreenVertex up[4] = {{4.5, 4.5, 5, 0}, {18.5, 6.5, 5, 0}, {8.5, 20.5, 5, 0}, {10.5, 10.5, 3, 0}};
  expect_projected_fan_matches(up, 3, corner_values(rng));
  // Class 2, the two crossing edges meeting on the centre of pixel (20, 20).
  const ScreenVertex cross[4] = {{10.5, 10.5, 1, 0}, {30.5, 30.5, 1, 0}, {30.5, 10.5, 4, 0}, {10.5, 30.5, 4, 0}};
  const Corners c = corner_values(rng);
  const ProjectedTet p2 = expect_projected_fan_matches(cross, 4, c);
  ASSERT_EQ(p2.hull_size, 4);
  // The crossing's pixel has the thick vertex's values.
  const DrawnFan d = draw_fan(p2, c);
  const int r = 20 - d.box.j0, i = 20 - d.box.i0;
  ASSERT_TRUE(d.f.first[r] <= i && i <= d.f.last[r]);
  for (int m = 0; m < kFanQuantities; ++m) EXPECT_NEAR(d.at(m, r, i), c.thick[m], 1e-12) << "quantity " << m;
}

TEST(TetFan, RowsFromTheBoxMiddleGiveTheSameValues) {
  // A tile's share of the box (rows from its middle) has the same bits as the whole box's rows:
  // 1 and N threads draw the same picture.
  std::mt19937 rng(11);
  const ScreenVertex v[4] = {{3.2, 2.7, 5, 0}, {21.9, 8.1, 5, 0}, {9.4, 25.3, 2, 0}, {12.6, 11.8, 3, 0}};
  const ProjectedTet pt = projected(v);
  const Corners c = corner_values(rng);
  const DrawnFan whole = draw_fan(pt, c), part = draw_fan(pt, c, 7);
  for (int r = 7; r < whole.height(); ++r) {
    ASSERT_EQ(whole.f.first[r], part.f.first[r - 7]);
    ASSERT_EQ(whole.f.last[r], part.f.last[r - 7]);
    for (int i = whole.f.first[r]; i <= whole.f.last[r]; ++i)
      for (int m = 0; m < kFanQuantities; ++m) ASSERT_EQ(whole.at(m, r, i), part.at(m, r - 7, i));
  }
}

TEST(TetFan, EdgeOnFacesAndEdgesAlongTheViewKeepTheirPixels) {
  // Seen straight down a grid: an edge along the view (two vertices on one image point, the thick
  // vertex on a corner of the outline) and a face edge-on (the thick vertex on an outline edge).
  // Their fans have triangles of zero area, which must not take the outline's pixels with them.
  std::mt19937 rng(5);
  const ScreenVertex along[4] = {{9, 27, 1, 0}, {9, 27, 3, 0}, {9, 31.5, 2, 0}, {4.5, 31.5, 2, 0}};
  const ProjectedTet p1 = expect_projected_fan_matches(along, 3, corner_values(rng));
  const ScreenVertex edge_on[4] = {{2.5, 2.5, 1, 0}, {20.5, 2.5, 1, 0}, {8.5, 2.5, 4, 0}, {10.5, 14.5, 2, 0}};
  const ProjectedTet p2 = expect_projected_fan_matches(edge_on, 3, corner_values(rng));
  // The renderer leaves such fans to the triangle rasterizer (their outline is thick).
  EXPECT_TRUE(p1.edge_on && p2.edge_on);
  // Both draw pixels: the whole outline's.
  for (const ProjectedTet* pt : {&p1, &p2}) {
    const DrawnFan d = draw_fan(*pt, corner_values(rng));
    int drawn = 0;
    for (int r = 0; r < d.height(); ++r) drawn += std::max(0, d.f.last[r] - d.f.first[r] + 1);
    EXPECT_GT(drawn, 5);
  }
}

TEST(TetFan, ThickVertexOnOrBesideTheOutlineKeepsThePixels) {
  // Crossing edges whose crossing rounds onto a corner (project_tet's weights are inexact where a
  // vertex nearly meets the other edge): two fan triangles of no area beside that corner. And a
  // thick vertex a hair inside an outline edge: a sliver triangle next to two whole ones.
  std::mt19937 rng(9);
  ProjectedTet corner;
  corner.hull_size = 4;
  const double h[4][2] = {{61.25141787494848, 51.369359171238656},
                          {60.794477048002115, 42.267171302912018},
                          {42.28075787622533, 47.148219547302176},
                          {61.989767381904493, 66.077162738961604}};
  for (int k = 0; k < 4; ++k) corner.hull[k] = {h[k][0], h[k][1], 2, 2, 0, 0};
  corner.thick = corner.hull[0];
  corner.thick.zb = 3;
  expect_fan_matches_triangles(corner, corner_values(rng));
  ProjectedTet beside;
  beside.hull_size = 3;
  beside.hull[0] = {5.2, 3.1, 2, 2, 0, 0}, beside.hull[1] = {40.7, 9.3, 2, 2, 0, 0},
  beside.hull[2] = {12.9, 30.4, 2, 2, 0, 0};
  const double t = 0.37;  // on edge 0-1, then 1e-12 pixels inwards
  beside.thick = {5.2 + t * 35.5 - 1e-12 * 6.2, 3.1 + t * 6.2 + 1e-12 * 35.5, 1, 4, 0, 0};
  expect_fan_matches_triangles(beside, corner_values(rng));
}

// The kernels of the fan (FanLanes): two pixels with their quantities in the lanes (AVX-512 only;
// pt-linear's, elsewhere the next), one pixel with its quantities in the lanes (AVX2 only;
// elsewhere the last), and four pixels at a time.
class FanKernels : public testing::TestWithParam<FanLanes> {};

TEST_P(FanKernels, SegmentsStraightIntoTheBatchHaveSegmentEndsBits) {
  // The exact rungs' fan appends its pixels' segments to the batch with the lengths, clamped end
  // scalars and extinctions segment_ends would compute from the stored quantities: the same bits,
  // in perspective and orthographic projection, from the box's first row or a tile's middle one.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(1.0, kW - 1.0), y(1.0, kH - 1.0), z(2.0, 6.0), u(0.0, 1.0);
  Camera persp;
  persp.projection = Projection::Perspective, persp.fov_y = 40.0;
  LinearPiece piece;
  piece.s0 = 0.2, piece.ds = 1.0 / 0.5, piece.k0 = 0.5, piece.dk = 3.0;
  int segments = 0;
  for (const Camera& cam : {Camera{}, persp}) {
    const PixelRays rays(cam, kW, kH);
    for (int t = 0; t < 200; ++t) {
      const double cx = x(rng), cy = y(rng);
      std::uniform_real_distribution<double> d(-8.0, 8.0);
      ScreenVertex v[4];
      for (auto& p : v) p = {cx + d(rng), cy + d(rng), z(rng), u(rng)};
      const ProjectedTet pt = project_tet(v, rays.perspective());
      if (pt.hull_size == 0 || pt.edge_on) continue;
      // The ends' quantities as project_fan gives them: 1/z and s/z in perspective.
      const auto ends = [&](const ThickVertex& w, double* q) {
        const double f = rays.perspective() ? 1.0 / w.zf : 1.0, b = rays.perspective() ? 1.0 / w.zb : 1.0;
        q[0] = rays.perspective() ? f : w.zf, q[1] = rays.perspective() ? b : w.zb, q[2] = w.sf * f, q[3] = w.sb * b;
      };
      double thick[kFanQuantities] = {}, hull[4][kFanQuantities] = {};
      ends(pt.thick, thick);
      for (int k = 0; k < pt.hull_size; ++k) ends(pt.hull[k], hull[k]);
      const PixelBox box = fan_box(pt);
      if (box.empty()) continue;
      const FanPlanes planes = fan_planes(pt, box.i0 + 0.5, box.j0 + 0.5, 4, thick, hull);
      ASSERT_GT(planes.sectors, 0);
      const int bw = box.i1 - box.i0 + 1, row0 = t % 3 == 0 ? (box.j1 - box.j0) / 2 : 0,
                rows = box.j1 - box.j0 + 1 - row0;
      FanPixels f;
      fan_pixels(planes, row0, rows, bw, f);
      SegmentBatch want, got;
      for (int r = 0; r < rows; ++r)
        for (int i = f.first[r]; i <= f.last[r]; ++i) {
          const std::size_t k = static_cast<std::size_t>(r) * f.stride + i;
          want.push(box.i0 + i, box.j0 + row0 + r, f.quantity(0)[k], f.quantity(1)[k], f.quantity(2)[k],
                    f.quantity(3)[k]);
        }
      segment_ends(want, rays, 0.25, 0.6, piece);
      got.push(-1, -1, 0, 0, 0, 0);  // appended after what the batch holds
      fan_segments(planes, {rays, box.i0, box.j0, row0, rows, bw, 0.25, 0.6, piece}, got, GetParam());
      ASSERT_EQ(got.n, want.n + 1) << "tetrahedron " << t;
      for (std::size_t k = 0; k < want.n; ++k) {
        ASSERT_EQ(got.i[k + 1], want.i[k]);
        ASSERT_EQ(got.j[k + 1], want.j[k]);
        ASSERT_EQ(got.length[k + 1], want.length[k]) << "tetrahedron " << t << " fragment " << k;
        ASSERT_EQ(got.sf[k + 1], want.sf[k]);
        ASSERT_EQ(got.sb[k + 1], want.sb[k]);
        ASSERT_EQ(got.k0[k + 1], want.k0[k]);
        ASSERT_EQ(got.k1[k + 1], want.k1[k]);
      }
      segments += static_cast<int>(want.n);
    }
  }
  EXPECT_GT(segments, 5000);
}

// Fans composited in their lanes against fan_pixels' stored values composited one by one with
// over(): pt-linear's (fan_composite_over in `lanes`; table null: the stored opacity and
// premultiplied colour) or pt-table's (fan_composite_table; each pixel's opacity from the table at
// its kappa_avg and thickness clamped to >= 0, its colour clamped to >= 0 times it, as project_fan
// did). The same image bits, the same count, nothing outside the outline touched; opacities (or
// kappa_avg) past their range, negative colours and tetrahedra adding nothing included, from a
// tile's middle row too; every third tetrahedron's corners on pixel centres, so that spokes pass
// through centres (a wedge value of 0: ties between triangles, which the AVX2 kernel breaks apart
// from the rest; either triangle gives the value to rounding, so this checks that one is chosen).
void expect_composited_as_stored(FanLanes lanes, const OpacityTable* table) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> x(1.0, kW - 1.0), y(1.0, kH - 1.0), z(1.0, 5.0), u(-0.3, 1.4);
  Image want(kW, kH);
  for (float& v : want.rgba) v = static_cast<float>(std::uniform_real_distribution<double>(0.0, 1.0)(rng));
  Image got = want;
  std::int64_t composited = 0;
  const int nq = table ? 5 : 4;
  for (int t = 0; t < 300; ++t) {
    const double cx = x(rng), cy = y(rng);
    std::uniform_real_distribution<double> d(-9.0, 9.0);
    ScreenVertex v[4];
    for (auto& p : v) p = {cx + d(rng), cy + d(rng), z(rng), 0.0};
    if (t % 3 == 1)
      for (auto& p : v) p.x = std::floor(p.x) + 0.5, p.y = std::floor(p.y) + 0.5;
    const ProjectedTet pt = projected(v);
    if (pt.hull_size == 0 || pt.edge_on) continue;
    double thick[kFanQuantities] = {}, hull[4][kFanQuantities] = {};
    const auto corner = [&](double* q) {
      q[0] = t % 5 == 0 ? -u(rng) - 0.31 : u(rng);  // opacity or kappa_avg (never above 0 for every fifth)
      for (int m = 1; m < nq; ++m) q[m] = u(rng);   // (pt-table: thickness, then colour)
    };
    corner(thick);
    for (int k = 0; k < pt.hull_size; ++k) corner(hull[k]);
    const PixelBox box = fan_box(pt);
    if (box.empty()) continue;
    FanPlanes planes = fan_planes(pt, box.i0 + 0.5, box.j0 + 0.5, nq, thick, hull);
    ASSERT_GT(planes.sectors, 0);
    planes.linear_opacity = !table;
    const int bw = box.i1 - box.i0 + 1, row0 = t % 3 == 0 ? (box.j1 - box.j0) / 2 : 0,
              rows = box.j1 - box.j0 + 1 - row0;
    FanPixels f;
    fan_pixels(planes, row0, rows, bw, f);
    std::int64_t n = 0;
    for (int r = 0; r < rows; ++r)
      for (int i = f.first[r]; i <= f.last[r]; ++i) {
        const std::size_t k = static_cast<std::size_t>(r) * f.stride + i;
        const auto q = [&](int m) { return f.quantity(m)[k]; };
        const double a = table ? (*table)(std::max(q(0), 0.0), std::max(q(1), 0.0)) : q(0);
        double c[3];
        for (int m = 0; m < 3; ++m) c[m] = table ? std::max(q(2 + m), 0.0) * a : q(1 + m);
        if (a == 0.0 && c[0] == 0.0 && c[1] == 0.0 && c[2] == 0.0) continue;
        const float src[4] = {static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]),
                              static_cast<float>(a)};
        over(want.pixel(box.i0 + i, box.j0 + row0 + r), src);
        ++n;
      }
    EXPECT_EQ(table ? fan_composite_table(planes, *table, got, box.i0, box.j0, row0, rows, bw, lanes)
                    : fan_composite_over(planes, got, box.i0, box.j0, row0, rows, bw, lanes),
              n)
        << "tetrahedron " << t;
    composited += n;
    ASSERT_EQ(std::memcmp(got.rgba.data(), want.rgba.data(), want.rgba.size() * sizeof(float)), 0)
        << "tetrahedron " << t;
  }
  EXPECT_GT(composited, 3000);
}

TEST_P(FanKernels, CompositedOverTheImageAsItsStoredPixelsAre) { expect_composited_as_stored(GetParam(), nullptr); }

TEST(TetFan, PtTableCompositedOverTheImageAsItsStoredPixelsThroughTheTableAre) {
  const OpacityTable table(64, 1.2, 1.1);  // kappa_avg and thickness past its range too (clamped)
  for (FanLanes lanes : {FanLanes::quantities, FanLanes::pixels}) expect_composited_as_stored(lanes, &table);
}

INSTANTIATE_TEST_SUITE_P(TetFan, FanKernels, testing::Values(FanLanes::pairs, FanLanes::quantities, FanLanes::pixels),
                         [](const testing::TestParamInfo<FanLanes>& p) {
                           return p.param == FanLanes::pairs        ? "PairsInLanes"
                                  : p.param == FanLanes::quantities ? "QuantitiesInLanes"
                                                                    : "PixelsInLanes";
                         });

// The opacity table (the paper's 2D alpha texture): 1 - exp(-kappa l) at its nodes, bilinear in
// between, clamped past its range; its read four at a time the same bits as one by one, a NaN
// giving NaN without reading outside the table.
#pragma GCC diagnostic ignored "-Wpsabi"  // (the four-at-a-time read inlined: no call passes a vector)
TEST(OpacityTable, NodesExactBetweenBilinearFourAtATimeAsOneByOne) {
  const OpacityTable table(64, 2.0, 3.0);  // nodes every 2/63 in kappa, 3/63 in l
  const double dk = 2.0 / 63, dl = 3.0 / 63;
  EXPECT_NEAR(table(7 * dk, 11 * dl), static_cast<float>(-std::expm1(-(7 * dk) * (11 * dl))), 1e-15);
  const double mid = table(7.5 * dk, 11 * dl), lo = table(7 * dk, 11 * dl), hi = table(8 * dk, 11 * dl);
  EXPECT_NEAR(mid, 0.5 * (lo + hi), 1e-15);
  EXPECT_NEAR(table(2.0, 3.0), 1 - std::exp(-6.0), 1e-7);  // the last node
  EXPECT_EQ(table(50.0, 3.0), table(2.0, 3.0));            // clamped
  EXPECT_EQ(table(2.0, 1e300), table(2.0, 3.0));
  EXPECT_TRUE(std::isnan(table(std::nan(""), 1.0)));
  typedef double Lanes __attribute__((vector_size(32)));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> k(0.0, 2.5), l(0.0, 3.5);
  for (int t = 0; t < 1000; ++t) {
    Lanes kl = {k(rng), k(rng), t % 7 == 0 ? -0.0 : k(rng), t % 11 == 0 ? 1e300 : k(rng)};
    Lanes ll = {l(rng), t % 5 == 0 ? 0.0 : l(rng), l(rng), t % 13 == 0 ? std::nan("") : l(rng)};
    const Lanes four = table(kl, ll);
    for (int m = 0; m < 4; ++m) {
      const double one = table(kl[m], ll[m]);
      if (std::isnan(one))
        EXPECT_TRUE(std::isnan(four[m]));
      else
        EXPECT_EQ(std::memcmp(&one, &four[m], sizeof one), 0) << kl[m] << " " << ll[m];
    }
  }
}
