#include "mesh/clip.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "mesh/geometry.hpp"
#include "mesh/tetrahedralize.hpp"

namespace cellproj {
namespace {

// Per point of a mesh being clipped, the original points it is made of, with their weights.
using Sources = std::vector<std::vector<std::pair<std::int64_t, double>>>;

// One plane's pass: `in` clipped into `out` (which starts with in's points and fields). `sources`,
// when given, grows with out's new points.
class PlaneClipper {
 public:
  PlaneClipper(const Mesh& in, const ClipPlane& plane, Mesh& out, ClipReport& report, Sources* sources)
      : view_(in.view()), out_(out), report_(report), sources_(sources) {
    out_.points = in.points;
    out_.fields = in.fields;
    const glm::dvec3 n = glm::normalize(plane.normal);
    double size = 0.0;
    distance_.resize(static_cast<std::size_t>(in.n_points()));
    for (std::int64_t p = 0; p < in.n_points(); ++p) {
      distance_[p] = glm::dot(n, view_.point(p) - plane.point);
      size = std::max(size, std::abs(distance_[p]));
    }
    for (double& d : distance_)  // a point within rounding of the plane is on it, and kept
      if (std::abs(d) <= 1e-12 * size) d = 0.0;
  }

  void cell(std::int64_t c) {
    const MeshView& v = view_;
    const std::int64_t* ids = v.cell(c);
    int inside = 0, strictly = 0;
    for (int k = 0; k < v.cell_size(c); ++k) inside += kept(ids[k]), strictly += distance_[ids[k]] < 0.0;
    if (inside == v.cell_size(c)) {
      out_.add_cell(v.type(c), ids);
      ++report_.kept_whole;
      return;
    }
    if (strictly == 0) {  // at most a face or an edge on the plane: nothing of its volume is kept
      ++report_.dropped;
      return;
    }
    ++report_.cut;
    Tet tets[kMaxTetsPerCell];
    const int n = canonical_tetrahedra(v, c, tets);
    for (int t = 0; t < n; ++t) tet(tets[t]);
  }

 private:
  bool kept(std::int64_t p) const { return distance_[p] <= 0.0; }

  // The point where the plane cuts edge (a kept, b not), made once per edge and shared by the cells around it.
  std::int64_t cut(std::int64_t a, std::int64_t b) {
    if (distance_[a] == 0.0) return a;
    const auto key = std::minmax(a, b);
    if (const auto it = edge_point_.find(key); it != edge_point_.end()) return it->second;
    const double t = distance_[a] / (distance_[a] - distance_[b]);  // in [0, 1): d(a) < 0 < d(b)
    const std::int64_t p = out_.add_point(view_.point(a) + t * (view_.point(b) - view_.point(a)));
    for (PointField& f : out_.fields)
      for (int k = 0; k < f.components; ++k) {
        const double va = f.values[a * f.components + k], vb = f.values[b * f.components + k];
        f.values.push_back(va + t * (vb - va));
      }
    if (sources_) {  // (1 - t) a + t b, over the original points
      auto mix = (*sources_)[a];
      for (auto& [q, w] : mix) w *= 1.0 - t;
      for (const auto& [q, w] : (*sources_)[b]) {
        const auto same = std::find_if(mix.begin(), mix.end(), [q = q](const auto& e) { return e.first == q; });
        if (same != mix.end())
          same->second += t * w;
        else
          mix.emplace_back(q, t * w);
      }
      sources_->push_back(std::move(mix));
    }
    edge_point_.emplace(key, p);
    return p;
  }

  // The kept part of one tetrahedron: itself, a smaller tetrahedron, or a wedge split canonically.
  void tet(const Tet& t) {
    std::int64_t in[4], out[4];
    int ni = 0, no = 0;
    for (std::int64_t p : t) (kept(p) ? in[ni++] : out[no++]) = p;
    if (no == 0) return emit(t);
    if (ni == 0) return;  // one of a cut cell's tetrahedra wholly on the other side
    if (ni == 1) return emit({in[0], cut(in[0], out[0]), cut(in[0], out[1]), cut(in[0], out[2])});
    if (ni == 3)  // the wedge between the kept face and its cut across the edges to the cut vertex
      return wedge({in[0], in[1], in[2], cut(in[0], out[0]), cut(in[1], out[0]), cut(in[2], out[0])});
    // ni == 2: the wedge between the kept edge's two cut triangles
    wedge({in[0], cut(in[0], out[0]), cut(in[0], out[1]), in[1], cut(in[1], out[0]), cut(in[1], out[1])});
  }

  void wedge(const std::array<std::int64_t, 6>& w) {
    MeshView one = out_.view();
    const std::int64_t offsets[2] = {0, 6};
    const std::uint8_t type = static_cast<std::uint8_t>(CellType::Wedge);
    one.connectivity = w.data(), one.offsets = offsets, one.types = &type, one.n_cells = 1;
    Tet tets[kMaxTetsPerCell];
    const int n = canonical_tetrahedra(one, 0, tets);
    for (int k = 0; k < n; ++k) emit(tets[k]);
  }

  // A positively oriented tetrahedron, unless it has no volume (a cut through a vertex or an edge).
  void emit(Tet t) {
    const MeshView v = out_.view();
    const glm::dvec3 a = v.point(t[0]), b = v.point(t[1]), c = v.point(t[2]), d = v.point(t[3]);
    const double v6 = tet_volume6(a, b, c, d);
    const double size = std::max({glm::length(b - a), glm::length(c - a), glm::length(d - a)});
    if (degenerate_volume(v6, size)) return;
    if (v6 < 0) std::swap(t[1], t[2]);
    out_.add_cell(CellType::Tetra, t.data());
    ++report_.tetrahedra;
  }

  const MeshView view_;
  Mesh& out_;
  ClipReport& report_;
  Sources* sources_;
  std::vector<double> distance_;
  std::map<std::pair<std::int64_t, std::int64_t>, std::int64_t> edge_point_;
};

// The mesh without the points no cell uses; `sources` (when given) as `weights`, in the same order.
Mesh compact(Mesh m, const Sources* sources, ClipWeights* weights) {
  std::vector<std::int64_t> index(static_cast<std::size_t>(m.n_points()), -1);
  for (std::int64_t p : m.connectivity) index[p] = 0;
  std::int64_t next = 0;
  for (auto& i : index)
    if (i == 0) i = next++;
  Mesh out;
  out.source = m.source;
  out.notes = m.notes;
  std::vector<std::int64_t> used;  // the points kept, in order
  used.reserve(static_cast<std::size_t>(next));
  for (std::int64_t p = 0; p < m.n_points(); ++p)
    if (index[p] >= 0) used.push_back(p);
  out.points.reserve(static_cast<std::size_t>(3 * next));
  for (std::int64_t p : used)
    out.points.insert(out.points.end(), m.points.begin() + 3 * p, m.points.begin() + 3 * p + 3);
  for (const PointField& f : m.fields) out.fields.push_back(gather(f, used));
  if (sources && weights) {
    *weights = ClipWeights{};
    for (std::int64_t p = 0; p < m.n_points(); ++p)
      if (index[p] >= 0) {
        for (const auto& [q, w] : (*sources)[p]) weights->source.push_back(q), weights->weight.push_back(w);
        weights->start.push_back(static_cast<std::int64_t>(weights->source.size()));
      }
  }
  out.offsets = std::move(m.offsets);
  out.types = std::move(m.types);
  out.connectivity = std::move(m.connectivity);
  for (auto& p : out.connectivity) p = index[p];
  return out;
}

}  // namespace

void check(const ClipPlane& p) {
  const double n = glm::length(p.normal);
  if (!std::isfinite(glm::length(p.point)) || !std::isfinite(n) || !(n > 0))
    throw InputError("setting 'clip': the plane needs a finite point and a non-zero finite normal");
}

std::vector<double> ClipWeights::apply(const std::vector<double>& field) const {
  std::vector<double> out(static_cast<std::size_t>(size()));
  for (std::int64_t p = 0; p < size(); ++p) {
    double v = 0.0;
    for (std::int64_t k = start[p]; k < start[p + 1]; ++k) v += weight[k] * field[source[k]];
    out[p] = v;
  }
  return out;
}

Mesh clip_mesh(const Mesh& mesh, const std::vector<ClipPlane>& planes, ClipReport* report, ClipWeights* weights) {
  ClipReport r;
  Mesh current = mesh;
  Sources sources;
  if (weights)
    for (std::int64_t p = 0; p < mesh.n_points(); ++p) sources.push_back({{p, 1.0}});
  for (const ClipPlane& plane : planes) {
    check(plane);
    ClipReport pass;
    Mesh next;
    next.source = mesh.source;
    next.notes = current.notes;
    PlaneClipper clipper(current, plane, next, pass, weights ? &sources : nullptr);
    for (std::int64_t c = 0; c < current.n_cells(); ++c) clipper.cell(c);
    r.dropped += pass.dropped;
    r.cut += pass.cut;
    r.tetrahedra += pass.tetrahedra;
    r.kept_whole = pass.kept_whole;  // of the last pass: whole through every plane
    current = std::move(next);
  }
  if (planes.empty()) r.kept_whole = mesh.n_cells();
  if (report) *report = r;
  return compact(std::move(current), weights ? &sources : nullptr, weights);
}

Mesh clip_mesh_kept(const Mesh& mesh, const std::vector<ClipPlane>& planes, const std::string& source,
                    ClipReport* report) {
  Mesh kept = clip_mesh(mesh, planes, report);
  if (kept.n_cells() == 0)
    throw InputError(where(source,
                           "nothing of the mesh is on the kept side of the clipping planes (each keeps the "
                           "side its normal points away from)"));
  return kept;
}

}  // namespace cellproj
