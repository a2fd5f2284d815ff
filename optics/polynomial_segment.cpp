#include "optics/polynomial_segment.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <boost/container/small_vector.hpp>

namespace cellproj {
namespace {

constexpr int kN = ScalarPolynomial::kTerms;
constexpr double kPi = 3.14159265358979323846;
constexpr double kNode[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
constexpr double kWeight[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
constexpr double kDepthStep = 0.25;
constexpr int kScan = 32;  // sign changes are looked for between this many samples

// A polynomial in x of degree < kN + 1 (room for an antiderivative).
struct Poly {
  double c[kN + 1] = {};
  double operator()(double x) const {
    double v = 0.0;
    for (int k = kN; k >= 0; --k) v = v * x + c[k];
    return v;
  }
};

// Root of s(x) = b in [xa, xb], where s - b changes sign: bisection to 1e-14.
double crossing(const ScalarPolynomial& s, double b, double xa, double xb) {
  const bool rising = s(xa) < b;
  for (int i = 0; i < 60 && xb - xa > 1e-14; ++i) {
    const double xm = 0.5 * (xa + xb);
    ((s(xm) < b) == rising ? xa : xb) = xm;
  }
  return 0.5 * (xa + xb);
}

}  // namespace

double chebyshev_node(int k) {
  static constexpr double kNodes[kN] = {0.98078528040323043,  0.83146961230254524,  0.55557023301960218,
                                        0.19509032201612825,  -0.19509032201612825, -0.55557023301960218,
                                        -0.83146961230254524, -0.98078528040323043};  // cos((2k + 1) pi / 16)
  return kNodes[k];
}

namespace {

// M[m][k]: the monomial coefficient m of the interpolant of the k-th node's unit value. Chebyshev
// coefficients a_j = (2/n) sum_k v_k T_j(x_k) (a_0 halved), then T_j expanded by
// T_{j+1} = 2x T_j - T_{j-1}.
struct InterpolationMatrix {
  double M[kN][kN] = {};
  InterpolationMatrix() {
    double T[kN][kN] = {};  // T[j][m]: monomial coefficient m of T_j
    T[0][0] = 1.0, T[1][1] = 1.0;
    for (int j = 2; j < kN; ++j)
      for (int m = 0; m < kN; ++m) T[j][m] = (m > 0 ? 2.0 * T[j - 1][m - 1] : 0.0) - T[j - 2][m];
    for (int j = 0; j < kN; ++j)
      for (int k = 0; k < kN; ++k) {
        const double a = std::cos(j * (2 * k + 1) * kPi / (2 * kN)) * (j == 0 ? 1.0 : 2.0) / kN;
        for (int m = 0; m < kN; ++m) M[m][k] += a * T[j][m];
      }
  }
};

}  // namespace

void chebyshev_to_monomial(const double v[kN], ScalarPolynomial& out) {
  static const InterpolationMatrix matrix;  // a constant, built once
  for (int m = 0; m < kN; ++m) {
    double c = 0.0;
    for (int k = 0; k < kN; ++k) c += matrix.M[m][k] * v[k];
    out.c[m] = c;
  }
}

SegmentLight integrate_polynomial_reference(const TransferFunction& tf, double length, const ScalarPolynomial& s) {
  if (!(length > 0.0)) return {};
  // Cut points: every x where s crosses a breakpoint.
  double sample[kScan + 1];
  double lo = s(-1.0), hi = lo;
  for (int i = 0; i <= kScan; ++i) {
    sample[i] = s(-1.0 + 2.0 * i / kScan);
    lo = std::min(lo, sample[i]), hi = std::max(hi, sample[i]);
  }
  boost::container::small_vector<double, 16> cuts{-1.0, 1.0};  // called per cell per ray: no heap
  const auto& bp = tf.breakpoints();
  for (auto it = std::upper_bound(bp.begin(), bp.end(), lo); it != bp.end() && *it < hi; ++it)
    for (int i = 0; i < kScan; ++i)
      if ((sample[i] - *it) * (sample[i + 1] - *it) < 0)
        cuts.push_back(crossing(s, *it, -1.0 + 2.0 * i / kScan, -1.0 + 2.0 * (i + 1) / kScan));
      else if (sample[i + 1] == *it && i + 1 < kScan)
        cuts.push_back(-1.0 + 2.0 * (i + 1) / kScan);
  std::sort(cuts.begin(), cuts.end());

  const double dt_dx = 0.5 * length;
  SegmentLight acc;
  for (std::size_t k = 0; k + 1 < cuts.size() && acc.depth < kOpaqueDepth; ++k) {
    const double xa = cuts[k], xb = cuts[k + 1];
    if (!(xb > xa)) continue;
    // The transfer function's linear piece over s's range on [xa, xb] (no breakpoint inside).
    double plo = std::min(s(xa), s(xb)), phi = std::max(s(xa), s(xb));
    for (int i = 1; i < 8; ++i) {
      const double v = s(xa + (xb - xa) * i / 8);
      plo = std::min(plo, v), phi = std::max(phi, v);
    }
    const auto e = tf.piece(plo, phi);
    const double slope = phi > plo ? 1.0 / (phi - plo) : 0.0;
    auto u_of = [&](double x) { return std::clamp((s(x) - plo) * slope, 0.0, 1.0); };
    // kappa(x) = ka + (kb - ka) u(x), a polynomial; K its antiderivative, so depth is closed form.
    Poly kappa, K;
    for (int m = 0; m < kN; ++m) kappa.c[m] = (e.kb - e.ka) * slope * s.c[m];
    kappa.c[0] += e.ka - (e.kb - e.ka) * slope * plo;
    for (int m = 0; m < kN; ++m) K.c[m + 1] = kappa.c[m] / (m + 1);
    const double depth0 = acc.depth;
    auto depth_at = [&](double x) { return depth0 + dt_dx * (K(x) - K(xa)); };
    // Pieces of optical depth <= 1/4, each by 8-point Gauss-Legendre.
    boost::container::small_vector<std::pair<double, double>, 48> todo{{xa, xb}};  // depth-first: <= 45 deep
    glm::dvec3 sum(0.0);
    while (!todo.empty()) {
      auto [a, b] = todo.back();
      todo.pop_back();
      if (depth_at(a) > kOpaqueDepth) continue;
      if (depth_at(b) - depth_at(a) > kDepthStep && b - a > 1e-12) {
        todo.push_back({0.5 * (a + b), b});  // the front half is done first
        todo.push_back({a, 0.5 * (a + b)});
        continue;
      }
      const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
      for (int i = 0; i < 8; ++i) {
        const double x = mid + (i < 4 ? -kNode[i] : kNode[i - 4]) * half;
        const double u = u_of(x);
        const double kap = std::max(0.0, e.ka + (e.kb - e.ka) * u);
        sum += kWeight[i < 4 ? i : i - 4] * half * kap * std::exp(-depth_at(x)) * (e.ca + (e.cb - e.ca) * u);
      }
    }
    acc.rgb += dt_dx * sum;
    acc.depth = std::max(acc.depth, depth_at(xb));
  }
  return acc;
}

}  // namespace cellproj
