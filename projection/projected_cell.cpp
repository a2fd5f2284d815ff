#include "projection/projected_cell.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace cellproj {
namespace {

constexpr int kMaxTriangles = 12;  // a hexahedron: 6 quads, 2 triangles each

// A face triangle in the cell's local vertex numbers, turning outward.
struct FaceTriangle {
  int v[3];
  double x0, x1, y0, y1;  // image bounding box
};

// The exact orientation of every triple of the cell's projected vertices (C(8,3) = 56 for a
// hexahedron), computed once: every decision of the subdivision is a lookup, and all of them agree.
class Orientations {
 public:
  Orientations(const ScreenVertex* v, int n) {
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        for (int c = b + 1; c < n; ++c) {
          const std::int8_t o = static_cast<std::int8_t>(exact_sign(v[a], v[b], v[c]));
          s_[a][b][c] = s_[b][c][a] = s_[c][a][b] = o;
          s_[b][a][c] = s_[a][c][b] = s_[c][b][a] = static_cast<std::int8_t>(-o);
        }
  }
  int operator()(int a, int b, int c) const { return s_[a][b][c]; }

 private:
  std::int8_t s_[8][8][8] = {};  // 0 where an index repeats
};

// A corner of a front ∩ back polygon, with the ends of the ray segment through it.
struct Corner {
  double x, y, zf, sf, zb, sb;
};

// Depth and scalar along edge (a, b) at parameter t (image-linear: through 1/z in perspective).
void on_edge(const ScreenVertex& a, const ScreenVertex& b, double t, bool persp, double& z, double& s) {
  if (!persp) {
    z = a.z + t * (b.z - a.z), s = a.s + t * (b.s - a.s);
    return;
  }
  const double qa = (1 - t) / a.z, qb = t / b.z, inv = 1.0 / (qa + qb);
  z = inv, s = (qa * a.s + qb * b.s) * inv;
}

// Depth and scalar at image point (x, y) on the plane of triangle t (barycentric weights).
void on_triangle(const ScreenVertex* v, const int t[3], double x, double y, bool persp, double& z, double& s) {
  const ScreenVertex& a = v[t[0]];
  const ScreenVertex& b = v[t[1]];
  const ScreenVertex& c = v[t[2]];
  const double area = area2(a, b, c);
  const ScreenVertex p{x, y, 0, 0};
  double w[3] = {area2(p, b, c) / area, area2(a, p, c) / area, 0};
  w[2] = 1.0 - w[0] - w[1];
  interpolate(v, t, w, 3, persp, z, s);
}

// A number increasing with the angle of (dx, dy) over [0, 4): ordering without atan2.
inline double pseudo_angle(double dx, double dy) {
  const double a = std::abs(dx) + std::abs(dy);
  if (!(a > 0)) return 0.0;
  const double p = dy / a;  // in [-1, 1]
  return dx >= 0 ? (p >= 0 ? p : 4 + p) : 2 - p;
}

bool has_vertex(const FaceTriangle& t, int k) { return t.v[0] == k || t.v[1] == k || t.v[2] == k; }

// Point k inside or on triangle t (turning with sign `turn`), by exact orientations.
bool inside(const Orientations& orient, const FaceTriangle& t, int turn, int k) {
  for (int e = 0; e < 3; ++e)
    if (orient(t.v[e], t.v[(e + 1) % 3], k) == -turn) return false;
  return true;
}

// The corners of front ∩ back as recipes: the vertices of each inside the other and the proper
// crossings of their edges, by exact orientations only. Returns how many (fewer than 3: empty).
int overlay(const Orientations& orient, const FaceTriangle& F, int fturn, const FaceTriangle& B, int bturn,
            CornerRecipe out[12]) {
  int n = 0;
  auto set = [](CornerRecipe& c, std::uint8_t kind, int a, int b, int x, int y, int z) {
    c.kind = kind, c.v[0] = static_cast<std::uint8_t>(a), c.v[1] = static_cast<std::uint8_t>(b);
    c.v[2] = static_cast<std::uint8_t>(x), c.v[3] = static_cast<std::uint8_t>(y), c.v[4] = static_cast<std::uint8_t>(z);
  };
  for (int k = 0; k < 3; ++k) {  // front vertices inside the back triangle (or shared with it)
    const int p = F.v[k];
    if (has_vertex(B, p))
      set(out[n++], CornerRecipe::shared, p, 0, 0, 0, 0);
    else if (inside(orient, B, bturn, p))
      set(out[n++], CornerRecipe::front_vertex, p, 0, B.v[0], B.v[1], B.v[2]);
  }
  for (int k = 0; k < 3; ++k) {  // back vertices inside the front triangle
    const int p = B.v[k];
    if (!has_vertex(F, p) && inside(orient, F, fturn, p))
      set(out[n++], CornerRecipe::back_vertex, p, 0, F.v[0], F.v[1], F.v[2]);
  }
  for (int i = 0; i < 3; ++i)  // proper crossings of a front edge with a back edge
    for (int j = 0; j < 3; ++j) {
      int p = F.v[i], q = F.v[(i + 1) % 3], r = B.v[j], t = B.v[(j + 1) % 3];
      if (p == r || p == t || q == r || q == t) continue;
      const int o1 = orient(r, t, p), o2 = orient(r, t, q);
      if (o1 == 0 || o2 == 0 || o1 == o2) continue;
      const int o3 = orient(p, q, r), o4 = orient(p, q, t);
      if (o3 == 0 || o4 == 0 || o3 == o4) continue;
      // Endpoints in a canonical order, so the same two edges cross at the same bits in every
      // polygon (and every cell) they bound.
      set(out[n++], CornerRecipe::crossing, std::min(p, q), std::max(p, q), std::min(r, t), std::max(r, t), 0);
    }
  return n;
}

Corner make_corner(const ScreenVertex* v, const CornerRecipe& r, bool persp) {
  Corner c;
  const int a = r.v[0];
  const int tri[3] = {r.v[2], r.v[3], r.v[4]};
  switch (r.kind) {
    case CornerRecipe::shared: c = {v[a].x, v[a].y, v[a].z, v[a].s, v[a].z, v[a].s}; break;
    case CornerRecipe::front_vertex:
      c.x = v[a].x, c.y = v[a].y, c.zf = v[a].z, c.sf = v[a].s;
      on_triangle(v, tri, c.x, c.y, persp, c.zb, c.sb);
      break;
    case CornerRecipe::back_vertex:
      c.x = v[a].x, c.y = v[a].y, c.zb = v[a].z, c.sb = v[a].s;
      on_triangle(v, tri, c.x, c.y, persp, c.zf, c.sf);
      break;
    default: {  // crossing of front edge (p, q) and back edge (r, t)
      const int p = a, q = r.v[1], s = r.v[2], t = r.v[3];
      const double dp = area2(v[s], v[t], v[p]), dq = area2(v[s], v[t], v[q]);
      const double u = dp / (dp - dq);  // along p -> q
      const double dr = area2(v[p], v[q], v[s]), dt = area2(v[p], v[q], v[t]);
      const double w = dr / (dr - dt);  // along s -> t
      c.x = v[p].x + u * (v[q].x - v[p].x), c.y = v[p].y + u * (v[q].y - v[p].y);
      on_edge(v[p], v[q], u, persp, c.zf, c.sf);
      on_edge(v[s], v[t], w, persp, c.zb, c.sb);
    }
  }
  return c;
}

// Whether corners c[0..n) turn strictly counter-clockwise with a margin far above rounding: then
// their order is the polygon's combinatorial order, the same for every cell of this topology.
// Slivers (nearly collinear or coincident corners) fail, and always take the general path.
bool convex_with_margin(const Corner* c, int n) {
  double scale = 0;
  for (int k = 1; k < n; ++k) scale = std::max(scale, std::abs(c[k].x - c[0].x) + std::abs(c[k].y - c[0].y));
  const double margin = 1e-9 * scale * scale;
  for (int k = 0; k < n; ++k) {
    const Corner& a = c[k];
    const Corner& b = c[(k + 1) % n];
    const Corner& d = c[(k + 2) % n];
    if (!((b.x - a.x) * (d.y - b.y) - (b.y - a.y) * (d.x - b.x) > margin)) return false;
  }
  return true;
}

// Puts a convex polygon's corners in counter-clockwise angular order, starting from the corner
// whose recipe compares lowest, so that every cell with this subdivision fans it alike. Returns
// whether that order can be trusted for other cells (convex_with_margin).
bool order_corners(const ScreenVertex* v, bool persp, CornerRecipe* r, int n) {
  Corner c[12];
  double cx = 0, cy = 0;
  for (int k = 0; k < n; ++k) c[k] = make_corner(v, r[k], persp), cx += c[k].x / n, cy += c[k].y / n;
  double angle[12];
  int order[12];
  for (int k = 0; k < n; ++k) angle[k] = pseudo_angle(c[k].x - cx, c[k].y - cy), order[k] = k;
  std::sort(order, order + n, [&](int a, int b) { return angle[a] < angle[b]; });
  int first = 0;
  for (int k = 1; k < n; ++k)
    if (std::memcmp(&r[order[k]], &r[order[first]], sizeof(CornerRecipe)) < 0) first = k;
  CornerRecipe sorted[12];
  Corner at[12];
  for (int k = 0; k < n; ++k) sorted[k] = r[order[(first + k) % n]], at[k] = c[order[(first + k) % n]];
  std::copy(sorted, sorted + n, r);
  return convex_with_margin(at, n);
}

// The cell's triangles, their facing, and the key of its subdivision: the cell type, which
// diagonal each quad takes, and the exact orientation of every triple of projected vertices.
struct CellFaces {
  FaceTriangle front[kMaxTriangles], back[kMaxTriangles];
  int n_front = 0, n_back = 0;
  SubdivisionKey key{};
};

// Calls add(a, b, c) for each triangle of the cell's faces, in local vertex numbers, turning
// outward: a quad splits along the diagonal from its lowest id (mesh/tetrahedralize's split_quad).
// Returns the diagonals taken, 2 bits per face.
template <class Add>
std::uint64_t split_faces(const CellDef& def, const std::int64_t* ids, Add&& add) {
  std::uint64_t diagonals = 0;
  for (int f = 0; f < def.faces; ++f) {
    const FaceDef& face = def.face[f];
    if (face.size == 3) {
      add(face.v[0], face.v[1], face.v[2]);
      continue;
    }
    int k = 0;
    for (int m = 1; m < 4; ++m)
      if (ids[face.v[m]] < ids[face.v[k]]) k = m;
    diagonals |= static_cast<std::uint64_t>(k) << (2 * f);
    const int a = face.v[k], b = face.v[(k + 1) % 4], c = face.v[(k + 2) % 4], d = face.v[(k + 3) % 4];
    add(a, b, c);
    add(a, c, d);
  }
  return diagonals;
}

CellFaces cell_faces(const ScreenVertex* v, const std::int64_t* ids, const CellDef& def, CellType type,
                     const Orientations& orient, int front_sign) {
  CellFaces cf;
  auto add = [&](int a, int b, int c) {
    const int turn = orient(a, b, c);
    if (turn == 0) return;  // edge-on: covers no pixel
    FaceTriangle t{{a, b, c},
                   std::min({v[a].x, v[b].x, v[c].x}),
                   std::max({v[a].x, v[b].x, v[c].x}),
                   std::min({v[a].y, v[b].y, v[c].y}),
                   std::max({v[a].y, v[b].y, v[c].y})};
    if (turn == front_sign)
      cf.front[cf.n_front++] = t;
    else
      cf.back[cf.n_back++] = t;
  };
  const std::uint64_t diagonals = split_faces(def, ids, add);
  cf.key[0] = static_cast<std::uint64_t>(type) | static_cast<std::uint64_t>(front_sign > 0) << 8 | diagonals << 16;
  int bit = 0;
  for (int a = 0; a < def.vertices; ++a)
    for (int b = a + 1; b < def.vertices; ++b)
      for (int c = b + 1; c < def.vertices; ++c, bit += 2)
        cf.key[1 + bit / 64] |= static_cast<std::uint64_t>(orient(a, b, c) & 3) << (bit % 64);
  return cf;
}

// The general path: every (front, back) pair through the exact overlay.
// Returns whether every polygon's order is robust (convex_with_margin): only then is it learnt.
bool build_subdivision(const ScreenVertex* v, const CellFaces& cf, int front_sign, bool persp, SubdivisionRecipe& out,
                       const Orientations& orient) {
  out.polygons.clear();
  bool cacheable = true;
  PolygonRecipe poly;
  for (int i = 0; i < cf.n_front; ++i)
    for (int j = 0; j < cf.n_back; ++j) {
      const FaceTriangle& F = cf.front[i];
      const FaceTriangle& B = cf.back[j];
      if (F.x1 < B.x0 || B.x1 < F.x0 || F.y1 < B.y0 || B.y1 < F.y0) continue;
      const int n = overlay(orient, F, front_sign, B, -front_sign, poly.corner);
      if (n < 3) continue;
      poly.n = static_cast<std::uint8_t>(n);
      cacheable = order_corners(v, persp, poly.corner, n) && cacheable;
      out.polygons.push_back(poly);
    }
  return cacheable;
}

// Appends the recipe's polygons, each fanned from its first corner, and returns how many. With
// `check`, a polygon that is not robustly convex here undoes the whole cell and returns -1.
int fan_recipe(const ScreenVertex* v, const SubdivisionRecipe& recipe, bool persp, bool check,
               std::vector<ProjectedTriangle>& out) {
  auto thick = [](const Corner& k) {
    ThickVertex t{k.x, k.y, k.zf, k.zb, k.sf, k.sb};
    if (t.zb < t.zf) t.zb = t.zf;  // rounding at a silhouette corner
    return t;
  };
  const std::size_t start = out.size();
  for (const PolygonRecipe& p : recipe.polygons) {
    Corner c[12];
    for (int k = 0; k < p.n; ++k) c[k] = make_corner(v, p.corner[k], persp);
    if (check && !convex_with_margin(c, p.n)) {
      out.resize(start);
      return -1;
    }
    for (int k = 1; k + 1 < p.n; ++k) out.push_back({{thick(c[0]), thick(c[k]), thick(c[k + 1])}});
  }
  return static_cast<int>(recipe.polygons.size());
}

}  // namespace

std::size_t SubdivisionKeyHash::operator()(const SubdivisionKey& k) const {
  std::uint64_t h = k[0] * 0x9E3779B97F4A7C15ull;
  for (int i = 1; i < 3; ++i) h = (h ^ (h >> 31) ^ k[i]) * 0x9E3779B97F4A7C15ull;
  return static_cast<std::size_t>(h ^ (h >> 29));
}

FaceLayers face_layers(const ScreenVertex* v, const std::int64_t* ids, CellType type, int front_sign) {
  FaceLayers out;
  split_faces(cell_def(type), ids, [&](int a, int b, int c) {
    const int turn = exact_sign(v[a], v[b], v[c]);
    if (turn == 0) return;  // edge-on: covers no pixel
    auto& t = turn == front_sign ? out.front[out.n_front++] : out.back[out.n_back++];
    t = {static_cast<std::uint8_t>(a), static_cast<std::uint8_t>(b), static_cast<std::uint8_t>(c)};
  });
  return out;
}

CellProjection project_cell(const ScreenVertex* v, const std::int64_t* ids, CellType type, bool perspective,
                            int front_sign, std::vector<ProjectedTriangle>& out, SubdivisionCache* cache) {
  const CellDef& def = cell_def(type);
  const Orientations orient(v, def.vertices);
  const CellFaces cf = cell_faces(v, ids, def, type, orient, front_sign);
  CellProjection r;
  // The fast path: a known topology, taken when its corners here are as robustly convex as where
  // it was learnt (else this cell goes the general way, so the bits never depend on the cache).
  if (cache) {
    const auto it = cache->recipes.find(cf.key);
    if (it != cache->recipes.end() && (r.polygons = fan_recipe(v, it->second, perspective, true, out)) >= 0) {
      ++cache->hits;
      r.looked_up = true;
      return r;
    }
  }
  SubdivisionRecipe recipe;
  const bool robust = build_subdivision(v, cf, front_sign, perspective, recipe, orient);
  r.polygons = fan_recipe(v, recipe, perspective, false, out);
  if (cache) {
    ++cache->misses;
    if (robust) {
      if (cache->recipes.size() >= SubdivisionCache::kMaxRecipes) cache->recipes.clear();
      cache->recipes.emplace(cf.key, std::move(recipe));
    }
  }
  return r;
}

}  // namespace cellproj
