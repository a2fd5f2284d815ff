#include "parallel/projection_renderer.hpp"

#include <algorithm>
#include <chrono>
#include <optional>

#include <tbb/blocked_range.h>
#include <tbb/concurrent_queue.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include "grid/geometry.hpp"
#include "grid/error.hpp"
#include "projection/gl_compositor.hpp"
#include "projection/screen.hpp"

namespace cellproj {
namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Cells per pipeline token: the option, or enough tokens to keep every thread busy on small meshes
// (a few large cells cover most pixels there) without per-token overhead on large ones.
std::size_t batch_size(int option, std::size_t cells) {
  if (option > 0) return static_cast<std::size_t>(option);
  const std::size_t per = cells / (16 * static_cast<std::size_t>(tbb::this_task_arena::max_concurrency()));
  return std::clamp<std::size_t>(per, 64, 2048);
}

// A token also closes once its cells' image bounding boxes add up to this many pixels, so that
// its fragments (20 bytes each, at most one per covered pixel and cell) stay near 100 MB.
constexpr double kBatchPixels = 5e6;
// A cell whose bounding box covers more than this is not buffered: the compositor draws it itself,
// in order, straight onto the image (a few huge cells in a large image would otherwise buffer
// gigabytes of fragments).
constexpr double kDirectPixels = 1e6;

// Pixels under each cell's image bounding box (clamped to the image); a cell reaching behind the
// eye in perspective covers the whole image.
std::vector<float> cell_footprints(const MeshView& cells, const ScreenPoints& screen, const PixelRays& rays) {
  std::vector<float> area(static_cast<std::size_t>(cells.n_cells));
  const double w = rays.width(), h = rays.height();
  tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, cells.n_cells, 4096), [&](const tbb::blocked_range<std::int64_t>& r) {
    for (std::int64_t c = r.begin(); c < r.end(); ++c) {
      const std::int64_t* id = cells.cell(c);
      double x0 = w, x1 = 0, y0 = h, y1 = 0;
      bool behind = false;
      for (int k = 0, n = cells.cell_size(c); k < n; ++k) {
        const ScreenVertex& v = screen.v[static_cast<std::size_t>(id[k])];
        behind = behind || (rays.perspective() && !(v.z > 0.0));
        x0 = std::min(x0, v.x), x1 = std::max(x1, v.x), y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
      }
      const double dx = std::clamp(x1, 0.0, w) - std::clamp(x0, 0.0, w), dy = std::clamp(y1, 0.0, h) - std::clamp(y0, 0.0, h);
      area[static_cast<std::size_t>(c)] = behind ? static_cast<float>(w * h) : static_cast<float>((dx + 1) * (dy + 1));
    }
  });
  return area;
}

struct Batch {
  std::size_t begin = 0, end = 0;
  std::vector<Fragment> fragments;
  // The cells left to the compositor: (position in the order, fragments emitted before it).
  std::vector<std::pair<std::size_t, std::size_t>> direct;
  ProjectionCounters counters;
  CellScratch scratch;
};

}  // namespace

ProjectionRenderer::ProjectionRenderer(const MeshView& mesh, Tetrahedralize mode) : mesh_(mesh), sorter_(mesh, mode) {
  const RecentredPoints& pts = sorter_.points();
  for (std::int64_t c = 0; c < mesh.n_cells; ++c) {
    const std::int64_t* id = mesh.cell(c);
    const int n = mesh.cell_size(c);
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b) max_diameter_ = std::max(max_diameter_, glm::distance(pts(id[a]), pts(id[b])));
  }
}

ProjectionRenderer::~ProjectionRenderer() = default;

bool ProjectionRenderer::convex_boundary() const { return sorter_.base().hull.convex; }

Image ProjectionRenderer::render(const TransferFunction& tf, const Camera& camera, int width, int height,
                                 const ProjectionOptions& options, ProjectionStats* stats) const {
  const auto start = std::chrono::steady_clock::now();
  ProjectionStats st;
  const RecentredPoints& points = sorter_.points();

  auto t = std::chrono::steady_clock::now();
  const PixelRays rays(recentred(camera, points.centre), width, height);  // as the A-buffer's
  const ScreenPoints screen = project_points(points, mesh_.scalar, rays);
  st.phase_seconds.emplace_back("project points", since(t));

  t = std::chrono::steady_clock::now();
  SortView sort_view{camera, width, height};
  sort_view.gaps = options.gaps;
  ViewOrder view = sorter_.sort(options.sort, sort_view);
  SortResult& sorted = view.sorted;
  const MeshView& cells = view.mesh->cells;
  st.tetrahedralize = sorter_.mode();
  st.cells = cells.n_cells;
  st.tets = std::count(cells.types, cells.types + cells.n_cells, static_cast<std::uint8_t>(CellType::Tetra));
  st.problem_cells = view.problem_cells;
  st.cells_split = view.mesh->split.cells_split;
  st.cycle_splits = view.cycle_splits;
  st.phase_seconds.emplace_back("sort", since(t));

  std::optional<OpacityTable> table;
  if (options.method == ProjectionMethod::pt_table) {
    double kmax = 0.0;
    for (const auto& p : tf.extinction_points()) kmax = std::max(kmax, p.kappa);
    table.emplace(options.table_size, kmax, max_diameter_);
  }
  PointOptics optics;
  if (options.method == ProjectionMethod::pt_linear || options.method == ProjectionMethod::pt_table)
    optics = point_optics(mesh_.scalar, mesh_.n_points, tf);
  if (options.backend != ProjectionBackend::software && options.method != ProjectionMethod::pt_linear &&
      options.method != ProjectionMethod::pt_table)
    throw InputError(std::string("the ") + name_of(options.backend) + " back end draws pt-linear and pt-table only, not " +
                     name_of(options.method) + " (per-pixel integrals need the software back end)");
  const CellFragments project(screen, rays, points, tf, options.method, table ? &*table : nullptr, &optics);

  t = std::chrono::steady_clock::now();
  if (options.backend != ProjectionBackend::software) {
    Image image = render_gl(project, cells, sorted.order, table ? &*table : nullptr, width, height, options, st);
    st.phase_seconds.emplace_back("project and composite", since(t));
    st.sort = std::move(sorted.stats);
    st.seconds = since(start);
    if (stats) *stats = std::move(st);
    return image;
  }
  Image image(width, height);
  const std::vector<std::int64_t>& order = sorted.order;
  const std::vector<float> footprint = cell_footprints(cells, screen, rays);
  const std::size_t batch = batch_size(options.batch_cells, order.size());
  const int tokens = 2 * tbb::this_task_arena::max_concurrency();
  std::vector<Batch> batches(static_cast<std::size_t>(tokens));
  tbb::concurrent_bounded_queue<Batch*> free;  // batches are reused, keeping their fragment buffers
  for (auto& b : batches) free.push(&b);
  std::size_t next = 0;
  tbb::parallel_pipeline(
      static_cast<std::size_t>(tokens),
      tbb::make_filter<void, Batch*>(tbb::filter_mode::serial_in_order,
                                     [&](tbb::flow_control& fc) -> Batch* {
                                       if (next >= order.size()) {
                                         fc.stop();
                                         return nullptr;
                                       }
                                       Batch* b = nullptr;
                                       free.pop(b);
                                       b->begin = next;
                                       double pixels = 0;
                                       for (const std::size_t last = std::min(order.size(), next + batch);
                                            next < last && pixels < kBatchPixels; ++next) {
                                         const double a = footprint[static_cast<std::size_t>(order[next])];
                                         if (a <= kDirectPixels) pixels += a;
                                       }
                                       b->end = next;
                                       return b;
                                     }) &
          tbb::make_filter<Batch*, Batch*>(tbb::filter_mode::parallel,
                                           [&](Batch* b) {
                                             b->fragments.clear();
                                             b->direct.clear();
                                             b->counters = {};
                                             for (std::size_t k = b->begin; k < b->end; ++k) {
                                               if (footprint[static_cast<std::size_t>(order[k])] > kDirectPixels) {
                                                 b->direct.emplace_back(k, b->fragments.size());
                                                 continue;
                                               }
                                               const std::int64_t c = order[k];
                                               project.project(cells.cell(c), cells.type(c), b->fragments, b->scratch,
                                                               b->counters);
                                             }
                                             return b;
                                           }) &
          tbb::make_filter<Batch*, void>(tbb::filter_mode::serial_in_order, [&](Batch* b) {
            std::size_t done = 0;  // fragments composited; the direct cells go in between, in order
            for (const auto& [k, at] : b->direct) {
              composite_over(image, b->fragments.data() + done, at - done);
              done = at;
              project.project(cells.cell(order[k]), cells.type(order[k]), image, b->scratch, b->counters);
              ++b->counters.direct_cells;
            }
            composite_over(image, b->fragments.data() + done, b->fragments.size() - done);
            st.counters.add(b->counters);
            free.push(b);
          }));
  st.phase_seconds.emplace_back("project and composite", since(t));
  st.sort = std::move(sorted.stats);
  st.seconds = since(start);
  if (stats) *stats = std::move(st);
  return image;
}

Image ProjectionRenderer::render_gl(const CellFragments& project, const MeshView& cells,
                                    const std::vector<std::int64_t>& order, const OpacityTable* table, int width, int height, const ProjectionOptions& options,
                                    ProjectionStats& st) const {
  const GLTarget target = options.backend == ProjectionBackend::opengl        ? GLTarget::float32
                          : options.backend == ProjectionBackend::opengl_8bit ? GLTarget::rgba8
                                                                              : GLTarget::rgba8_dithered;
  GLCompositor gl(width, height, target);  // its calls stay on this thread; workers only make triangles
  st.gl_renderer = gl.renderer();
  gl.begin(table);
  const std::size_t batch = batch_size(options.batch_cells, order.size());
  const std::size_t window = 64;  // batches made at once, then drawn in order
  std::vector<std::vector<GLCorner>> corners(window);
  std::vector<ProjectionCounters> counters(window);
  std::vector<CellScratch> scratch(window);
  for (std::size_t first = 0; first < order.size(); first += window * batch) {
    const std::size_t n = std::min(window, (order.size() - first + batch - 1) / batch);
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t b) {
      corners[b].clear();
      counters[b] = {};
      const std::size_t end = std::min(order.size(), first + (b + 1) * batch);
      for (std::size_t k = first + b * batch; k < end; ++k) {
        const std::int64_t c = order[k];
        project.triangles(cells.cell(c), cells.type(c), c, corners[b], scratch[b], counters[b]);
      }
    });
    for (std::size_t b = 0; b < n; ++b) gl.draw(corners[b]), st.counters.add(counters[b]);
  }
  return gl.finish();
}

}  // namespace cellproj
