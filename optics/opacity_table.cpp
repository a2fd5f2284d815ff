#include "optics/opacity_table.hpp"

#include <cmath>
#include <string>

#include "base/error.hpp"

namespace cellproj {

void OpacityTable::check_size(int size) {
  if (size < 2 || size > 8192) throw InputError("opacity table size " + std::to_string(size) + " is outside [2, 8192]");
}

OpacityTable::OpacityTable(int size, double kappa_max, double l_max) : size_(size) {
  check_size(size);
  if (!(kappa_max > 0) || !std::isfinite(kappa_max)) kappa_max = 1.0;
  if (!(l_max > 0) || !std::isfinite(l_max)) l_max = 1.0;
  max_index_ = size - 1;
  kscale_ = max_index_ / kappa_max, lscale_ = max_index_ / l_max;
  alpha_.resize(static_cast<std::size_t>(size) * size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i)
      alpha_[static_cast<std::size_t>(j) * size + i] = static_cast<float>(-std::expm1(-(i / kscale_) * (j / lscale_)));
}

}  // namespace cellproj
