#include "raycast/order_oracle.hpp"

#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>

#include <tbb/enumerable_thread_specific.h>

namespace cellproj {
namespace {

constexpr double kContact = 1e-10;

// Pairs a < b with v[a] < v[b] (merge sort into decreasing order, counting as it merges).
std::int64_t ascending_pairs(std::vector<std::int64_t>& v, std::vector<std::int64_t>& tmp, std::size_t lo,
                             std::size_t hi) {
  if (hi - lo < 2) return 0;
  const std::size_t mid = (lo + hi) / 2;
  std::int64_t count = ascending_pairs(v, tmp, lo, mid) + ascending_pairs(v, tmp, mid, hi);
  std::size_t i = lo, j = mid, k = lo;
  while (i < mid && j < hi) {
    if (v[i] >= v[j])
      tmp[k++] = v[i++];
    else {  // v[j] is larger than every v[i..mid): each of those pairs ascends
      count += static_cast<std::int64_t>(mid - i);
      tmp[k++] = v[j++];
    }
  }
  while (i < mid) tmp[k++] = v[i++];
  while (j < hi) tmp[k++] = v[j++];
  std::copy(tmp.begin() + lo, tmp.begin() + hi, v.begin() + lo);
  return count;
}

}  // namespace

OrderCheck check_order(const CellRayTracer& tracer, std::int64_t n_cells, const std::vector<std::int64_t>& order,
                       const Camera& camera, int width, int height) {
  OrderCheck out;
  constexpr std::int64_t kAbsent = -1;
  std::vector<std::int64_t> position(static_cast<std::size_t>(n_cells), kAbsent);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::int64_t c = order[k];
    if (c < 0 || c >= n_cells) continue;
    if (position[c] != kAbsent)
      ++out.repeated_cells;
    else
      position[c] = static_cast<std::int64_t>(k);
  }
  for (std::int64_t p : position) out.missing_cells += p == kAbsent;

  std::atomic<std::int64_t> violations{0}, pixels{0}, covered{0}, overlapping{0}, clear{0};
  std::mutex first;
  tbb::enumerable_thread_specific<std::pair<std::vector<std::int64_t>, std::vector<std::int64_t>>> scratch;
  tracer.trace(camera, width, height, nullptr, [&](int i, int j, const Ray&, const RaySegment* seg, std::size_t n) {
    // The positions in the order of the cells along the ray, front to back; a cell crossed in
    // several consecutive tetrahedra counts once. Back to front, each must come after the next.
    // Segments shorter than kContact of their distance are rounding-level contacts (the ray
    // through an edge or a vertex): no compositing order can show them, and they are skipped.
    auto& [pos, tmp] = scratch.local();
    pos.clear();
    std::int64_t last = -1;
    double reach = -std::numeric_limits<double>::infinity();  // the farthest end of a segment so far
    std::int64_t reach_cell = -1;
    bool overlap = false;
    for (std::size_t k = 0; k < n; ++k) {
      if (seg[k].t1 - seg[k].t0 <= kContact * seg[k].t1) continue;
      // A segment that starts before another cell's has ended, by more than a contact.
      overlap = overlap || (seg[k].cell != reach_cell && seg[k].t0 < reach - kContact * std::abs(reach));
      if (seg[k].t1 > reach) reach = seg[k].t1, reach_cell = seg[k].cell;
      if (seg[k].cell == last) continue;
      last = seg[k].cell;
      if (position[last] != kAbsent) pos.push_back(position[last]);
    }
    if (n) ++covered;
    if (overlap) ++overlapping;
    tmp.resize(pos.size());
    const std::int64_t bad = ascending_pairs(pos, tmp, 0, pos.size());
    if (bad) {
      violations += bad;
      ++pixels;
      if (!overlap) ++clear;
      std::lock_guard<std::mutex> lock(first);
      if (out.first_pixel_i < 0) out.first_pixel_i = i, out.first_pixel_j = j;
    }
  });
  out.violations = violations;
  out.violating_pixels = pixels;
  out.pixels = static_cast<std::int64_t>(width) * height;
  out.pixels_covered = covered;
  out.overlapping_pixels = overlapping;
  out.violating_pixels_without_overlap = clear;
  return out;
}

}  // namespace cellproj
