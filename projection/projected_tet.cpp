#include "projection/projected_tet.hpp"

#include <algorithm>
#include <utility>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace cellproj {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

int exact_orientation(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
  return static_cast<int>(
      CGAL::orientation(Kernel::Point_2(a.x, a.y), Kernel::Point_2(b.x, b.y), Kernel::Point_2(c.x, c.y)));
}

void interpolate(const ScreenVertex* v, const int* ids, const double* w, int n, bool perspective, double& z,
                 double& s) {
  double sz = 0, ss = 0;
  if (!perspective) {
    for (int k = 0; k < n; ++k) sz += w[k] * v[ids[k]].z, ss += w[k] * v[ids[k]].s;
    z = sz, s = ss;
    return;
  }
  for (int k = 0; k < n; ++k) {
    const double q = w[k] / v[ids[k]].z;
    sz += q, ss += q * v[ids[k]].s;
  }
  z = 1.0 / sz, s = ss / sz;
}

namespace {

void set_ends(ThickVertex& t, double za, double sa, double zb, double sb) {
  if (za <= zb)
    t.zf = za, t.sf = sa, t.zb = zb, t.sb = sb;
  else
    t.zf = zb, t.sf = sb, t.zb = za, t.sb = sa;
}

}  // namespace

ProjectedTet project_tet(const ScreenVertex v[4], bool perspective) {
  ProjectedTet out;
  project_tet(v, perspective, out);
  return out;
}

void project_tet(const ScreenVertex v[4], bool perspective, ProjectedTet& out) {
  // sigma_i = (-1)^i * orient(the other three, in order): sum_i sigma_i (p_i, 1) = 0, so the
  // signs tell which vertex lies inside the others' triangle, or which two edges cross.
  static constexpr int kOthers[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  int sign[4];
  double sigma[4];
  int pos = 0, neg = 0;
  for (int i = 0; i < 4; ++i) {
    const auto& o = kOthers[i];
    const int parity = i % 2 ? -1 : 1;
    double area;
    sign[i] = parity * turn_sign(v[o[0]], v[o[1]], v[o[2]], area);
    sigma[i] = parity * area;
    pos += sign[i] > 0, neg += sign[i] < 0;
  }
  out.hull_size = 0, out.edge_on = pos + neg < 4;
  if (pos == 1 || neg == 1) {  // class 1: the lone-signed vertex projects inside the others' triangle
    const int lone_sign = pos == 1 ? 1 : -1;
    int t = 0;
    while (sign[t] != lone_sign) ++t;
    const auto& o = kOthers[t];
    double w[3], sum = 0;
    for (int k = 0; k < 3; ++k) {  // weights -sigma_j / sigma_t, kept >= 0 where the exact sign says so
      w[k] = sign[o[k]] == -lone_sign ? std::max(0.0, -sigma[o[k]] / sigma[t]) : 0.0;
      sum += w[k];
    }
    if (!(sum > 0)) return;
    for (double& x : w) x /= sum;
    double z, s;
    interpolate(v, o, w, 3, perspective, z, s);
    out.thick.x = v[t].x, out.thick.y = v[t].y;
    set_ends(out.thick, v[t].z, v[t].s, z, s);
    out.hull_size = 3;
    for (int k = 0; k < 3; ++k) out.hull[k] = corner(v[o[k]]), out.hull_vertex[k] = o[k];
    return;
  }
  if (pos != 2 || neg != 2) return;  // every face edge-on: zero area
  // class 2: the edge joining the two positive vertices crosses the edge joining the negative ones
  int a = -1, c = -1, b = -1, d = -1;
  for (int i = 0; i < 4; ++i) {
    if (sign[i] > 0)
      (a < 0 ? a : c) = i;
    else
      (b < 0 ? b : d) = i;
  }
  const auto weights = [&](int i, int j, double w[2]) {
    const double si = std::max(0.0, sign[i] * sigma[i]), sj = std::max(0.0, sign[j] * sigma[j]);
    const double sum = si + sj;
    w[0] = sum > 0 ? si / sum : 0.5, w[1] = sum > 0 ? sj / sum : 0.5;
  };
  double wac[2], wbd[2];
  weights(a, c, wac);
  weights(b, d, wbd);
  const int ac[2] = {a, c}, bd[2] = {b, d};
  double z1, s1, z2, s2;
  interpolate(v, ac, wac, 2, perspective, z1, s1);
  interpolate(v, bd, wbd, 2, perspective, z2, s2);
  out.thick.x = wac[0] * v[a].x + wac[1] * v[c].x;
  out.thick.y = wac[0] * v[a].y + wac[1] * v[c].y;
  set_ends(out.thick, z1, s1, z2, s2);
  out.hull_size = 4;
  const int around[4] = {a, b, c, d};
  for (int k = 0; k < 4; ++k) out.hull[k] = corner(v[around[k]]), out.hull_vertex[k] = around[k];
}

}  // namespace cellproj
