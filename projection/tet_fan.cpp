#include "projection/tet_fan.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "base/simd.hpp"
#include "projection/fan_row.hpp"

namespace cellproj {
namespace {

// The edge function of a -> b, (b - a) x (p - a), as a plane over p = (x0 + x, y0 + y), times sign.
Plane edge_plane(const ThickVertex& a, const ThickVertex& b, double x0, double y0, double sign) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  return {sign * (dx * (y0 - a.y) - dy * (x0 - a.x)), -sign * dy, sign * dx};
}

// Lanes (fan_row.hpp): four doubles, one pixel each.
typedef double UnalignedLanes __attribute__((vector_size(32), aligned(8)));
typedef float Floats __attribute__((vector_size(16)));
typedef long long Counts __attribute__((vector_size(32)));  // a comparison of Lanes: -1 where true

// Row by row over the box: the outline's pixels on the row (from its edges' crossings), then four
// pixels at a time the fan triangle whose wedge around the thick vertex holds them (the largest of
// the smaller of its two spokes' functions) and its quantities.
// S triangles, Q quantities (compile-time, so the loops unroll). For each row r, out.row(r, b, e)
// with its pixels b .. e (none: e < b), then out.lanes(i, v) for i = b, b + 4, ... <= e with the
// quantities v of pixels i .. i + 3 (those past e are the planes' values beyond the outline).
template <int S, int Q, class Out>
[[gnu::always_inline]] inline void fan_rows(const FanPlanes& f, int row0, int rows, int width, Out& out) {
  int first[4], last[4];
  for (int r = 0; r < rows; ++r) {
    const double y = row0 + r;
    double p0[S], px[S], q0[S][Q], qx[S][Q];
    if (r % 4 == 0) row_spans<S>(f, y, width, first, last);
    const int b = first[r % 4], e = last[r % 4];
    if (e < b) {
      out.row(r, 0, -1);
      continue;
    }
    out.row(r, b, e);
    for (int a = 0; a < S; ++a) {
      p0[a] = f.spoke[a].c + f.spoke[a].gy * y, px[a] = f.spoke[a].gx;
      for (int m = 0; m < Q; ++m) q0[a][m] = f.q[a].c[m] + f.q[a].gy[m] * y, qx[a][m] = f.q[a].gx[m];
    }
    for (int i = b; i <= e; i += 4) {
      const Lanes x = Lanes{0.0, 1.0, 2.0, 3.0} + static_cast<double>(i);
      Lanes spoke[S];
      for (int k = 0; k < S; ++k) spoke[k] = p0[k] + px[k] * x;
      Lanes best = Lanes{} - std::numeric_limits<double>::infinity(), v[Q] = {};
      for (int a = 0; a < S; ++a) {
        // >= 0 in the triangle's wedge between spoke[a] and spoke[a + 1], < 0 outside it
        const Lanes s1 = -spoke[(a + 1) % S], w = (spoke[a] < s1 ? spoke[a] : s1) + f.left_out[a];
        const auto take = w > best;
        best = take ? w : best;
        for (int m = 0; m < Q; ++m) v[m] = take ? q0[a][m] + qx[a][m] * x : v[m];
      }
      out.lanes(i, v);
    }
  }
}

// pt-linear's pixels from their opacity and colour: the opacity clamped to [0, 1], the colour
// clamped to >= 0 and premultiplied by it.
template <int Q>
[[gnu::always_inline]] inline void finish_linear(Lanes* v) {
  const Lanes zero{};
  Lanes alpha = v[0] > zero ? v[0] : zero;
  alpha = alpha < 1.0 ? alpha : zero + 1.0;
  v[0] = alpha;
  for (int m = 1; m < Q; ++m) v[m] = (v[m] > zero ? v[m] : zero) * alpha;
}

// fan_pixels' rows: the quantities stored at r * stride + i (pt-linear's finished: its opacity
// and colour clamped as its runs, the colour premultiplied).
template <int Q, bool Linear>
struct StoreQuantities {
  int stride;
  std::size_t size;
  int *first, *last;
  double* q;
  double* out = nullptr;
  [[gnu::always_inline]] void row(int r, int b, int e) {
    first[r] = b, last[r] = e, out = q + static_cast<std::size_t>(r) * stride;
  }
  [[gnu::always_inline]] void lanes(int i, Lanes* v) {
    if constexpr (Linear) finish_linear<Q>(v);
    for (int m = 0; m < Q; ++m) *reinterpret_cast<UnalignedLanes*>(out + m * size + i) = v[m];
  }
};

// Four pixels' premultiplied (r, g, b, opacity) composited "over" the image at dst, the first n
// of them (composite/fragment.hpp's over, in float: the same operations, so the same bits).
[[gnu::always_inline]] inline void over_four(float* dst, int n, Lanes red, Lanes green, Lanes blue, Lanes alpha) {
  const Floats a = __builtin_convertvector(alpha, Floats), r = __builtin_convertvector(red, Floats),
               g = __builtin_convertvector(green, Floats), b = __builtin_convertvector(blue, Floats);
  // The four pixels' (r, g, b, a), a 4 x 4 transpose.
  const Floats rg01 = __builtin_shufflevector(r, g, 0, 4, 1, 5), ba01 = __builtin_shufflevector(b, a, 0, 4, 1, 5),
               rg23 = __builtin_shufflevector(r, g, 2, 6, 3, 7), ba23 = __builtin_shufflevector(b, a, 2, 6, 3, 7);
  const Floats src[4] = {
      __builtin_shufflevector(rg01, ba01, 0, 1, 4, 5), __builtin_shufflevector(rg01, ba01, 2, 3, 6, 7),
      __builtin_shufflevector(rg23, ba23, 0, 1, 4, 5), __builtin_shufflevector(rg23, ba23, 2, 3, 6, 7)};
  const Floats t = 1.0f - a;
  const Floats t_of[4] = {__builtin_shufflevector(t, t, 0, 0, 0, 0), __builtin_shufflevector(t, t, 1, 1, 1, 1),
                          __builtin_shufflevector(t, t, 2, 2, 2, 2), __builtin_shufflevector(t, t, 3, 3, 3, 3)};
  for (int k = 0; k < n; ++k) {
    Floats d;
    std::memcpy(&d, dst + 4 * k, sizeof d);
    d = src[k] + t_of[k] * d;
    std::memcpy(dst + 4 * k, &d, sizeof d);
  }
}

// -1 in the first n lanes whose pixel adds something (composite/fragment.hpp's adds_nothing, false).
[[gnu::always_inline]] inline Counts adds_something(int n, Lanes r, Lanes g, Lanes b, Lanes alpha) {
  return ((alpha != 0.0) | (r != 0.0) | (g != 0.0) | (b != 0.0)) & (Counts{0, 1, 2, 3} < n);
}

// pt-linear's fan composited straight onto the image: each pixel's opacity and colour finished as
// fan_pixels stores them, then "over" (over_four), counting only the pixels that add something
// (as CompositeFragments, which skips the others).
struct CompositeOver {
  Image& image;
  int i0, j0, row0;
  Counts added{};         // per lane, minus the pixels composited that add something
  float* line = nullptr;  // the image at the row's box pixel 0
  int last = -1;
  [[gnu::always_inline]] void row(int r, int /*first*/, int e) { line = image.pixel(i0, j0 + row0 + r), last = e; }
  [[gnu::always_inline]] void lanes(int i, Lanes* v) {
    finish_linear<4>(v);
    // A pixel adding nothing (opacity and colour +0 after finish_linear) is composited too, and
    // changes nothing: 0 + 1 d is d (bit for bit but for a -0, which becomes +0); it is not counted.
    const int n = std::min(4, last - i + 1);
    added += adds_something(n, v[1], v[2], v[3], v[0]);
    over_four(line + 4 * i, n, v[1], v[2], v[3], v[0]);
  }
  std::int64_t fragments() const { return -(added[0] + added[1] + added[2] + added[3]); }
};

// pt-table's fan composited straight onto the image: each pixel's opacity from the table at its
// kappa_avg and thickness, its colour clamped to >= 0 times it, then "over" (over_four), as
// project_fan did with fan_pixels' values and CompositeFragments (the same operations, so the same
// bits). A pixel adding nothing (opacity and colour 0) is composited too but not counted: 0 + 1 d
// is d, as the image never holds a -0 (its +0 start plus sources >= 0).
struct CompositeTable {
  Image& image;
  const OpacityTable& table;
  int i0, j0, row0;
  Counts added{};         // per lane, minus the pixels composited that add something
  float* line = nullptr;  // the image at the row's box pixel 0
  int last = -1;
  [[gnu::always_inline]] void row(int r, int /*first*/, int e) { line = image.pixel(i0, j0 + row0 + r), last = e; }
  [[gnu::always_inline]] void lanes(int i, const Lanes* v) {
    const Lanes zero{};
    const auto clamped = [&](Lanes x) { return x < zero ? zero : x; };  // std::max(x, 0.0) and glm::max's rule
    const Lanes alpha = table(clamped(v[0]), clamped(v[1]));
    const Lanes r = clamped(v[2]) * alpha, g = clamped(v[3]) * alpha, b = clamped(v[4]) * alpha;
    const int n = std::min(4, last - i + 1);
    added += adds_something(n, r, g, b, alpha);
    over_four(line + 4 * i, n, r, g, b, alpha);
  }
  std::int64_t fragments() const { return -(added[0] + added[1] + added[2] + added[3]); }
};

template <int S, int Q, bool Linear = false>
[[gnu::always_inline]] inline void pixels(const FanPlanes& f, int row0, int rows, int width, int stride,
                                          std::size_t size, int* __restrict first, int* __restrict last,
                                          double* __restrict q) {
  StoreQuantities<Q, Linear> out{stride, size, first, last, q};
  fan_rows<S, Q>(f, row0, rows, width, out);
}

// fan_segments' rows: each pixel appended to the batch with its segment's length, clamped end
// scalars and end extinctions, as segment_ends computes them from the four ends' quantities (the
// same operations in the same order, lane by lane: segment_between, LinearPiece::kappa).
template <bool Perspective>
struct AppendSegments {
  const FanSegments& at;
  SegmentBatch& b;
  double v2 = 0;
  std::size_t base = 0;  // the batch position of the row's pixel 0
  [[gnu::always_inline]] void row(int r, int first, int last) {
    const int j = at.j0 + at.row0 + r;
    if (Perspective) v2 = at.rays.v_squared()[j];
    base = b.n - static_cast<std::size_t>(first);
    for (int i = first; i <= last; ++i) b.i[base + i] = at.i0 + i, b.j[base + i] = j;
    if (last >= first) b.n += static_cast<std::size_t>(last - first + 1);
  }
  [[gnu::always_inline]] void lanes(int i, const Lanes* v) {
    Lanes sf = v[2], sb = v[3], per_depth = Lanes{} + 1.0;
    if constexpr (Perspective) {  // PixelRays::length_per_depth_from, four columns at a time
      const Lanes d = 1.0 + *reinterpret_cast<const UnalignedLanes*>(at.rays.u_squared() + at.i0 + i) + v2;
      for (int m = 0; m < 4; ++m) per_depth[m] = std::sqrt(d[m]);
    }
    const Lanes length =
        segment_between<Perspective>(v[0], v[1], sf, sb, per_depth, Lanes{} + at.smin, Lanes{} + at.smax);
    const std::size_t k = base + static_cast<std::size_t>(i);
    *reinterpret_cast<UnalignedLanes*>(&b.length[k]) = length;
    *reinterpret_cast<UnalignedLanes*>(&b.sf[k]) = sf, *reinterpret_cast<UnalignedLanes*>(&b.sb[k]) = sb;
    *reinterpret_cast<UnalignedLanes*>(&b.k0[k]) = at.piece.kappa(sf);
    *reinterpret_cast<UnalignedLanes*>(&b.k1[k]) = at.piece.kappa(sb);
  }
};

using PixelsFn = void (*)(const FanPlanes&, int, int, int, int, std::size_t, int*, int*, double*);
// One function per triangle count, quantity count and pt-linear finish, each compiled for the
// build's target and for AVX2.
#define CELLPROJ_FAN_KERNEL(name, S, Q, linear)                                                                    \
  CELLPROJ_AVX2_CLONES void name(const FanPlanes& f, int r0, int n, int w, int st, std::size_t sz, int* b, int* e, \
                                 double* q) {                                                                      \
    pixels<S, Q, linear>(f, r0, n, w, st, sz, b, e, q);                                                            \
  }
CELLPROJ_FAN_KERNEL(pixels_3_4, 3, 4, false)
CELLPROJ_FAN_KERNEL(pixels_4_4, 4, 4, false)
CELLPROJ_FAN_KERNEL(pixels_3_5, 3, 5, false)
CELLPROJ_FAN_KERNEL(pixels_4_5, 4, 5, false)
CELLPROJ_FAN_KERNEL(linear_3, 3, 4, true)
CELLPROJ_FAN_KERNEL(linear_4, 4, 4, true)
#undef CELLPROJ_FAN_KERNEL

// pt-linear's fan over the image, per triangle count, for the build's target and AVX2.
#define CELLPROJ_FAN_OVER(name, S)                                                                                 \
  CELLPROJ_AVX2_CLONES std::int64_t name(const FanPlanes& f, Image& image, int i0, int j0, int r0, int n, int w) { \
    CompositeOver out{image, i0, j0, r0};                                                                          \
    fan_rows<S, 4>(f, r0, n, w, out);                                                                              \
    return out.fragments();                                                                                        \
  }
CELLPROJ_FAN_OVER(over_3, 3)
CELLPROJ_FAN_OVER(over_4, 4)
#undef CELLPROJ_FAN_OVER

// pt-table's fan over the image, per triangle count, for the build's target and AVX2.
#define CELLPROJ_FAN_TABLE(name, S)                                                                                   \
  CELLPROJ_AVX2_CLONES std::int64_t name(const FanPlanes& f, const OpacityTable& table, Image& image, int i0, int j0, \
                                         int r0, int n, int w) {                                                      \
    CompositeTable out{image, table, i0, j0, r0};                                                                     \
    fan_rows<S, 5>(f, r0, n, w, out);                                                                                 \
    return out.fragments();                                                                                           \
  }
CELLPROJ_FAN_TABLE(table_3, 3)
CELLPROJ_FAN_TABLE(table_4, 4)
#undef CELLPROJ_FAN_TABLE

using SegmentsFn = void (*)(const FanPlanes&, const FanSegments&, SegmentBatch&);
#define CELLPROJ_FAN_SEGMENTS(name, S, perspective)                                            \
  CELLPROJ_AVX2_CLONES void name(const FanPlanes& f, const FanSegments& at, SegmentBatch& b) { \
    AppendSegments<perspective> out{at, b};                                                    \
    fan_rows<S, 4>(f, at.row0, at.rows, at.width, out);                                        \
  }
CELLPROJ_FAN_SEGMENTS(segments_3_perspective, 3, true)
CELLPROJ_FAN_SEGMENTS(segments_4_perspective, 4, true)
CELLPROJ_FAN_SEGMENTS(segments_3_orthographic, 3, false)
CELLPROJ_FAN_SEGMENTS(segments_4_orthographic, 4, false)
#undef CELLPROJ_FAN_SEGMENTS

// fan_planes for an outline of S corners (compile-time: the four-at-a-time steps unroll and
// stay in registers).
template <int S>
[[gnu::always_inline]] inline void planes_of(const ProjectedTet& pt, double x0, double y0, double turn, int quantities,
                                             const double* thick, const double (*hull)[kFanQuantities], FanPlanes& f) {
  const double sign = turn > 0 ? 1.0 : -1.0;
  f.sectors = S, f.quantities = quantities;
  for (int k = 0; k < S; ++k) f.spoke[k] = edge_plane(pt.thick, pt.hull[k], x0, y0, sign);
  // The outline's slopes and the triangles' areas (twice: the hull edge's function at the thick
  // vertex), inverted four at a time (a division is the same bits in a lane as alone).
  double gx[4] = {1, 1, 1, 1}, area[4] = {1, 1, 1, 1};
  for (int a = 0; a < S; ++a) {
    const ThickVertex &ha = pt.hull[a], &hb = pt.hull[(a + 1) % S];
    f.outline[a] = edge_plane(ha, hb, x0, y0, sign);
    gx[a] = f.outline[a].gx;
    area[a] = sign * ((hb.x - ha.x) * (pt.thick.y - ha.y) - (hb.y - ha.y) * (pt.thick.x - ha.x));
  }
  const Lanes inv_gx = 1.0 / Lanes{gx[0], gx[1], gx[2], gx[3]},
              inv_area = 1.0 / Lanes{area[0], area[1], area[2], area[3]};
  const auto load = [](const double* v) {
    Lanes l;
    std::memcpy(&l, v, sizeof l);
    return l;
  };
  const Lanes thick4 = load(thick);
  for (int a = 0; a < S; ++a) {
    // 0 for a flat edge (or one too near it for 1 / gx)
    f.inv_gx[a] = std::abs(inv_gx[a]) < std::numeric_limits<double>::infinity() ? inv_gx[a] : 0.0;
    QuantityPlanes& q = f.q[a];
    // A triangle of no area to rounding (the thick vertex on the outline, or as good as) is left
    // out: its weights' planes would be huge, and its neighbours reach across it.
    if (!(area[a] > 1e-9 * std::abs(turn)) || !(area[a] < std::numeric_limits<double>::infinity())) {
      f.left_out[a] = -1e300;  // never the largest
      std::fill_n(q.c, quantities, 0.0), std::fill_n(q.gx, quantities, 0.0), std::fill_n(q.gy, quantities, 0.0);
      continue;
    }
    f.left_out[a] = 0;
    // Weights: thick vertex G_a / A, hull[a] -spoke[b] / A, hull[b] spoke[a] / A; the quantities'
    // planes four at a time, then the fifth (as Lanes or as double: the same operations).
    const Plane &g = f.outline[a], &sa = f.spoke[a], &sb = f.spoke[(a + 1) % S];
    const double *qa_of = hull[a], *qb_of = hull[(a + 1) % S], ia = inv_area[a];
    const auto planes = [&](auto qt, auto qa, auto qb, auto& c, auto& px, auto& py) {
      c = g.c * qt - sb.c * qa + sa.c * qb, px = g.gx * qt - sb.gx * qa + sa.gx * qb;
      py = g.gy * qt - sb.gy * qa + sa.gy * qb;
    };
    Lanes c, px, py;
    planes(thick4 * ia, load(qa_of) * ia, load(qb_of) * ia, c, px, py);
    std::memcpy(q.c, &c, sizeof c), std::memcpy(q.gx, &px, sizeof px), std::memcpy(q.gy, &py, sizeof py);
    for (int m = 4; m < quantities; ++m) planes(thick[m] * ia, qa_of[m] * ia, qb_of[m] * ia, q.c[m], q.gx[m], q.gy[m]);
  }
}

#define CELLPROJ_FAN_PLANES(name, S)                                                                        \
  CELLPROJ_AVX2_CLONES void name(const ProjectedTet& pt, double x0, double y0, double turn, int quantities, \
                                 const double* thick, const double(*hull)[kFanQuantities], FanPlanes& f) {  \
    planes_of<S>(pt, x0, y0, turn, quantities, thick, hull, f);                                             \
  }
CELLPROJ_FAN_PLANES(planes_3, 3)
CELLPROJ_FAN_PLANES(planes_4, 4)
#undef CELLPROJ_FAN_PLANES

#if CELLPROJ_AVX2_DISPATCH
// Whether the processor has what the pair kernels need (fan_avx512.cpp).
bool avx512() {
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq");
}
#endif

}  // namespace

FanPlanes fan_planes(const ProjectedTet& pt, double x0, double y0, int quantities, const double* thick,
                     const double (*hull)[kFanQuantities]) {
  FanPlanes f;
  const int n = pt.hull_size;
  if (n < 3) return f;
  double turn = 0;  // twice the outline's signed area (from its first corner: no large products)
  for (int k = 1; k + 1 < n; ++k) {
    const ThickVertex &o = pt.hull[0], &a = pt.hull[k], &b = pt.hull[k + 1];
    turn += (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  }
  if (!(turn != 0.0)) return f;
  (n == 4 ? planes_4 : planes_3)(pt, x0, y0, turn, quantities, thick, hull, f);
  return f;
}

void fan_pixels(const FanPlanes& f, int row0, int rows, int width, FanPixels& out) {
  out.stride = (width + 3) / 4 * 4 + 4;  // a row's last four pixels may start at its last pixel
  out.size = static_cast<std::size_t>(rows) * static_cast<std::size_t>(out.stride);
  if (out.first.size() < static_cast<std::size_t>(rows)) out.first.resize(rows), out.last.resize(rows);
  if (out.q.size() < kFanQuantities * out.size) out.q.resize(kFanQuantities * out.size);
  const bool four = f.sectors == 4, five = f.quantities == 5;
  const PixelsFn fn = f.linear_opacity ? (four ? linear_4 : linear_3)
                      : four           ? (five ? pixels_4_5 : pixels_4_4)
                                       : (five ? pixels_3_5 : pixels_3_4);
  fn(f, row0, rows, width, out.stride, out.size, out.first.data(), out.last.data(), out.q.data());
}

void fan_segments(const FanPlanes& f, const FanSegments& at, SegmentBatch& out, FanLanes lanes) {
  // Room for every pixel of the rows, and three more for the last lanes' stores.
  out.reserve(out.n + static_cast<std::size_t>(at.rows) * static_cast<std::size_t>(at.width) + 3);
#if CELLPROJ_AVX2_DISPATCH
  if (lanes == FanLanes::pairs && avx512()) return fan_segments_avx512(f, at, out);
  if (lanes != FanLanes::pixels && __builtin_cpu_supports("avx2")) return fan_segments_avx2(f, at, out);
#endif
  const bool four = f.sectors == 4;
  const SegmentsFn fn = at.rays.perspective() ? (four ? segments_4_perspective : segments_3_perspective)
                                              : (four ? segments_4_orthographic : segments_3_orthographic);
  fn(f, at, out);
}

std::int64_t fan_composite_over(const FanPlanes& f, Image& image, int i0, int j0, int row0, int rows, int width,
                                FanLanes lanes) {
#if CELLPROJ_AVX2_DISPATCH
  if (lanes == FanLanes::pairs && avx512()) return fan_over_avx512(f, image, i0, j0, row0, rows, width);
  if (lanes != FanLanes::pixels && __builtin_cpu_supports("avx2"))
    return fan_over_avx2(f, image, i0, j0, row0, rows, width);
#endif
  return (f.sectors == 4 ? over_4 : over_3)(f, image, i0, j0, row0, rows, width);
}

std::int64_t fan_composite_table(const FanPlanes& f, const OpacityTable& table, Image& image, int i0, int j0, int row0,
                                 int rows, int width, FanLanes lanes) {
#if CELLPROJ_AVX2_DISPATCH
  if (lanes != FanLanes::pixels && __builtin_cpu_supports("avx2"))
    return fan_table_avx2(f, table, image, i0, j0, row0, rows, width);
#endif
  return (f.sectors == 4 ? table_4 : table_3)(f, table, image, i0, j0, row0, rows, width);
}

}  // namespace cellproj
