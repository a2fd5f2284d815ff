#include "optics/linear_segment.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include "base/simd.hpp"

namespace cellproj {
namespace {

constexpr double kSqrtPi = 1.7724538509055160273;

// |b| below this share of 1 + a: F by its series in b (the erfcx and Dawson forms cancel there).
constexpr double kSeriesB = 0.03;
constexpr int kSeriesTerms = 13;  // n = 0 .. 12: relative error below 1e-13 within kSeriesB

// 1 / k for k < 128: the recursions' divisions, as multiplications (the same values: IEEE division
// is correctly rounded at compile time as at run time).
constexpr std::array<double, 128> kInverse = [] {
  std::array<double, 128> r{};
  for (int k = 1; k < 128; ++k) r[k] = 1.0 / k;
  return r;
}();

// Small cells: up to these optical depths at the front (a) and changes along the ray (|b|), G = 1 - F
// and 1 - e^-D come from their Taylor series in (a, b), with no exp and no loop that ends on a test.
constexpr double kSmallA = 0.5, kSmallB = 1e-2;
constexpr int kSmallPowersOfB = 7;                                          // b^0 .. b^6
constexpr int kSmallDegreeInA[kSmallPowersOfB] = {14, 12, 11, 9, 7, 4, 1};  // of a, per power of b: within the
// bounds above each dropped term is below 1e-16 of G (G >= a/3 and >= b/3 since a + 2b >= 0)
// kG[n][j] = -(-1)^(j+n) / (j! n! (j + 2n + 1)): the integral over [0, 1] of the a^j b^n term of
// 1 - e^{-a u - b u^2}; the constant term cancels the 1.
constexpr auto kG = [] {
  std::array<std::array<double, 15>, kSmallPowersOfB> g{};
  double n_factorial = 1.0;
  for (int n = 0; n < kSmallPowersOfB; ++n) {
    double j_factorial = 1.0;
    for (int j = 0; j < 15; ++j) {
      g[n][j] = ((j + n) % 2 ? 1.0 : -1.0) / (j_factorial * n_factorial * (j + 2 * n + 1));
      j_factorial *= j + 1;
    }
    n_factorial *= n + 1;
  }
  g[0][0] = 0.0;
  return g;
}();
// kE[m] = -(-1)^m / m!: 1 - e^-D = sum_m kE[m] D^m, m = 1 .. 16 (the first dropped term below 1e-19 D
// for D <= kSmallA + kSmallB).
constexpr auto kE = [] {
  std::array<double, 17> e{};
  double factorial = 1.0;
  for (int m = 1; m < 17; ++m) factorial *= m, e[m] = (m % 2 ? 1.0 : -1.0) / factorial;
  return e;
}();

constexpr int floor_log2(int n) { return n < 2 ? 0 : 1 + floor_log2(n / 2); }

// Segments' values side by side in one register (GCC's vector extension, also clang's): each
// lane is computed by the scalar code's operations in the scalar code's order, so it holds the same
// bits. Four lanes with AVX2, two with SSE2 (every x86-64 processor; NEON elsewhere).
using f64x4 = double __attribute__((vector_size(32)));
using f64x2 = double __attribute__((vector_size(16)));
// The templates below take and return vectors by value, always inlined into a function of the
// vector's target: no call passes one, so the ABI note for 32-byte vectors does not apply.
#pragma GCC diagnostic ignored "-Wpsabi"

// A coefficient as a value of the evaluation's type: itself, or the same in every lane.
template <class T, class C>
[[gnu::always_inline]] inline T lift(const C& c) {
  if constexpr (std::is_same_v<T, C>) {
    return c;
  } else {
    T v{};
    for (std::size_t m = 0; m < sizeof(T) / sizeof(double); ++m) v[m] = c;
    return v;
  }
}

// c[0] + c[1] x + ... + c[N-1] x^(N-1) by Estrin's scheme: the two halves independently, joined by
// a power of x (x_pow[k] = x^(2^k)), so the dependent chain is log2(N) steps instead of N.
template <int N, class C, class T>
[[gnu::always_inline]] inline T estrin(const C* c, const T* x_pow) {
  if constexpr (N == 1) {
    return lift<T>(c[0]);
  } else {
    constexpr int k = floor_log2(N - 1), half = 1 << k;
    return estrin<half>(c, x_pow) + x_pow[k] * estrin<N - half>(c + half, x_pow);
  }
}

// The weights of a small cell (a <= kSmallA, |b| <= kSmallB) from the series above: of one segment
// (T = double) or of four (T = f64x4), with the same operations.
template <class T, std::size_t... n>
[[gnu::always_inline]] inline T small_cell_front(T a, T b, std::index_sequence<n...>) {
  const T a2 = a * a, a4 = a2 * a2, a_pow[4] = {a, a2, a4, a4 * a4};
  const T b2 = b * b, b_pow[3] = {b, b2, b2 * b2};
  const T p[] = {estrin<kSmallDegreeInA[n] + 1>(kG[n].data(), a_pow)...};  // the powers of b's coefficients
  return estrin<sizeof...(n)>(p, b_pow);
}

template <class T>
struct SmallCellWeights {
  T front, back, depth, opacity;
};

template <class T>
[[gnu::always_inline]] inline SmallCellWeights<T> small_cell_weights(T a, T b) {
  const T g = small_cell_front(a, b, std::make_index_sequence<kSmallPowersOfB>());
  const T d = a + b, d2 = d * d, d4 = d2 * d2, d_pow[4] = {d, d2, d4, d4 * d4};
  const T e = d * estrin<16>(kE.data() + 1, d_pow);  // 1 - e^-D
  return {g, e - g, d, e};
}

// The weights of segments 0 .. n - 1 (n a multiple of 4) that are small cells by
// linear_segment_weights' rule, V's lanes at a time; the others get a NaN depth (a small cell's is
// finite), for the caller to work out one by one.
template <class V>
[[gnu::always_inline]] inline void small_cells(std::size_t n, const double* L, const double* k0, const double* k1,
                                               EndWeights* w) {
  constexpr std::size_t lanes = sizeof(V) / sizeof(double);
  for (std::size_t k = 0; k < n; k += lanes) {
    V l, c0, c1;
    std::memcpy(&l, L + k, sizeof l), std::memcpy(&c0, k0 + k, sizeof c0), std::memcpy(&c1, k1 + k, sizeof c1);
    const V a = c0 * l, b = 0.5 * (c1 - c0) * l;  // as linear_segment_weights
    const auto small = (l > 0.0) & (c0 + c1 > 0.0) & (a <= kSmallA) & ((b < 0.0 ? -b : b) <= kSmallB);
    const SmallCellWeights<V> s = small_cell_weights(a, b);
    for (std::size_t m = 0; m < lanes; ++m)
      w[k + m] = {s.front[m], s.back[m], small[m] ? s.depth[m] : std::numeric_limits<double>::quiet_NaN(),
                  s.opacity[m]};
  }
}

#if CELLPROJ_AVX2_DISPATCH
__attribute__((target("avx2"))) void small_cells_avx2(std::size_t n, const double* L, const double* k0,
                                                      const double* k1, EndWeights* w) {
  small_cells<f64x4>(n, L, k0, k1, w);
}
#endif

// Four lanes where the processor has AVX2, else two.
void small_cells(std::size_t n, const double* L, const double* k0, const double* k1, EndWeights* w) {
#if CELLPROJ_AVX2_DISPATCH
  if (__builtin_cpu_supports("avx2")) return small_cells_avx2(n, L, k0, k1, w);
#endif
  small_cells<f64x2>(n, L, k0, k1, w);
}

// M_k(a) = int_0^1 u^k e^{-a u} du for k = 0 .. kmax, by the recursion M_k = (k M_{k-1} - e^-a) / a
// (by parts): downward from kmax when a is small (where it damps errors by a/k per step), upward
// when a is large (where it damps them by k/a). The downward start M_kmax is its series
// e^-a sum_j a^j kmax! / (kmax + j + 1)! (expand e^{a (1 - u)}), of positive terms: no cancellation.
void exponential_moments(double a, int kmax, double* m) {
  const double e = std::exp(-a);
  if (a > 8.0) {
    const double ia = 1.0 / a;
    m[0] = -std::expm1(-a) * ia;
    for (int k = 1; k <= kmax; ++k) m[k] = (k * m[k - 1] - e) * ia;
    return;
  }
  // Terms shrink by a / (kmax + j + 1) once past a: below 1e-17 of the sum within 64 terms for
  // a <= 8, kmax <= 24 (the table's 128 entries bound j).
  double term = kInverse[kmax + 1], sum = term;
  for (int j = kmax + 2; j < 128 && term > 1e-17 * sum; ++j) term *= a * kInverse[j], sum += term;
  m[kmax] = e * sum;
  for (int k = kmax; k > 0; --k) m[k - 1] = (a * m[k] + e) * kInverse[k];
}

// F(a, b) = int_0^1 exp(-a u - b u^2) du for a >= 0 and a + 2b >= 0 (kappa >= 0 at both ends).
double mean_transmittance(double a, double b, double depth) {
  if (b == 0.0) return -std::expm1(-a) / a;   // constant kappa (a > kSmallA here)
  if (std::abs(b) <= kSeriesB * (1.0 + a)) {  // sum_n (-b)^n / n! M_2n(a), M_2n <= 1
    double coef[kSeriesTerms];
    int n = 0;
    for (double c = 1.0; n < kSeriesTerms && (n == 0 || std::abs(c) > 1e-17); ++n)
      coef[n] = c, c *= -b * kInverse[n + 1];
    double m[2 * kSeriesTerms];
    exponential_moments(a, 2 * (n - 1), m);
    double sum = 0.0;
    for (int k = n - 1; k >= 0; --k) sum += coef[k] * m[2 * k];
    return sum;
  }
  const double rb = std::sqrt(std::abs(b)), x0 = a / (2.0 * rb), e = std::exp(-depth);
  if (b > 0)  // kappa grows: completing the square gives erfc differences, scaled to avoid overflow
    return 0.5 * kSqrtPi / rb * (erfcx(x0) - erfcx(x0 + rb) * e);
  // kappa falls: the square has the other sign and the integral is Dawson's
  return (dawson(x0) - e * dawson(std::max(0.0, x0 - rb))) / rb;
}

}  // namespace

double erfcx(double x) {
  if (x < 25.0) return std::exp(x * x) * std::erfc(x);
  // Laplace's continued fraction 1 / (x + (1/2) / (x + 1 / (x + (3/2) / (x + ...)))) / sqrt(pi).
  double f = x;
  for (int k = 16; k >= 1; --k) f = x + 0.5 * k / f;
  return 1.0 / (kSqrtPi * f);
}

double dawson(double x) {
  if (x < 0.2) {  // sum (-2x^2)^n x / (2n+1)!!
    double term = x, sum = x;
    for (int n = 1; n < 20 && std::abs(term) > 1e-18 * std::abs(sum); ++n) {
      term *= -2.0 * x * x / (2 * n + 1);
      sum += term;
    }
    return sum;
  }
  if (x < 10.0) {
    // Rybicki's sampling theorem: D(x) = lim_{h->0} pi^-1/2 sum_{n odd} e^{-(x - n h)^2} / n, centred
    // on the even n0 nearest x / h; with h = 1/4 the error is about e^{-(pi / 2h)^2} ~ 1e-17.
    constexpr double h = 0.25;
    constexpr int kTerms = 13;  // e^{-((2i+1) h)^2} < 1e-17 beyond
    static const auto weight = [] {
      std::array<double, kTerms> c{};
      for (int i = 0; i < kTerms; ++i) c[i] = std::exp(-((2 * i + 1) * h) * ((2 * i + 1) * h));
      return c;
    }();
    const int n0 = 2 * static_cast<int>(std::lround(0.5 * x / h));
    const double xp = x - n0 * h, e1 = std::exp(2.0 * xp * h), e2 = e1 * e1;
    double up = e1, sum = 0.0;
    for (int i = 0; i < kTerms; ++i) {
      const int odd = 2 * i + 1;
      sum += weight[i] * (up / (n0 + odd) + 1.0 / (up * (n0 - odd)));
      up *= e2;
    }
    return std::exp(-xp * xp) * sum / kSqrtPi;
  }
  // Asymptotic series (1 / 2x) sum (2k-1)!! / (2x^2)^k, cut at its smallest term (< 1e-16 here).
  const double r = 1.0 / (2.0 * x * x);
  double term = 1.0, sum = 1.0;
  for (int k = 1; k < 40; ++k) {
    const double next = term * (2 * k - 1) * r;
    if (next >= term || next < 1e-18 * sum) break;
    term = next;
    sum += term;
  }
  return sum / (2.0 * x);
}

EndWeights linear_segment_weights(double L, double k0, double k1) {
  EndWeights w;
  if (!(L > 0.0) || !(k0 + k1 > 0.0)) return w;
  // tau(u) = a u + b u^2 along u = t / L in [0, 1].
  const double a = k0 * L, b = 0.5 * (k1 - k0) * L;
  // Every optical depth D below 0.01 is a small cell (a + 2b >= 0 bounds a by 2D and |b| by D): tiny
  // depths keep their relative accuracy, as no 1 - F cancels there.
  if (a <= kSmallA && std::abs(b) <= kSmallB) {
    const SmallCellWeights<double> s = small_cell_weights(a, b);
    return {s.front, s.back, s.depth, s.opacity};
  }
  w.depth = a + b;
  const double F = mean_transmittance(a, b, w.depth);
  w.front = 1.0 - F;
  w.back = F - std::exp(-w.depth);
  return w;
}

SegmentLight integrate_segment_closed_form(const TransferFunction& tf, double length, double s0, double s1) {
  return integrate_pieces(tf, length, s0, s1, integrate_linear_closed_form);
}

namespace {
// The first `lanes` segments (a multiple of 4) in SIMD lanes, then those of 0 .. n - 1 that were
// not small cells or not in a lane, one by one.
void weights_in_lanes(std::size_t lanes, std::size_t n, const double* L, const double* k0, const double* k1,
                      EndWeights* w) {
  small_cells(lanes, L, k0, k1, w);
  for (std::size_t k = 0; k < n; ++k)
    if (k >= lanes || std::isnan(w[k].depth)) w[k] = linear_segment_weights(L[k], k0[k], k1[k]);
}
}  // namespace

void linear_segment_weights(std::size_t n, const double* L, const double* k0, const double* k1, EndWeights* w) {
  weights_in_lanes(n - n % 4, n, L, k0, k1, w);
}

void linear_segment_weights_padded(std::size_t n, const double* L, const double* k0, const double* k1, EndWeights* w) {
  weights_in_lanes((n + 3) / 4 * 4, n, L, k0, k1, w);
}

}  // namespace cellproj
