#pragma once
// The coverage rule of every rasterizing path (the A-buffer of the visibility sort, the projection
// back ends): a triangle covers the pixel centres (i + 0.5, j + 0.5) strictly inside it, and a
// centre exactly on an edge belongs to the triangle for which that edge is a top or left edge.
// Edge functions are evaluated with the edge's endpoints in a fixed order, so two triangles sharing
// an edge compute exactly opposite values: a centre on a shared edge is covered exactly once.
#include <algorithm>
#include <cmath>

#include <glm/vec2.hpp>

namespace cellproj {

namespace raster_detail {
inline bool before(const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }
// (b - a) x (p - a), computed from the lesser endpoint so that edge (b, a) gives exactly the negation.
inline double edge(const glm::dvec2& a, const glm::dvec2& b, double px, double py) {
  if (before(b, a)) return -edge(b, a, px, py);
  return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}
// Whether a centre exactly on edge a->b (of a positively oriented triangle) belongs to it: true for
// exactly one of the two directions of any edge.
inline bool owns(const glm::dvec2& a, const glm::dvec2& b) { return a.y > b.y || (a.y == b.y && a.x < b.x); }

// edge(a, b, x, y) with its differences hoisted: the same operations on the same values, so the
// same bits, evaluated per row (row) and then per pixel (at).
struct EdgeFunction {
  double ax, ay, dx, dy, sign;
  bool own;
  EdgeFunction(const glm::dvec2& a, const glm::dvec2& b) : own(owns(a, b)) {
    const bool flip = before(b, a);
    const glm::dvec2& lo = flip ? b : a;
    const glm::dvec2& hi = flip ? a : b;
    ax = lo.x, ay = lo.y, dx = hi.x - lo.x, dy = hi.y - lo.y, sign = flip ? -1.0 : 1.0;
    slope = dx / dy, right_bound = sign * dy > 0;
  }
  double row(double y) const { return dx * (y - ay); }
  double at(double row_value, double x) const { return sign * (row_value - dy * (x - ax)); }
  double step() const { return -sign * dy; }  // at(r, x + 1) - at(r, x), up to rounding
  bool inside(double e) const { return e > 0 || (e == 0 && own); }
  // Narrows the pixels begin <= i < end of row y (row_value = row(y)) to those inside this edge,
  // exactly. Along the row the edge's test holds on one side of the crossing (the edge function is
  // monotone in x: each rounding step is); the crossing's estimate only says where to start, and
  // the test itself finds the side's last pixel, however far the estimate is off (huge coordinates).
  void bound(double row_value, double y, int& begin, int& end) const {
    if (begin >= end) return;
    auto in = [&](int i) { return inside(at(row_value, i + 0.5)); };
    if (dy == 0) {  // the same value along the row
      if (!in(begin)) end = begin;
      return;
    }
    const double x = ax + slope * (y - ay) - 0.5;  // the pixel whose centre is the crossing
    int i = !(x > begin) ? begin : !(x < end - 1) ? end - 1 : static_cast<int>(x);  // (NaN: begin)
    if (right_bound) {                                                              // inside up to the crossing
      if (in(i)) {
        while (i + 1 < end && in(i + 1)) ++i;
        end = i + 1;
      } else {
        while (i > begin && !in(i - 1)) --i;
        end = i;
      }
    } else {  // inside from the crossing on
      if (in(i)) {
        while (i > begin && in(i - 1)) --i;
        begin = i;
      } else {
        while (i + 1 < end && !in(i + 1)) ++i;
        begin = i + 1;
      }
    }
  }
  double slope;      // dx / dy: the crossing's x per unit of y
  bool right_bound;  // the inside is left of the crossing
};
}  // namespace raster_detail

// The pixels i0 <= i <= i1, j0 <= j <= j1 of a width x height image whose centres lie in the
// bounding box of a triangle (none when i1 < i0 or j1 < j0): the only ones it can cover.
struct PixelBox {
  int i0 = 0, i1 = -1, j0 = 0, j1 = -1;
  PixelBox() = default;
  PixelBox(const glm::dvec2& p0, const glm::dvec2& p1, const glm::dvec2& p2, int width, int height) {
    const double xmin = std::min({p0.x, p1.x, p2.x}), xmax = std::max({p0.x, p1.x, p2.x});
    const double ymin = std::min({p0.y, p1.y, p2.y}), ymax = std::max({p0.y, p1.y, p2.y});
    // Clamped to [-1, size] before the conversion: a triangle far outside the image (a vertex
    // just in front of the eye) would overflow int, and then cover nothing, not every row.
    i0 = clamped(std::ceil(xmin - 0.5), width), i1 = clamped(std::floor(xmax - 0.5), width);
    j0 = clamped(std::ceil(ymin - 0.5), height), j1 = clamped(std::floor(ymax - 0.5), height);
    i0 = std::max(i0, 0), i1 = std::min(i1, width - 1), j0 = std::max(j0, 0), j1 = std::min(j1, height - 1);
  }
  static int clamped(double v, int size) {
    return !(v > -1.0) ? -1 : v > size ? size : static_cast<int>(v);  // NaN: -1
  }
  bool empty() const { return i1 < i0 || j1 < j0; }
  // Whether it holds a pixel centre of rows row_begin <= j < row_end (an image tile's).
  bool reaches(int row_begin, int row_end) const { return !empty() && j1 >= row_begin && j0 < row_end; }
};

// A triangle in pixel coordinates (x right, y down), turned positive, with its edge functions:
// which pixel centres of each row it covers. Along a row every edge function is monotone (each
// rounding step is), so the centres a triangle covers on one row are one run of pixels.
class TriangleCoverage {
 public:
  TriangleCoverage(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, int width, int height)
      : TriangleCoverage(p0, p1, p2, PixelBox(p0, p1, p2, width, height)) {}
  // The same with the triangle's pixel box already known (PixelBox(p0, p1, p2, width, height)).
  TriangleCoverage(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, const PixelBox& box)
      : TriangleCoverage(p0, p1, p2, raster_detail::edge(p0, p1, p2.x, p2.y), box) {}
  // Rows first_row() <= j <= last_row() may hold covered centres (none when last < first).
  int first_row() const { return box_.j0; }
  int last_row() const { return box_.j1; }

  struct Row {
    double y, r0, r1, r2;  // y = j + 0.5 and the edge functions' row terms there
  };
  Row row(int j) const {
    const double y = j + 0.5;
    return {y, f0_.row(y), f1_.row(y), f2_.row(y)};
  }
  // The covered pixels begin <= i < end of a row, exactly (begin == end when none): the pixels
  // inside all three edges, each of which holds on one side of the row (a half-line of pixels, or
  // all or none of them for a horizontal edge).
  void run(const Row& r, int& begin, int& end) const {
    begin = box_.i0, end = box_.i1 + 1;
    f0_.bound(r.r0, r.y, begin, end), f1_.bound(r.r1, r.y, begin, end), f2_.bound(r.r2, r.y, begin, end);
    end = std::max(begin, end);
  }
  // The barycentric weights of p0, p1 and p2 (in the caller's order) at the centre of pixel i.
  void weights(const Row& r, int i, double w[3]) const {
    const double x = i + 0.5;
    const double e0 = f0_.at(r.r0, x), e1 = f1_.at(r.r1, x), e2 = f2_.at(r.r2, x);
    // e1 is opposite p0, e2 opposite p1, e0 opposite p2 (in the possibly swapped order).
    w[0] = e1 * inv_, w[1] = (swapped_ ? e0 : e2) * inv_, w[2] = (swapped_ ? e2 : e0) * inv_;
  }
  // How much each weight changes from one pixel of a row to the next: the weights are affine in x.
  void weight_steps(double dw[3]) const {
    const double d0 = f0_.step(), d1 = f1_.step(), d2 = f2_.step();
    dw[0] = d1 * inv_, dw[1] = (swapped_ ? d0 : d2) * inv_, dw[2] = (swapped_ ? d2 : d0) * inv_;
  }

 private:
  // The edges of (p0, p1, p2), or of (p0, p2, p1) when that turns negative.
  TriangleCoverage(const glm::dvec2& p0, const glm::dvec2& p1, const glm::dvec2& p2, double area, const PixelBox& box)
      : swapped_(area < 0),
        f0_(p0, swapped_ ? p2 : p1),
        f1_(swapped_ ? p2 : p1, swapped_ ? p1 : p2),
        f2_(swapped_ ? p1 : p2, p0),
        inv_(1.0 / std::abs(area)) {
    if (!(area != 0.0) || !std::isfinite(area)) return;  // degenerate: covers nothing
    box_ = box;
  }
  bool swapped_;
  raster_detail::EdgeFunction f0_, f1_, f2_;
  double inv_;
  PixelBox box_;
};

// Calls f(j, row, begin, end) for every row row_begin <= j < row_end on which the triangle covers the
// centres of pixels begin <= i < end (and at least one): the row loop of the rasterizers below.
template <class F>
void for_each_run(const TriangleCoverage& t, int row_begin, int row_end, F&& f) {
  for (int j = std::max(t.first_row(), row_begin); j <= std::min(t.last_row(), row_end - 1); ++j) {
    const TriangleCoverage::Row r = t.row(j);
    int b, e;
    t.run(r, b, e);
    if (b < e) f(j, r, b, e);
  }
}

// Calls run(j, begin, end) for every row j of a width x height image on which the triangle covers
// the centres of pixels begin <= i < end (and at least one).
template <class Run>
void rasterize_triangle_runs(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, int width, int height, Run&& run) {
  const TriangleCoverage t(p0, p1, p2, width, height);
  for_each_run(t, 0, height, [&](int j, const TriangleCoverage::Row&, int b, int e) { run(j, b, e); });
}

// Calls covered(i, j, w0, w1, w2) for every pixel of rows row_begin <= j < row_end of a width x
// height image whose centre the triangle (p0, p1, p2) in pixel coordinates (x right, y down)
// covers, with the barycentric weights of p0, p1 and p2 at that centre. Degenerate triangles cover
// nothing.
template <class Covered>
void rasterize_triangle_weights(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, int width, int height, int row_begin,
                                int row_end, Covered&& covered) {
  const TriangleCoverage t(p0, p1, p2, width, height);
  for_each_run(t, row_begin, row_end, [&](int j, const TriangleCoverage::Row& r, int b, int e) {
    double w[3];
    for (int i = b; i < e; ++i) t.weights(r, i, w), covered(i, j, w[0], w[1], w[2]);
  });
}

// Calls steps(dw) once with how much the barycentric weights of p0, p1 and p2 change from one pixel
// of a row to the next (they are affine in x), then span(j, begin, end, w) for every row j of a
// width x height image on which the triangle covers the centres of pixels begin <= i < end (and at
// least one), with the weights w at the centre of pixel `begin`: for shading a run of pixels by
// plane equations instead of weights per pixel.
// Only rows row_begin <= j < row_end are visited (an image tile's rows). A triangle whose box holds
// no pixel centre of them (most of a small cell's image-plane subdivision) is passed over before
// its set-up: steps() is not called.
// The triangle's pixel box, PixelBox(p0, p1, p2, width, height), is given when the caller has it.
template <class Steps, class Span>
void rasterize_triangle_spans(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, const PixelBox& box, int row_begin,
                              int row_end, Steps&& steps, Span&& span) {
  if (!box.reaches(row_begin, row_end)) return;  // (a NaN vertex gives an empty box)
  const TriangleCoverage t(p0, p1, p2, box);
  double w[3];
  t.weight_steps(w);
  steps(static_cast<const double*>(w));
  for_each_run(t, row_begin, row_end, [&](int j, const TriangleCoverage::Row& r, int b, int e) {
    t.weights(r, b, w);
    span(j, b, e, static_cast<const double*>(w));
  });
}

template <class Steps, class Span>
void rasterize_triangle_spans(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, int width, int height, int row_begin,
                              int row_end, Steps&& steps, Span&& span) {
  rasterize_triangle_spans(p0, p1, p2, PixelBox(p0, p1, p2, width, height), row_begin, row_end, steps, span);
}

template <class Steps, class Span>
void rasterize_triangle_spans(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, int width, int height, Steps&& steps,
                              Span&& span) {
  rasterize_triangle_spans(p0, p1, p2, width, height, 0, height, steps, span);
}

// The same over every row of the image.
template <class Covered>
void rasterize_triangle_weights(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, int width, int height, Covered&& covered) {
  rasterize_triangle_weights(p0, p1, p2, width, height, 0, height, covered);
}

}  // namespace cellproj
