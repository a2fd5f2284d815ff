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
    const int i = std::min(static_cast<int>(u), size_ - 2), j = std::min(static_cast<int>(v), size_ - 2);
    const double fu = u - i, fv = v - j;
    const float* row = alpha_.data() + static_cast<std::size_t>(j) * size_ + i;
    return (1 - fv) * ((1 - fu) * row[0] + fu * row[1]) + fv * ((1 - fu) * row[size_] + fu * row[size_ + 1]);
  }
  int size() const { return size_; }
  const float* data() const { return alpha_.data(); }  // size x size, kappa fastest

 private:
  int size_;
  double kscale_, lscale_, max_index_;
  std::vector<float> alpha_;
};

}  // namespace cellproj
