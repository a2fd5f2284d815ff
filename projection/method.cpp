#include "projection/method.hpp"

#include <cmath>

#include "grid/error.hpp"

namespace cellproj {

namespace {
constexpr std::pair<ProjectionMethod, const char*> kNames[] = {
    {ProjectionMethod::pt_linear, "pt-linear"},
    {ProjectionMethod::pt_table, "pt-table"},
    {ProjectionMethod::pt_analytic, "pt-analytic"},
    {ProjectionMethod::pt_breakpoints, "pt-breakpoints"},
};
}  // namespace

ProjectionMethod projection_method_from_name(const std::string& name) {
  for (const auto& [m, n] : kNames)
    if (name == n) return m;
  throw InputError("unknown projection method '" + name + "' (known: " + projection_method_names() + ")");
}

const char* name_of(ProjectionMethod method) {
  for (const auto& [m, n] : kNames)
    if (m == method) return n;
  return "?";
}

std::string projection_method_names() {
  std::string out;
  for (const auto& [m, n] : kNames) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

OpacityTable::OpacityTable(int size, double kappa_max, double l_max) : size_(size) {
  if (size < 2 || size > 8192) throw InputError("opacity table size " + std::to_string(size) + " is outside [2, 8192]");
  if (!(kappa_max > 0) || !std::isfinite(kappa_max)) kappa_max = 1.0;
  if (!(l_max > 0) || !std::isfinite(l_max)) l_max = 1.0;
  max_index_ = size - 1;
  kscale_ = max_index_ / kappa_max, lscale_ = max_index_ / l_max;
  alpha_.resize(static_cast<std::size_t>(size) * size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i)
      alpha_[static_cast<std::size_t>(j) * size + i] =
          static_cast<float>(-std::expm1(-(i / kscale_) * (j / lscale_)));
}

}  // namespace cellproj
