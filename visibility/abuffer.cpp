// The software A-buffer of Cook et al. (MWSC section 3.2): the boundary faces of a non-convex mesh
// that are off its convex hull are sampled at the image's own pixel centres with the rasterizer's
// coverage rule; along each pixel's list, a face where the ray leaves the mesh followed by one where
// it enters again is a gap, and the cell entered is composited before the cell left.
//
// The lists are not built pixel by pixel. Each face covers one run of pixels per row
// (view/raster.hpp), and a row is swept from left to right: between two places where a run starts
// or ends, the same faces cover every pixel, and since each face's depth key is affine along the
// row, a list that is front to back at both ends of such a stretch is front to back at every pixel
// centre of it. Only a stretch whose order differs at its two ends (faces crossing in depth) is
// sampled pixel by pixel. The cost is O(b + r + n), r the runs, not the sampled pixels. Bands of
// rows are rasterized and swept on worker threads.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <glm/geometric.hpp>

#include "visibility/image_faces.hpp"

namespace cellproj {
namespace {

// The pixels begin <= p < end (row-major) of one row that a face covers.
struct Run {
  std::uint32_t begin, end, face;
};

// A face on the sweep's list, with its key at the pixel centre the list was last ordered at.
struct Listed {
  std::uint32_t face, end;
  double key;
  bool entering;
};

// Front to back; at (nearly) equal distance a leaving face comes first, so that a ray through an
// edge where two faces meet, or a seam whose two sides are not bit-identical (mesh/seams.cpp glues
// the others), still reads as "leave one cell, enter the next".
bool in_front(const Listed& a, const Listed& b) {
  const double tol = 1e-9 * std::max(std::abs(a.key), std::abs(b.key));
  if (a.key < b.key - tol) return true;
  if (a.key > b.key + tol) return false;
  return !a.entering && b.entering;
}

// Stable LSD radix sort of the runs by their first pixel, all in first <= pixel < first + pixels,
// 11 bits a pass.
void sort_by_pixel(std::vector<Run>& runs, std::uint32_t first, std::uint32_t pixels) {
  std::unique_ptr<Run[]> tmp(new Run[runs.size()]);  // every element is written before it is read
  Run* from = runs.data();
  Run* to = tmp.get();
  for (int shift = 0; shift < 32 && (pixels - 1) >> shift; shift += 11) {
    std::uint32_t count[2049] = {};
    for (std::size_t k = 0; k < runs.size(); ++k) ++count[(((from[k].begin - first) >> shift) & 2047u) + 1];
    for (int b = 0; b < 2048; ++b) count[b + 1] += count[b];
    for (std::size_t k = 0; k < runs.size(); ++k) to[count[((from[k].begin - first) >> shift) & 2047u]++] = from[k];
    std::swap(from, to);
  }
  if (from != runs.data()) std::copy(from, from + runs.size(), runs.data());
}

constexpr int kBandsPerThread = 4;  // bands of rows per worker thread: enough to balance the load
constexpr int kMinBandRows = 16;    // fewer rows: the faces over two bands are rasterized twice too often

// Sweeps the image row by row, keeping the list of faces over the current pixel front to back, and
// reads its "leave, then enter" pairs once per stretch of pixels over which the list is the same.
class GapSweep {
 public:
  GapSweep(const std::vector<ImageFace>& faces, const SortView& view, bool every_pixel)
      : faces_(faces), width_(static_cast<std::uint32_t>(view.width)), every_pixel_(every_pixel) {}
  std::int64_t crossings() const { return crossings_; }  // stretches ordered pixel by pixel

  // The "leave, then enter" pairs of every list, as (cell entered, cell left): the cell entered is
  // composited first.
  std::vector<std::pair<std::int64_t, std::int64_t>> run(const std::vector<Run>& runs) {
    for (std::size_t at = 0; at < runs.size();) {
      const std::uint32_t row = runs[at].begin / width_;
      std::size_t end = at;
      while (end < runs.size() && runs[end].begin < (row + 1) * width_) ++end;
      sweep_row(runs, at, end, row);
      at = end;
    }
    return std::move(found_.pairs);
  }

 private:
  void sweep_row(const std::vector<Run>& runs, std::size_t k, std::size_t end, std::uint32_t row) {
    const double y = row + 0.5;
    const std::uint32_t first = row * width_;
    list_.clear();
    for (std::uint32_t x = runs[k].begin;;) {
      list_.erase(std::remove_if(list_.begin(), list_.end(), [x](const Listed& l) { return l.end == x; }), list_.end());
      for (; k < end && runs[k].begin == x; ++k)
        list_.push_back({runs[k].face, runs[k].end, 0.0, faces_[runs[k].face].entering()});
      if (list_.empty()) {
        if (k == end) return;
        x = runs[k].begin;
        continue;
      }
      std::uint32_t next = k < end ? runs[k].begin : first + width_;
      std::size_t entering = 0;
      for (const Listed& l : list_) next = std::min(next, l.end), entering += l.entering;
      // The pixels x <= p < next are covered by the same faces; a gap needs a face of each kind.
      if (entering > 0 && entering < list_.size()) {
        order_at(x - first + 0.5, y);
        emit_gaps();
        if (next - x > 1 && (every_pixel_ || !ordered_at(next - 1 - first + 0.5, y))) {
          crossings_ += !every_pixel_;
          for (std::uint32_t q = x + 1; q < next; ++q) order_at(q - first + 0.5, y), emit_gaps();
        }
      }
      x = next;
    }
  }

  double key(const Listed& l, double x, double y) const {
    const ImageFace& f = faces_[l.face];
    return f.k0 + f.kx * x + f.ky * y;
  }
  // The list front to back at pixel centre (x, y) (insertion sort: it mostly is already).
  void order_at(double x, double y) {
    for (Listed& l : list_) l.key = key(l, x, y);
    for (std::size_t k = 1; k < list_.size(); ++k)
      for (std::size_t m = k; m > 0 && !in_front(list_[m - 1], list_[m]); --m) std::swap(list_[m - 1], list_[m]);
  }
  // Whether the list, front to back where it was last ordered, is so at (x, y) too.
  bool ordered_at(double x, double y) const {
    Listed prev = list_[0];
    prev.key = key(prev, x, y);
    for (std::size_t k = 1; k < list_.size(); ++k) {
      Listed here = list_[k];
      here.key = key(here, x, y);
      if (!in_front(prev, here)) return false;
      prev = here;
    }
    return true;
  }
  void emit_gaps() {
    for (std::size_t k = 0; k + 1 < list_.size(); ++k) {
      const Listed &leave = list_[k], &enter = list_[k + 1];
      if (leave.entering || !enter.entering) continue;
      const std::int64_t left = faces_[leave.face].cell(), entered = faces_[enter.face].cell();
      if (left != entered) found_.add(entered, left);
    }
  }

  const std::vector<ImageFace>& faces_;
  const std::uint32_t width_;
  const bool every_pixel_;
  std::int64_t crossings_ = 0;
  std::vector<Listed> list_;
  GapPairs found_;
};

// The image cut into bands of rows (kBandsPerThread per worker thread, at least kMinBandRows
// rows), each with the faces whose rows reach into it.
struct RowBands {
  int rows = 0, count = 0;
  std::vector<std::uint32_t> start, face;  // band b's faces: face[start[b] .. start[b + 1])

  RowBands(const ProjectedFaces& faces, int height) {
    const int wanted = kBandsPerThread * tbb::this_task_arena::max_concurrency();
    rows = std::max(kMinBandRows, (height + wanted - 1) / wanted);
    count = (height + rows - 1) / rows;
    start.assign(static_cast<std::size_t>(count) + 1, 0);
    for (const ProjectedFace& f : faces)
      for (int b = f.box.j0 / rows; b <= f.box.j1 / rows; ++b) ++start[b + 1];
    for (int b = 0; b < count; ++b) start[b + 1] += start[b];
    face.resize(start.back());
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t k = 0; k < faces.size(); ++k)
      for (int b = faces[k].box.j0 / rows; b <= faces[k].box.j1 / rows; ++b)
        face[fill[b]++] = static_cast<std::uint32_t>(k);
  }
};

struct BandGaps {
  std::vector<std::pair<std::int64_t, std::int64_t>> pairs;  // (cell entered, cell left)
  std::int64_t runs = 0, fragments = 0, crossings = 0;
};

// Band b's rows on their own: the runs of its faces there, sorted by pixel, swept.
BandGaps sweep_band(const RowBands& bands, int b, const ProjectedFaces& projected, const std::vector<ImageFace>& faces,
                    const SortView& view) {
  const int row0 = b * bands.rows, row1 = std::min(view.height, row0 + bands.rows);
  const auto width = static_cast<std::uint32_t>(view.width);
  std::vector<Run> runs;
  runs.reserve(8 * (bands.start[b + 1] - bands.start[b]));
  for (std::uint32_t at = bands.start[b]; at < bands.start[b + 1]; ++at) {
    const std::uint32_t k = bands.face[at];
    const ProjectedFace& f = projected[k];
    const TriangleCoverage t(f.s[0], f.s[1], f.s[2], view.width, view.height);
    for (int j = std::max(row0, t.first_row()); j <= std::min(row1 - 1, t.last_row()); ++j) {
      int i0, i1;
      t.run(t.row(j), i0, i1);
      const std::uint32_t row = static_cast<std::uint32_t>(j) * width;
      if (i0 < i1) runs.push_back({row + static_cast<std::uint32_t>(i0), row + static_cast<std::uint32_t>(i1), k});
    }
  }
  sort_by_pixel(runs, static_cast<std::uint32_t>(row0) * width, static_cast<std::uint32_t>(row1 - row0) * width);
  BandGaps out;
  out.runs = static_cast<std::int64_t>(runs.size());
  for (const Run& r : runs) out.fragments += r.end - r.begin;
  GapSweep sweep(faces, view, view.abuffer_every_pixel);
  out.pairs = sweep.run(runs);
  out.crossings = sweep.crossings();
  return out;
}

}  // namespace

Relations gap_relations(const VisibilitySorter::Prepared& p, const ProjectedFaces& projected, const SortView& view,
                        SortStats& stats) {
  std::vector<ImageFace> faces(projected.size());
  for (std::size_t k = 0; k < projected.size(); ++k) faces[k] = projected[k].face;
  // The bands are swept apart, in parallel (oneTBB); the pairs do not depend on the bands.
  const RowBands bands(projected, view.height);
  std::vector<BandGaps> band(static_cast<std::size_t>(bands.count));
  tbb::parallel_for(0, bands.count, [&](int b) { band[b] = sweep_band(bands, b, projected, faces, view); });
  std::vector<std::pair<std::int64_t, std::int64_t>> pairs;
  for (const BandGaps& g : band) {
    stats.abuffer_runs += g.runs, stats.abuffer_fragments += g.fragments, stats.abuffer_crossings += g.crossings;
    pairs.insert(pairs.end(), g.pairs.begin(), g.pairs.end());
  }
  Relations rel;
  stats.gap_relations = rel.build(p.mesh.n_cells, pairs);
  return rel;
}

}  // namespace cellproj
