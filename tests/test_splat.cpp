// Splatting small cells (splat/): the cell's ellipsoid against its analytic moments, a splat's
// total light against the exact integral of a cell much larger than a pixel (and against the
// closed form of its Gaussian at any optical depth), splats straddling the image edge, refused
// cells, the small cells' rule, and splats in cell projection and slicing against the anti-aliased
// exact image and for 1 against N threads.
#include <cmath>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>
#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "render/renderer.hpp"
#include "splat/splat.hpp"
#include "test_util.hpp"

using namespace cellproj;

namespace {

// No stencil: every pixel open.
constexpr auto kEverywhere = [](int, int) { return true; };

// A mesh of one cell.
Mesh one_cell(CellType type, const std::vector<glm::dvec3>& p) {
  Mesh m;
  for (const auto& q : p) m.points.insert(m.points.end(), {q.x, q.y, q.z});
  std::vector<std::int64_t> ids(p.size());
  for (std::size_t k = 0; k < p.size(); ++k) ids[k] = static_cast<std::int64_t>(k);
  m.add_cell(type, ids.data());
  m.add_field("s", "test").values.assign(p.size(), 0.0);
  return m;
}

const std::vector<glm::dvec3> kUnitCube = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                           {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const std::vector<glm::dvec3> kTet = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

CellMoments moments_of(const Mesh& m) {
  const RecentredPoints pts = recentre(m.view());
  CellMoments c = cell_moments(m.view().cell(0), m.view().type(0), pts);
  c.centre += pts.centre;
  return c;
}

// The splat of a one-cell mesh's cell in the image of `camera` (fragments, counters).
Fragments splat_of(const Mesh& m, const TransferFunction& tf, const Camera& camera, int size, SplatCounters& counters,
                   double prefilter = 0.7) {
  const MeshView v = m.view();
  const RecentredPoints pts = recentre(v);
  const PixelRays rays(recentred(camera, pts.centre), size, size);
  const SplatContext frame{pts, m.fields[0].values.data(), tf, rays, prefilter};
  FragmentBands out(size, size, 30);  // one band: the fragments in the order made
  append_fragments(cell_splat(frame, v.cell(0), v.type(0), counters), size, size, kEverywhere, out, counters);
  return out.band(0);
}

double total_alpha(const Fragments& f) {
  double a = 0.0;
  for (const Fragment& g : f) a += g.rgba[3];
  return a;
}

double total_alpha(const Image& image) {
  double a = 0.0;
  for (std::size_t k = 3; k < image.rgba.size(); k += 4) a += image.rgba[k];
  return a;
}

}  // namespace

TEST(Splat, TheEllipsoidHasTheCellsMoments) {
  const CellMoments cube = moments_of(one_cell(CellType::Hexahedron, kUnitCube));
  EXPECT_NEAR(cube.volume, 1.0, 1e-12);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(cube.centre[a], 0.5, 1e-12);
    for (int b = 0; b < 3; ++b) EXPECT_NEAR(cube.covariance[a][b], a == b ? 1.0 / 12.0 : 0.0, 1e-12);
  }
  // The corner tetrahedron: volume 1/6, centroid 1/4, variance 3/80, covariance -1/80.
  const CellMoments tet = moments_of(one_cell(CellType::Tetra, kTet));
  EXPECT_NEAR(tet.volume, 1.0 / 6.0, 1e-12);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(tet.centre[a], 0.25, 1e-12);
    for (int b = 0; b < 3; ++b) EXPECT_NEAR(tet.covariance[a][b], a == b ? 3.0 / 80.0 : -1.0 / 80.0, 1e-12);
  }
}

TEST(Splat, ALargeSplatIntegratesToTheCellsExactTotalLight) {
  // Thin (kappa l < 1e-4), the light of the cell over the image, in pixels, is kappa times the
  // integral over the cell of |det J|, J the ray-space Jacobian: kappa V over a pixel's area in
  // orthographic views; in perspective the integral by the midpoint rule (40^3 points).
  const Mesh m = one_cell(CellType::Hexahedron, kUnitCube);
  const double kappa = 5e-5;
  const TransferFunction tf = test::constant_tf(kappa, {1.0, 0.5, 0.25});
  // Perspective from afar: EWA's affine map at the centre is exact to (size / distance)^2.
  for (const Camera& c :
       {test::looking_down(8.0, {0.5, 0.5, 0.5}), test::perspective({60.0, -48.0, 52.0}, {0.5, 0.5, 0.5}, 7.5)}) {
    SplatCounters n;
    const Fragments f = splat_of(m, tf, c, 128, n);
    const PixelRays rays(c, 128, 128);
    double exact = 0.0;
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 40; ++j)
        for (int k = 0; k < 40; ++k) {
          const auto J = rays.ray_space_jacobian(glm::dvec3(i + 0.5, j + 0.5, k + 0.5) / 40.0);
          exact += kappa * std::abs(glm::dot(J[0], glm::cross(J[1], J[2]))) / (40.0 * 40.0 * 40.0);
        }
    EXPECT_EQ(n.splats, 1);
    EXPECT_NEAR(total_alpha(f) / exact, 1.0, 1e-3);
    EXPECT_NEAR(f[f.size() / 2].rgba[0] / f[f.size() / 2].rgba[3], 1.0, 1e-6);  // premultiplied by the colour
  }
}

// Ein(z) = integral over [0, z] of (1 - exp(-t)) / t: the opacity of a 2D Gaussian optical depth of
// peak z is 2 pi sqrt(det V) Ein(z).
double ein(double z) {
  double term = z, sum = z;  // sum of (-1)^(k+1) z^k / (k k!)
  for (int k = 2; k < 200 && std::abs(term) > 1e-17 * std::abs(sum); ++k) {
    term *= -z / k;
    sum += term / k;
  }
  return sum;
}

TEST(Splat, AtAnyOpticalDepthTheOpacityIsItsGaussiansClosedForm) {
  const Mesh m = one_cell(CellType::Hexahedron, kUnitCube);
  for (double kappa : {0.01, 1.0, 30.0}) {
    SplatCounters n;
    const TransferFunction tf = test::constant_tf(kappa, {1.0, 1.0, 1.0});
    const Camera c = test::looking_down(8.0, {0.5, 0.5, 0.5});
    const MeshView v = m.view();
    const RecentredPoints pts = recentre(v);
    const PixelRays rays(recentred(c, pts.centre), 96, 96);
    const Footprint f = cell_splat({pts, m.fields[0].values.data(), tf, rays, 0.7}, v.cell(0), v.type(0), n);
    FragmentBands bands(96, 96, 30);
    append_fragments(f, 96, 96, kEverywhere, bands, n);
    const Fragments& out = bands.band(0);
    const double closed = 2.0 * 3.14159265358979323846 * std::sqrt(glm::determinant(f.covariance)) * ein(f.peak);
    EXPECT_NEAR(total_alpha(out) / closed, 1.0, 1e-3) << "kappa " << kappa;
    EXPECT_NEAR(f.total, kappa * 1.0 * (96.0 / 8.0) * (96.0 / 8.0), 1e-9 * f.total);  // kappa V over a pixel's area
  }
}

TEST(Splat, ASplatStraddlingTheImageEdgeKeepsWhatFallsInside) {
  // The cube's centre on the image's left edge: half its (thin) light is inside.
  const Mesh m = one_cell(CellType::Hexahedron, kUnitCube);
  const TransferFunction tf = test::constant_tf(1e-4, {1.0, 1.0, 1.0});
  SplatCounters n;
  const double whole = total_alpha(splat_of(m, tf, test::looking_down(8.0, {0.5, 0.5, 0.5}), 64, n));
  const double half = total_alpha(splat_of(m, tf, test::looking_down(8.0, {4.5, 0.5, 0.5}), 64, n));
  EXPECT_NEAR(half / whole, 0.5, 1e-3);
  // Wholly outside: nothing, and no pixel out of range.
  const Fragments none = splat_of(m, tf, test::looking_down(8.0, {20.0, 0.5, 0.5}), 64, n);
  EXPECT_TRUE(none.empty());
}

TEST(Splat, ZeroVolumeAndInvertedCellsAreRefusedAndCounted) {
  const TransferFunction tf = test::constant_tf(1.0, {1.0, 1.0, 1.0});
  const Camera c = test::looking_down(3.0, {0.5, 0.5, 0.5});
  std::vector<glm::dvec3> flat = kUnitCube;
  for (int k = 4; k < 8; ++k) flat[k].z = 0.0;  // the top face on the bottom one
  SplatCounters n;
  EXPECT_TRUE(splat_of(one_cell(CellType::Hexahedron, flat), tf, c, 32, n).empty());
  EXPECT_EQ(n.refused_degenerate, 1);
  std::vector<glm::dvec3> inverted = kTet;
  std::swap(inverted[1], inverted[2]);
  EXPECT_TRUE(splat_of(one_cell(CellType::Tetra, inverted), tf, c, 32, n).empty());
  EXPECT_EQ(n.refused_inverted, 1);
  EXPECT_EQ(n.splats, 0);
  // A sliver of nearly zero thickness still has a finite footprint (the pre-filter's).
  std::vector<glm::dvec3> sliver = kTet;
  sliver[3].z = 1e-9;
  const Fragments f = splat_of(one_cell(CellType::Tetra, sliver), tf, c, 32, n);
  EXPECT_FALSE(f.empty());
  for (const Fragment& g : f)
    for (float v : g.rgba) EXPECT_TRUE(std::isfinite(v) && v >= 0.0f && v <= 1.0f);
}

TEST(Splat, TheRuleCountsThePixelCentresTheHullCovers) {
  // Against a brute-force test of every centre (random points: no centre on an edge).
  std::uint64_t seed = 12345;
  auto next = [&] {
    return static_cast<double>((seed = seed * 6364136223846793005ull + 1442695040888963407ull) >> 11) /
           9007199254740992.0;
  };
  for (int trial = 0; trial < 200; ++trial) {
    ScreenVertex v[8];
    const int n = 4 + trial % 5;
    const double cx = 2 + 12 * next(), cy = 2 + 12 * next(), r = 0.2 + 4 * next();
    for (int k = 0; k < n; ++k) v[k] = {cx + r * (2 * next() - 1), cy + r * (2 * next() - 1), 1.0, 0.0};
    const ScreenVertex* p[8];
    for (int k = 0; k < n; ++k) p[k] = &v[k];
    int brute = 0;
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i) {
        // Inside the hull: on the inner side of every hull edge, i.e. in some triangle of the points.
        bool in = false;
        for (int a = 0; a < n && !in; ++a)
          for (int b = a + 1; b < n && !in; ++b)
            for (int c = b + 1; c < n && !in; ++c) {
              auto side = [&](const ScreenVertex& s, const ScreenVertex& t) {
                return (t.x - s.x) * (j + 0.5 - s.y) - (t.y - s.y) * (i + 0.5 - s.x);
              };
              const double d0 = side(v[a], v[b]), d1 = side(v[b], v[c]), d2 = side(v[c], v[a]);
              in = (d0 > 0 && d1 > 0 && d2 > 0) || (d0 < 0 && d1 < 0 && d2 < 0);
            }
        brute += in;
      }
    EXPECT_EQ(covered_pixels(p, n, 16, 16, 1000), brute) << "trial " << trial;
    EXPECT_EQ(covered_pixels(p, n, 16, 16, 3), std::min(brute, 3));
    EXPECT_EQ(covered_pixels(p, n, 16, 16, 1), std::min(brute, 1)) << "trial " << trial;  // the early answer
  }
  // Centres on a hull edge or vertex, against the rule's count: with a limit of 1 the centre nearest
  // the mean is tried first, and one on an edge must not be taken as covered unless the rule says so.
  const ScreenVertex on[][4] = {
      {{1.5, 1.5, 1, 0}, {3.5, 1.5, 1, 0}, {1.5, 3.5, 1, 0}, {2.5, 2.5, 1, 0}},  // centres on every edge
      {{2.5, 2.0, 1, 0}, {3.0, 2.5, 1, 0}, {2.5, 3.0, 1, 0}, {2.0, 2.5, 1, 0}},  // the diamond around centre (2.5, 2.5)
      {{2.5, 2.5, 1, 0}, {2.6, 2.5, 1, 0}, {2.5, 2.6, 1, 0}, {2.55, 2.55, 1, 0}},         // a corner on a centre
      {{1.0, 1.0, 1, 0}, {9.0, 1.0, 1, 0}, {1.0, 1.0 + 1e-13, 1, 0}, {5.0, 1.0, 1, 0}}};  // a sliver
  for (const auto& cell : on) {
    const ScreenVertex* q[4] = {&cell[0], &cell[1], &cell[2], &cell[3]};
    EXPECT_EQ(covered_pixels(q, 4, 16, 16, 1), std::min(covered_pixels(q, 4, 16, 16, 1000), 1));
  }
  ScreenVertex behind[4] = {{1, 1, 1, 0}, {2, 1, 1, 0}, {1, 2, 1, 0}, {1, 1, -1, 0}};
  const ScreenVertex* b[4] = {&behind[0], &behind[1], &behind[2], &behind[3]};
  EXPECT_EQ(covered_pixels(b, 4, 16, 16, 4), -1);
}

namespace {

// The graded mesh (cells thinning to 1e-4 at a filament, 1/10 of a pixel at 64 x 64) with an
// optically thin transfer function, framed as bench/scenes/graded_thin.json.
struct Graded {
  Mesh mesh = make_graded(6, kGradedFirstCell, false);
  TransferFunction tf{{{0.0, {0.15, 0.25, 0.6}}, {0.3, {0.9, 0.6, 0.2}}, {0.8, {1.0, 0.95, 0.8}}},
                      {{0.0, 0.02}, {0.2, 0.04}, {0.4, 4.0}, {0.8, 16.0}}};
  Camera camera = test::perspective({3.2, -5.2, 1.6}, {0, 0, 0}, 30.0);
};

ProjectionOptions projection_with(SmallCells mode, double threshold = SplatOptions{}.threshold) {
  ProjectionOptions o;
  o.splat.small_cells = mode, o.splat.threshold = threshold;
  return o;
}

RenderSettings slicing_with(SmallCells mode, int slices) {
  RenderSettings s;
  s.mode = RenderMode::slicing;
  s.slicing.slices = slices;
  s.slicing.splat.small_cells = mode;
  return s;
}

Image render_slicing(const Mesh& m, const TransferFunction& tf, const Camera& c, int size, const RenderSettings& s,
                     RenderReport* report = nullptr) {
  const Volume volume(m.view());
  return render(volume, {test::field_values(m), m.n_points(), "scalar"}, tf, s, c, {size, size}, report);
}

std::int64_t counter(const RenderReport& r, const std::string& name) {
  for (const auto& [n, v] : r.values)
    if (n == name) return std::get<std::int64_t>(v);
  ADD_FAILURE() << "no counter " << name;
  return -1;
}

}  // namespace

TEST(Splat, SmallCellsSplattedLowerTheErrorAgainstTheAntialiasedExactImage) {
  // The reference: exact at 8 x 8 samples per pixel, box-filtered (cellproj compare --downsample 8).
  const Graded g;
  const int size = 48;
  const Image ref = downsample(test::exact(g.mesh, "scalar", g.tf, g.camera, 8 * size, 8 * size), 8);
  ProjectionStats draw_st, splat_st;
  const Image draw = test::project(g.mesh, "scalar", g.tf, g.camera, size, projection_with(SmallCells::draw),
                                   Tetrahedralize::problem, &draw_st);
  const Image splat = test::project(g.mesh, "scalar", g.tf, g.camera, size, projection_with(SmallCells::splat, 8),
                                    Tetrahedralize::problem, &splat_st);
  EXPECT_GT(draw_st.splat.covering_no_pixel, 100);  // cells no pixel centre sees: missed without splats
  EXPECT_EQ(splat_st.splat.splats, splat_st.splat.small_cells);
  EXPECT_LT(compare(splat, ref).rmse, 0.8 * compare(draw, ref).rmse);

  RenderReport draw_r, splat_r;
  const Image sliced = render_slicing(g.mesh, g.tf, g.camera, size, slicing_with(SmallCells::draw, 64), &draw_r);
  const Image splatted = render_slicing(g.mesh, g.tf, g.camera, size, slicing_with(SmallCells::splat, 64), &splat_r);
  EXPECT_GT(counter(draw_r, "cells_between_planes"), 100);
  EXPECT_EQ(counter(splat_r, "cells_between_planes"), 0);    // every one of them splatted
  EXPECT_GT(counter(splat_r, "splat_fragments_masked"), 0);  // the stencil held some splat pixels back
  EXPECT_LT(compare(splatted, ref).rmse, 0.8 * compare(sliced, ref).rmse);
}

TEST(Splat, DrawnTilesCountTheCellsCoveringNoCentreAfterwardsAsTheStreamDoesBefore) {
  // By default (tiles, every cell drawn, a threshold of one centre) the cells covering no pixel
  // centre are counted after the frame, testing only those that added no fragment; the stream
  // tests every cell first. The same counts, with cells adding nothing (extinction 0 below 0.3:
  // they cover centres but add no fragment) and with cells culled as transparent or not.
  const Graded g;
  const TransferFunction part_clear{{{0.0, {0.15, 0.25, 0.6}}, {1.0, {1.0, 0.95, 0.8}}},
                                    {{0.0, 0.0}, {0.3, 0.0}, {0.31, 4.0}, {1.0, 16.0}}};
  for (const TransferFunction* tf : {&g.tf, &part_clear})
    for (bool cull : {true, false}) {
      ProjectionOptions tiles = projection_with(SmallCells::draw), stream = tiles;
      tiles.cull_transparent = stream.cull_transparent = cull;
      stream.compositing = Compositing::stream;
      ProjectionStats after, before;
      test::project(g.mesh, "scalar", *tf, g.camera, 48, tiles, Tetrahedralize::problem, &after);
      test::project(g.mesh, "scalar", *tf, g.camera, 48, stream, Tetrahedralize::problem, &before);
      EXPECT_GT(before.splat.covering_no_pixel, 100);
      EXPECT_EQ(after.splat.covering_no_pixel, before.splat.covering_no_pixel) << "cull " << cull;
      EXPECT_EQ(after.splat.small_cells, before.splat.small_cells) << "cull " << cull;
    }
}

TEST(Splat, WithoutSmallCellsThePictureIsUnchanged) {
  const Mesh box = make_box(6, 6, 6, glm::dvec3(-1), glm::dvec3(1), true);
  Mesh m = box;
  set_field(m, "scalar", [](const glm::dvec3& x) { return 0.5 + 0.4 * x.x; });
  const Graded g;
  ProjectionStats st;
  const Image splat =
      test::project(m, "scalar", g.tf, g.camera, 64, projection_with(SmallCells::splat), Tetrahedralize::problem, &st);
  EXPECT_EQ(st.splat.small_cells, 0);
  EXPECT_EQ(compare(splat, test::project(m, "scalar", g.tf, g.camera, 64, projection_with(SmallCells::draw))).max_abs,
            0.0);
  RenderReport r;
  const Image sliced = render_slicing(m, g.tf, g.camera, 64, slicing_with(SmallCells::splat, 32), &r);
  EXPECT_EQ(counter(r, "small_cells"), 0);
  EXPECT_EQ(compare(sliced, render_slicing(m, g.tf, g.camera, 64, slicing_with(SmallCells::draw, 32))).max_abs, 0.0);
}

TEST(Splat, OneAndManyThreadsGiveTheSameImage) {
  const Graded g;
  auto both = [&] {
    return std::make_pair(test::project(g.mesh, "scalar", g.tf, g.camera, 64, projection_with(SmallCells::splat, 4)),
                          render_slicing(g.mesh, g.tf, g.camera, 64, slicing_with(SmallCells::splat, 48)));
  };
  std::pair<Image, Image> one, many;
  tbb::task_arena(1).execute([&] { one = both(); });
  tbb::task_arena(4).execute([&] { many = both(); });
  EXPECT_EQ(compare(one.first, many.first).max_abs, 0.0);
  EXPECT_EQ(compare(one.second, many.second).max_abs, 0.0);
}

TEST(Splat, SkippedSmallCellsAddNothingAndBadOptionsAreRefused) {
  const Graded g;
  ProjectionStats st;
  test::project(g.mesh, "scalar", g.tf, g.camera, 64, projection_with(SmallCells::skip), Tetrahedralize::problem, &st);
  EXPECT_GT(st.splat.small_cells, 0);
  EXPECT_EQ(st.splat.splats, 0);
  ProjectionOptions bad = projection_with(SmallCells::splat, -1.0);
  EXPECT_THROW(check_options(bad), InputError);
  bad = projection_with(SmallCells::splat);
  bad.splat.prefilter = 0.1;
  EXPECT_THROW(check_options(bad), InputError);
  EXPECT_EQ(resolve(SplatOptions{}, Backend::opengl), SmallCells::draw);  // the default, on every back end
  EXPECT_EQ(resolve(SplatOptions{}, Backend::software), SmallCells::draw);
  SplatOptions on_gl;
  on_gl.small_cells = SmallCells::splat;
  EXPECT_THROW(resolve(on_gl, Backend::opengl), InputError);
}
