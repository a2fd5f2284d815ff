#pragma once
// Internal to the fan's kernels (tet_fan.cpp, fan_avx2.cpp): a row's pixels inside the outline,
// and the AVX2 kernels that take a fan one pixel at a time.
#include <cmath>
#include <cstdint>

#include "base/simd.hpp"
#include "projection/tet_fan.hpp"

namespace cellproj {

// Four doubles (GCC's and clang's vector extensions: AVX2 in an AVX2 function, two SSE2 halves
// elsewhere).
typedef double Lanes __attribute__((vector_size(32)));

// The pixels b[k] .. e[k] of rows y + k, k < 4 (from the box's first), inside every outline edge:
// x >= its crossing where the edge's function rises along the row, x <= where it falls, all or
// none where it is flat; e[k] < b[k] where there are none. Four rows at a time, a lane each.
template <int S>
[[gnu::always_inline]] inline void row_spans(const FanPlanes& f, double y, int width, int* b, int* e) {
  const Lanes zero{}, rows = Lanes{0.0, 1.0, 2.0, 3.0} + y;
  Lanes lo = zero, hi = zero + (width - 1);
  for (int a = 0; a < S; ++a) {
    const Lanes g = f.outline[a].c + f.outline[a].gy * rows, inv = zero + f.inv_gx[a], cross = -g * inv;
    lo = ((inv > 0) & (cross > lo)) ? cross : lo;
    hi = ((inv < 0) & (cross < hi)) ? cross : hi;
    hi = ((inv == 0) & (g < 0)) ? zero - 1.0 : hi;
  }
  const auto none = !(lo <= hi);                       // (NaN: none)
  lo = none ? zero : lo, hi = none ? zero - 1.0 : hi;  // (0 <= lo <= hi < width, or none: no overflow below)
  for (int k = 0; k < 4; ++k) b[k] = static_cast<int>(std::ceil(lo[k])), e[k] = static_cast<int>(std::floor(hi[k]));
}

// The rows of a fan's box that hold pixels, in order: rows [row0, row0 + rows) from the box's
// first, `width` pixels wide. next(b, e) moves to the next such row (its index from row0 in r, its
// pixels b .. e); false past the last.
template <int S>
struct RowSpans {
  const FanPlanes& f;
  int row0, rows, width;
  int r = -1, first[4] = {}, last[4] = {};
  [[gnu::always_inline]] bool next(int& b, int& e) {
    while (++r < rows) {
      if (r % 4 == 0) row_spans<S>(f, row0 + r, width, first, last);
      b = first[r % 4], e = last[r % 4];
      if (b <= e) return true;
    }
    return false;
  }
};

#if CELLPROJ_AVX2_DISPATCH
// fan_composite_over, fan_composite_table and fan_segments one pixel at a time, the pixel's
// quantities in an AVX2 vector (pt-table's fifth beside it; fan_avx2.cpp); call only where the
// processor has AVX2.
std::int64_t fan_over_avx2(const FanPlanes& f, Image& image, int i0, int j0, int row0, int rows, int width);
std::int64_t fan_table_avx2(const FanPlanes& f, const OpacityTable& table, Image& image, int i0, int j0, int row0,
                            int rows, int width);
void fan_segments_avx2(const FanPlanes& f, const FanSegments& at, SegmentBatch& out);
// fan_composite_over two pixels at a time, each one's quantities in half of an AVX-512 vector
// (fan_avx512.cpp); call only where the processor has AVX-512 F, VL and DQ.
std::int64_t fan_over_avx512(const FanPlanes& f, Image& image, int i0, int j0, int row0, int rows, int width);
// fan_segments two pixels at a time, the same way (fan_avx512.cpp; AVX-512 F, VL and DQ only).
void fan_segments_avx512(const FanPlanes& f, const FanSegments& at, SegmentBatch& out);
#endif

}  // namespace cellproj
