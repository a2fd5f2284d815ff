#include "slicing/slice_renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "base/timing.hpp"
#include "slicing/slab_compositor.hpp"
#include "slicing/slice_splats.hpp"
#ifdef CELLPROJ_HAVE_OPENGL
#include "composite/gl_compositor.hpp"
#endif

namespace cellproj {
namespace {

constexpr double kNoHeight = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kSliceImageBytes = 64u << 20;  // the slices' scalar images of one chunk
// Planes cut and scan converted together: more keep the threads busy on small images; fewer keep
// the polygons of a chunk (which are written once, then read) small enough to stay in memory once
// touched.
constexpr std::size_t kMaxChunk = 16;
constexpr std::size_t kReuseBytes = 512u << 20;  // polygons kept for the next level

#ifdef CELLPROJ_HAVE_OPENGL
// A slice's polygons as Gouraud triangles for OpenGL (the paper's hardware slicing): each corner
// with its colour and the opacity of one spacing along its own ray, C(s), 1 - exp(-kappa(s) l).
void gl_corners(const PlanePolygons& plane, const TransferFunction& tf, const PixelRays& rays, const glm::dvec3& normal,
                double spacing, const DitherShift& shift, std::vector<GLCorner>& out, ScanCounts& st) {
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

// InputError unless the levels are plane counts the image allows, increasing.
void check_levels(const std::vector<int>& levels, int width, int height) {
  if (levels.empty()) throw InputError("progressive slicing: no levels given");
  for (std::size_t l = 0; l < levels.size(); ++l) {
    check_slices(levels[l], width, height);
    if (l > 0 && levels[l] <= levels[l - 1])
      throw InputError("progressive slicing: the levels must increase (" + std::to_string(levels[l - 1]) + " then " +
                       std::to_string(levels[l]) + ")");
  }
}

// The frame's points for every level: screen attributes, and heights along the family's normal.
FramePoints frame_points(const RecentredPoints& points, const PixelRays& rays, const double* scalar,
                         const glm::dvec3& normal) {
  FramePoints out;
  out.perspective = rays.perspective();
  out.near = 1e-9 * std::max(points.half_diagonal, 1e-300);
  const std::size_t n = points.xyz.size() / 3;
  out.screen.resize(n), out.height.resize(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t p) {
    glm::dvec4& a = out.screen[p];
    rays.project_homogeneous(points(static_cast<std::int64_t>(p)), a.x, a.y, a.z);
    a.w = scalar ? scalar[p] : 0.0;
  });
  tbb::parallel_for(std::size_t{0}, n,
                    [&](std::size_t p) { out.height[p] = glm::dot(points(static_cast<std::int64_t>(p)), normal); });
  return out;
}

// The software back end's ray lengths between a stack's planes and, for the preintegrated
// integral, its table over the field's range [s_lo, s_hi].
struct LevelTables {
  PixelLengths lengths;
  std::unique_ptr<PreintegratedTable> table;
};
LevelTables level_tables(const PixelRays& rays, const SlicePlanes& planes, const SlicingOptions& options,
                         const TransferFunction& tf, double s_lo, double s_hi, int visible, SlicingStats& st) {
  LevelTables out;
  if (is_opengl(options.backend)) return out;
  PixelLengths& lengths = out.lengths;
  lengths = pixel_lengths(rays, planes.normal(), planes.spacing());
  st.rays_along_planes = lengths.along;
  if (options.integral != SliceIntegral::preintegrated || visible == 0) return out;
  out.table = std::make_unique<PreintegratedTable>(tf, s_lo, s_hi, lengths.lo, lengths.hi, options.table_size);
  st.table_layers = out.table->layers();
  if (out.table->layers() > 1) {
    lengths.layer.resize(lengths.length.size());
    for (std::size_t k = 0; k < lengths.length.size(); ++k)
      lengths.layer[k] = static_cast<float>(out.table->layer_of(lengths.length[k]));
  }
  return out;
}

// The polygons of a level's planes kept for the next level, by plane, within kReuseBytes.
struct KeptPlanes {
  std::vector<std::optional<SlicePolygons>> planes;
  int count = 0;  // the planes of the level that made them
  std::size_t bytes = 0;
};

// Planes first.. of this level (`count` planes) that coincide with a plane of the previous level
// keep its polygons: those are not cut again (wanted 0).
void reuse_kept(const KeptPlanes& previous, int count, int first, std::vector<PlanePolygons>& plane,
                std::vector<char>& wanted, SlicingStats& st) {
  if (previous.planes.empty()) return;
  for (std::size_t k = 0; k < plane.size(); ++k) {
    const std::int64_t coarse = static_cast<std::int64_t>(first + static_cast<int>(k)) * previous.count;
    if (coarse % count != 0) continue;
    const std::size_t pj = static_cast<std::size_t>(coarse / count);
    if (pj < previous.planes.size() && previous.planes[pj]) {
      plane[k].kept = &*previous.planes[pj], wanted[k] = 0;
      ++st.planes_reused;
    }
  }
}

// Keeps the polygons of planes first.. for the next level, while the budget lasts.
void keep(const std::vector<PlanePolygons>& plane, int first, KeptPlanes& kept) {
  for (std::size_t k = 0; k < plane.size(); ++k) {
    SlicePolygons p;
    plane[k].for_each([&](const SlicePolygons& part) { p.append(part); });
    if (kept.bytes + p.bytes() > kReuseBytes) return;
    kept.bytes += p.bytes();
    kept.planes[static_cast<std::size_t>(first) + k] = std::move(p);
  }
}

}  // namespace

SliceRenderer::SliceRenderer(const MeshView& mesh, Tetrahedralize mode)
    : local_(mesh), mesh_(local_.view()), points_(recentre(mesh_)), boundary_(boundary_triangles(mesh_)) {
  cells_ = slice_cells(mesh_, points_, mode);
  volume_.resize(static_cast<std::size_t>(cells_.size()));
  tbb::parallel_for(std::int64_t{0}, cells_.size(), [&](std::int64_t c) {
    const std::int64_t* ids = cells_.ids.data() + cells_.offsets[static_cast<std::size_t>(c)];
    volume_[static_cast<std::size_t>(c)] =
        cell_moments(ids, static_cast<CellType>(cells_.types[static_cast<std::size_t>(c)]), points_).volume;
  });
}

Image SliceRenderer::render(const double* scalar, const TransferFunction& tf, const Camera& camera, int width,
                            int height, const SlicingOptions& options, SlicingStats* stats) const {
  Image result;
  render_levels(scalar, tf, camera, width, height, options, {options.slices},
                [&](std::size_t, int, Image&& image, const SlicingStats& st) {
                  result = std::move(image);
                  if (stats) *stats = st;
                });
  return result;
}

void SliceRenderer::render_levels(const double* scalar, const TransferFunction& tf, const Camera& camera, int width,
                                  int height, const SlicingOptions& options, const std::vector<int>& levels,
                                  const SliceLevelDone& done) const {
  check_options(options);
  check_levels(levels, width, height);
  const PixelRays rays(recentred(camera, points_.centre), width, height);

  // What every level shares: the family (the plane count changes neither its normal nor its
  // extent), the points on screen and their heights along the normal, the field's range, and for
  // the software back end the boundary crossings and the slices' images (OpenGL takes each
  // corner's values itself).
  const bool software = !is_opengl(options.backend);
  const SliceAxis axis = options.axis == SliceAxis::automatic ? automatic_axis(points_, rays) : options.axis;
  const FramePoints points = frame_points(points_, rays, scalar, slice_normal(axis, rays));
  double s_lo = 0.0, s_hi = 0.0;
  if (mesh_.n_points > 0 && scalar) {
    const auto [lo, hi] = std::minmax_element(scalar, scalar + mesh_.n_points);
    s_lo = *lo, s_hi = *hi;
  }
  auto t = std::chrono::steady_clock::now();
  std::optional<BoundaryCrossings> crossings;
  if (software) crossings.emplace(boundary_, points, width, height);
  const double boundary_seconds = seconds_since(t);
  const int chunk = static_cast<int>(std::clamp<std::size_t>(
      kSliceImageBytes / (static_cast<std::size_t>(width) * height * sizeof(float)), 2, kMaxChunk));
  const std::size_t pixels = software ? static_cast<std::size_t>(width) * height : 0;
  std::vector<SliceImage> slice(static_cast<std::size_t>(chunk));
  SliceImage behind;  // the last plane of the previous chunk
  for (SliceImage& s : slice) s.s.assign(pixels, kEmpty);
  behind.s.assign(pixels, kEmpty);
  std::vector<SplatLayer> layer(static_cast<std::size_t>(chunk));
  const SmallCells small_mode = resolve(options.splat, options.backend);
  const double threshold = threshold_or(options.splat, kDefaultVolumeThreshold);
  const SplatContext splat_frame{points_, scalar, tf, rays, options.splat.prefilter};

  KeptPlanes previous;              // the last level's polygons by plane, where kept
  std::vector<char> previous_skip;  // the cells the last level did not cut
  for (std::size_t level = 0; level < levels.size(); ++level) {
    const auto t_frame = std::chrono::steady_clock::now();
    SlicingStats st;
    const int count = levels[level];
    const SlicePlanes planes(points_, rays, axis, count);
    st.axis = planes.axis(), st.spacing = planes.spacing();
    const int visible = planes.visible_end() - 1;  // planes 1..visible are drawn
    st.slices = visible, st.planes_behind_eye = count - visible;
    // The small cells of this stack: splatted or skipped (draw: counted only, and cut).
    CellSweep sweep(cells_, points, planes);
    const SliceSplats splats(cells_, volume_, sweep, splat_frame, planes, small_mode == SmallCells::splat ? visible : 0,
                             threshold);
    st.small_cells = small_mode, st.splat_threshold = threshold, st.splat = splats.counters();
    const std::vector<char>* skip = small_mode == SmallCells::draw ? nullptr : &splats.small();
    if (skip) sweep.drop(*skip);
    st.cells_between_planes = sweep.between_planes();
    // Polygons kept from the last level hold the cells it cut: only the same cells may reuse them.
    if (skip ? *skip != previous_skip : !previous_skip.empty()) previous.planes.clear();
    previous_skip = skip ? *skip : std::vector<char>();

    t = std::chrono::steady_clock::now();
    const LevelTables tables = level_tables(rays, planes, options, tf, s_lo, s_hi, visible, st);
    st.phase_seconds.push_back({"table", seconds_since(t)});

    Image image(width, height);
#ifdef CELLPROJ_HAVE_OPENGL
    std::unique_ptr<GLCompositor> gl;  // its calls stay on this thread
    std::vector<GLCorner> corners;
    ScanCounts gl_counts;
    if (is_opengl(options.backend)) {
      gl = std::make_unique<GLCompositor>(width, height, gl_target(options.backend));
      st.gl_renderer = gl->renderer();
      gl->begin(nullptr);
    }
#endif
    st.phase_seconds.push_back({"boundary", level == 0 ? boundary_seconds : 0.0});
    behind.clear(width);
    behind.height = planes.height(0);  // the back end of the mesh: no plane covers it
    KeptPlanes kept;
    kept.count = count;
    if (level + 1 < levels.size()) kept.planes.resize(static_cast<std::size_t>(visible) + 1);
    double cut_s = 0.0, scan_s = 0.0, comp_s = 0.0;
    CutBlocks blocks;
    for (int first = 1; first <= visible; first += chunk) {
      const int end = std::min(visible + 1, first + chunk);
      const std::size_t here = static_cast<std::size_t>(end - first);
      std::vector<char> wanted(here, 1);
      std::vector<PlanePolygons> plane(here);
      for (std::size_t k = 0; k < here; ++k) plane[k].blocks = &blocks, plane[k].index = k;
      reuse_kept(previous, count, first, plane, wanted, st);
      t = std::chrono::steady_clock::now();
      cut_planes(cells_, points, planes, sweep, sweep.advance(first, end), first, end, wanted, blocks);
      cut_s += seconds_since(t);

#ifdef CELLPROJ_HAVE_OPENGL
      if (gl) {  // the planes drawn in order, back to front, blended by OpenGL
        t = std::chrono::steady_clock::now();
        for (std::size_t k = 0; k < here; ++k) {
          gl_corners(plane[k], tf, rays, planes.normal(), planes.spacing(),
                     DitherShift(static_cast<std::uint64_t>(first) + k), corners, gl_counts);
          gl->draw(corners);
        }
        comp_s += seconds_since(t);
        continue;
      }
#endif
      t = std::chrono::steady_clock::now();
      std::vector<ScanCounts> counts(here);
      tbb::parallel_for(std::size_t{0}, here, [&](std::size_t k) {
        slice[k].clear(width);
        slice[k].height = planes.height(first + static_cast<int>(k));
        scan_convert(plane[k], width, height, slice[k], counts[k]);
      });
      scan_s += seconds_since(t);
      for (const ScanCounts& c : counts) {
        st.fragments += c.fragments, st.overlapping_fragments += c.overlapping_fragments;
        st.polygons += c.polygons, st.clipped_polygons += c.clipped_polygons;
      }

      t = std::chrono::steady_clock::now();
      std::vector<const SliceImage*> in_order;
      for (std::size_t k = 0; k < here; ++k) in_order.push_back(&slice[k]);
      std::vector<const SplatLayer*> layers;  // the planes' splats where their slices left pixels empty
      if (splats.any()) {
        std::vector<SplatCounters> drawn(here);
        tbb::parallel_for(std::size_t{0}, here, [&](std::size_t k) {
          const int j = first + static_cast<int>(k);
          splat_layer(splats.begin(j), splats.end(j), slice[k], width, height, layer[k], drawn[k]);
        });
        for (std::size_t k = 0; k < here; ++k) {
          st.splat.add(drawn[k]);
          layers.push_back(layer[k].empty() ? nullptr : &layer[k]);
        }
      }
      const Compositor compositor{tf,    options, tables.lengths, tables.table.get(), *crossings, planes.eye_height(),
                                  width, height};
      compositor(image, behind, in_order, layers, end == visible + 1 ? planes.front_end() : kNoHeight);
      comp_s += seconds_since(t);
      std::swap(behind, slice[here - 1]);
      if (!kept.planes.empty()) keep(plane, first, kept);  // for the next level
    }
#ifdef CELLPROJ_HAVE_OPENGL
    if (gl) image = gl->finish(), st.polygons = gl_counts.polygons, st.clipped_polygons = gl_counts.clipped_polygons;
#endif
    previous = std::move(kept);
    st.phase_seconds.push_back({"cut", cut_s});
    st.phase_seconds.push_back({"scan convert", scan_s});
    st.phase_seconds.push_back({"composite", comp_s});
    st.seconds = seconds_since(t_frame);
    done(level, count, std::move(image), st);
  }
}

}  // namespace cellproj
