#include "frame/cell_passes.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace cellproj {
namespace {

// A cell's image box: its vertices' extent on the screen, whether one reaches behind the eye (or
// the orthographic eye plane), whether one has no image position (NaN).
struct ImageExtent {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  bool behind = false, nan = false;
};

ImageExtent image_extent(const MeshView& cells, std::int64_t c, const ScreenPoints& screen) {
  ImageExtent e;
  const std::int64_t* id = cells.cell(c);
  for (int k = 0, n = cells.cell_size(c); k < n; ++k) {
    const ScreenVertex& v = screen.v[static_cast<std::size_t>(id[k])];
    e.behind = e.behind || behind_eye(v.z), e.nan = e.nan || std::isnan(v.x) || std::isnan(v.y);
    e.x0 = std::min(e.x0, v.x), e.x1 = std::max(e.x1, v.x), e.y0 = std::min(e.y0, v.y), e.y1 = std::max(e.y1, v.y);
  }
  return e;
}

// f(c) for every cell, in parallel.
template <class F>
void for_each_cell(const MeshView& cells, F&& f) {
  tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, cells.n_cells, 4096),
                    [&](const tbb::blocked_range<std::int64_t>& r) {
                      for (std::int64_t c = r.begin(); c < r.end(); ++c) f(c);
                    });
}

// The image rows a cell may draw on: those whose centres its vertices' image box holds; one
// more each way for a cell reaching behind an orthographic eye plane (ray cast over that wider
// box), every row for one reaching behind a perspective eye (ray cast over the whole image).
RowRange cell_rows(const ImageExtent& e, const PixelRays& rays) {
  const int h = rays.height();
  const double lo = e.behind ? std::floor(e.y0 - 0.5) : std::ceil(e.y0 - 0.5),
               hi = e.behind ? std::ceil(e.y1 - 0.5) : std::floor(e.y1 - 0.5);
  return (e.behind && rays.perspective()) || e.nan
             ? RowRange{0, h}
             : RowRange{int(std::clamp(lo, 0.0, double(h))), int(std::clamp(hi + 1.0, 0.0, double(h)))};
}

// The pixel centres cell c covers, counted up to `limit` (covered_pixels); -1 for a cell reaching
// behind the eye.
int covered(const MeshView& cells, std::int64_t c, const ScreenPoints& screen, const PixelRays& rays, int limit) {
  const std::int64_t* id = cells.cell(c);
  const ScreenVertex* v[8];
  const int n = std::min(cells.cell_size(c), 8);
  for (int k = 0; k < n; ++k) v[k] = &screen.v[static_cast<std::size_t>(id[k])];
  return covered_pixels(v, n, rays.width(), rays.height(), limit);
}

// small_cells' counts of the cells into `counters`: those covering fewer than `threshold` pixel
// centres, and those covering none. Cells whose `drew` is set (when given) are not tested: they
// cover a centre. With `small`, each small cell's flag is set; with `rows`, each cell's rows.
void count_small(const MeshView& cells, const ScreenPoints& screen, const PixelRays& rays, double threshold,
                 const std::uint8_t* drew, std::uint8_t* small, RowRange* rows, SplatCounters& counters) {
  const int limit = std::max(static_cast<int>(std::min(std::ceil(threshold), 1e9)), 1);
  std::atomic<std::int64_t> n_small{0}, none{0};
  tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, cells.n_cells, 4096),
                    [&](const tbb::blocked_range<std::int64_t>& r) {
                      std::int64_t here = 0, empty = 0;
                      for (std::int64_t c = r.begin(); c < r.end(); ++c) {
                        if (rows) rows[c] = cell_rows(image_extent(cells, c, screen), rays);
                        if (drew && drew[c]) continue;
                        const int n = covered(cells, c, screen, rays, limit);
                        if (n < 0) continue;  // reaching behind the eye: projected (ray cast)
                        empty += n == 0;
                        if (n >= threshold) continue;
                        ++here;
                        if (small) small[c] = 1;
                      }
                      n_small += here, none += empty;
                    });
  counters.small_cells = n_small, counters.covering_no_pixel = none;
}

}  // namespace

std::vector<float> cell_footprints(const MeshView& cells, const ScreenPoints& screen, const PixelRays& rays) {
  std::vector<float> area(static_cast<std::size_t>(cells.n_cells));
  const double w = rays.width(), h = rays.height();
  for_each_cell(cells, [&](std::int64_t c) {
    const ImageExtent e = image_extent(cells, c, screen);
    const double dx = std::clamp(e.x1, 0.0, w) - std::clamp(e.x0, 0.0, w),
                 dy = std::clamp(e.y1, 0.0, h) - std::clamp(e.y0, 0.0, h);
    area[static_cast<std::size_t>(c)] =
        e.behind && rays.perspective() ? static_cast<float>(w * h) : static_cast<float>((dx + 1) * (dy + 1));
  });
  return area;
}

std::vector<std::uint8_t> small_cells(const MeshView& cells, const ScreenPoints& screen, const PixelRays& rays,
                                      double threshold, SplatCounters& counters, FrameBuffer<RowRange>* rows) {
  std::vector<std::uint8_t> small(static_cast<std::size_t>(cells.n_cells), 0);
  if (rows) rows->resize(static_cast<std::size_t>(cells.n_cells));
  count_small(cells, screen, rays, threshold, nullptr, small.data(), rows ? rows->data() : nullptr, counters);
  return small;
}

void cell_reach(const MeshView& cells, const ScreenPoints& screen, const PixelRays& rays, FrameBuffer<RowRange>& rows) {
  rows.resize(static_cast<std::size_t>(cells.n_cells));
  for_each_cell(cells, [&](std::int64_t c) {
    rows[static_cast<std::size_t>(c)] = cell_rows(image_extent(cells, c, screen), rays);
  });
}

void count_small_after(const MeshView& cells, const ScreenPoints& screen, const PixelRays& rays, double threshold,
                       const std::uint8_t* drew, SplatCounters& counters) {
  count_small(cells, screen, rays, threshold, drew, nullptr, nullptr, counters);
}

}  // namespace cellproj
