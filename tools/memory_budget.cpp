#include "tools/memory_budget.hpp"

#include <algorithm>
#include <cstdio>

#include "base/error.hpp"

namespace cellproj {

void refuse_beyond_memory(std::uint64_t need, double max_memory_gib, const std::string& what, const std::string& source,
                          const std::string& remedy) {
  const std::uint64_t limit =
      max_memory_gib > 0 ? static_cast<std::uint64_t>(max_memory_gib * double(1ull << 30)) : available_memory_bytes();
  if (limit == 0 || need <= limit) return;
  throw InputError(
      where(source, what + " needs about " + format_bytes(need) + ", more than the " + format_bytes(limit) +
                        (max_memory_gib > 0 ? " allowed by --max-memory"
                                            : " this machine has available (raise it with --max-memory GiB)") +
                        "; " + remedy));
}

}  // namespace cellproj
