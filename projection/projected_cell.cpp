#include "projection/projected_cell.hpp"

#include <algorithm>
#include <cmath>

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
void on_triangle(const ScreenVertex* v, const FaceTriangle& t, double x, double y, bool persp, double& z, double& s) {
  const ScreenVertex& a = v[t.v[0]];
  const ScreenVertex& b = v[t.v[1]];
  const ScreenVertex& c = v[t.v[2]];
  const double area = area2(a, b, c);
  const ScreenVertex p{x, y, 0, 0};
  double w[3] = {area2(p, b, c) / area, area2(a, p, c) / area, 0};
  w[2] = 1.0 - w[0] - w[1];
  interpolate(v, t.v, w, 3, persp, z, s);
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

// The polygon front ∩ back: the vertices of each inside the other and the proper crossings of
// their edges. Returns the number of corners (fewer than 3: empty).
int overlay(const ScreenVertex* v, const Orientations& orient, const FaceTriangle& F, int fturn, const FaceTriangle& B,
            int bturn, bool persp, Corner out[12]) {
  int n = 0;
  for (int k = 0; k < 3; ++k) {  // front vertices inside the back triangle
    const int p = F.v[k];
    if (!has_vertex(B, p) && !inside(orient, B, bturn, p)) continue;
    Corner& c = out[n++];
    c.x = v[p].x, c.y = v[p].y, c.zf = v[p].z, c.sf = v[p].s;
    if (has_vertex(B, p)) c.zb = v[p].z, c.sb = v[p].s;
    else on_triangle(v, B, c.x, c.y, persp, c.zb, c.sb);
  }
  for (int k = 0; k < 3; ++k) {  // back vertices inside the front triangle (shared ones are in)
    const int p = B.v[k];
    if (has_vertex(F, p) || !inside(orient, F, fturn, p)) continue;
    Corner& c = out[n++];
    c.x = v[p].x, c.y = v[p].y, c.zb = v[p].z, c.sb = v[p].s;
    on_triangle(v, F, c.x, c.y, persp, c.zf, c.sf);
  }
  for (int i = 0; i < 3; ++i)  // proper crossings of a front edge with a back edge
    for (int j = 0; j < 3; ++j) {
      int p = F.v[i], q = F.v[(i + 1) % 3], r = B.v[j], t = B.v[(j + 1) % 3];
      if (p == r || p == t || q == r || q == t) continue;
      const int o1 = orient(r, t, p), o2 = orient(r, t, q);
      if (o1 == 0 || o2 == 0 || o1 == o2) continue;
      const int o3 = orient(p, q, r), o4 = orient(p, q, t);
      if (o3 == 0 || o4 == 0 || o3 == o4) continue;
      // The same two edges cross at the same bits in every polygon they bound: endpoints in a
      // canonical order before the arithmetic.
      const bool fswap = p > q, bswap = r > t;
      if (fswap) std::swap(p, q);
      if (bswap) std::swap(r, t);
      const double dp = area2(v[r], v[t], v[p]), dq = area2(v[r], v[t], v[q]);
      const double u = dp / (dp - dq);  // along p -> q
      const double dr = area2(v[p], v[q], v[r]), dt = area2(v[p], v[q], v[t]);
      const double w = dr / (dr - dt);  // along r -> t
      Corner& c = out[n++];
      c.x = v[p].x + u * (v[q].x - v[p].x), c.y = v[p].y + u * (v[q].y - v[p].y);
      on_edge(v[p], v[q], u, persp, c.zf, c.sf);
      on_edge(v[r], v[t], w, persp, c.zb, c.sb);
    }
  return n;
}

}  // namespace

CellProjection project_cell(const ScreenVertex* v, const std::int64_t* ids, CellType type, bool perspective,
                            int front_sign, std::vector<ProjectedTriangle>& out) {
  const CellDef& def = cell_def(type);
  const Orientations orient(v, def.vertices);
  FaceTriangle front[kMaxTriangles], back[kMaxTriangles];
  CellProjection r;
  auto add = [&](int a, int b, int c) {
    const int turn = orient(a, b, c);
    if (turn == 0) return;  // edge-on: covers no pixel
    FaceTriangle t{{a, b, c}, std::min({v[a].x, v[b].x, v[c].x}), std::max({v[a].x, v[b].x, v[c].x}),
                   std::min({v[a].y, v[b].y, v[c].y}), std::max({v[a].y, v[b].y, v[c].y})};
    if (turn == front_sign) front[r.front++] = t;
    else back[r.back++] = t;
  };
  for (int f = 0; f < def.faces; ++f) {
    const FaceDef& face = def.face[f];
    if (face.size == 3) {
      add(face.v[0], face.v[1], face.v[2]);
      continue;
    }
    int k = 0;  // the diagonal from the lowest id (grid/tetrahedralize's split_quad)
    for (int m = 1; m < 4; ++m)
      if (ids[face.v[m]] < ids[face.v[k]]) k = m;
    const int a = face.v[k], b = face.v[(k + 1) % 4], c = face.v[(k + 2) % 4], d = face.v[(k + 3) % 4];
    add(a, b, c);
    add(a, c, d);
  }
  Corner poly[12];
  for (int i = 0; i < r.front; ++i)
    for (int j = 0; j < r.back; ++j) {
      const FaceTriangle& F = front[i];
      const FaceTriangle& B = back[j];
      if (F.x1 < B.x0 || B.x1 < F.x0 || F.y1 < B.y0 || B.y1 < F.y0) continue;
      const int n = overlay(v, orient, F, front_sign, B, -front_sign, perspective, poly);
      if (n < 3) continue;
      // A convex polygon: its corners in angular order about their mean.
      double cx = 0, cy = 0;
      for (int k = 0; k < n; ++k) cx += poly[k].x / n, cy += poly[k].y / n;
      double angle[12];
      int order[12];
      for (int k = 0; k < n; ++k) angle[k] = pseudo_angle(poly[k].x - cx, poly[k].y - cy), order[k] = k;
      std::sort(order, order + n, [&](int a, int b) { return angle[a] < angle[b]; });
      ++r.polygons;
      auto thick = [&](const Corner& c) {
        ThickVertex t{c.x, c.y, c.zf, c.zb, c.sf, c.sb};
        if (t.zb < t.zf) t.zb = t.zf;  // rounding at a silhouette corner
        return t;
      };
      for (int k = 1; k + 1 < n; ++k)
        out.push_back({{thick(poly[order[0]]), thick(poly[order[k]]), thick(poly[order[k + 1]])}});
    }
  return r;
}

}  // namespace cellproj
