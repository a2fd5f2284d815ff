#include "projection/cell_fragments.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "optics/linear_segment.hpp"
#include "projection/projected_tet.hpp"
#include "projection/tet_clip.hpp"
#include "view/raster.hpp"

namespace cellproj {
namespace {

// What pt-analytic's and pt-breakpoints' light of a cell's segments needs: the cell's scalar range
// and transfer-function piece (or whether a breakpoint cuts it), and the segment's ends per pixel
// from the ray's entry and exit, depth and scalar, or in perspective 1/z and s/z (segment_between).
struct ExactShade {
  const TransferFunction& tf;
  const PixelRays& rays;
  bool persp, has_breakpoint, cut;  // cut: pt-breakpoints across a breakpoint
  double smin, smax;
  LinearPiece piece;  // the cell's piece when its scalar range holds no breakpoint
  // The segment's length and its ends' scalars (clamped to the cell's range) from the
  // interpolated quantities.
  double ends(int i, int j, double zf, double zb, double& sf, double& sb) const {
    const double per_depth = rays.length_per_depth_at_pixel(i, j);
    return persp ? segment_between<true>(zf, zb, sf, sb, per_depth, smin, smax)
                 : segment_between<false>(zf, zb, sf, sb, per_depth, smin, smax);
  }
};

struct CompositeFragments;

// The exact methods' fragments of one cell, gathered, their light computed together, then emitted
// in the order they were given: segment_ends, then the weights over the batch (the same bits as
// one by one, small cells in SIMD lanes), of the cell's one linear piece, or of each segment's
// pieces where the cell's scalar range holds a breakpoint. A tile's compositing (CompositeFragments)
// takes them four at a time (composite_over).
template <class Emit>
struct ExactFragments {
  const ExactShade& shade;
  Emit& emit;
  SegmentBatch& batch;
  std::int64_t emitted = 0;
  ExactFragments(const ExactShade& s, Emit& e, SegmentBatch& b) : shade(s), emit(e), batch(b) { batch.n = 0; }
  void operator()(int i, int j, double zf, double zb, double sf, double sb) {
    if (emit.hidden(i, j)) return;  // an opaque pixel (front to back): no integral
    batch.push(i, j, zf, zb, sf, sb);
  }
  // Emits the gathered fragments; returns how many were emitted in all.
  // ends: compute the segments' ends first (false: the batch holds them, fan_segments).
  std::int64_t finish(bool ends = true) {
    SegmentBatch& b = batch;
    if (ends) segment_ends(b, shade.rays, shade.smin, shade.smax, shade.piece);
    if (shade.has_breakpoint) {
      segment_light_across(b, shade.tf, shade.cut);
    } else {
      linear_segment_weights_padded(b.n, b.length.data(), b.k0.data(), b.k1.data(), b.weights.data());
      segment_light(b, shade.piece);
    }
    if constexpr (std::is_same_v<Emit, CompositeFragments>) return emitted += composite_over(b, emit.image);
    for (std::size_t k = 0; k < b.n; ++k) {  // (across a breakpoint opacity is set: depth is not read)
      const SegmentLight light{{b.red[k], b.green[k], b.blue[k]}, b.weights[k].depth, b.opacity[k]};
      emitted += emit(b.i[k], b.j[k], light.rgb, light.opacity());
    }
    return emitted;
  }
};

// The box of a cell's n vertices in the image, vertex(k) giving the k-th: its lower and upper corner.
template <class Vertex>
std::array<glm::dvec2, 2> vertex_box(int n, Vertex&& vertex) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  glm::dvec2 lo(inf), hi(-inf);
  for (int k = 0; k < n; ++k) {
    const auto& v = vertex(k);
    lo.x = std::min(lo.x, v.x), hi.x = std::max(hi.x, v.x), lo.y = std::min(lo.y, v.y), hi.y = std::max(hi.y, v.y);
  }
  return {lo, hi};
}

// A thick vertex's corner (MWSC section 2): opacity 1 - exp(-kappa_avg l) (pt-linear) or kappa_avg
// (pt-table), thickness l, and the mean of the segment's end colours.
GouraudCorner thick_corner(double kf, double kb, const glm::dvec3& cf, const glm::dvec3& cb, double l, bool table) {
  const double kavg = 0.5 * (kf + kb);
  return {table ? kavg : -std::expm1(-kavg * l), l, 0.5 * (cf + cb)};
}

// pt-linear's and pt-table's fragments of a whole cell drawn by its layers: every pixel is a thick
// vertex, its segment's ends from the front and back layers (no polygon to interpolate across).
template <class Emit>
struct ThickPixelFragments {
  const ExactShade& shade;
  const OpacityTable* table;  // pt-table's
  Emit& emit;
  std::int64_t emitted = 0;
  void operator()(int i, int j, double zf, double zb, double sf, double sb) {
    if (emit.hidden(i, j)) return;
    const double l = shade.ends(i, j, zf, zb, sf, sb);
    const LinearPiece& piece = shade.piece;
    const TransferFunction& tf = shade.tf;
    const GouraudCorner g =
        shade.has_breakpoint
            ? thick_corner(tf.extinction(sf), tf.extinction(sb), tf.color(sf), tf.color(sb), l, table)
            : thick_corner(piece.kappa(sf), piece.kappa(sb), piece.color(sf), piece.color(sb), l, table);
    const double alpha = table ? (*table)(g.a, g.l) : g.a;
    emitted += emit(i, j, g.c * alpha, alpha);
  }
  std::int64_t finish() const { return emitted; }
};

// The shade of a cell with scalar range [smin, smax]: its transfer-function piece, or whether a
// breakpoint lies inside the range (then cut there by pt-breakpoints, `cuts`).
bool holds_breakpoint(const TransferFunction& tf, double smin, double smax) {
  const std::size_t above = tf.breakpoints_not_above(smin);
  return above < tf.breakpoints().size() && tf.breakpoints()[above] < smax;
}

ExactShade exact_shade(const TransferFunction& tf, const PixelRays& rays, bool cuts, double smin, double smax) {
  const bool has_breakpoint = holds_breakpoint(tf, smin, smax);
  ExactShade shade{tf, rays, rays.perspective(), has_breakpoint, has_breakpoint && cuts, smin, smax, {}};
  if (!has_breakpoint) {
    const auto e = tf.piece(smin, smax);
    LinearPiece& piece = shade.piece;
    piece.s0 = smin, piece.ds = smax > smin ? 1.0 / (smax - smin) : 0.0;
    piece.k0 = e.ka, piece.dk = e.kb - e.ka, piece.c0 = e.ca, piece.dc = e.cb - e.ca;
  }
  return shade;
}

// The per-pixel quantities of a vertex that interpolate affinely over a face's image: depth and
// scalar, or 1/z and s/z in perspective.
inline void affine_depth_scalar(const ScreenVertex& v, bool persp, double& q_depth, double& q_scalar) {
  const double f = persp ? 1.0 / v.z : 1.0;
  q_depth = persp ? f : v.z, q_scalar = v.s * f;
}

// The same for both ends of a thick vertex's segment: front and back depth, front and back scalar.
inline void affine_ends(const ThickVertex& v, bool persp, double q[4]) {
  affine_depth_scalar({v.x, v.y, v.zf, v.sf}, persp, q[0], q[2]);
  affine_depth_scalar({v.x, v.y, v.zb, v.sb}, persp, q[1], q[3]);
}

// Appends fragments to a batch's bands.
struct AppendFragments {
  FragmentBands& out;
  bool operator()(int i, int j, const glm::dvec3& rgb, double alpha) const {
    if (adds_nothing(rgb, alpha)) return false;
    out.append(i, j, rgb.r, rgb.g, rgb.b, alpha);
    return true;
  }
  static bool hidden(int, int) { return false; }
  static constexpr bool may_hide = false;
};

// Composites fragments onto the image at once (a cell drawn in order by the compositor itself).
struct CompositeFragments {
  Image& image;
  bool operator()(int i, int j, const glm::dvec3& rgb, double alpha) const {
    return over_fragment(image.pixel(i, j), rgb, alpha);
  }
  static bool hidden(int, int) { return false; }
  static constexpr bool may_hide = false;
};

// Composites fragments front to back ("under") onto the image: early ray termination drops those
// at pixels within kOpaqueWithin of opaque (counted) and marks the pixels that become so.
struct UnderFragments {
  Image& image;
  OpaqueMask& opaque;
  ProjectionCounters& counters;
  static constexpr bool may_hide = true;  // hidden() may drop a fragment before its integral
  bool hidden(int i, int j) {
    if (!opaque.opaque(i, j)) return false;
    ++counters.hidden_fragments;
    return true;
  }
  bool operator()(int i, int j, const glm::dvec3& rgb, double alpha) {
    if (adds_nothing(rgb, alpha)) return false;
    float* dst = image.pixel(i, j);
    if (dst[3] >= kOpaqueAlpha) {
      ++counters.hidden_fragments;
      return false;
    }
    const float src[4] = {static_cast<float>(rgb.r), static_cast<float>(rgb.g), static_cast<float>(rgb.b),
                          static_cast<float>(alpha)};
    under(dst, src);
    if (dst[3] >= kOpaqueAlpha) opaque.set(i, j);
    return true;
  }
};

}  // namespace

void ProjectionCounters::add(const ProjectionCounters& o) {
  tets += o.tets, class1 += o.class1, class2 += o.class2, empty += o.empty, behind_eye += o.behind_eye;
  polyhedra += o.polyhedra, polygons += o.polygons, layered += o.layered, unmatched += o.unmatched;
  subdivisions_looked_up += o.subdivisions_looked_up;
  fragments += o.fragments, breakpoint_cells += o.breakpoint_cells, direct_cells += o.direct_cells;
  hidden_cells += o.hidden_cells, hidden_fragments += o.hidden_fragments;
  depth_cut_cells += o.depth_cut_cells, depth_hidden_cells += o.depth_hidden_cells;
}

PointOptics point_optics(const double* scalar, std::int64_t n_points, const TransferFunction& tf) {
  PointOptics o;
  o.kappa.resize(static_cast<std::size_t>(n_points));
  o.color.resize(static_cast<std::size_t>(n_points));
  tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, n_points, 4096),
                    [&](const tbb::blocked_range<std::int64_t>& r) {
                      for (std::int64_t p = r.begin(); p < r.end(); ++p) {
                        const double s = scalar ? scalar[p] : 0.0;  // as ScreenPoints
                        o.kappa[p] = tf.extinction(s), o.color[p] = tf.color(s);
                      }
                    });
  return o;
}

CellFragments::CellFragments(const ScreenPoints& screen, const PixelRays& rays, const RecentredPoints& points,
                             const TransferFunction& tf, ProjectionMethod method, const OpacityTable* table,
                             const PointOptics* optics, WholeCells whole_cells, const ColorField* color,
                             const DepthLimit* limit)
    : screen_(screen),
      rays_(rays),
      points_(points),
      tf_(tf),
      method_(traits(method)),
      table_(table),
      optics_(optics),
      whole_cells_(whole_cells),
      color_(color),
      limit_(limit) {
  // Which way a triangle facing the eye turns in this image: (c, c + r, c + u) with r x u towards
  // the eye, ahead of it on the view axis.
  const Camera& cam = rays.camera();
  const glm::dvec3 f = rays.forward();
  const glm::dvec3 r = glm::normalize(glm::cross(f, cam.up)), u = glm::cross(r, f);  // r x u = -f
  const double d = glm::length(cam.target - cam.eye);
  const glm::dvec3 c = cam.eye + d * f;
  ScreenVertex s[3];
  const glm::dvec3 q[3] = {c, c + 0.1 * d * r, c + 0.1 * d * u};
  for (int k = 0; k < 3; ++k) rays.project(q[k], s[k].x, s[k].y, s[k].z);
  front_sign_ = exact_sign(s[0], s[1], s[2]);
  if (front_sign_ == 0) front_sign_ = 1;
}

void CellFragments::prefetch_points(const std::int64_t* ids, int n) const {
  for (int k = 0; k < n; ++k) {
    const auto q = static_cast<std::size_t>(ids[k]);
    __builtin_prefetch(&screen_.v[q]);
    if (method_.gouraud && optics_) __builtin_prefetch(&optics_->color[q]), __builtin_prefetch(&optics_->kappa[q]);
  }
}

PixelBox CellFragments::cast_box(const std::int64_t* ids, int n, RowRange rows) const {
  PixelBox box;
  box.i0 = 0, box.i1 = rays_.width() - 1, box.j0 = 0, box.j1 = rays_.height() - 1;
  bool in_front = true;  // in perspective, a point behind the eye has no image position
  for (int k = 0; k < n && rays_.perspective(); ++k)
    in_front = in_front && !behind_eye(screen_.v[static_cast<std::size_t>(ids[k])].z);
  if (in_front) {
    const auto [v0, v1] =
        vertex_box(n, [&](int k) -> const ScreenVertex& { return screen_.v[static_cast<std::size_t>(ids[k])]; });
    auto lo = [](double v, int n) { return static_cast<int>(std::clamp(std::floor(v - 0.5), 0.0, double(n))); };
    auto hi = [](double v, int n) { return static_cast<int>(std::clamp(std::ceil(v - 0.5), -1.0, double(n - 1))); };
    box.i0 = lo(v0.x, rays_.width()), box.i1 = hi(v1.x, rays_.width());
    box.j0 = lo(v0.y, rays_.height()), box.j1 = hi(v1.y, rays_.height());
  }
  box.j0 = std::max(box.j0, rows.begin), box.j1 = std::min(box.j1, rows.end - 1);
  return box;
}

template <class Emit>
void CellFragments::ray_cast_cell(const std::int64_t* ids, CellType type, RowRange rows, Emit& emit,
                                  ProjectionCounters& counters) const {
  // Each tetrahedron's planes, and both fields as s(x) = s0 + g . (x - p0).
  struct Part {
    TetClip clip;
    glm::dvec3 p0, gs, gu;
    double s0, u0;
  };
  Part part[kMaxTetsPerCell];
  Tet tets[kMaxTetsPerCell];
  int parts = 0;
  for (int t = 0, n = canonical_tetrahedra(ids, type, tets); t < n; ++t) {
    glm::dvec3 p[4];
    double s[4], u[4];
    for (int k = 0; k < 4; ++k) {
      const auto q = static_cast<std::size_t>(tets[t][k]);
      p[k] = points_(tets[t][k]), s[k] = screen_.v[q].s, u[k] = color_ ? color_->values[q] : s[k];
    }
    const double det = edges_triple_product(p);
    if (!(std::abs(det) > 0.0)) continue;  // zero volume: nothing to see
    part[parts++] = {TetClip(p), p[0], linear_gradient(p, s, det), linear_gradient(p, u, det), s[0], u[0]};
  }
  const PixelBox box = cast_box(ids, cell_def(type).vertices, rows);
  const bool cut = method_.cuts_at_breakpoints;
  std::int64_t emitted = 0;
  for (int j = box.j0; j <= box.j1; ++j)
    for (int i = box.i0; i <= box.i1; ++i) {
      const Ray r = rays_.ray(i + 0.5, j + 0.5);
      struct Hit {
        double t0, t1;
        const Part* part;
      } hit[kMaxTetsPerCell];
      int hits = 0;
      const double t_max = limit_ ? limit_->t_max(i, j) : std::numeric_limits<double>::infinity();
      for (int k = 0; k < parts; ++k)
        if (double t0, t1; part[k].clip.clip(r, t0, t1) && t0 < t_max)
          hit[hits++] = {t0, std::min(t1, t_max), &part[k]};
      if (hits == 0 || emit.hidden(i, j)) continue;  // (hidden: an opaque pixel, front to back)
      for (int k = 1; k < hits; ++k)                 // front to back (insertion: at most kMaxTetsPerCell)
        for (int m = k; m > 0 && hit[m].t0 < hit[m - 1].t0; --m) std::swap(hit[m], hit[m - 1]);
      SegmentLight acc;
      for (int k = 0; k < hits && acc.depth < kOpaqueDepth; ++k) {
        const Part& q = *hit[k].part;
        const glm::dvec3 xf = r.origin + hit[k].t0 * r.dir - q.p0, xb = r.origin + hit[k].t1 * r.dir - q.p0;
        const double length = hit[k].t1 - hit[k].t0, sf = q.s0 + glm::dot(q.gs, xf), sb = q.s0 + glm::dot(q.gs, xb);
        const SegmentLight light = color_
                                       ? integrate_two_fields_closed_form(color_->tf, length, q.u0 + glm::dot(q.gu, xf),
                                                                          q.u0 + glm::dot(q.gu, xb), sf, sb, cut)
                                       : integrate_segment_closed_form(tf_, length, sf, sb);
        acc = k == 0 ? light : under(acc, light);
      }
      emitted += emit(i, j, acc.rgb, acc.opacity());
    }
  counters.fragments += emitted;
}

CellFragments::Seen CellFragments::classify(const Tet& tet, ScreenVertex v[4], ProjectedTet& pt,
                                            ProjectionCounters& counters) const {
  ++counters.tets;
  for (int k = 0; k < 4; ++k) {
    v[k] = screen_.v[static_cast<std::size_t>(tet[k])];
    if (behind_eye(v[k].z)) {
      ++counters.behind_eye;
      return Seen::behind_eye;  // project() ray casts it; the OpenGL back ends leave it out
    }
  }
  project_tet(v, rays_.perspective(), pt);
  if (pt.hull_size == 0) {
    ++counters.empty;
    return Seen::empty;
  }
  ++(pt.hull_size == 3 ? counters.class1 : counters.class2);
  return Seen::projected;
}

GouraudCorner CellFragments::shade(const ThickVertex& t) const {
  // Corner values from the transfer function, Gouraud-interpolated across each triangle (MWSC sec. 2).
  return thick_corner(tf_.extinction(t.sf), tf_.extinction(t.sb), tf_.color(t.sf), tf_.color(t.sb),
                      (t.zb - t.zf) * rays_.length_per_depth(t.x, t.y), method_.opacity_table);
}

CellFragments::Seen CellFragments::tet_triangles(const Tet& tet, CellScratch& p, ProjectionCounters& counters,
                                                 bool triangles) const {
  ScreenVertex v[4];
  ProjectedTet& pt = p.tet;
  const Seen seen = classify(tet, v, pt, counters);
  if (seen != Seen::projected) return seen;
  p.smin = std::min({v[0].s, v[1].s, v[2].s, v[3].s}), p.smax = std::max({v[0].s, v[1].s, v[2].s, v[3].s});
  if (method_.gouraud) {
    // The outline's corners are zero thick: their values per point, computed once per frame.
    const bool table = method_.opacity_table;
    p.tet_corner[0] = shade(pt.thick);
    for (int k = 0; k < pt.hull_size; ++k) {
      const std::int64_t q = tet[pt.hull_vertex[k]];
      p.tet_corner[1 + k] = {table ? optics_->kappa[q] : 0.0, 0.0, optics_->color[q]};
    }
  }
  if (triangles) fan_triangles(p);
  return seen;
}

void CellFragments::fan_triangles(CellScratch& p) const {
  const ProjectedTet& pt = p.tet;
  const int n = pt.hull_size;
  p.tri.resize(static_cast<std::size_t>(n));
  for (int a = 0; a < n; ++a) p.tri[a] = {{pt.thick, pt.hull[a], pt.hull[(a + 1) % n]}};
  if (!method_.gouraud) return;
  p.corner.resize(3 * p.tri.size());
  for (int a = 0; a < n; ++a)
    p.corner[3 * a] = p.tet_corner[0], p.corner[3 * a + 1] = p.tet_corner[1 + a],
                 p.corner[3 * a + 2] = p.tet_corner[1 + (a + 1) % n];
}

bool CellFragments::load_cell(const std::int64_t* ids, CellType type, ScreenVertex* v, CellScratch& p,
                              ProjectionCounters& counters) const {
  ++counters.polyhedra;
  const int n = cell_def(type).vertices;
  p.smin = std::numeric_limits<double>::infinity(), p.smax = -p.smin;
  for (int k = 0; k < n; ++k) {
    v[k] = screen_.v[static_cast<std::size_t>(ids[k])];
    p.smin = std::min(p.smin, v[k].s), p.smax = std::max(p.smax, v[k].s);
    if (behind_eye(v[k].z)) {
      ++counters.behind_eye;  // split into tetrahedra for the view (--tetrahedralize problem), or not drawn
      return false;
    }
  }
  return true;
}

CellFragments::Seen CellFragments::cell_triangles(const std::int64_t* ids, CellType type, CellScratch& p,
                                                  ProjectionCounters& counters, bool shade) const {
  ScreenVertex v[8];
  if (!load_cell(ids, type, v, p, counters)) return Seen::behind_eye;
  p.tri.clear();
  const CellProjection cp = project_cell(v, ids, type, rays_.perspective(), front_sign_, p.tri, &p.subdivisions);
  counters.polygons += cp.polygons;
  counters.subdivisions_looked_up += cp.looked_up;
  if (p.tri.empty()) {
    ++counters.empty;
    return Seen::empty;
  }
  if (method_.gouraud) {
    p.corner.resize(3 * p.tri.size());
    if (shade)
      for (std::size_t t = 0; t < p.tri.size(); ++t) shade_corners(p, t, t > 0 ? t - 1 : t);  // t: none before
  }
  return Seen::projected;
}

void CellFragments::shade_corners(CellScratch& p, std::size_t t, std::size_t reuse) const {
  // The same thick vertex, bit for bit, gives the same corner: shaded once.
  for (int k = 0; k < 3; ++k) {
    const ThickVertex& v = p.tri[t].v[k];
    int m = 0;
    while (reuse < t && m < 3 && std::memcmp(&p.tri[reuse].v[m], &v, sizeof v) != 0) ++m;
    p.corner[3 * t + k] = reuse < t && m < 3 ? p.corner[3 * reuse + m] : shade(v);
  }
}

CellFragments::Seen CellFragments::triangles_of(const std::int64_t* ids, CellType type, CellScratch& p,
                                                ProjectionCounters& counters, bool shade_cells) const {
  if (type == CellType::Tetra) return tet_triangles({ids[0], ids[1], ids[2], ids[3]}, p, counters);
  return cell_triangles(ids, type, p, counters, shade_cells);
}

void CellFragments::triangles(const std::int64_t* ids, CellType type, std::int64_t cell, std::vector<GLCorner>& out,
                              CellScratch& p, ProjectionCounters& counters) const {
  if (triangles_of(ids, type, p, counters, true) != Seen::projected) return;
  const bool table = method_.opacity_table;
  // Texel centres: node i of n sits at (i + 0.5) / n, so GL_LINEAR reads the table as OpacityTable does.
  const double n = table ? table_->size() : 1.0;
  const DitherShift shift(static_cast<std::uint64_t>(cell));
  for (std::size_t t = 0; t < p.tri.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const double x = p.tri[t].v[k].x, y = p.tri[t].v[k].y;
      const GouraudCorner& g = p.corner[3 * t + k];
      const double u = table ? (table_->kappa_index(g.a) + 0.5) / n : 0.0;
      const double w = table ? (table_->length_index(g.l) + 0.5) / n : 0.0;
      out.push_back({static_cast<float>(x), static_cast<float>(y), static_cast<float>(u), static_cast<float>(w),
                     static_cast<float>(g.c.r), static_cast<float>(g.c.g), static_cast<float>(g.c.b),
                     table ? 1.0f : static_cast<float>(g.a), (static_cast<float>(x) + shift.u) / kDitherTile,
                     (static_cast<float>(y) + shift.v) / kDitherTile});
    }
}

void CellFragments::project(const std::int64_t* ids, CellType type, FragmentBands& out, CellScratch& scratch,
                            ProjectionCounters& counters) const {
  AppendFragments emit{out};
  project_with(ids, type, {0, rays_.height()}, emit, scratch, counters);
}

void CellFragments::project(const std::int64_t* ids, CellType type, Image& image, CellScratch& scratch,
                            ProjectionCounters& counters) const {
  project(ids, type, image, {0, rays_.height()}, scratch, counters);
}

void CellFragments::project(const std::int64_t* ids, CellType type, Image& image, RowRange rows, CellScratch& scratch,
                            ProjectionCounters& counters) const {
  CompositeFragments emit{image};
  project_with(ids, type, rows, emit, scratch, counters);
}

void CellFragments::project_under(const std::int64_t* ids, CellType type, Image& image, RowRange rows,
                                  OpaqueMask& opaque, CellScratch& scratch, ProjectionCounters& counters) const {
  UnderFragments emit{image, opaque, counters};
  project_with(ids, type, rows, emit, scratch, counters);
}

bool CellFragments::hidden_by(const std::int64_t* ids, CellType type, RowRange rows, const OpaqueMask& opaque) const {
  const int n = cell_def(type).vertices;
  const auto vertex = [&](int k) -> const ScreenVertex& { return screen_.v[static_cast<std::size_t>(ids[k])]; };
  for (int k = 0; k < n; ++k)
    if (behind_eye(vertex(k).z)) return false;
  // Every triangle of the cell has its pixels in this box (the same rounding as PixelBox's).
  const auto [lo, hi] = vertex_box(n, vertex);
  const PixelBox box(lo, hi, lo, rays_.width(), rays_.height());
  const int j0 = std::max(box.j0, rows.begin), j1 = std::min(box.j1, rows.end - 1);
  return !box.empty() && j0 <= j1 && opaque.all(box.i0, box.i1, j0, j1);
}

bool CellFragments::by_layers(const std::int64_t* ids, CellType type) const {
  if (!method_.gouraud || whole_cells_ == WholeCells::layers) return true;
  if (whole_cells_ == WholeCells::polygons) return false;
  const auto [lo, hi] = vertex_box(cell_def(type).vertices, [&](int k) -> const ScreenVertex& {
    return screen_.v[static_cast<std::size_t>(ids[k])];
  });
  // The pixels of its box (the whole image's, not the tile's share: every tile decides alike); NaN: no.
  return (hi.x - lo.x + 1) * (hi.y - lo.y + 1) <= kLayersUpToPixels;
}

DepthSide CellFragments::depth_side(const std::int64_t* ids, CellType type, RowRange rows) const {
  const int n = cell_def(type).vertices;
  double z_near = std::numeric_limits<double>::infinity(), z_far = -z_near;
  for (int k = 0; k < n; ++k) {
    const double z = screen_.v[static_cast<std::size_t>(ids[k])].z;
    z_near = std::min(z_near, z), z_far = std::max(z_far, z);
  }
  return side_of(z_near, z_far, limit_->range(cast_box(ids, n, rows)));
}

template <class Emit>
void CellFragments::project_with(const std::int64_t* ids, CellType type, RowRange rows, Emit& emit, CellScratch& p,
                                 ProjectionCounters& counters) const {
  if (limit_) switch (depth_side(ids, type, rows)) {
      case DepthSide::behind: ++counters.depth_hidden_cells; return;
      case DepthSide::cut:
        ++counters.depth_cut_cells, ++(type == CellType::Tetra ? counters.tets : counters.polyhedra);
        return ray_cast_cell(ids, type, rows, emit, counters);
      case DepthSide::in_front: break;
    }
  if (color_) {
    ++(type == CellType::Tetra ? counters.tets : counters.polyhedra);
    return ray_cast_cell(ids, type, rows, emit, counters);
  }
  if (type != CellType::Tetra && by_layers(ids, type)) return project_layers(ids, type, rows, emit, p, counters);
  const bool tet = type == CellType::Tetra;
  const Seen seen = tet ? tet_triangles({ids[0], ids[1], ids[2], ids[3]}, p, counters, false)
                        : cell_triangles(ids, type, p, counters, false);
  if (seen == Seen::behind_eye && tet) ray_cast_cell(ids, type, rows, emit, counters);  // (counted by classify)
  if (seen != Seen::projected) return;
  counters.breakpoint_cells += holds_breakpoint(tf_, p.smin, p.smax);
  if (tet) {  // small ones as one fan, the others triangle by triangle
    if (project_fan(rows, emit, p, counters)) return;
    fan_triangles(p);
  }
  std::int64_t emitted = 0;
  const int width = rays_.width(), height = rays_.height();
  const bool persp = rays_.perspective();
  if (method_.gouraud) {
    // Colour, opacity (pt-table: kappa and thickness) are affine along a row of a triangle (Gouraud
    // shading, MWSC section 2): a run of pixels starts from its first pixel's values and steps.
    const bool table = method_.opacity_table;
    // A cell's image-plane subdivision has many triangles covering no pixel centre: their corners
    // are not shaded (a tetrahedron's were, from its thick vertex and the point optics).
    const bool shade_when_drawn = type != CellType::Tetra;
    std::size_t shaded = p.tri.size();  // the last triangle shaded here (none yet)
    for (std::size_t t = 0; t < p.tri.size(); ++t) {
      const ThickVertex* V = p.tri[t].v;
      const PixelBox box({V[0].x, V[0].y}, {V[1].x, V[1].y}, {V[2].x, V[2].y}, width, height);
      if (!box.reaches(rows.begin, rows.end)) continue;
      if (shade_when_drawn) shade_corners(p, t, shaded), shaded = t;
      const GouraudCorner* g = &p.corner[3 * t];
      // A corner quantity weighted by w: at a pixel (the weights) or its change per pixel (their steps).
      const auto mix = [g](const double* w, auto GouraudCorner::*q) {
        return w[0] * (g[0].*q) + w[1] * (g[1].*q) + w[2] * (g[2].*q);
      };
      glm::dvec3 dc;
      double da = 0, dl = 0;
      rasterize_triangle_spans(
          glm::dvec2(V[0].x, V[0].y), glm::dvec2(V[1].x, V[1].y), glm::dvec2(V[2].x, V[2].y), box, rows.begin, rows.end,
          [&](const double* dw) {
            dc = mix(dw, &GouraudCorner::c), da = mix(dw, &GouraudCorner::a), dl = mix(dw, &GouraudCorner::l);
          },
          [&](int j, int b, int e, const double* w) {
            const glm::dvec3 c0 = mix(w, &GouraudCorner::c);
            const double a0 = mix(w, &GouraudCorner::a), l0 = mix(w, &GouraudCorner::l);
            for (int i = b; i < e; ++i) {
              const double k = i - b;  // steps from the run's start (no running sum: no drift)
              // Clamped: a step's rounding may leave a value that is 0 at an edge a hair below it.
              const glm::dvec3 c = glm::max(c0 + k * dc, 0.0);
              const double x = std::max(a0 + k * da, 0.0);
              const double alpha = table ? (*table_)(x, std::max(l0 + k * dl, 0.0)) : std::min(x, 1.0);
              emitted += emit(i, j, c * alpha, alpha);
            }
          });
    }
    counters.fragments += emitted;
    return;
  }

  // pt-analytic and pt-breakpoints on a tetrahedron: the segment's ends per pixel, then the
  // closed-form integral. Depths and scalars (1/z and s/z in perspective) are affine along a run of
  // a triangle's pixels: a run starts from its first pixel's values and steps, as the Gouraud path.
  const ExactShade exact = exact_shade(tf_, rays_, method_.cuts_at_breakpoints, p.smin, p.smax);
  ExactFragments<Emit> fragments(exact, emit, p.segments);
  for (std::size_t t = 0; t < p.tri.size(); ++t) {
    const ThickVertex* V = p.tri[t].v;
    double q[3][4];  // per corner: front and back depth, front and back scalar (over depth in perspective)
    for (int k = 0; k < 3; ++k) {
      affine_ends(V[k], persp, q[k]);
    }
    const auto mix = [&q](const double* w, int m) { return w[0] * q[0][m] + w[1] * q[1][m] + w[2] * q[2][m]; };
    double dq[4];
    rasterize_triangle_spans(
        glm::dvec2(V[0].x, V[0].y), glm::dvec2(V[1].x, V[1].y), glm::dvec2(V[2].x, V[2].y), width, height, rows.begin,
        rows.end,
        [&](const double* dw) {
          for (int m = 0; m < 4; ++m) dq[m] = mix(dw, m);
        },
        [&](int j, int b, int e, const double* w) {
          const double q0[4] = {mix(w, 0), mix(w, 1), mix(w, 2), mix(w, 3)};
          for (int i = b; i < e; ++i) {
            const double k = i - b;  // steps from the run's start (no running sum: no drift)
            fragments(i, j, q0[0] + k * dq[0], q0[1] + k * dq[1], q0[2] + k * dq[2], q0[3] + k * dq[3]);
          }
        });
  }
  counters.fragments += fragments.finish();
}

template <class Emit>
bool CellFragments::project_fan(RowRange rows, Emit& emit, CellScratch& p, ProjectionCounters& counters) const {
  // The fan is (thick, hull[a], hull[a + 1]), its corners p.tet_corner[0], [1 + a] (tet_triangles).
  const ProjectedTet& pt = p.tet;
  const int n = pt.hull_size;
  if (pt.edge_on) return false;
  const auto [lo, hi] = vertex_box(n, [&](int k) -> const ThickVertex& { return pt.hull[k]; });
  const PixelBox box(lo, hi, lo, rays_.width(), rays_.height());
  const int bw = box.i1 - box.i0 + 1;
  // A tile's pt-linear composites the fan straight onto the image, at any size; the other uses
  // fill a buffer the size of the box (the exact rungs' batch, a stream's pixels), and pt-table's
  // kernel, a table look-up a pixel, is slower than the triangles' on large tetrahedra.
  const bool any_size = std::is_same_v<Emit, CompositeFragments> && method_.gouraud && !method_.opacity_table;
  if (box.empty() || (!any_size && std::int64_t{bw} * (box.j1 - box.j0 + 1) > kFanUpToPixels)) return box.empty();
  const int j0 = std::max(box.j0, rows.begin), j1 = std::min(box.j1, rows.end - 1);
  if (j0 > j1) return true;
  // The quantities interpolated: pt-linear opacity and colour, pt-table kappa_avg, thickness and
  // colour (the corners'), the exact rungs the ends' depth and scalar (the thick vertices').
  const bool gouraud = method_.gouraud, table = method_.opacity_table, persp = rays_.perspective();
  const int nq = table ? 5 : 4;
  double thick[kFanQuantities], hull[4][kFanQuantities];
  const auto values = [&](int corner, const ThickVertex& v, double* q) {
    if (!gouraud) return affine_ends(v, persp, q);
    const GouraudCorner& g = p.tet_corner[corner];
    int m = 0;
    q[m++] = g.a;
    if (table) q[m++] = g.l;
    q[m++] = g.c.r, q[m++] = g.c.g, q[m] = g.c.b;
  };
  values(0, pt.thick, thick);
  for (int a = 0; a < n; ++a) values(1 + a, pt.hull[a], hull[a]);
  FanPlanes planes = fan_planes(pt, box.i0 + 0.5, box.j0 + 0.5, nq, thick, hull);
  if (planes.sectors == 0) return false;  // no area to rounding: the triangles' rule decides
  planes.linear_opacity = gouraud && !table;
  if (!gouraud && !Emit::may_hide) {  // the segments straight into the batch (no pixel is hidden)
    const ExactShade exact = exact_shade(tf_, rays_, method_.cuts_at_breakpoints, p.smin, p.smax);
    ExactFragments<Emit> fragments(exact, emit, p.segments);
    fan_segments(planes, {rays_, box.i0, box.j0, j0 - box.j0, j1 - j0 + 1, bw, p.smin, p.smax, exact.piece},
                 p.segments);
    counters.fragments += fragments.finish(/*ends=*/false);
    return true;
  }
  // A tile's compositing, pt-linear and pt-table: composited in the fan's lanes.
  if constexpr (std::is_same_v<Emit, CompositeFragments>)
    if (gouraud) {
      const int r0 = j0 - box.j0, rows_drawn = j1 - j0 + 1;
      counters.fragments += table ? fan_composite_table(planes, *table_, emit.image, box.i0, box.j0, r0, rows_drawn, bw)
                                  : fan_composite_over(planes, emit.image, box.i0, box.j0, r0, rows_drawn, bw);
      return true;
    }
  FanPixels& f = p.fan;
  fan_pixels(planes, j0 - box.j0, j1 - j0 + 1, bw, f);
  const double *q0 = f.quantity(0), *q1 = f.quantity(1), *q2 = f.quantity(2), *q3 = f.quantity(3);
  const double* q4 = f.quantity(4);
  // visit(i, j, k) for every pixel (i, j) of the fan's rows, k its quantities' index.
  const auto for_each_pixel = [&](auto&& visit) {
    for (int j = j0; j <= j1; ++j) {
      const int r = j - j0;
      const std::size_t row = static_cast<std::size_t>(r) * f.stride;
      for (int i = f.first[r]; i <= f.last[r]; ++i) visit(box.i0 + i, j, row + i);
    }
  };
  if (!gouraud) {
    const ExactShade exact = exact_shade(tf_, rays_, method_.cuts_at_breakpoints, p.smin, p.smax);
    ExactFragments<Emit> fragments(exact, emit, p.segments);
    for_each_pixel([&](int i, int j, std::size_t k) { fragments(i, j, q0[k], q1[k], q2[k], q3[k]); });
    counters.fragments += fragments.finish();
    return true;
  }
  std::int64_t emitted = 0;
  if (!table)  // opacity and premultiplied colour already
    for_each_pixel([&](int i, int j, std::size_t k) { emitted += emit(i, j, glm::dvec3(q1[k], q2[k], q3[k]), q0[k]); });
  else
    for_each_pixel([&](int i, int j, std::size_t k) {
      // Clamped as project_with's runs: rounding may leave a value a hair below 0 at an edge.
      const double alpha = (*table_)(std::max(q0[k], 0.0), std::max(q1[k], 0.0));
      emitted += emit(i, j, glm::max(glm::dvec3(q2[k], q3[k], q4[k]), 0.0) * alpha, alpha);
    });
  counters.fragments += emitted;
  return true;
}

template <class Emit>
void CellFragments::project_layers(const std::int64_t* ids, CellType type, RowRange rows, Emit& emit, CellScratch& p,
                                   ProjectionCounters& counters) const {
  ScreenVertex v[8];
  if (!load_cell(ids, type, v, p, counters)) return;  // split into tetrahedra for the view, or not drawn
  const FaceLayers faces = face_layers(v, ids, type, front_sign_);
  const int n = cell_def(type).vertices;
  const int width = rays_.width(), height = rays_.height();
  // Every face triangle's pixels lie in the box of the cell's vertices (the same rounding).
  const auto [lo, hi] = vertex_box(n, [&](int k) -> const ScreenVertex& { return v[k]; });
  PixelBox box(lo, hi, lo, width, height);
  if (faces.n_front == 0 || box.empty()) {
    ++counters.empty;
    return;
  }
  ++counters.layered;
  counters.breakpoint_cells += holds_breakpoint(tf_, p.smin, p.smax);
  box.j0 = std::max(box.j0, rows.begin), box.j1 = std::min(box.j1, rows.end - 1);  // the tile's rows of it
  if (box.empty()) return;
  const bool persp = rays_.perspective();
  const ExactShade exact = exact_shade(tf_, rays_, method_.cuts_at_breakpoints, p.smin, p.smax);
  const int bw = box.i1 - box.i0 + 1;
  // The back layer: 1/z and s/z (depth and scalar in orthographic projection) where the ray leaves,
  // NaN where no back triangle covers the centre.
  p.back.assign(2 * static_cast<std::size_t>(bw) * static_cast<std::size_t>(box.j1 - box.j0 + 1),
                std::numeric_limits<double>::quiet_NaN());
  // Calls at(i, j, depth, scalar) for every pixel centre triangle t covers, its two quantities
  // stepped along each run from the run's first pixel (as project_with's runs).
  double qv[8][2];  // per vertex, once: every face triangle interpolates these
  for (int k = 0; k < n; ++k) affine_depth_scalar(v[k], persp, qv[k][0], qv[k][1]);
  const auto rasterize = [&](const std::array<std::uint8_t, 3>& t, auto&& at) {
    const double q[3][2] = {{qv[t[0]][0], qv[t[0]][1]}, {qv[t[1]][0], qv[t[1]][1]}, {qv[t[2]][0], qv[t[2]][1]}};
    const auto mix = [&q](const double* w, int m) { return w[0] * q[0][m] + w[1] * q[1][m] + w[2] * q[2][m]; };
    double dq[2];
    rasterize_triangle_spans(
        glm::dvec2(v[t[0]].x, v[t[0]].y), glm::dvec2(v[t[1]].x, v[t[1]].y), glm::dvec2(v[t[2]].x, v[t[2]].y), width,
        height, box.j0, box.j1 + 1, [&](const double* dw) { dq[0] = mix(dw, 0), dq[1] = mix(dw, 1); },
        [&](int j, int b, int e, const double* w) {
          const double q0 = mix(w, 0), q1 = mix(w, 1);
          for (int i = b; i < e; ++i) at(i, j, q0 + (i - b) * dq[0], q1 + (i - b) * dq[1]);
        });
  };
  const auto back_at = [&](int i, int j) {
    return &p.back[2 * (static_cast<std::size_t>(j - box.j0) * bw + (i - box.i0))];
  };
  for (int t = 0; t < faces.n_back; ++t)
    rasterize(faces.back[t], [&](int i, int j, double depth, double scalar) {
      double* b = back_at(i, j);
      b[0] = depth, b[1] = scalar;
    });
  // The front layer: the back triangles tile the same image with the same coverage rule (a
  // silhouette edge is one front and one back triangle's, traversed alike once each is turned
  // positive), so each centre a front triangle covers has its back; one that has none (a sliver's
  // rounding) adds nothing.
  const auto draw_front = [&](auto& fragments) {
    for (int t = 0; t < faces.n_front; ++t)
      rasterize(faces.front[t], [&](int i, int j, double depth, double scalar) {
        const double* b = back_at(i, j);
        if (std::isnan(b[0])) {
          ++counters.unmatched;
          return;
        }
        fragments(i, j, depth, b[0], scalar, b[1]);
      });
    counters.fragments += fragments.finish();
  };
  if (method_.gouraud) {
    ThickPixelFragments<Emit> fragments{exact, table_, emit};
    return draw_front(fragments);
  }
  ExactFragments<Emit> fragments(exact, emit, p.segments);
  draw_front(fragments);
}

}  // namespace cellproj
