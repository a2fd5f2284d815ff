// The closed-form weights of one linear segment (optics/linear_segment.hpp), in ns per call, over
// four regimes of the optical depth a = kappa L at the front and its change along the segment:
// small cells (a in [0.002, 0.05], kappa within 1%), [0.05, 0.55], [0.5, 3.5], and kappa growing
// by up to 50%. Built by bench/closed_form.sh against two versions of the file in one run.
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>
#include "optics/linear_segment.hpp"
using namespace cellproj;
int main() {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> U(0, 1);
  struct P { double L, k0, k1; };
  for (int regime = 0; regime < 4; ++regime) {
    std::vector<P> ps(1000000);
    for (auto& p : ps) {
      double a = regime == 0 ? 0.002 + 0.05 * U(rng) : regime == 1 ? 0.05 + 0.5 * U(rng) : regime == 2 ? 0.5 + 3 * U(rng) : 0.01 + 0.3 * U(rng);
      double rel = regime == 3 ? 0.5 * U(rng) : 0.02 * (U(rng) - 0.5);  // k1/k0 - 1
      p.L = 0.03; p.k0 = a / p.L; p.k1 = p.k0 * (1 + rel);
    }
    double sink = 0;
    auto t = std::chrono::steady_clock::now();
    for (const auto& p : ps) { auto w = linear_segment_weights(p.L, p.k0, p.k1); sink += w.front + w.back; }
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    std::printf("regime %d: %.1f ns per call (%g)\n", regime, s * 1e9 / ps.size(), sink);
  }
}
