#pragma once
// The transfer function: colour C(s) and extinction kappa(s), each piecewise linear in the scalar s
// and clamped outside its first and last control points. Two control points at the same s make a
// step; at the step itself the value on the right applies.
#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace cellproj {

struct ColorPoint {
  double s;
  glm::dvec3 rgb;  // each in [0, 1]
};
struct ExtinctionPoint {
  double s;
  double kappa;  // >= 0, per unit of world length
};

class TransferFunction {
 public:
  // Throws InputError (prefixed with `source`) for an empty list, a non-finite number, a colour
  // outside [0, 1], a negative extinction, or control points out of order.
  TransferFunction(std::vector<ColorPoint> color, std::vector<ExtinctionPoint> extinction,
                   const std::string& source = "transfer function");

  glm::dvec3 color(double s) const;
  double extinction(double s) const;

  // Whether the extinction is 0 over the whole of [sa, sb] (either order): a cell whose scalar
  // stays there adds nothing to any ray (emission is C kappa), so it need not be drawn.
  bool transparent_over(double sa, double sb) const;
  bool has_transparent_range() const;  // whether some scalar range has extinction 0

  // Every s at which colour or extinction changes slope, sorted, without repeats.
  const std::vector<double>& breakpoints() const { return breakpoints_; }

  // Colour and extinction at the ends of [sa, sb] (either order) as the linear function of s that
  // holds inside that interval, which must not contain a breakpoint in its interior. At a step,
  // the limit from inside the interval is used, so a piece never picks up the other side's value.
  struct Ends {
    glm::dvec3 ca, cb;
    double ka, kb;
  };
  Ends piece(double sa, double sb) const;
  // piece() takes the interval that holds the midpoint, which tolerates ends a rounding past a
  // breakpoint (polynomial_segment's sampled ranges) but, for a piece one ulp long below a step,
  // can round onto the step. piece_in is for a piece known to lie in breakpoint interval
  // `interval` (its points s have breakpoints_not_above(s) == interval, for_each_linear_piece's
  // cuts): no search, no midpoint.
  Ends piece_in(std::size_t interval, double sa, double sb) const;

  // How many breakpoints are <= s (std::upper_bound's index), and < s (std::lower_bound's).
  std::size_t breakpoints_not_above(double s) const {
    const auto& b = breakpoints_;
    return static_cast<std::size_t>(std::upper_bound(b.begin(), b.end(), s) - b.begin());
  }
  std::size_t breakpoints_below(double s) const {
    const auto& b = breakpoints_;
    return static_cast<std::size_t>(std::lower_bound(b.begin(), b.end(), s) - b.begin());
  }

  const std::vector<ColorPoint>& color_points() const { return color_; }
  const std::vector<ExtinctionPoint>& extinction_points() const { return extinction_; }
  bool is_linear() const { return breakpoints_.size() <= 2; }  // one linear piece between clamps

 private:
  std::vector<ColorPoint> color_;
  std::vector<ExtinctionPoint> extinction_;
  std::vector<double> breakpoints_;
  // Per breakpoint interval j (between breakpoints j - 1 and j): the colour's and the extinction's
  // segment that holds inside it (piece_in).
  std::vector<std::size_t> color_segment_, extinction_segment_;
};

}  // namespace cellproj
