// Filling a fresh array: a plain std::vector (4 KB pages, one fault each) against one given
// reserve_in_huge_pages first (base/huge_pages.hpp), 3 times each, in turn. Each array is freed
// before the next, and at 48 MB it is above glibc's largest mapping threshold, so every one is a
// fresh mapping. Built and run by bench/fresh_pages.sh.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "base/huge_pages.hpp"

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : std::size_t(6) << 20;  // 48 MB of int64
  auto fill = [n](bool huge) {
    const auto t = std::chrono::steady_clock::now();
    std::vector<long long> v;
    if (huge) cellproj::reserve_in_huge_pages(v, n);
    v.assign(n, -1);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  for (int r = 0; r < 3; ++r)
    std::printf("%.1f MB: 4 KB pages %.4f s, huge pages %.4f s\n", n * 8 / 1048576.0, fill(false), fill(true));
}
