// Volumetric depth peeling (--method layers, issue 20): the crossings of an iso-value along each
// ray against the closed form on nested spheres, the shading against the spheres' analytic
// normals, blending, silhouettes, robustness where a vertex value equals the iso-value.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <tbb/task_arena.h>
#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "mesh/generate.hpp"
#include "raycast/iso_layers.hpp"
#include "raycast/isoparametric.hpp"
#include "render/renderer.hpp"
#include "render/settings_table.hpp"
#include "tests/test_util.hpp"

namespace cellproj {
namespace {

std::vector<IsoCrossing> crossings_of(const std::vector<RaySegment>& segs, double iso) {
  std::vector<IsoCrossing> out;
  iso_crossings(segs.data(), segs.size(), iso, 1e-12, [&](const IsoCrossing& c) { out.push_back(c); });
  return out;
}

TEST(IsoLayers, CrossingsOfHandMadeRaysAreCountedOnceAndTouchesNotAtAll) {
  // {t0, t1, s0, s1, cell, tet}
  auto c = crossings_of({{0, 1, 0, 2, 0, 0}}, 1.0);  // a root inside a segment
  ASSERT_EQ(c.size(), 1u);
  EXPECT_DOUBLE_EQ(c[0].t, 0.5);
  EXPECT_TRUE(c[0].entering);
  c = crossings_of({{0, 1, 0, 1, 0, 0}, {1, 2, 1, 0, 1, 1}}, 1.0);  // touches V at a vertex, turns back
  EXPECT_EQ(c.size(), 0u);
  c = crossings_of({{0, 1, 0, 1, 0, 0}, {1, 2, 1, 2, 1, 1}}, 1.0);  // passes through V at a vertex
  ASSERT_EQ(c.size(), 1u);
  EXPECT_DOUBLE_EQ(c[0].t, 1.0);
  c = crossings_of({{0, 1, 3, 1, 0, 0}, {1, 2, 1, 1, 1, 1}, {2, 3, 1, 0, 2, 2}}, 1.0);  // along V, then through
  ASSERT_EQ(c.size(), 1u);
  EXPECT_DOUBLE_EQ(c[0].t, 1.0);
  EXPECT_FALSE(c[0].entering);
  c = crossings_of({{0, 1, 3, 1, 0, 0}, {1, 2, 1, 1, 1, 1}, {2, 3, 1, 2, 2, 2}}, 1.0);  // along V, then back
  EXPECT_EQ(c.size(), 0u);
  // Rounding at a shared face: the two cells disagree about the side by an ulp; one crossing.
  c = crossings_of({{0, 1, 0, 1 + 1e-16, 0, 0}, {1, 2, 1 - 1e-16, 2, 1, 1}}, 1.0);
  EXPECT_EQ(c.size(), 1u);
  // A gap (the ray outside a non-convex mesh) is no crossing, whichever side the ray re-enters on.
  c = crossings_of({{0, 1, 2, 2, 0, 0}, {2, 3, 0, 0, 1, 1}}, 1.0);
  EXPECT_EQ(c.size(), 0u);
  c = crossings_of({{0, 1, 0, 2, 0, 0}, {2, 3, 2, 0, 1, 1}}, 1.0);  // one crossing in each part
  ASSERT_EQ(c.size(), 2u);
  EXPECT_DOUBLE_EQ(c[1].t, 2.5);
  EXPECT_FALSE(c[1].entering);
}

// The ray of pixel (i, j), and its distance b from the centre of the shells and the t of closest approach.
struct PixelRay {
  Ray ray;
  double b, tc;
};
PixelRay pixel_ray(const Camera& camera, int n, int i, int j) {
  const Ray r = PixelRays(camera, n, n).ray(i + 0.5, j + 0.5);
  const double tc = -glm::dot(r.origin, r.dir);
  return {r, glm::length(r.origin + tc * r.dir), tc};
}

// Views of the shells: orthographic from above and obliquely, perspective from a corner.
std::vector<Camera> shell_views() {
  return {test::looking_down(2.2), test::view_from({2.0, -3.0, 4.0}, Projection::Orthographic, 2.2),
          test::perspective({2.2, -2.6, 1.8}, {0.05, 0.02, 0}, 45)};
}

// The depths at which a pixel's ray crosses the shells' spheres, in order; near_tangent when it
// passes within 1.5 h of a sphere's tangent (where the mesh's contour may cross it otherwise).
std::vector<double> sphere_crossings(const PixelRay& pr, double h, bool& near_tangent) {
  std::vector<double> expect;
  for (double r : kShellRadii) {
    near_tangent |= std::abs(pr.b - r) < 1.5 * h;
    if (r > pr.b) expect.push_back(pr.tc - std::sqrt(r * r - pr.b * pr.b));
  }
  for (std::size_t k = expect.size(); k-- > 0;) expect.push_back(2 * pr.tc - expect[k]);
  std::sort(expect.begin(), expect.end());
  return expect;
}

TEST(IsoLayers, CountsAndDepthsOnNestedShellsMatchTheClosedForm) {
  // Iso-value 0 of `generate shells` is the spheres r = 1/6, 1/2, 5/6: a ray passing at b from the
  // centre crosses each larger sphere at t = tc -/+ sqrt(r^2 - b^2). The piecewise-linear field
  // moves the roots by O(h^2) away from the spheres' tangent rays; rays within 1.5 h of a tangent are
  // not compared.
  const int n = 40;
  for (const char* kind : {"shells-tets", "shells"}) {
    const Mesh m = generate(kind, 24);
    const double h = 2.0 / 24;
    const CellRayTracer tracer(m.view());
    for (const Camera& camera : shell_views()) {
      const LayerDepths d = layer_depths(tracer, test::field_values(m), 0.0, 1e-12, camera, n, n, 6);
      int compared = 0;
      double worst = 0.0;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          bool near_tangent = false;
          const std::vector<double> expect = sphere_crossings(pixel_ray(camera, n, i, j), h, near_tangent);
          if (near_tangent) continue;
          ++compared;
          const std::size_t p = static_cast<std::size_t>(j) * n + i;
          ASSERT_EQ(d.count[p], static_cast<int>(expect.size())) << kind << " pixel " << i << "," << j;
          for (std::size_t k = 0; k < expect.size(); ++k) worst = std::max(worst, std::abs(d.t[p * 6 + k] - expect[k]));
        }
      EXPECT_GT(compared, n * n / 3) << kind;
      EXPECT_LT(worst, 0.02) << kind << ": the depth of a crossing against the sphere's";
    }
  }
}

// The crossings of V along one ray of the isoparametric field (raycast/isoparametric.hpp): in each
// run of a cell's segments, sign changes among 33 samples, each root bisected to 1e-12.
std::vector<double> isoparametric_crossings(const IsoparametricField& iso, const double* scalar, const Ray& ray,
                                            const RaySegment* seg, std::size_t n, double v) {
  std::vector<double> roots;
  for (std::size_t k = 0; k < n;) {
    std::size_t end = k + 1;
    while (end < n && seg[end].cell == seg[k].cell) ++end;
    const double ta = seg[k].t0, tb = seg[end - 1].t1;
    glm::dvec3 xi = iso.centre_guess(seg[k].cell);
    const auto f = [&](double t) {
      double s = 0.0;
      if (!iso.value(scalar, seg[k].cell, ray.origin + t * ray.dir, xi, s)) xi = iso.centre_guess(seg[k].cell);
      return s - v;
    };
    double t0 = ta, f0 = f(ta);
    for (int q = 1; q <= 32; ++q) {
      const double t1 = ta + (tb - ta) * q / 32, f1 = f(t1);
      if ((f0 < 0) != (f1 < 0)) {
        double lo = t0, hi = t1, flo = f0;
        while (hi - lo > 1e-12) {
          const double mid = 0.5 * (lo + hi), fm = f(mid);
          ((fm < 0) == (flo < 0) ? lo : hi) = mid;
          if ((fm < 0) == (flo < 0)) flo = fm;
        }
        roots.push_back(0.5 * (lo + hi));
      }
      t0 = t1, f0 = f1;
    }
    k = end;
  }
  return roots;
}

TEST(IsoLayers, TheHexahedraContourOfTheCanonicalTetsAgainstTheIsoparametricOne) {
  // Iso-surfaces and layers follow the field linear in each canonical tetrahedron. On hexahedra
  // the solver's field is trilinear (isoparametric): per ray, the crossings of both on the shells
  // (cos 3 pi r = 0: r = 1/6, 1/2, 5/6), against each other and the spheres, for two resolutions.
  // Rays within 1.5 h of a tangent, and rays where the two contours cross a different number of
  // times, are left out of the depths (counted). The figures are quoted in docs/methods.md.
  for (int res : {24, 48}) {
    const Mesh m = generate("shells", res);
    const double h = 2.0 / res;
    const CellRayTracer tracer(m.view());
    const IsoparametricField iso(m.view(), tracer.points());
    const double* scalar = test::field_values(m);
    double tets_vs_iso = 0.0, sum2 = 0.0, tets_vs_sphere = 0.0, iso_vs_sphere = 0.0;
    int compared = 0, differing = 0, crossings = 0;
    const int n = 48;
    for (const Camera& camera : shell_views()) {
      std::vector<std::vector<double>> lin(n * n), tri(n * n);
      tracer.trace(camera, n, n, scalar, [&](int i, int j, const Ray& ray, const RaySegment* seg, std::size_t ns) {
        iso_crossings(seg, ns, 0.0, 1e-12, [&](const IsoCrossing& c) { lin[j * n + i].push_back(c.t); });
        tri[j * n + i] = isoparametric_crossings(iso, scalar, ray, seg, ns, 0.0);
      });
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          bool near_tangent = false;
          const std::vector<double> expect = sphere_crossings(pixel_ray(camera, n, i, j), h, near_tangent);
          const auto& a = lin[j * n + i];
          const auto& b = tri[j * n + i];
          if (near_tangent) continue;
          if (a.size() != b.size() || a.size() != expect.size()) {
            ++differing;
            continue;
          }
          ++compared;
          crossings += static_cast<int>(a.size());
          for (std::size_t k = 0; k < a.size(); ++k) {
            tets_vs_iso = std::max(tets_vs_iso, std::abs(a[k] - b[k]));
            sum2 += (a[k] - b[k]) * (a[k] - b[k]);
            tets_vs_sphere = std::max(tets_vs_sphere, std::abs(a[k] - expect[k]));
            iso_vs_sphere = std::max(iso_vs_sphere, std::abs(b[k] - expect[k]));
          }
        }
    }
    std::printf(
        "shells %d^3 (h = %.4f): %d rays, %d crossings compared, %d rays with a different crossing count; "
        "depth, canonical tets vs isoparametric: max %.4f (%.2f h), rms %.5f; against the spheres: tets %.4f, "
        "isoparametric %.4f\n",
        res, h, compared, crossings, differing, tets_vs_iso, tets_vs_iso / h, std::sqrt(sum2 / std::max(crossings, 1)),
        tets_vs_sphere, iso_vs_sphere);
    EXPECT_GT(crossings, 1000);
    EXPECT_GT(compared, differing * 10);
    EXPECT_LT(tets_vs_iso, 0.3 * h);  // second order in h: the two contours differ well inside a cell
  }
}

Image layers_image(const Mesh& m, const Camera& camera, int n, const LayerOptions& o, LayerStats* st = nullptr) {
  const CellRayTracer tracer(m.view());
  const TransferFunction tf = test::constant_tf(1.0, {0.9, 0.6, 0.3});
  return render_layers(tracer, test::field_values(m), m.n_points(), tf, camera, n, n, o, st);
}

TEST(IsoLayers, EachLayerIsShadedByTheSpheresNormalAndBlendsAsItsWeightsSay) {
  const Mesh m = generate("shells-tets", 24);
  const int n = 48;
  const Camera camera = test::perspective({2.2, -2.6, 1.8}, {0, 0, 0}, 45);
  const glm::dvec3 base(0.9, 0.6, 0.3);
  const CellRayTracer tracer(m.view());
  const LayerDepths d = layer_depths(tracer, test::field_values(m), 0.0, 1e-12, camera, n, n, 3);
  Image layer[4];
  for (int k = 1; k <= 3; ++k) {
    LayerOptions o;
    o.layers = {k};
    layer[k] = layers_image(m, camera, n, o);
    double sum = 0.0;
    int shaded = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::size_t p = static_cast<std::size_t>(j) * n + i;
        const float* px = layer[k].pixel(i, j);
        ASSERT_EQ(px[3], d.count[p] >= k ? 1.0f : 0.0f) << "layer " << k << " pixel " << i << "," << j;
        if (d.count[p] < k) continue;
        // An independent shade: the sphere's radial normal at the crossing found by the depths.
        const PixelRay pr = pixel_ray(camera, n, i, j);
        const glm::dvec3 at = pr.ray.origin + d.t[p * 3 + k - 1] * pr.ray.dir;
        const glm::dvec3 expect = shade_layer(base, glm::normalize(at), pr.ray.dir);
        for (int c = 0; c < 3; ++c) sum += std::abs(px[c] - expect[c]);
        ++shaded;
      }
    ASSERT_GT(shaded, 50);
    EXPECT_LT(sum / (3 * shaded), 0.03) << "layer " << k << ": mean shade error against the analytic normal";
  }
  LayerOptions o;
  o.layers = {1, 3};
  o.weights = {3.0, 1.0};
  const Image blend = layers_image(m, camera, n, o);
  for (std::size_t p = 0; p < static_cast<std::size_t>(n) * n; ++p) {
    const float* b = blend.rgba.data() + 4 * p;
    const float *l1 = layer[1].rgba.data() + 4 * p, *l3 = layer[3].rgba.data() + 4 * p;
    for (int c = 0; c < 3; ++c) {
      const double expect = l3[3] > 0 ? (3.0 * l1[c] + l3[c]) / 4.0 : l1[c];  // only the layers the ray reaches
      ASSERT_NEAR(b[c], expect, 1e-6);
    }
  }
}

TEST(IsoLayers, SilhouettesLieWhereTheViewGrazesASphereVisibleOnTheFrontOneOnly) {
  const Mesh m = generate("shells-tets", 32);
  const int n = 64;
  const Camera camera = test::looking_down(2.2);
  LayerOptions o;
  o.layers = {1, 2, 3};
  o.silhouettes = Silhouettes::both;
  LayerStats st;
  const Image img = layers_image(m, camera, n, o, &st);
  int visible = 0, hidden = 0;
  const double h = 2.0 / 32, eps = o.silhouette_epsilon;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const float* px = img.pixel(i, j);
      const bool grey = px[3] == 1.0f && px[0] == px[1] && px[1] == px[2] && px[0] > 0.3f && px[0] < 0.9f;
      const bool black = px[3] == 1.0f && px[0] == 0.0f && px[1] == 0.0f && px[2] == 0.0f;
      if (!grey && !black) continue;
      // Where |d . n| < eps on a sphere of radius r: b in [r sqrt(1 - eps^2), r], widened by the mesh's h.
      const double b = pixel_ray(camera, n, i, j).b;
      int near = -1;
      for (int s = 0; s < 3; ++s)
        if (b > kShellRadii[s] * std::sqrt(1 - eps * eps) - 1.5 * h && b < kShellRadii[s] + 1.5 * h) near = s;
      ASSERT_GE(near, 0) << "a silhouette pixel at b = " << b << " is near no sphere's contour";
      if (black) {
        EXPECT_EQ(near, 2) << "visible silhouettes are on the outer sphere, the front layer";
        ++visible;
      } else {
        ++hidden;
      }
    }
  EXPECT_GT(visible, 20);
  EXPECT_GT(hidden, 10);
  EXPECT_EQ(st.silhouette_pixels, visible + hidden);
}

TEST(IsoLayers, TheSamePictureFromOneAndTwoThreads) {
  const Mesh m = generate("shells", 10);
  LayerOptions o;
  o.layers = {1, 2};
  o.silhouettes = Silhouettes::hidden;
  Image a, b;
  tbb::task_arena(1).execute([&] { a = layers_image(m, test::view_from({2, -3, 4}, Projection::Perspective), 40, o); });
  tbb::task_arena(2).execute([&] { b = layers_image(m, test::view_from({2, -3, 4}, Projection::Perspective), 40, o); });
  EXPECT_EQ(a.rgba, b.rgba);
}

TEST(IsoLayers, BadOptionsAreRefusedNamingTheOption) {
  const auto refused = [](std::vector<std::pair<std::string, std::string>> given, const std::string& says) {
    try {
      RenderOptions o;
      for (const auto& [name, value] : given) set_option(o, name, value);  // each value checked as it is set
      settings_from(o);
      ADD_FAILURE() << "accepted; expected: " << says;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  };
  refused({{"method", "layers"}}, "needs setting 'iso'");
  refused({{"method", "layers"}, {"iso", "x"}}, "setting 'iso'");
  refused({{"method", "layers"}, {"iso", "0.5:1,2"}}, "colour");
  refused({{"method", "layers"}, {"iso", "0"}, {"layer", "2,1"}}, "increasing");
  refused({{"method", "layers"}, {"iso", "0"}, {"layer", "0"}}, "numbered from 1");
  refused({{"method", "layers"}, {"iso", "0"}, {"layer", "1,2"}, {"layer-weights", "1"}}, "one per layer");
  refused({{"method", "layers"}, {"iso", "0"}, {"layer-weights", "-1"}}, ">= 0");
  refused({{"method", "layers"}, {"iso", "0"}, {"silhouettes", "some"}}, "setting 'silhouettes'");
  refused({{"method", "layers"}, {"iso", "0"}, {"silhouette-epsilon", "2"}}, "setting 'silhouette-epsilon'");
  RenderOptions o;
  set_option(o, "method", "layers");
  set_option(o, "iso", "0.25:1,0,0");
  set_option(o, "layer", "1,3");
  const RenderSettings s = settings_from(o);
  EXPECT_EQ(s.mode, RenderMode::layers);
  EXPECT_EQ(s.layers.iso, 0.25);
  EXPECT_EQ(s.layers.layers, (std::vector<int>{1, 3}));
  ASSERT_TRUE(s.layers.color.has_value());
  EXPECT_EQ(s.layers.color->r, 1.0);
}

}  // namespace
}  // namespace cellproj
