#pragma once
// Segments along which the scalar is not linear (isoparametric cells): s(t) is given as a
// polynomial, and the optical model is integrated for the piecewise-linear transfer function
// without approximating s any further.
#include "optics/segment_integral.hpp"

namespace cellproj {

// s along a segment as a polynomial of x in [-1, 1] (x = -1 the front end, x = 1 the back end),
// in the monomial basis: s(x) = sum c[k] x^k.
struct ScalarPolynomial {
  static constexpr int kTerms = 8;
  double c[kTerms] = {};
  double operator()(double x) const {
    double v = 0.0;
    for (int k = kTerms - 1; k >= 0; --k) v = v * x + c[k];
    return v;
  }
};

// The polynomial interpolating f at the 8 Chebyshev points of [-1, 1] (f(x) evaluated 8 times).
template <class F>
ScalarPolynomial chebyshev_interpolant(F&& f);

// Cut where s crosses a breakpoint of the transfer function (roots found on the polynomial to
// 1e-14); between cuts kappa and C are polynomials in x, so the optical depth is integrated in
// closed form and the emission by 8-point Gauss-Legendre on pieces of optical depth <= 1/4
// (relative error below 1e-12, as integrate_linear_reference).
SegmentLight integrate_polynomial_reference(const TransferFunction& tf, double length, const ScalarPolynomial& s);

// --- implementation of the template ---
void chebyshev_to_monomial(const double values_at_nodes[ScalarPolynomial::kTerms], ScalarPolynomial& out);
double chebyshev_node(int k);  // cos((2k + 1) pi / 16)

template <class F>
ScalarPolynomial chebyshev_interpolant(F&& f) {
  double v[ScalarPolynomial::kTerms];
  for (int k = 0; k < ScalarPolynomial::kTerms; ++k) v[k] = f(chebyshev_node(k));
  ScalarPolynomial p;
  chebyshev_to_monomial(v, p);
  return p;
}

}  // namespace cellproj
