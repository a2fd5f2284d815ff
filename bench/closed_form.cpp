// The closed-form weights of one linear segment (optics/linear_segment.hpp), in ns per call, over
// four regimes of the optical depth a = kappa L at the front and its change along the segment:
// small cells (a in [0.002, 0.05], kappa within 1%), [0.05, 0.55], [0.5, 3.5], and kappa growing
// by up to 50%. Built by bench/closed_form.sh against two versions of the file in one run.
// With `--dump`: the weights (front, back) of 2M random segments of the series region instead
// (a in [1e-3, 16], |b| <= 0.03 (1 + a), 17 digits), for comparing the two versions' values.
// With `--accuracy`: the largest relative error of the weights against long double quadrature
// (64 pieces of 5-point Gauss-Legendre) over 300k segments of small cells (a <= 0.5, |b| <= 0.01).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>
#include "optics/linear_segment.hpp"
using namespace cellproj;
int main(int argc, char** argv) {
  std::mt19937 rng(1);
  if (argc > 1 && std::strcmp(argv[1], "--dump") == 0) {
    std::uniform_real_distribution<double> V(0, 1);
    for (int n = 0; n < 2000000; ++n) {
      const double a = std::pow(10.0, -3 + 4.2 * V(rng)), share = 0.03 * (2 * V(rng) - 1) * std::pow(10.0, -6 * V(rng));
      const double b = share * (1 + a);  // tau = a u + b u^2 over L = 1: k0 = a, k1 = a + 2b
      if (a + 2 * b < 0) continue;
      const EndWeights w = linear_segment_weights(1.0, a, a + 2 * b);
      std::printf("%.17g %.17g\n", w.front, w.back);
    }
    return 0;
  }
  std::uniform_real_distribution<double> U(0, 1);
  if (argc > 1 && std::strcmp(argv[1], "--accuracy") == 0) {
    const long double node[5] = {0.046910077030668004L, 0.230765344947158454L, 0.5L, 0.769234655052841546L,
                                 0.953089922969331996L};
    const long double weight[5] = {0.118463442528094544L, 0.239314335249683234L, 0.284444444444444444L,
                                   0.239314335249683234L, 0.118463442528094544L};
    double worst[2] = {0, 0};
    for (int n = 0; n < 300000; ++n) {
      const double a = 0.5 * (n % 10 ? std::pow(10.0, -8 * U(rng)) : U(rng));
      const double b = 0.01 * (2 * U(rng) - 1) * (n % 3 ? 1.0 : std::pow(10.0, -6 * U(rng)));
      if (a + 2 * b < 0 || a + b <= 0) continue;
      // front = int (1 - e^-tau) du, back = int (e^-tau - e^-D) du = e^-D int expm1(D - tau) du
      long double front = 0, back = 0;
      for (int piece = 0; piece < 64; ++piece)
        for (int i = 0; i < 5; ++i) {
          const long double u = (piece + node[i]) / 64, tau = u * (a + b * u);
          front -= weight[i] * expm1l(-tau) / 64;
          back += weight[i] * expl(-(long double)(a + b)) * expm1l(a * (1 - u) + b * (1 - u * u)) / 64;
        }
      const EndWeights w = linear_segment_weights(1.0, a, a + 2 * b);
      const double b_used = 0.5 * ((a + 2 * b) - a);  // the b the function sees
      if (b_used != b) continue;
      worst[0] = std::max(worst[0], double(std::abs(w.front - front) / front));
      worst[1] = std::max(worst[1], double(std::abs(w.back - back) / back));
    }
    std::printf("small cells: largest relative error front %.2g, back %.2g\n", worst[0], worst[1]);
    return 0;
  }
  struct P {
    double L, k0, k1;
  };
  for (int regime = 0; regime < 4; ++regime) {
    std::vector<P> ps(1000000);
    for (auto& p : ps) {
      double a = regime == 0   ? 0.002 + 0.05 * U(rng)
                 : regime == 1 ? 0.05 + 0.5 * U(rng)
                 : regime == 2 ? 0.5 + 3 * U(rng)
                               : 0.01 + 0.3 * U(rng);
      double rel = regime == 3 ? 0.5 * U(rng) : 0.02 * (U(rng) - 0.5);  // k1/k0 - 1
      p.L = 0.03;
      p.k0 = a / p.L;
      p.k1 = p.k0 * (1 + rel);
    }
    double sink = 0;
    auto t = std::chrono::steady_clock::now();
    for (const auto& p : ps) {
      auto w = linear_segment_weights(p.L, p.k0, p.k1);
      sink += w.front + w.back;
    }
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    std::printf("regime %d: %.1f ns per call (%g)\n", regime, s * 1e9 / ps.size(), sink);
  }
}
