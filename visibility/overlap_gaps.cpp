// The relations across the gaps of a non-convex mesh from the overlaps of its boundary faces in the
// image: wherever a face where rays leave the mesh lies in front of a face where they enter it
// again, somewhere over the area where the two overlap in the image, the cell entered is
// composited before the cell left. Every pair of faces the A-buffer (visibility/abuffer.cpp) finds
// consecutive at some pixel centre is such a pair, so an order that keeps all of these relations
// keeps the A-buffer's too; pairs that are not consecutive anywhere add relations that are true
// wherever their rays go, harmless unless they close a visibility cycle, which the caller checks (a
// cycle holding one of these relations makes it ask the A-buffer instead, and so do two faces that
// pass through each other, which close such a cycle).
//
// The work is per pair of faces whose pixel boxes overlap, not per row or pixel. Pairs are found in
// square tiles of the image, tested on worker threads.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "visibility/image_faces.hpp"

namespace cellproj {
namespace {

struct ClipPoint {
  double x, y;
};

// Clips the convex polygon (n points) to a x + b y + c >= -eps (Sutherland-Hodgman); out has room
// for n + 1 points.
int clip(const ClipPoint* poly, int n, double a, double b, double c, double eps, ClipPoint* out) {
  int m = 0;
  const ClipPoint* P = &poly[n - 1];
  double eP = a * P->x + b * P->y + c + eps;
  for (int k = 0; k < n; ++k) {
    const ClipPoint* Q = &poly[k];
    const double eQ = a * Q->x + b * Q->y + c + eps;
    if ((eP >= 0) != (eQ >= 0)) {
      const double t = eP / (eP - eQ);
      out[m++] = {P->x + t * (Q->x - P->x), P->y + t * (Q->y - P->y)};
    }
    if (eQ >= 0) out[m++] = *Q;
    P = Q, eP = eQ;
  }
  return m;
}

// A face's triangle as the lines of its edges, a x + b y + c positive inside, each with |a| + |b|
// (at least its Euclidean length), and eps: how far from an edge a point is still on it (pixel
// coordinates' rounding, many times over).
struct EdgeLines {
  double a[3], b[3], c[3], length[3];
  double eps;
  explicit EdgeLines(const glm::dvec2* s) {
    const double turn = (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[2].x - s[0].x) * (s[1].y - s[0].y) > 0 ? 1.0 : -1.0;
    double extent = 1.0;
    for (int k = 0; k < 3; ++k) {
      const glm::dvec2 &p = s[k], &q = s[(k + 1) % 3];
      a[k] = -turn * (q.y - p.y), b[k] = turn * (q.x - p.x), c[k] = -(a[k] * p.x + b[k] * p.y);
      length[k] = std::abs(a[k]) + std::abs(b[k]);
      extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
    }
    eps = 1e-9 * extent;
  }
  double at(int k, const glm::dvec2& x) const { return a[k] * x.x + b[k] * x.y + c[k]; }
  // Whether an edge has triangle t wholly outside it or within e of it (e > 0: then the two
  // overlap over no area wider than e), or beyond -e outside it (e < 0: they are apart by more).
  bool has_outside(const glm::dvec2* t, double e) const {
    for (int k = 0; k < 3; ++k) {
      const double inside = e * length[k];
      if (at(k, t[0]) < inside && at(k, t[1]) < inside && at(k, t[2]) < inside) return true;
    }
    return false;
  }
};

enum class Pair { apart, gap, crossing };

// Whether two faces share a vertex in the image (the same point, or the two sides of a seam:
// points with bit-identical coordinates project to the same bits).
bool share_a_point(const ProjectedFace& f, const ProjectedFace& g) {
  for (const glm::dvec2& x : f.s)
    if (x == g.s[0] || x == g.s[1] || x == g.s[2]) return true;
  return false;
}

// Whether rays can leave the mesh through face f and enter it again through face g: whether the
// two overlap in the image, and f is in front of g somewhere there (a gap; a crossing when g is in
// front of f elsewhere: the faces pass through each other), or level with it all over (the two
// sides of a seam that are not bit-identical: the A-buffer reads those as "leave, then enter"
// too). Faces that share a vertex must overlap over an area wider than eps: where they only
// touch, at that vertex or along a shared edge, the coverage rule gives a pixel centre to one of
// them (a shared edge's function is exactly negated; a centre exactly on a shared vertex is the
// one case left), and their keys there are equal, which would read as a gap. Other faces count as
// overlapping within eps of touching: then every pair the A-buffer can find at a pixel centre is
// found here.
Pair leaves_then_enters(const ProjectedFace& f, const EdgeLines& fe, const ProjectedFace& g, const EdgeLines& ge,
                        bool neighbours) {
  const double slack = key_slack(f.kmin, g.kmax) + f.rounding + g.rounding;
  if (f.kmin > g.kmax + slack) return Pair::apart;  // f behind g wherever they overlap
  const double eps = neighbours ? std::max(fe.eps, ge.eps) : -std::max(fe.eps, ge.eps);  // shrink, or grow
  if (fe.has_outside(g.s, eps) || ge.has_outside(f.s, eps)) return Pair::apart;
  if (f.kmax < g.kmin - slack) return Pair::gap;  // f in front of g wherever they overlap
  // Where the two overlap (g clipped to f, shrunk or grown by eps), the key difference is affine:
  // its extremes are at the corners.
  ClipPoint a[8], b[8];
  for (int k = 0; k < 3; ++k) a[k] = {g.s[k].x, g.s[k].y};
  ClipPoint *from = a, *to = b;
  int n = 3;
  for (int k = 0; k < 3 && n > 0; ++k, std::swap(from, to))
    n = clip(from, n, fe.a[k], fe.b[k], fe.c[k], -eps * fe.length[k], to);
  if (n == 0) return Pair::apart;
  double dmin = std::numeric_limits<double>::infinity(), dmax = -dmin;
  for (int k = 0; k < n; ++k) {
    const double d =
        (f.face.k0 - g.face.k0) + (f.face.kx - g.face.kx) * from[k].x + (f.face.ky - g.face.ky) * from[k].y;
    dmin = std::min(dmin, d), dmax = std::max(dmax, d);
  }
  if (dmin < -slack) return dmax > slack ? Pair::crossing : Pair::gap;
  return dmax <= slack ? Pair::gap : Pair::apart;
}

// A face in a tile: its pixel box, its cell and its index, packed for the search for pairs.
struct Binned {
  PixelBox box;
  std::uint32_t cell, face;
};

// The faces' pixel boxes binned into square tiles (twice as large as the boxes on average: larger
// tiles hold more pairs to reject, smaller ones more copies of each face), each tile's leaving
// faces before its entering ones.
struct TileBins {
  int tile = 8, across = 0, down = 0;
  std::vector<std::uint32_t> start, entering_from;  // tile t: entry[start[t] .. entering_from[t] .. start[t + 1])
  FrameBuffer<Binned> entry;
  std::size_t scans = 0;  // pairs of a leaving and an entering face in one tile: the search's work

  TileBins(const ProjectedFaces& faces, int width, int height) {
    double sides = 0;
    for (const ProjectedFace& f : faces) sides += (f.box.i1 - f.box.i0 + f.box.j1 - f.box.j0 + 2) * 0.5;
    if (!faces.empty()) tile = std::max(8, static_cast<int>(2 * sides / static_cast<double>(faces.size())));
    across = (width + tile - 1) / tile, down = (height + tile - 1) / tile;
    const std::size_t tiles = static_cast<std::size_t>(across) * down;
    std::vector<std::uint32_t> leaving(tiles + 1, 0);
    start.assign(tiles + 1, 0);
    each_tile(faces,
              [&](std::uint32_t k, std::size_t t) { ++start[t + 1], leaving[t + 1] += !faces[k].face.entering(); });
    for (std::size_t t = 0; t < tiles; ++t) start[t + 1] += start[t];
    entering_from.resize(tiles);
    for (std::size_t t = 0; t < tiles; ++t) entering_from[t] = start[t] + leaving[t + 1];
    entry.resize(start.back());
    for (std::size_t t = 0; t < tiles; ++t)
      scans += std::size_t(leaving[t + 1]) * (start[t + 1] - start[t] - leaving[t + 1]);
    std::vector<std::uint32_t> fill_leaving(start.begin(), start.end() - 1), fill_entering(entering_from);
    each_tile(faces, [&](std::uint32_t k, std::size_t t) {
      const ImageFace& f = faces[k].face;
      entry[f.entering() ? fill_entering[t]++ : fill_leaving[t]++] = {faces[k].box,
                                                                      static_cast<std::uint32_t>(f.cell()), k};
    });
  }
  std::size_t tiles() const { return entering_from.size(); }

 private:
  template <class Visit>
  void each_tile(const ProjectedFaces& faces, Visit&& visit) const {
    for (std::uint32_t k = 0; k < faces.size(); ++k) {
      const PixelBox& b = faces[k].box;
      for (int ty = b.j0 / tile; ty <= b.j1 / tile; ++ty)
        for (int tx = b.i0 / tile; tx <= b.i1 / tile; ++tx) visit(k, static_cast<std::size_t>(ty) * across + tx);
    }
  }
};

struct FoundGaps {
  GapPairs found;
  std::int64_t tests = 0, crossings = 0;
};

}  // namespace

Relations overlap_gap_relations(const VisibilitySorter::Prepared& p, const ProjectedFaces& faces, const SortView& view,
                                SortStats& stats, bool stop_at_crossing) {
  const TileBins bins(faces, view.width, view.height);
  FrameBuffer<EdgeLines> edges;
  edges.reserve(faces.size());
  for (const ProjectedFace& f : faces) edges.emplace_back(f.s);
  // Tiles per task; a small search stays on the calling thread, since waking a worker costs more
  // than it saves (on this project's 2-core machine, for angular_sector's few thousand scans).
  constexpr std::size_t kSerialScans = 8192;
  const std::size_t kTilesPerTask = bins.scans < kSerialScans ? std::max<std::size_t>(1, bins.tiles()) : 64;
  tbb::enumerable_thread_specific<FoundGaps> found;
  std::atomic<bool> crossed{false};
  tbb::parallel_for(std::size_t(0), (bins.tiles() + kTilesPerTask - 1) / kTilesPerTask, [&](std::size_t task) {
    FoundGaps& out = found.local();
    for (std::size_t t = task * kTilesPerTask; t < std::min(bins.tiles(), (task + 1) * kTilesPerTask); ++t) {
      if (stop_at_crossing && crossed.load(std::memory_order_relaxed)) return;
      // Each pair once: in the tile of the first pixel their boxes share (both boxes reach into
      // this tile, so that pixel is in it when it is not left of or above it).
      const int x0 = static_cast<int>(t % bins.across) * bins.tile, y0 = static_cast<int>(t / bins.across) * bins.tile;
      for (std::uint32_t i = bins.start[t]; i < bins.entering_from[t]; ++i) {
        const Binned& f = bins.entry[i];
        const bool f_x = f.box.i0 >= x0, f_y = f.box.j0 >= y0;
        for (std::uint32_t j = bins.entering_from[t]; j < bins.start[t + 1]; ++j) {
          const Binned& g = bins.entry[j];
          if (g.box.i0 > f.box.i1 || f.box.i0 > g.box.i1 || g.box.j0 > f.box.j1 || f.box.j0 > g.box.j1) continue;
          if (!(f_x || g.box.i0 >= x0) || !(f_y || g.box.j0 >= y0) || g.cell == f.cell || out.found.met(g.cell, f.cell))
            continue;
          ++out.tests;
          const ProjectedFace &ff = faces[f.face], &gf = faces[g.face];
          const Pair pair = leaves_then_enters(ff, edges[f.face], gf, edges[g.face], share_a_point(ff, gf));
          if (pair != Pair::apart) out.found.add(g.cell, f.cell);
          if (pair == Pair::crossing) ++out.crossings, crossed.store(true, std::memory_order_relaxed);
        }
      }
    }
  });
  std::vector<std::pair<std::int64_t, std::int64_t>> pairs;
  for (const FoundGaps& g : found) {
    pairs.insert(pairs.end(), g.found.pairs.begin(), g.found.pairs.end());
    stats.gap_pair_tests += g.tests, stats.gap_face_crossings += g.crossings;
  }
  Relations rel;
  stats.gap_relations = rel.build(p.mesh.n_cells, pairs);
  return rel;
}

}  // namespace cellproj
