// pt-linear's fan kernels (projection/tet_fan.hpp's FanLanes) on the same tetrahedra, timed in
// turn in one process: random tetrahedra of about the 1M box's size on screen at 1024² (bench/
// scenes/box_1m.json: ~36 pixels each) composited over a 256² image again and again. Prints each
// kernel's ns per pixel (the fastest of its rounds) and its ratio to `quantities` (AVX2, one pixel
// at a time), and whether the images are the same bits; then the AVX2 kernel's per-pixel
// arithmetic alone (arithmetic_alone). Built and run by bench/fan_kernels.sh.
// usage: fan_kernels [SPREAD_PIXELS=4] [ROUNDS=7]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

#include <immintrin.h>

#include "projection/projected_tet.hpp"
#include "projection/tet_fan.hpp"
#include "view/raster.hpp"

using namespace cellproj;

namespace {

constexpr int kSize = 256;

struct Fan {
  FanPlanes planes;
  int i0, j0, rows, width;
};

std::vector<Fan> random_fans(double spread, int n) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> centre(spread + 1, kSize - spread - 1), d(-spread, spread), z(1, 5), u(0, 1);
  std::vector<Fan> fans;
  while (static_cast<int>(fans.size()) < n) {
    const double cx = centre(rng), cy = centre(rng);
    ScreenVertex v[4];
    for (auto& p : v) p = {cx + d(rng), cy + d(rng), z(rng), 0.0};
    const ProjectedTet pt = project_tet(v, false);
    if (pt.hull_size == 0 || pt.edge_on) continue;
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (int k = 0; k < pt.hull_size; ++k)
      x0 = std::min(x0, pt.hull[k].x), x1 = std::max(x1, pt.hull[k].x), y0 = std::min(y0, pt.hull[k].y),
      y1 = std::max(y1, pt.hull[k].y);
    const PixelBox box({x0, y0}, {x1, y1}, {x0, y0}, kSize, kSize);
    if (box.empty()) continue;
    double thick[kFanQuantities] = {}, hull[4][kFanQuantities] = {};
    thick[0] = 0.05 + 0.1 * u(rng);  // opacity at the thick vertex, colour
    for (int m = 1; m < 4; ++m) thick[m] = u(rng);
    for (int k = 0; k < pt.hull_size; ++k)
      for (int m = 1; m < 4; ++m) hull[k][m] = u(rng);  // the outline: zero thick, zero opacity
    Fan f{fan_planes(pt, box.i0 + 0.5, box.j0 + 0.5, 4, thick, hull), box.i0, box.j0, box.j1 - box.j0 + 1,
          box.i1 - box.i0 + 1};
    if (f.planes.sectors == 0) continue;
    f.planes.linear_opacity = true;
    fans.push_back(f);
  }
  return fans;
}

// The AVX2 kernel's per-pixel arithmetic alone, on one synthetic row of n pixels: the wedge values,
// one triangle's interpolation (no choice among them), the finish and "over" onto 1024 pixels
// (in L1): the floor the kernel's instruction mix sets, without its loads, choice or row ends.
__attribute__((target("avx2"), noinline)) std::int64_t arithmetic_alone(std::int64_t n, float* image) {
  const __m256d one = _mm256_set1_pd(1.0), spoke_c = _mm256_set_pd(1, 2, 3, 4),
                spoke_gx = _mm256_set_pd(.1, .2, -.3, .4), q0 = _mm256_set_pd(.5, .1, .2, .3),
                qx = _mm256_set_pd(.001, .002, .003, .004), left_out = _mm256_set1_pd(-0.5);
  __m256d x = _mm256_set1_pd(0.5);
  std::int64_t added = 0;
  for (std::int64_t i = 0; i < n; ++i, x = _mm256_add_pd(x, one)) {
    const __m256d spoke = _mm256_add_pd(spoke_c, _mm256_mul_pd(spoke_gx, x));
    const __m256d next = _mm256_permute4x64_pd(spoke, 0x39);
    const __m256d w = _mm256_add_pd(_mm256_min_pd(spoke, _mm256_xor_pd(next, _mm256_set1_pd(-0.0))), left_out);
    const __m256d inside = _mm256_and_pd(_mm256_cmp_pd(w, _mm256_setzero_pd(), _CMP_GT_OQ), one);
    const __m256d u =
        _mm256_max_pd(_mm256_add_pd(q0, _mm256_mul_pd(qx, _mm256_add_pd(inside, x))), _mm256_setzero_pd());
    const __m256d alpha = _mm256_min_pd(_mm256_permute4x64_pd(u, 0xFF), one);
    const __m256d src = _mm256_blend_pd(_mm256_mul_pd(u, alpha), alpha, 0x8);
    const __m128 s = _mm256_cvtpd_ps(src), t = _mm_sub_ps(_mm_set1_ps(1.0f), _mm_shuffle_ps(s, s, 0xFF));
    float* dst = image + 4 * (i & 1023);
    _mm_storeu_ps(dst, _mm_add_ps(s, _mm_mul_ps(t, _mm_loadu_ps(dst))));
    added += _mm256_movemask_pd(_mm256_cmp_pd(src, _mm256_setzero_pd(), _CMP_NEQ_UQ)) != 0;
  }
  return added;
}

}  // namespace

int main(int argc, char** argv) {
  const double spread = argc > 1 ? std::atof(argv[1]) : 4.0;
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 7;
  const std::vector<Fan> fans = random_fans(spread, 20000);
  const FanLanes kernels[] = {FanLanes::quantities, FanLanes::pairs, FanLanes::pixels};
  const char* names[] = {"quantities", "pairs", "pixels"};
  double best[3] = {INFINITY, INFINITY, INFINITY};
  std::int64_t pixels[3] = {};
  std::vector<Image> images(3, Image(kSize, kSize));
  for (int r = 0; r < rounds; ++r)
    for (int k = 0; k < 3; ++k) {
      Image& image = images[k];
      std::fill(image.rgba.begin(), image.rgba.end(), 0.0f);
      const auto t0 = std::chrono::steady_clock::now();
      std::int64_t n = 0;
      for (int pass = 0; pass < 10; ++pass)
        for (const Fan& f : fans) n += fan_composite_over(f.planes, image, f.i0, f.j0, 0, f.rows, f.width, kernels[k]);
      best[k] = std::min(best[k], std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      pixels[k] = n;
    }
  std::printf("spread %.1f px: %.1f pixels a tetrahedron\n", spread, pixels[0] / 10.0 / fans.size());
  for (int k = 0; k < 3; ++k)
    std::printf(
        "%-10s %6.2f ns a pixel  %.3f of quantities  %s\n", names[k], 1e9 * best[k] / pixels[k], best[k] / best[0],
        pixels[k] == pixels[0] &&
                std::memcmp(images[k].rgba.data(), images[0].rgba.data(), images[0].rgba.size() * sizeof(float)) == 0
            ? "same bits"
            : "DIFFERENT");
  if (__builtin_cpu_supports("avx2")) {
    std::vector<float> row(4 * 1024, 0.0f);
    double alone = INFINITY;
    const std::int64_t n = 100000000;
    for (int r = 0; r < 3; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      if (arithmetic_alone(n, row.data()) < 0) std::printf("?");
      alone = std::min(alone, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    std::printf("%-10s %6.2f ns a pixel  %.3f of quantities  (its arithmetic alone)\n", "arithmetic", 1e9 * alone / n,
                alone / n / (best[0] / pixels[0]));
  }
}
