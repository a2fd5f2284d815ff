// The coverage rule (view/raster.hpp): the runs a triangle covers per row are exactly the pixel
// centres the per-pixel rule covers, for every shape, and triangles sharing edges cover each centre
// once.
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "view/raster.hpp"

namespace cellproj {
namespace {

using Pixels = std::set<std::pair<int, int>>;

// The rule pixel by pixel: a centre in the triangle's bounding box, inside all three edge functions
// of the positively turned triangle, a centre on an edge going to the triangle that owns that edge.
// (With huge coordinates the edge functions' rounding would also take in centres outside the box.)
Pixels covered_one_by_one(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, int width, int height) {
  using namespace raster_detail;
  Pixels out;
  const double area = edge(p0, p1, p2.x, p2.y);
  if (!(area != 0.0) || !std::isfinite(area)) return out;
  if (area < 0) std::swap(p1, p2);
  auto in = [](const glm::dvec2& a, const glm::dvec2& b, double x, double y) {
    const double e = edge(a, b, x, y);
    return e > 0 || (e == 0 && owns(a, b));
  };
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const double x = i + 0.5, y = j + 0.5;
      if (x < std::min({p0.x, p1.x, p2.x}) || x > std::max({p0.x, p1.x, p2.x}) || y < std::min({p0.y, p1.y, p2.y}) ||
          y > std::max({p0.y, p1.y, p2.y}))
        continue;
      if (in(p0, p1, x, y) && in(p1, p2, x, y) && in(p2, p0, x, y)) out.insert({i, j});
    }
  return out;
}

Pixels covered_by_runs(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, int width, int height) {
  Pixels out;
  rasterize_triangle_runs(p0, p1, p2, width, height, [&](int j, int begin, int end) {
    EXPECT_LT(begin, end);
    for (int i = begin; i < end; ++i) out.insert({i, j});
  });
  return out;
}

// The weighted rasterizer's centres; on triangles near the image (where the weights keep their
// digits) the weights interpolate the vertices to each centre.
Pixels covered_with_weights(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, int width, int height) {
  Pixels out;
  const bool near =
      std::max({std::abs(p0.x), std::abs(p0.y), std::abs(p1.x), std::abs(p1.y), std::abs(p2.x), std::abs(p2.y)}) < 1e3;
  rasterize_triangle_weights(p0, p1, p2, width, height, [&](int i, int j, double w0, double w1, double w2) {
    out.insert({i, j});
    if (!near) return;
    EXPECT_NEAR(w0 + w1 + w2, 1.0, 1e-9);
    const glm::dvec2 c = w0 * p0 + w1 * p1 + w2 * p2;
    EXPECT_NEAR(c.x, i + 0.5, 1e-9);
    EXPECT_NEAR(c.y, j + 0.5, 1e-9);
  });
  return out;
}

void expect_same_coverage(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, int width, int height) {
  const Pixels want = covered_one_by_one(p0, p1, p2, width, height);
  EXPECT_EQ(covered_by_runs(p0, p1, p2, width, height), want)
      << "(" << p0.x << ", " << p0.y << ") (" << p1.x << ", " << p1.y << ") (" << p2.x << ", " << p2.y << ")";
  EXPECT_EQ(covered_with_weights(p0, p1, p2, width, height), want);
}

TEST(Raster, RunsAreThePixelRuleOnRandomTriangles) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-10.0, 50.0);
  std::uniform_int_distribution<int> grid(-4, 44);
  std::uniform_real_distribution<double> tiny(-0.7, 0.7);
  for (int n = 0; n < 3000; ++n) {
    glm::dvec2 p[3];
    for (auto& q : p) {
      switch (n % 4) {
        case 0: q = {pos(rng), pos(rng)}; break;                                       // anywhere
        case 1: q = {grid(rng) * 0.5, grid(rng) * 0.5}; break;                         // on centres and edges of pixels
        case 2: q = glm::dvec2(20.3, 17.8) + glm::dvec2(tiny(rng), tiny(rng)); break;  // smaller than a pixel
        default: q = {pos(rng), 17.5 + 1e-9 * tiny(rng)}; break;                       // slivers along a row of centres
      }
    }
    expect_same_coverage(p[0], p[1], p[2], 40, 32);
  }
}

// Edges passing within 1e-16 to 1e-9 of a pixel's width from rows of centres, on either side or
// through them: the crossing's estimate is then as likely to fall on either side of a centre as
// the edge's test, and only the test may decide. (A shortcut deciding by the estimate alone where
// it is far enough from every centre gained nothing measurable and was dropped; this test caught
// it with too small a margin.)
TEST(Raster, RunsAreThePixelRuleForEdgesGrazingCentres) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> column(0, 39), row(-3, 35), sign(0, 1);
  std::uniform_real_distribution<double> exponent(-16.0, -9.0), pos(-10.0, 50.0);
  for (int n = 0; n < 4000; ++n) {
    // An edge through (i + 0.5 + d, j + 0.5) and another point of the same column, nearly vertical
    // (or horizontal, transposed): every row it crosses has its crossing that near a centre.
    const double d = (sign(rng) ? 1 : -1) * (n % 5 == 0 ? 0.0 : std::pow(10.0, exponent(rng)));
    const double x = column(rng) + 0.5 + d, slant = n % 3 == 0 ? 0.0 : 1e-12 * (sign(rng) ? 1 : -1);
    glm::dvec2 a(x, row(rng) + 0.5), b(x + slant * 40, a.y + 20 + column(rng)), c(pos(rng), pos(rng));
    if (n % 2) std::swap(a.x, a.y), std::swap(b.x, b.y), std::swap(c.x, c.y);
    expect_same_coverage(a, b, c, 40, 40);
  }
}

// A vertex far off the image: the crossing's estimate is off by many pixels there (cancellation),
// and the edge's own test must still give the exact run.
TEST(Raster, RunsAreThePixelRuleWithHugeCoordinates) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> on(0.0, 40.0), angle(0.0, 6.283185307179586), exponent(9.0, 17.0);
  for (int n = 0; n < 2000; ++n) {
    // One or two vertices far out in any direction, the rest on the image: the long edges cross it.
    const double r = std::pow(10.0, exponent(rng)), a = angle(rng);
    const glm::dvec2 far1(r * std::cos(a), r * std::sin(a)),
        far2(-r * std::cos(a) + on(rng), -r * std::sin(a) + on(rng));
    const glm::dvec2 p(on(rng), on(rng)), q(on(rng), on(rng));
    expect_same_coverage(far1, p, q, 40, 32);
    expect_same_coverage(far1, far2, p, 40, 32);
  }
}

// A jittered grid of triangles whose vertices lie on pixel centres and edges: every centre inside
// the grid is covered exactly once, by runs and by the weighted rasterizer alike.
TEST(Raster, SharedEdgesCoverEachCentreOnce) {
  const int w = 48, h = 40, n = 6;
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> jitter(-2, 2);
  std::vector<glm::dvec2> v((n + 1) * (n + 1));
  for (int b = 0; b <= n; ++b)
    for (int a = 0; a <= n; ++a) {
      const bool inner = a > 0 && a < n && b > 0 && b < n;
      v[b * (n + 1) + a] = {4.0 + 6.5 * a + (inner ? jitter(rng) * 0.5 : 0.0),
                            3.0 + 5.5 * b + (inner ? jitter(rng) * 0.5 : 0.0)};
    }
  std::vector<int> runs(w * h, 0), weighted(w * h, 0);
  for (int b = 0; b < n; ++b)
    for (int a = 0; a < n; ++a) {
      const glm::dvec2 &q00 = v[b * (n + 1) + a], &q10 = v[b * (n + 1) + a + 1], &q01 = v[(b + 1) * (n + 1) + a],
                       &q11 = v[(b + 1) * (n + 1) + a + 1];
      const glm::dvec2 tris[2][3] = {{q00, q10, q11}, {q00, q11, q01}};
      for (const auto& t : tris) {
        rasterize_triangle_runs(t[0], t[1], t[2], w, h, [&](int j, int begin, int end) {
          for (int i = begin; i < end; ++i) ++runs[j * w + i];
        });
        rasterize_triangle_weights(t[2], t[0], t[1], w, h,
                                   [&](int i, int j, double, double, double) { ++weighted[j * w + i]; });
      }
    }
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const double x = i + 0.5, y = j + 0.5;
      const bool inside = x > 4.0 && x < 4.0 + 6.5 * n && y > 3.0 && y < 3.0 + 5.5 * n;
      if (!inside) continue;  // the outer border's centres go to one side or none
      EXPECT_EQ(runs[j * w + i], 1) << i << ", " << j;
      EXPECT_EQ(weighted[j * w + i], 1) << i << ", " << j;
    }
}

// A triangle far outside the image (a vertex just in front of the eye projects to ~1e12 pixels)
// covers nothing, and its box holds no row: the conversion to int is clamped first (it once
// overflowed and made the rows run from INT_MIN).
TEST(Raster, ATriangleFarOutsideTheImageHasNoRows) {
  for (double far : {1e12, -1e12, 1e300}) {
    const TriangleCoverage below({10, far}, {20, far}, {15, 2 * far}, 48, 48);
    EXPECT_GT(below.first_row(), below.last_row()) << far;
    const PixelBox right({far, 10}, {2 * far, 20}, {far, 30}, 48, 48);
    EXPECT_TRUE(right.empty()) << far;
  }
  // One reaching from inside to far outside keeps its rows inside the image.
  const TriangleCoverage t({10, 10}, {1e12, 20}, {10, 1e12}, 48, 48);
  EXPECT_EQ(t.first_row(), 10);
  EXPECT_EQ(t.last_row(), 47);
}

TEST(Raster, SpansCoverThePixelsOfTheWeightsAndStepToTheirValues) {
  // A run's first weights plus k steps are pixel k's weights (the shading of pt-linear and
  // pt-table), and the runs cover exactly the pixels rasterize_triangle_weights visits.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> pos(-10.0, 80.0);
  for (int n = 0; n < 500; ++n) {
    const glm::dvec2 a(pos(rng), pos(rng)), b(pos(rng), pos(rng)), c(pos(rng), pos(rng));
    std::vector<std::pair<long, std::array<double, 3>>> per_pixel, stepped;
    rasterize_triangle_weights(a, b, c, 64, 48, [&](int i, int j, double w0, double w1, double w2) {
      per_pixel.push_back({j * 64L + i, {w0, w1, w2}});
    });
    double dw[3] = {0, 0, 0};
    rasterize_triangle_spans(
        a, b, c, 64, 48, [&](const double* steps) { std::copy(steps, steps + 3, dw); },
        [&](int j, int begin, int end, const double* w) {
          ASSERT_LT(begin, end);
          for (int i = begin; i < end; ++i)
            stepped.push_back(
                {j * 64L + i, {w[0] + (i - begin) * dw[0], w[1] + (i - begin) * dw[1], w[2] + (i - begin) * dw[2]}});
        });
    ASSERT_EQ(stepped.size(), per_pixel.size()) << n;
    for (std::size_t k = 0; k < stepped.size(); ++k) {
      ASSERT_EQ(stepped[k].first, per_pixel[k].first) << n;
      for (int v = 0; v < 3; ++v) EXPECT_NEAR(stepped[k].second[v], per_pixel[k].second[v], 1e-12) << n;
    }
  }
}

}  // namespace
}  // namespace cellproj
