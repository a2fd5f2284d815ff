#include "slicing/slice_renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "composite/fragment.hpp"
#include "slicing/boundary_crossings.hpp"
#include "slicing/preintegration.hpp"
#include "slicing/slice_cut.hpp"
#include "view/raster.hpp"
#ifdef CELLPROJ_HAVE_OPENGL
#include "composite/gl_compositor.hpp"
#endif

namespace cellproj {
namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

constexpr float kEmpty = std::numeric_limits<float>::quiet_NaN();  // a pixel no polygon of the slice covers
constexpr double kNoHeight = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kSliceImageBytes = 64u << 20;  // the slices' scalar images of one chunk
// Planes cut and scan converted together: more keep the threads busy on small images; fewer keep
// the polygons of a chunk (which are written once, then read) small enough to stay in memory once
// touched.
constexpr std::size_t kMaxChunk = 16;
constexpr std::size_t kReuseBytes = 512u << 20;  // polygons kept for the next level

// One slice scan converted: the scalar at each pixel centre it covers, and the box of those pixels.
struct SliceImage {
  std::vector<float> s;
  double height = 0.0;                 // of its plane
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // covered pixels lie in [x0, x1) x [y0, y1)
  bool covers(int i, int j) const { return i >= x0 && i < x1 && j >= y0 && j < y1; }
  float at(int i, int j, int width) const { return covers(i, j) ? s[static_cast<std::size_t>(j) * width + i] : kEmpty; }
  void clear(int width) {
    for (int j = y0; j < y1; ++j) std::fill_n(s.begin() + static_cast<std::ptrdiff_t>(j) * width + x0, x1 - x0, kEmpty);
    x0 = y0 = x1 = y1 = 0;
  }
};

// The polygons of a slice, fanned from their first vertex, into its scalar image (the coverage
// rule of view/raster.hpp: neighbouring polygons, whose shared edges have the same bits, cover
// each centre on them once). The scalar is interpolated perspective-correctly: s w / w.
void scan_convert(const SlicePolygons& p, int width, int height, SliceImage& out, std::int64_t& fragments,
                  std::int64_t& overlaps) {
  for (std::size_t q = 0; q < p.size(); ++q) {
    const std::uint32_t v0 = p.start[q];
    const glm::dvec2 a(p.x[v0], p.y[v0]);
    for (std::uint32_t v = v0 + 1; v + 1 < p.start[q + 1]; ++v) {
      const TriangleCoverage t(a, {p.x[v], p.y[v]}, {p.x[v + 1], p.y[v + 1]}, width, height);
      const double w[3] = {p.w[v0], p.w[v], p.w[v + 1]}, sw[3] = {p.sw[v0], p.sw[v], p.sw[v + 1]};
      for (int j = t.first_row(); j <= t.last_row(); ++j) {
        const TriangleCoverage::Row r = t.row(j);
        int b, e;
        t.run(r, b, e);
        if (b == e) continue;
        out.y0 = std::min(out.y0, j), out.y1 = std::max(out.y1, j + 1);
        out.x0 = std::min(out.x0, b), out.x1 = std::max(out.x1, e);
        float* row = out.s.data() + static_cast<std::size_t>(j) * width;
        for (int i = b; i < e; ++i) {
          double l[3];
          t.weights(r, i, l);
          const double s = (l[0] * sw[0] + l[1] * sw[1] + l[2] * sw[2]) / (l[0] * w[0] + l[1] * w[1] + l[2] * w[2]);
          overlaps += !std::isnan(row[i]);
          row[i] = static_cast<float>(s);
        }
        fragments += e - b;
      }
    }
  }
}

// A plane's polygons: those the previous level kept, or its entries of every block of cells.
struct PlanePolygons {
  const SlicePolygons* kept = nullptr;
  const CutBlocks* blocks = nullptr;
  std::size_t index = 0;  // in each block
  template <class F>
  void for_each(F&& f) const {
    if (kept) return f(*kept);
    for (const auto& block : *blocks) f(block[index]);
  }
};

void scan_convert(const PlanePolygons& plane, int width, int height, SliceImage& out, SlicingStats& st) {
  out.x0 = width, out.y0 = height, out.x1 = 0, out.y1 = 0;
  plane.for_each([&](const SlicePolygons& p) {
    scan_convert(p, width, height, out, st.fragments, st.overlapping_fragments);
    st.polygons += static_cast<std::int64_t>(p.size()), st.clipped_polygons += p.clipped;
  });
  if (out.x1 <= out.x0) out.x0 = out.y0 = out.x1 = out.y1 = 0;
}

// The light of a constant scalar over `length`: C (1 - exp(-kappa l)), 1 - exp(-kappa l).
void constant_light(const TransferFunction& tf, double s, double length, float rgba[4]) {
  const double alpha = -std::expm1(-tf.extinction(s) * length);
  const glm::dvec3 c = tf.color(s);
  rgba[0] = static_cast<float>(c.r * alpha), rgba[1] = static_cast<float>(c.g * alpha);
  rgba[2] = static_cast<float>(c.b * alpha), rgba[3] = static_cast<float>(alpha);
}

// What one frame composites from: the ray length between neighbouring planes at each pixel (the
// spacing over the cosine of the ray with the normal, per pixel: slanted and perspective rays cross
// farther), and the preintegrated table's layer for it.
struct PixelLengths {
  std::vector<float> length, layer;
  double lo = 0.0, hi = 0.0;
  std::int64_t along = 0;  // rays within 0.06 degrees of the planes, or turning away from the eye's side
};

PixelLengths pixel_lengths(const PixelRays& rays, const glm::dvec3& normal, double spacing) {
  PixelLengths p;
  const int w = rays.width(), h = rays.height();
  p.length.resize(static_cast<std::size_t>(w) * h);
  std::vector<int> along(static_cast<std::size_t>(h), 0);
  tbb::parallel_for(0, h, [&](int j) {
    for (int i = 0; i < w; ++i) {
      const double c = -glm::dot(rays.ray(i + 0.5, j + 0.5).dir, normal);  // the normal points to the eye
      along[static_cast<std::size_t>(j)] += !(c > 1e-3);
      p.length[static_cast<std::size_t>(j) * w + i] = static_cast<float>(spacing / std::max(std::abs(c), 1e-6));
    }
  });
  for (int a : along) p.along += a;
  const auto [lo, hi] = std::minmax_element(p.length.begin(), p.length.end());
  p.lo = *lo, p.hi = *hi;
  return p;
}

// Composites the slabs between neighbouring planes onto the image, back to front: for the planes
// of `slices` in order, the slab behind each (between it and the one before, `behind` for the
// first), and, when `front` is a height (not NaN), the slab from the last plane to that height.
// Where both planes of a slab cover the pixel, the slab is either two half-spacing samples, each
// plane's scalar held constant (sampled), or the preintegrated segment between the two scalars.
// Where only one does, the ray crosses the boundary inside the slab: the inside part, from the
// covering plane to the boundary crossing (half the slab when none is known), with that scalar.
struct Compositor {
  const TransferFunction& tf;
  const SlicingOptions& options;
  const PixelLengths& lengths;
  const PreintegratedTable* table;
  const BoundaryCrossings& boundary;
  double eye_height;  // perspective: the eye's height along the normal (infinity in orthographic views)
  int width, height;

  void operator()(Image& image, const SliceImage& behind, const std::vector<const SliceImage*>& slices,
                  double front) const {
    tbb::parallel_for(tbb::blocked_range<int>(0, height, 4), [&](const tbb::blocked_range<int>& rows) {
      for (int j = rows.begin(); j < rows.end(); ++j)
        for (int i = 0; i < width; ++i) pixel(image, i, j, behind, slices, front);
    });
  }

  void pixel(Image& image, int i, int j, const SliceImage& behind, const std::vector<const SliceImage*>& slices,
             double front_height) const {
    const std::size_t at = static_cast<std::size_t>(j) * width + i;
    float* dst = image.pixel(i, j);
    const double length = lengths.length[at], layer = lengths.layer.empty() ? 0.0 : lengths.layer[at];
    const bool sampled = options.integral == SliceIntegral::sampled;
    float back = behind.at(i, j, width), rgba[4], back_half[4], front_half[4];
    double back_height = behind.height;
    if (sampled && !std::isnan(back)) constant_light(tf, back, 0.5 * length, back_half);
    auto slab = [&](float front, double height) {
      const bool f = !std::isnan(front), b = !std::isnan(back);
      if (f && b) {
        if (sampled) {
          constant_light(tf, front, 0.5 * length, front_half);
          over(dst, back_half), over(dst, front_half);
        } else {
          (*table)(front, back, length, layer, rgba);
          over(dst, rgba);
        }
      } else if (f || b) {
        // No crossing in a slab that ends at the eye: inside the mesh up to the eye. None known
        // otherwise (too many, or its face reaches behind the eye): half the slab, on average.
        const double crossing = boundary.between(at, back_height, height, f);
        const double inside = std::isinf(crossing) && height == eye_height ? 1.0
                              : !std::isfinite(crossing)
                                  ? 0.5
                                  : (f ? height - crossing : crossing - back_height) / (height - back_height);
        constant_light(tf, f ? front : back, inside * length, rgba);
        over(dst, rgba);
        if (sampled && f) constant_light(tf, front, 0.5 * length, front_half);
      }
      back = front, back_height = height;
      if (sampled) std::copy(front_half, front_half + 4, back_half);
    };
    for (const SliceImage* s : slices) slab(s->at(i, j, width), s->height);
    if (!std::isnan(front_height)) slab(kEmpty, front_height);
  }
};

#ifdef CELLPROJ_HAVE_OPENGL
// A slice's polygons as Gouraud triangles for OpenGL (the paper's hardware slicing): each corner
// with its colour and the opacity of one spacing along its own ray, C(s), 1 - exp(-kappa(s) l).
void gl_corners(const PlanePolygons& plane, const TransferFunction& tf, const PixelRays& rays, const glm::dvec3& normal,
                double spacing, const DitherShift& shift, std::vector<GLCorner>& out, SlicingStats& st) {
  out.clear();
  plane.for_each([&](const SlicePolygons& p) {
    st.polygons += static_cast<std::int64_t>(p.size()), st.clipped_polygons += p.clipped;
    auto corner = [&](std::uint32_t v) {
      const double s = p.sw[v] / p.w[v];
      const double l = spacing / std::max(std::abs(glm::dot(rays.ray(p.x[v], p.y[v]).dir, normal)), 1e-6);
      const glm::dvec3 c = tf.color(s);
      const float x = static_cast<float>(p.x[v]), y = static_cast<float>(p.y[v]);
      out.push_back({x, y, 0.0f, 0.0f, static_cast<float>(c.r), static_cast<float>(c.g), static_cast<float>(c.b),
                     static_cast<float>(-std::expm1(-tf.extinction(s) * l)), (x + shift.u) / kDitherTile,
                     (y + shift.v) / kDitherTile});
    };
    for (std::size_t q = 0; q < p.size(); ++q)
      for (std::uint32_t v = p.start[q] + 1; v + 1 < p.start[q + 1]; ++v) corner(p.start[q]), corner(v), corner(v + 1);
  });
}
#endif

}  // namespace

SliceRenderer::SliceRenderer(const MeshView& mesh, Tetrahedralize mode)
    : mesh_(mesh), points_(recentre(mesh)), boundary_(boundary_triangles(mesh)) {
  cells_ = slice_cells(mesh_, points_, mode);
}

Image SliceRenderer::render(const double* scalar, const TransferFunction& tf, const Camera& camera, int width,
                            int height, const SlicingOptions& options, SlicingStats* stats) const {
  Image result;
  render_levels(scalar, tf, camera, width, height, options, {options.slices},
                [&](std::size_t, int, const Image& image, const SlicingStats& st) {
                  result = image;
                  if (stats) *stats = st;
                });
  return result;
}

void SliceRenderer::render_levels(const double* scalar, const TransferFunction& tf, const Camera& camera, int width,
                                  int height, const SlicingOptions& options, const std::vector<int>& levels,
                                  const SliceLevelDone& done) const {
  check_options(options);
  if (levels.empty()) throw InputError("progressive slicing: no levels given");
  for (std::size_t l = 0; l < levels.size(); ++l) {
    check_slices(levels[l], width, height);
    if (l > 0 && levels[l] <= levels[l - 1])
      throw InputError("progressive slicing: the levels must increase (" + std::to_string(levels[l - 1]) + " then " +
                       std::to_string(levels[l]) + ")");
  }
  const PixelRays rays(recentred(camera, points_.centre), width, height);

  // The frame's points, for every level: screen attributes (and heights, per level's family).
  FramePoints points;
  points.perspective = rays.perspective();
  points.near = 1e-9 * std::max(points_.half_diagonal, 1e-300);
  const std::size_t n = static_cast<std::size_t>(mesh_.n_points);
  points.screen.resize(n), points.height.resize(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t p) {
    glm::dvec4& a = points.screen[p];
    rays.project_homogeneous(points_(static_cast<std::int64_t>(p)), a.x, a.y, a.z);
    a.w = scalar ? scalar[p] : 0.0;
  });
  double s_lo = 0.0, s_hi = 0.0;
  if (n > 0 && scalar) {
    const auto [lo, hi] = std::minmax_element(scalar, scalar + n);
    s_lo = *lo, s_hi = *hi;
  }

  std::vector<SlicePolygons> previous;  // the last level's polygons by plane,
  std::vector<char> previous_kept;      // where they were kept (within the budget)
  int previous_count = 0;
  for (std::size_t level = 0; level < levels.size(); ++level) {
    const auto t_frame = std::chrono::steady_clock::now();
    SlicingStats st;
    const int count = levels[level];
    const SlicePlanes planes(points_, rays, options.axis, count);
    st.axis = planes.axis(), st.spacing = planes.spacing();
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t p) {
      points.height[p] = glm::dot(points_(static_cast<std::int64_t>(p)), planes.normal());
    });
    CellSweep sweep(cells_, points, planes);
    st.cells_between_planes = sweep.between_planes();
    const int visible = planes.visible_end() - 1;  // planes 1..visible are drawn
    st.slices = visible, st.planes_behind_eye = count - visible;

    auto t = std::chrono::steady_clock::now();
    PixelLengths lengths = pixel_lengths(rays, planes.normal(), planes.spacing());
    st.rays_along_planes = lengths.along;
    std::unique_ptr<PreintegratedTable> table;
    if (options.integral == SliceIntegral::preintegrated) {
      table = std::make_unique<PreintegratedTable>(tf, s_lo, s_hi, lengths.lo, lengths.hi, options.table_size);
      st.table_layers = table->layers();
      if (table->layers() > 1) {
        lengths.layer.resize(lengths.length.size());
        for (std::size_t k = 0; k < lengths.length.size(); ++k)
          lengths.layer[k] = static_cast<float>(table->layer_of(lengths.length[k]));
      }
    }
    st.phase_seconds.push_back({"table", since(t)});

    Image image(width, height);
#ifdef CELLPROJ_HAVE_OPENGL
    std::unique_ptr<GLCompositor> gl;  // its calls stay on this thread
    std::vector<GLCorner> corners;
    if (is_opengl(options.backend)) {
      gl = std::make_unique<GLCompositor>(width, height, gl_target(options.backend));
      st.gl_renderer = gl->renderer();
      gl->begin(nullptr);
    }
#endif
    t = std::chrono::steady_clock::now();
    const BoundaryCrossings crossings(boundary_, points, width, height);
    st.phase_seconds.push_back({"boundary", since(t)});
    const Compositor compositor{tf, options, lengths, table.get(), crossings, planes.eye_height(), width, height};
    const int chunk = static_cast<int>(std::clamp<std::size_t>(
        kSliceImageBytes / (static_cast<std::size_t>(width) * height * sizeof(float)), 2, kMaxChunk));
    std::vector<SliceImage> slice(static_cast<std::size_t>(chunk));
    SliceImage behind;  // the last plane of the previous chunk
    for (SliceImage* s = slice.data(); s != slice.data() + chunk; ++s)
      s->s.assign(static_cast<std::size_t>(width) * height, kEmpty);
    behind.s.assign(static_cast<std::size_t>(width) * height, kEmpty);
    behind.height = planes.height(0);  // the back end of the mesh: no plane covers it
    const bool keep = level + 1 < levels.size();
    std::vector<SlicePolygons> kept(keep ? static_cast<std::size_t>(visible) + 1 : 0);
    std::vector<char> kept_flag(kept.size(), 0);
    std::size_t kept_bytes = 0;
    double cut_s = 0.0, scan_s = 0.0, comp_s = 0.0;
    CutBlocks blocks;
    for (int first = 1; first <= visible; first += chunk) {
      const int end = std::min(visible + 1, first + chunk);
      const std::size_t here = static_cast<std::size_t>(end - first);
      // Planes of the previous level that coincide with these keep their polygons.
      std::vector<char> wanted(here, 1);
      std::vector<PlanePolygons> plane(here);
      for (std::size_t k = 0; k < here; ++k) {
        plane[k].blocks = &blocks, plane[k].index = k;
        const std::int64_t coarse = static_cast<std::int64_t>(first + static_cast<int>(k)) * previous_count;
        if (previous.empty() || coarse % count != 0) continue;
        const std::size_t pj = static_cast<std::size_t>(coarse / count);
        if (pj < previous.size() && previous_kept[pj]) {
          plane[k].kept = &previous[pj], wanted[k] = 0;
          ++st.planes_reused;
        }
      }
      t = std::chrono::steady_clock::now();
      cut_planes(cells_, points, planes, sweep, sweep.advance(first, end), first, end, wanted, blocks);
      cut_s += since(t);

#ifdef CELLPROJ_HAVE_OPENGL
      if (gl) {  // the planes drawn in order, back to front, blended by OpenGL
        t = std::chrono::steady_clock::now();
        for (std::size_t k = 0; k < here; ++k) {
          gl_corners(plane[k], tf, rays, planes.normal(), planes.spacing(),
                     DitherShift(static_cast<std::uint64_t>(first) + k), corners, st);
          gl->draw(corners);
        }
        comp_s += since(t);
        continue;
      }
#endif
      t = std::chrono::steady_clock::now();
      std::vector<SlicingStats> counts(here);
      tbb::parallel_for(std::size_t{0}, here, [&](std::size_t k) {
        slice[k].clear(width);
        slice[k].height = planes.height(first + static_cast<int>(k));
        scan_convert(plane[k], width, height, slice[k], counts[k]);
      });
      scan_s += since(t);
      for (const SlicingStats& c : counts) {
        st.fragments += c.fragments, st.overlapping_fragments += c.overlapping_fragments;
        st.polygons += c.polygons, st.clipped_polygons += c.clipped_polygons;
      }

      t = std::chrono::steady_clock::now();
      std::vector<const SliceImage*> in_order;
      for (std::size_t k = 0; k < here; ++k) in_order.push_back(&slice[k]);
      compositor(image, behind, in_order, end == visible + 1 ? planes.front_end() : kNoHeight);
      comp_s += since(t);
      std::swap(behind, slice[here - 1]);

      for (std::size_t k = 0; k < here && keep; ++k) {  // for the next level, within the budget
        SlicePolygons p;
        plane[k].for_each([&](const SlicePolygons& part) { p.append(part); });
        if (kept_bytes + p.bytes() > kReuseBytes) break;
        kept_bytes += p.bytes();
        kept[static_cast<std::size_t>(first) + k] = std::move(p);
        kept_flag[static_cast<std::size_t>(first) + k] = 1;
      }
    }
#ifdef CELLPROJ_HAVE_OPENGL
    if (gl) image = gl->finish();
#endif
    previous = std::move(kept), previous_kept = std::move(kept_flag);
    previous_count = count;
    st.phase_seconds.push_back({"cut", cut_s});
    st.phase_seconds.push_back({"scan convert", scan_s});
    st.phase_seconds.push_back({"composite", comp_s});
    st.seconds = since(t_frame);
    done(level, count, image, st);
  }
}

}  // namespace cellproj
