#pragma once
// The paper's 2D alpha texture (MWSC section 2): the opacity of a segment of constant extinction,
// tabulated once per frame for the Gouraud methods and the OpenGL back ends.
#include <algorithm>
#include <vector>

namespace cellproj {

// 1 - exp(-kappa l) tabulated on [0, kappa_max] x [0, l_max] at size x size nodes, read bilinearly:
// the paper's 2D alpha texture. Arguments beyond the table are clamped to its edge.
class OpacityTable {
 public:
  OpacityTable(int size, double kappa_max, double l_max);  // check_size(size) first
  static void check_size(int size);                        // InputError unless 2 <= size <= 8192
  // Where kappa and l fall between the nodes (fractional node index, clamped to the table).
  double kappa_index(double kappa) const { return std::min(kappa * kscale_, max_index_); }
  double length_index(double l) const { return std::min(l * lscale_, max_index_); }
  double operator()(double kappa, double l) const {
    const double u = kappa_index(kappa), v = length_index(l);
    const int i = node(u), j = node(v);
    const float* row = alpha_.data() + static_cast<std::size_t>(j) * size_ + i;
    return bilinear(u - i, v - j, row[0], row[1], row[size_], row[size_ + 1]);
  }
  // The same read four at a time, for a GCC/clang vector of four doubles (the same operations per
  // lane, so the same bits). Inlined into its caller (GCC's ABI note on passing such vectors
  // between builds with and without AVX does not apply).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
  template <class Lanes>
  [[gnu::always_inline]] Lanes operator()(Lanes kappa, Lanes l) const {
    static_assert(sizeof(Lanes) == 4 * sizeof(double));
    typedef int Ints __attribute__((vector_size(16)));  // (one instruction each way from doubles)
    Lanes u = kappa * kscale_, v = l * lscale_;
    u = max_index_ < u ? max_index_ : u, v = max_index_ < v ? max_index_ : v;  // std::min's rule
    Ints i = __builtin_convertvector(u, Ints), j = __builtin_convertvector(v, Ints);
    i = i > size_ - 2 ? size_ - 2 : i, j = j > size_ - 2 ? size_ - 2 : j;
    i = i < 0 ? 0 : i, j = j < 0 ? 0 : j;  // node(): a NaN (its read stays NaN) or a negative index
    typedef float Floats __attribute__((vector_size(16)));
    const Ints at = j * size_ + i;
    Floats a00, a10, a01, a11;
    for (int k = 0; k < 4; ++k) {
      const float* row = alpha_.data() + at[k];
      a00[k] = row[0], a10[k] = row[1], a01[k] = row[size_], a11[k] = row[size_ + 1];
    }
    const auto wide = [](Floats a) { return __builtin_convertvector(a, Lanes); };
    return bilinear(u - __builtin_convertvector(i, Lanes), v - __builtin_convertvector(j, Lanes), wide(a00), wide(a10),
                    wide(a01), wide(a11));
  }
  int size() const { return size_; }
  const float* data() const { return alpha_.data(); }  // size x size, kappa fastest

 private:
  // The node at or below fractional index u, at most the last but one (0 for a NaN or below 0).
  int node(double u) const { return u >= 0 ? std::min(static_cast<int>(u), size_ - 2) : 0; }
  template <class T, class A>
  [[gnu::always_inline]] static T bilinear(T fu, T fv, A a00, A a10, A a01, A a11) {
    return (1 - fv) * ((1 - fu) * a00 + fu * a10) + fv * ((1 - fu) * a01 + fu * a11);
  }
#pragma GCC diagnostic pop

  int size_;
  double kscale_, lscale_, max_index_;
  std::vector<float> alpha_;
};

}  // namespace cellproj
