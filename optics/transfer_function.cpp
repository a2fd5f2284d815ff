#include "optics/transfer_function.hpp"

#include <algorithm>
#include <cmath>

#include "base/error.hpp"

namespace cellproj {
namespace {

template <class P>
void check_order(const std::vector<P>& pts, const std::string& what) {
  if (pts.empty()) throw InputError(what + ": needs at least one control point");
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!std::isfinite(pts[i].s)) throw InputError(what + "[" + std::to_string(i) + "]: s is not finite");
    if (i > 0 && pts[i].s < pts[i - 1].s)
      throw InputError(what + "[" + std::to_string(i) + "]: s = " + std::to_string(pts[i].s) +
                       " comes after s = " + std::to_string(pts[i - 1].s) + "; control points must be in increasing s");
  }
}

// Index of the segment [i-1, i] whose linear function holds at s (0 or size() when clamped).
template <class P>
std::size_t segment_at(const std::vector<P>& pts, double s) {
  return static_cast<std::size_t>(
      std::upper_bound(pts.begin(), pts.end(), s, [](double v, const P& p) { return v < p.s; }) - pts.begin());
}

template <class P, class V, class Get>
V eval_on_segment(const std::vector<P>& pts, std::size_t i, double s, Get get) {
  if (i == 0) return get(pts.front());
  if (i >= pts.size()) return get(pts.back());
  const P& a = pts[i - 1];
  const P& b = pts[i];
  const double w = (s - a.s) / (b.s - a.s);  // b.s > a.s: a step is never the segment found
  return get(a) + (get(b) - get(a)) * w;
}

}  // namespace

TransferFunction::TransferFunction(std::vector<ColorPoint> color, std::vector<ExtinctionPoint> extinction,
                                   const std::string& source)
    : color_(std::move(color)), extinction_(std::move(extinction)) {
  check_order(color_, source + ": color");
  check_order(extinction_, source + ": extinction");
  for (std::size_t i = 0; i < color_.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (!(color_[i].rgb[k] >= 0.0 && color_[i].rgb[k] <= 1.0))
        throw InputError(source + ": color[" + std::to_string(i) + "]: " + "rgb"[k] + " = " +
                         std::to_string(color_[i].rgb[k]) + " is outside [0, 1]");
  for (std::size_t i = 0; i < extinction_.size(); ++i)
    if (!(extinction_[i].kappa >= 0.0) || !std::isfinite(extinction_[i].kappa))
      throw InputError(source + ": extinction[" + std::to_string(i) +
                       "]: kappa = " + std::to_string(extinction_[i].kappa) + " must be finite and >= 0");
  for (const auto& p : color_) breakpoints_.push_back(p.s);
  for (const auto& p : extinction_) breakpoints_.push_back(p.s);
  std::sort(breakpoints_.begin(), breakpoints_.end());
  breakpoints_.erase(std::unique(breakpoints_.begin(), breakpoints_.end()), breakpoints_.end());
  // Interval j's points lie in [breakpoint j - 1, breakpoint j): the segments there are those
  // found at breakpoint j - 1 (no control point between), or the first clamp.
  for (std::size_t j = 0; j <= breakpoints_.size(); ++j) {
    color_segment_.push_back(j == 0 ? 0 : segment_at(color_, breakpoints_[j - 1]));
    extinction_segment_.push_back(j == 0 ? 0 : segment_at(extinction_, breakpoints_[j - 1]));
  }
}

glm::dvec3 TransferFunction::color(double s) const {
  return eval_on_segment<ColorPoint, glm::dvec3>(color_, segment_at(color_, s), s,
                                                 [](const ColorPoint& p) { return p.rgb; });
}

double TransferFunction::extinction(double s) const {
  return eval_on_segment<ExtinctionPoint, double>(extinction_, segment_at(extinction_, s), s,
                                                  [](const ExtinctionPoint& p) { return p.kappa; });
}

bool TransferFunction::transparent_over(double sa, double sb) const {
  if (sa > sb) std::swap(sa, sb);
  if (extinction(sa) != 0.0 || extinction(sb) != 0.0) return false;
  // Between the ends kappa is linear but for its control points (a step's two sides included).
  for (const ExtinctionPoint& p : extinction_)
    if (p.s >= sa && p.s <= sb && p.kappa != 0.0) return false;
  return true;
}

bool TransferFunction::has_transparent_range() const {
  return std::any_of(extinction_.begin(), extinction_.end(), [](const ExtinctionPoint& p) { return p.kappa == 0.0; });
}

TransferFunction::Ends TransferFunction::piece(double sa, double sb) const {
  return piece_in(breakpoints_not_above(0.5 * (sa + sb)), sa, sb);
}

TransferFunction::Ends TransferFunction::piece_in(std::size_t interval, double sa, double sb) const {
  const std::size_t ic = color_segment_[interval], ik = extinction_segment_[interval];
  auto rgb = [](const ColorPoint& p) { return p.rgb; };
  auto kappa = [](const ExtinctionPoint& p) { return p.kappa; };
  return {eval_on_segment<ColorPoint, glm::dvec3>(color_, ic, sa, rgb),
          eval_on_segment<ColorPoint, glm::dvec3>(color_, ic, sb, rgb),
          std::max(0.0, eval_on_segment<ExtinctionPoint, double>(extinction_, ik, sa, kappa)),
          std::max(0.0, eval_on_segment<ExtinctionPoint, double>(extinction_, ik, sb, kappa))};
}

}  // namespace cellproj
