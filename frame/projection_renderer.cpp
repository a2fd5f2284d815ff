#include "frame/projection_renderer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include "base/check.hpp"
#include "base/error.hpp"
#include "base/timing.hpp"
#include "composite/ordered_pipeline.hpp"
#include "composite/tiled_compositor.hpp"
#include "frame/cell_passes.hpp"
#include "frame/frame_plan.hpp"
#include "frame/gl_frame.hpp"
#include "frame/splat_stencil.hpp"
#include "frame/tile_orders.hpp"
#include "mesh/geometry.hpp"
#include "raycast/cell_ray_tracer.hpp"
#include "splat/splat.hpp"
#include "view/depth_limit.hpp"
#include "view/screen.hpp"

namespace cellproj {
namespace {

struct FrameCounters {
  ProjectionCounters projection;
  SplatCounters splat;
  void add(const FrameCounters& o) { projection.add(o.projection), splat.add(o.splat); }
};

// The small cells' splats of the frame, and the stencil of the cells drawn by their polygons over
// the tiles the splats reach (the tracer's cells are the mesh's; a split cell is drawn when any of
// its parts is).
ProjectionSplats frame_splats(const SortableMesh& view_mesh, const std::vector<std::uint8_t>& small,
                              const SplatContext& frame, const CellRayTracer& tracer, std::int64_t mesh_cells,
                              SplatCounters& counters) {
  const MeshView& cells = view_mesh.cells;
  ProjectionSplats out;
  out.rays = &frame.rays;
  out.index.assign(static_cast<std::size_t>(cells.n_cells), -1);
  std::vector<std::int64_t> listed;
  std::vector<std::uint8_t> drawn(static_cast<std::size_t>(mesh_cells), 0);
  for (std::int64_t c = 0; c < cells.n_cells; ++c)
    if (small[static_cast<std::size_t>(c)])
      out.index[static_cast<std::size_t>(c)] = static_cast<std::int32_t>(listed.size()), listed.push_back(c);
    else
      drawn[static_cast<std::size_t>(view_mesh.parent(c))] = 1;
  out.footprint.resize(listed.size());
  std::vector<PixelBox> boxes(listed.size());
  tbb::enumerable_thread_specific<SplatCounters> counts;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, listed.size(), 1024),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      SplatCounters& n = counts.local();
                      for (std::size_t k = r.begin(); k < r.end(); ++k) {
                        const std::int64_t c = listed[k];
                        out.footprint[k] = cell_splat(frame, cells.cell(c), cells.type(c), n);
                        boxes[k] = out.footprint[k].pixels(frame.rays.width(), frame.rays.height());
                      }
                    });
  for (const SplatCounters& n : counts) counters.add(n);
  out.stencil = SplatStencil(tracer, frame.rays.camera(), frame.rays.width(), frame.rays.height(), boxes, drawn);
  return out;
}

// The cells of the order as a source of the ordered pipeline; the small ones splatted in their
// place (or skipped), the others projected.
struct OrderedCells {
  using Scratch = CellScratch;
  using Counters = FrameCounters;
  const CellFragments& project;
  const MeshView& cells;
  const std::vector<std::int64_t>& order;
  const std::vector<std::uint8_t>& small;  // per cell: drawn by its splat (or not at all)
  SmallCells mode;
  const ProjectionSplats& splats;
  OpaqueMask* opaque = nullptr;         // early ray termination: composited front to back, tiles only
  std::uint8_t* drew = nullptr;         // per cell, tiles only: set once it adds a fragment (count_small_after)
  const std::uint8_t* clear = nullptr;  // per cell, tiles only: not drawn (transparent, kept in the tiles' orders)
  void fragments(std::size_t k, FragmentBands& out, Scratch& s, Counters& c) const {
    const std::int64_t cell = order[k];
    if (mode != SmallCells::draw && small[static_cast<std::size_t>(cell)]) {
      if (mode == SmallCells::splat) splats.append(cell, out, c.splat);
      return;
    }
    project.project(cells.cell(cell), cells.type(cell), out, s, c.projection);
  }
  void composite(std::size_t k, Image& image, Scratch& s, Counters& c) const {
    project.project(cells.cell(order[k]), cells.type(order[k]), image, s, c.projection);
    ++c.projection.direct_cells;
  }
  // composite_in_tiles' look-ahead (its items keyed by cell), in the order a cell's data is
  // reached: its offset and type, then its point ids, then its points. (The image's pixels under
  // them were tried as a fourth stage: slower, bench/results/prefetch.txt.)
  void prefetch(std::size_t key, int stage) const {
    const auto cell = static_cast<std::int64_t>(key);
    if (stage == 0) return __builtin_prefetch(&cells.offsets[cell]), __builtin_prefetch(&cells.types[cell]);
    if (stage == 1) return __builtin_prefetch(cells.cell(cell));
    project.prefetch_points(cells.cell(cell), cells.cell_size(cell));
  }
  // A tile's rows of a cell (composite_in_tiles, keyed by cell; never with splats): the cell counted
  // by its first tile, its pixels by each.
  void composite(std::size_t key, Image& image, RowRange rows, bool first, Scratch& s, Counters& c) const {
    const auto cell = static_cast<std::int64_t>(key);
    if (mode == SmallCells::skip && small[static_cast<std::size_t>(cell)]) return;
    if (clear && clear[cell]) return;
    const std::int64_t* ids = cells.cell(cell);
    const CellType type = cells.type(cell);
    ProjectionCounters pixels;
    ProjectionCounters& into = first ? c.projection : pixels;
    const std::int64_t before = into.fragments;
    if (!opaque)
      project.project(ids, type, image, rows, s, into);
    else if (project.hidden_by(ids, type, rows, *opaque))
      ++into.hidden_cells;
    else
      project.project_under(ids, type, image, rows, *opaque, s, into);
    if (drew && into.fragments != before) __atomic_store_n(&drew[cell], std::uint8_t{1}, __ATOMIC_RELAXED);
    if (!first) c.projection.add_pixels(pixels);
  }
};
// The opacity table of pt-table: extinction up to the transfer function's largest, lengths up to
// the longest segment a ray can have in one cell.
OpacityTable opacity_table(const TransferFunction& tf, int size, double max_diameter) {
  double kmax = 0.0;
  for (const auto& p : tf.extinction_points()) kmax = std::max(kmax, p.kappa);
  return OpacityTable(size, kmax, max_diameter);
}

// The order without the cells whose scalar range has extinction 0 throughout: they add nothing to
// any ray (emission is C kappa, absorption kappa), so the picture is the same bits without them.
// Per cell, whether it is such a cell (empty when the transfer function has no transparent range).
std::vector<std::uint8_t> transparent_cells(const MeshView& cells, const double* scalar, const TransferFunction& tf) {
  if (!tf.has_transparent_range()) return {};
  std::vector<std::uint8_t> clear(static_cast<std::size_t>(cells.n_cells), 0);
  tbb::parallel_for(std::int64_t(0), cells.n_cells, [&](std::int64_t c) {
    const std::int64_t* id = cells.cell(c);
    double lo = scalar[id[0]], hi = lo;
    for (int k = 1; k < cells.cell_size(c); ++k) lo = std::min(lo, scalar[id[k]]), hi = std::max(hi, scalar[id[k]]);
    clear[static_cast<std::size_t>(c)] = tf.transparent_over(lo, hi);
  });
  return clear;
}

std::vector<std::int64_t> without_transparent(const std::vector<std::int64_t>& order, const MeshView& cells,
                                              const double* scalar, const TransferFunction& tf) {
  const std::vector<std::uint8_t> clear = transparent_cells(cells, scalar, tf);
  if (clear.empty()) return order;
  std::vector<std::int64_t> kept;
  kept.reserve(order.size());
  for (std::int64_t c : order)
    if (!clear[static_cast<std::size_t>(c)]) kept.push_back(c);
  return kept;
}

// Whether `order` holds each of the n cells once (a visibility order's first invariant).
bool is_permutation_of(const std::vector<std::int64_t>& order, std::int64_t n) {
  if (static_cast<std::int64_t>(order.size()) != n) return false;
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(n), 0);
  for (const std::int64_t c : order)
    if (c < 0 || c >= n || seen[static_cast<std::size_t>(c)]++) return false;
  return true;
}

// Colour by one field and extinction by another: drawn by the methods that integrate each pixel's
// segment (a cell ray cast over its tetrahedra), not by Gouraud corners, OpenGL or splats.
void check_two_fields(const ProjectionOptions& options, const FramePlan& plan) {
  if (traits(options.method).gouraud) throw two_fields_refused("", name_of(options.method));
  if (!plan.software) throw two_fields_refused("", "an OpenGL back end (setting 'backend' software draws it)");
  if (plan.small_cells == SmallCells::splat)
    throw two_fields_refused("", "splats (setting 'small-cells' draw draws the small cells)");
}

// Opaque geometry (a depth buffer) cuts each pixel's segments where it lies: drawn by the software
// back end's cells, not by OpenGL or splats.
void check_opaque_geometry(const FramePlan& plan) {
  const char* by = !plan.software                          ? "an OpenGL back end (setting 'backend' software draws it)"
                   : plan.small_cells == SmallCells::splat ? "splats (setting 'small-cells' draw draws the small cells)"
                                                           : nullptr;
  if (by) throw UnsupportedError(std::string("opaque geometry (a depth buffer) is not drawn among by ") + by);
}

}  // namespace

void check_options(const ProjectionOptions& o) {
  check_built(o.backend);
  OpacityTable::check_size(o.table_size);
  const SmallCells small = resolve(o.splat, o.backend);
  if (o.early_termination &&
      (is_opengl(o.backend) || o.compositing != Compositing::tiles || small == SmallCells::splat))
    throw InputError(
        "setting 'early-termination' on composites image tiles front to back: it needs the software back end, "
        "setting 'compositing' tiles and no splats (setting 'small-cells' draw or skip)");
  if (is_opengl(o.backend) && o.whole_cells == WholeCells::layers)  // never the default: the user asked
    throw InputError(
        "setting 'whole-cells' layers needs setting 'backend' software (the OpenGL back ends draw polygons)");
  if (is_opengl(o.backend) && !traits(o.method).opengl) {
    std::string drawable;
    for (const MethodTraits& t : kProjectionMethods)
      if (t.opengl) drawable += (drawable.empty() ? "" : " and ") + std::string(t.name);
    throw InputError(std::string("the OpenGL back ends draw ") + drawable + " only, not " + name_of(o.method) +
                     " (per-pixel integrals need the software back end)");
  }
}

ProjectionRenderer::ProjectionRenderer(const MeshView& mesh, Tetrahedralize mode)
    : local_(mesh), mesh_(local_.view()), sorter_(mesh_, mode) {
  const RecentredPoints& pts = sorter_.points();
  for (std::int64_t c = 0; c < mesh.n_cells; ++c) {
    const std::int64_t* id = mesh.cell(c);
    const int n = mesh.cell_size(c);
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b) max_diameter_ = std::max(max_diameter_, glm::distance(pts(id[a]), pts(id[b])));
  }
}

ProjectionRenderer::~ProjectionRenderer() = default;

const CellRayTracer& ProjectionRenderer::tracer() const {
  std::lock_guard<std::mutex> lock(tracer_mutex_);
  if (!tracer_) tracer_ = std::make_unique<CellRayTracer>(mesh_);
  return *tracer_;
}

bool ProjectionRenderer::convex_boundary() const { return sorter_.base().hull.convex; }

namespace {

// A frame's cells in visibility order (or, with the tiles' own orders, binned to the tiles and
// ordered there), and what the passes that need no order found about them.
struct FrameOrder {
  ViewOrder view;
  std::vector<std::int64_t> visible;  // the order without the transparent cells (cull_transparent)
  std::vector<std::uint8_t> clear;    // or, with the tiles' own orders, those cells flagged
  ViewRelations relations;            // the tiles' own orders: the face relations, no order
  std::optional<TileBins> tile_bins;  // the cells of each tile in the tile's own order
  std::vector<std::uint8_t> small;    // per cell: small (splatted or skipped)
  FrameBuffer<RowRange> reach;        // per cell: the image rows it reaches (tiles)
  const MeshView* passed = nullptr;   // the cells the passes ran on
  double sort_seconds = 0, small_seconds = 0, tile_seconds = 0;
};

// Everything a frame's order is made from.
struct OrderInputs {
  const FramePlan& plan;
  const ProjectionOptions& options;
  const SplittingSorter& sorter;
  SortView sort_view;
  const ScreenPoints& screen;
  const PixelRays& rays;
  const double* scalar;
  const TransferFunction& tf;
};

// The passes over `cells` that need no order: which are small (or, counted after, only the rows
// each reaches).
void cell_passes(const OrderInputs& in, const MeshView& cells, FrameOrder& f, SplatCounters& counted) {
  const auto t = std::chrono::steady_clock::now();
  if (in.plan.count_small_after)
    cell_reach(cells, in.screen, in.rays, f.reach);
  else
    f.small =
        small_cells(cells, in.screen, in.rays, in.plan.splat_threshold, counted, in.plan.by_tiles ? &f.reach : nullptr);
  f.small_seconds = seconds_since(t), f.passed = &cells;
}

// The sort of the whole mesh (relations only, with the tiles' own orders), the transparent cells
// culled or flagged.
void sort_cells(const OrderInputs& in, FrameOrder& f, bool relations_only) {
  const auto t = std::chrono::steady_clock::now();
  f.view = in.sorter.sort(in.options.sort, in.sort_view, relations_only ? &f.relations : nullptr);
  const MeshView& cells = f.view.mesh->cells;
  if (in.options.cull_transparent && f.view.sorted.relations_only)
    f.clear = transparent_cells(cells, in.scalar, in.tf);
  else if (in.options.cull_transparent)
    f.visible = without_transparent(f.view.sorted.order, cells, in.scalar, in.tf);
  f.sort_seconds += seconds_since(t);
}

// The frame's order: the sort with the passes beside it where the plan allows (the sort's serial
// part, the topological order, would leave the other threads idle), else after it; with the
// tiles' own orders, the tiles ordered, and the whole mesh sorted after all if a tile meets a
// visibility cycle.
FrameOrder order_frame(const OrderInputs& in, SplatCounters& counted) {
  FrameOrder f;
  const FramePlan& plan = in.plan;
  if (plan.passes_beside_sort)
    tbb::parallel_invoke([&] { sort_cells(in, f, plan.tile_orders); },
                         [&] { cell_passes(in, in.sorter.base().cells, f, counted); });
  else
    sort_cells(in, f, plan.tile_orders);
  if (plan.software && f.passed != &f.view.mesh->cells) cell_passes(in, f.view.mesh->cells, f, counted);
  if (!f.view.sorted.relations_only) return f;
  const auto t = std::chrono::steady_clock::now();
  const MeshView& base = f.view.mesh->cells;
  const int height = in.rays.height();
  f.tile_bins = bin_to_tiles(static_cast<std::size_t>(base.n_cells), height, plan.tile_rows,
                             [&](std::size_t c) { return f.reach[c]; });
  if (!order_tiles(*f.tile_bins, f.relations, base.n_cells, f.reach, height, plan.tile_rows)) {
    f.tile_bins.reset(), f.clear.clear();  // a cycle: the whole mesh sorted
    sort_cells(in, f, false);
    if (f.passed != &f.view.mesh->cells) cell_passes(in, f.view.mesh->cells, f, counted);
  }
  f.tile_seconds = seconds_since(t);
  return f;
}

// The software back end: the small cells' splats and their stencil, then every cell composited
// in order, by image tiles or by the ordered stream.
Image draw_in_software(const FramePlan& plan, const FrameOrder& f, const std::vector<std::int64_t>& order,
                       const CellFragments& project, const ScreenPoints& screen, const SplatContext& frame,
                       const std::function<const CellRayTracer&()>& stencil_tracer, std::int64_t mesh_cells,
                       const ProjectionOptions& options, ProjectionStats& st) {
  const MeshView& cells = f.view.mesh->cells;
  const PixelRays& rays = frame.rays;
  Image image(rays.width(), rays.height());
  ProjectionSplats splats;
  if (plan.small_cells == SmallCells::splat && st.splat.small_cells > 0) {  // no stencil without splats
    const auto t_tracer = std::chrono::steady_clock::now();
    const CellRayTracer& tracer = stencil_tracer();  // prepared on the first frame that splats
    st.phase_seconds.emplace_back("stencil tracer", seconds_since(t_tracer));
    const auto t_splats = std::chrono::steady_clock::now();
    splats = frame_splats(*f.view.mesh, f.small, frame, tracer, mesh_cells, st.splat);
    st.splat_stencil_tiles = splats.stencil.tiles_traced();
    st.phase_seconds.emplace_back("splats and stencil", seconds_since(t_splats));
  }
  const auto t = std::chrono::steady_clock::now();
  std::optional<OpaqueMask> opaque;
  if (options.early_termination) opaque.emplace(rays.width(), rays.height());
  FrameBuffer<std::uint8_t> drew;
  if (plan.count_small_after) drew.assign(static_cast<std::size_t>(cells.n_cells), 0);
  OrderedCells source{project, cells, order, f.small, plan.small_cells, splats, opaque ? &*opaque : nullptr};
  if (plan.count_small_after) source.drew = drew.data();
  if (!f.clear.empty()) source.clear = f.clear.data();
  FrameCounters counters;
  if (plan.by_tiles) {
    std::size_t visits = f.tile_bins ? f.tile_bins->items.size() : 0;
    if (f.tile_bins)
      counters = composite_bins(image, *f.tile_bins, plan.tile_rows, source, opaque.has_value());
    else
      counters = composite_in_tiles(
          image, order.size(), [&](std::size_t k) { return f.reach[static_cast<std::size_t>(order[k])]; },
          plan.tile_rows, source, &visits, opaque.has_value(),
          [&](std::size_t k) { return static_cast<std::size_t>(order[k]); });
    st.tiles = (rays.height() + plan.tile_rows - 1) / plan.tile_rows;
    st.tile_visits = static_cast<std::int64_t>(visits);
    if (plan.count_small_after) count_small_after(cells, screen, rays, plan.splat_threshold, drew.data(), st.splat);
  } else {
    const std::vector<float> footprint = cell_footprints(cells, screen, rays);
    PipelineLimits limits;
    limits.batch_items = static_cast<std::size_t>(std::max(options.batch_cells, 0));
    counters = composite_in_order(
        image, order.size(), [&](std::size_t k) { return footprint[static_cast<std::size_t>(order[k])]; }, limits,
        source, &st.blend_seconds);
  }
  st.counters = counters.projection;
  st.splat.add(counters.splat);
  st.phase_seconds.emplace_back("project and composite", seconds_since(t));
  return image;
}

}  // namespace

Image ProjectionRenderer::render(const double* color_scalar, const TransferFunction& tf, const Camera& camera,
                                 int width, int height, const ProjectionOptions& options, ProjectionStats* stats,
                                 const double* opacity, const OpaqueDepth* opaque) const {
  check_options(options);
  const auto start = std::chrono::steady_clock::now();
  const FramePlan plan = plan_frame(options, sorter_.mode(), height, tbb::this_task_arena::max_concurrency(),
                                    [this] { return sorter_.base().sorter->acyclic(); });
  ProjectionStats st;
  st.small_cells = plan.small_cells, st.splat_threshold = plan.splat_threshold;
  if (opacity) check_two_fields(options, plan);
  if (opaque) check_opaque_geometry(plan);
  const RecentredPoints& points = sorter_.points();
  // The screen points, the culling and the sort read the field the extinction comes from.
  const double* scalar = opacity ? opacity : color_scalar;
  std::optional<ColorField> color;
  if (opacity) color.emplace(ColorField{color_scalar, TwoFieldTransfer(tf)});

  // The points on screen (MWSC section 2), the rays as the A-buffer's.
  auto t = std::chrono::steady_clock::now();
  const PixelRays rays(recentred(camera, points.centre), width, height);
  const ScreenPoints screen = project_points(points, scalar, rays);
  st.phase_seconds.emplace_back("project points", seconds_since(t));

  // The cells in visibility order (MWSC section 3).
  SortView sort_view{camera, width, height};
  sort_view.gaps = options.gaps;
  FrameOrder f = order_frame({plan, options, sorter_, sort_view, screen, rays, scalar, tf}, st.splat);
  const MeshView& cells = f.view.mesh->cells;
  CELLPROJ_DCHECK(f.tile_bins || is_permutation_of(f.view.sorted.order, cells.n_cells),
                  "the visibility order does not hold every cell once");
  const std::vector<std::int64_t>& order = options.cull_transparent ? f.visible : f.view.sorted.order;
  st.tile_orders = f.tile_bins.has_value();
  st.culled_transparent = f.tile_bins ? std::count(f.clear.begin(), f.clear.end(), std::uint8_t{1})
                                      : static_cast<std::int64_t>(f.view.sorted.order.size() - order.size());
  st.cell_numbering_spread = local_.spread(), st.cells_renumbered = local_.renumbered();
  st.tetrahedralize = sorter_.mode();
  st.cells = cells.n_cells;
  st.tets = std::count(cells.types, cells.types + cells.n_cells, static_cast<std::uint8_t>(CellType::Tetra));
  st.problem_cells = f.view.problem_cells;
  st.cells_split = f.view.mesh->split.cells_split;
  st.cycle_splits = f.view.cycle_splits;
  st.phase_seconds.emplace_back("sort", f.sort_seconds);
  if (plan.software) st.phase_seconds.emplace_back("small cells", f.small_seconds);  // (beside the sort, or after it)
  if (st.tile_orders) st.phase_seconds.emplace_back("tile orders", f.tile_seconds);  // (binning included)

  // Each cell's light (MWSC section 2 and the per-pixel methods): the method's tables.
  const MethodTraits& method = traits(options.method);
  std::optional<OpacityTable> table;
  if (method.opacity_table) table.emplace(opacity_table(tf, options.table_size, max_diameter_));
  PointOptics optics;
  if (method.point_optics) optics = point_optics(scalar, mesh_.n_points, tf);
  std::optional<DepthLimit> limit;  // a depth with no surface is no limit
  if (opaque) limit.emplace(*opaque, rays);
  const CellFragments project(screen, rays, points, tf, options.method, table ? &*table : nullptr, &optics,
                              options.whole_cells, color ? &*color : nullptr,
                              limit && limit->any() ? &*limit : nullptr);

  // The cells drawn and composited in order (MWSC section 7).
  Image image;
  if (plan.software) {
    const SplatContext frame{points, scalar, tf, rays, options.splat.prefilter};
    image = draw_in_software(
        plan, f, order, project, screen, frame, [this]() -> const CellRayTracer& { return tracer(); }, mesh_.n_cells,
        options, st);
  } else {
    t = std::chrono::steady_clock::now();
    image = draw_with_opengl(project, cells, order, table ? &*table : nullptr, width, height, options, st);
    st.phase_seconds.emplace_back("project and composite", seconds_since(t));
  }
  st.sort = std::move(f.view.sorted.stats);
  st.seconds = seconds_since(start);
  if (stats) *stats = std::move(st);
  return image;
}

}  // namespace cellproj
