#include "projection/method.hpp"

#include <cmath>

#include "base/error.hpp"

namespace cellproj {

namespace {
constexpr bool listed_in_enum_order() {
  int i = 0;
  for (const MethodTraits& t : kProjectionMethods)
    if (static_cast<int>(t.method) != i++) return false;
  return true;
}
static_assert(listed_in_enum_order(), "traits() indexes kProjectionMethods by the enum's value");
}  // namespace

}  // namespace cellproj
