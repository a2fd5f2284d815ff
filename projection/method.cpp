#include "projection/method.hpp"

#include <cmath>

#include "grid/error.hpp"
#include "grid/name_table.hpp"

namespace cellproj {

namespace {
constexpr std::pair<ProjectionMethod, const char*> kNames[] = {
    {ProjectionMethod::pt_linear, "pt-linear"},
    {ProjectionMethod::pt_table, "pt-table"},
    {ProjectionMethod::pt_analytic, "pt-analytic"},
    {ProjectionMethod::pt_breakpoints, "pt-breakpoints"},
};
constexpr std::pair<ProjectionBackend, const char*> kBackends[] = {
    {ProjectionBackend::software, "software"},
    {ProjectionBackend::opengl, "opengl"},
    {ProjectionBackend::opengl_8bit, "opengl-8bit"},
    {ProjectionBackend::opengl_8bit_dithered, "opengl-8bit-dither"},
};

}  // namespace

ProjectionBackend projection_backend_from_name(const std::string& name) {
  return from_name(kBackends, name, "back end");
}
const char* name_of(ProjectionBackend backend) { return name_in(kBackends, backend); }
std::string projection_backend_names() { return names(kBackends); }

ProjectionMethod projection_method_from_name(const std::string& name) {
  return from_name(kNames, name, "projection method");
}
const char* name_of(ProjectionMethod method) { return name_in(kNames, method); }
std::string projection_method_names() { return names(kNames); }

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
