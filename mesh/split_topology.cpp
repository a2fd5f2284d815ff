#include "mesh/split_topology.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include "mesh/tetrahedralize.hpp"

namespace cellproj {
namespace {

using Key = FaceKey;

Key face_key(const MeshView& m, std::int64_t c, int local) {
  const FaceDef& f = cell_def(m.type(c)).face[local];
  std::int64_t ids[4];
  for (int k = 0; k < f.size; ++k) ids[k] = m.cell(c)[f.v[k]];
  return face_key_of(ids, f.size);
}

}  // namespace

FaceTopology split_topology(const MeshView& mesh, const FaceTopology& base, const SplitMesh& split) {
  const MeshView& s = split.view;
  const std::int64_t n = mesh.n_cells;
  // first[c]: the first cell of the split mesh that base cell c became; split: more than one, or
  // one tetrahedron for a cell that was not one.
  std::vector<std::int64_t> first(static_cast<std::size_t>(n) + 1, s.n_cells);
  for (std::int64_t sc = s.n_cells; sc-- > 0;) first[split.parent[sc]] = sc;
  auto is_split = [&](std::int64_t c) { return first[c + 1] - first[c] > 1 || s.type(first[c]) != mesh.type(c); };
  // A split cell with a non-manifold face or a repeated vertex (a collapsed cell) is matched the
  // general way.
  for (std::int64_t c = 0; c < n; ++c) {
    if (!is_split(c)) continue;
    for (std::int64_t cf = base.face_offsets[c]; cf < base.face_offsets[c + 1]; ++cf)
      if (base.neighbor[cf] == kNonManifold) return build_topology(s);
    const std::int64_t* ids = mesh.cell(c);
    for (int i = 0; i < mesh.cell_size(c); ++i)
      if (std::find(ids + i + 1, ids + mesh.cell_size(c), ids[i]) != ids + mesh.cell_size(c)) return build_topology(s);
  }

  FaceTopology t;
  t.face_offsets.resize(static_cast<std::size_t>(s.n_cells) + 1, 0);
  for (std::int64_t c = 0; c < s.n_cells; ++c) t.face_offsets[c + 1] = t.face_offsets[c] + cell_def(s.type(c)).faces;
  t.neighbor.assign(static_cast<std::size_t>(t.face_offsets.back()), kBoundary);
  auto scf = [&](std::int64_t base_cf) {  // an unsplit cell's face in the split mesh
    const std::int64_t c = base.cell_of(base_cf);
    return t.face_offsets[first[c]] + (base_cf - base.face_offsets[c]);
  };

  // Seams (matched by position) are matched again at the end, as build_topology does.
  std::vector<char> seam(base.seam.empty() ? 0 : base.neighbor.size(), 0);
  for (const std::int64_t cf : base.seam) seam[cf] = 1;
  auto on_seam = [&](std::int64_t base_cf) { return !seam.empty() && seam[base_cf]; };

  // Unsplit cells keep their neighbours (those across from split cells are set below).
  for (std::int64_t c = 0; c < n; ++c) {
    if (is_split(c)) continue;
    for (std::int64_t cf = base.face_offsets[c]; cf < base.face_offsets[c + 1]; ++cf) {
      if (on_seam(cf)) continue;
      const std::int64_t m = base.neighbor[cf];
      if (m >= 0 && !is_split(m))
        t.neighbor[t.face_offsets[first[c]] + (cf - base.face_offsets[c])] = first[m];
      else if (m == kNonManifold)
        t.neighbor[t.face_offsets[first[c]] + (cf - base.face_offsets[c])] = kNonManifold;
    }
  }
  // Quads matched to two triangles in the mesh itself stay so while the quad's cell is whole.
  for (const auto& [quad, t0, t1] : base.split_faces) {
    const std::int64_t qc = base.cell_of(quad);
    if (is_split(qc) || on_seam(quad)) continue;
    t.neighbor[scf(quad)] = kSplitFace;
    t.neighbor[scf(t0)] = t.neighbor[scf(t1)] = first[qc];
    t.split_faces.push_back({scf(quad), scf(t0), scf(t1)});
  }

  // Split cells: their tetrahedra's faces, matched among themselves and across each original face.
  struct TetFace {
    Key key;
    std::int64_t cell, cf;  // in the split mesh
  };
  auto faces_of = [&](std::int64_t c, std::vector<TetFace>& out) {
    out.clear();
    for (std::int64_t sc = first[c]; sc < first[c + 1]; ++sc)
      for (int f = 0; f < 4; ++f) out.push_back({face_key(s, sc, f), sc, t.face_offsets[sc] + f});
  };
  auto find = [](const std::vector<TetFace>& faces, const Key& k) -> const TetFace* {
    for (const TetFace& f : faces)
      if (f.key == k) return &f;
    return nullptr;
  };
  std::vector<TetFace> mine, theirs;
  for (std::int64_t c = 0; c < n; ++c) {
    if (!is_split(c)) continue;
    faces_of(c, mine);
    for (std::size_t i = 0; i < mine.size(); ++i)
      for (std::size_t j = i + 1; j < mine.size(); ++j)
        if (mine[i].key == mine[j].key) t.neighbor[mine[i].cf] = mine[j].cell, t.neighbor[mine[j].cf] = mine[i].cell;
    const CellDef& def = cell_def(mesh.type(c));
    for (int f = 0; f < def.faces; ++f) {
      const std::int64_t cf = base.face_offsets[c] + f, m = base.neighbor[cf];
      if (m == kBoundary || on_seam(cf)) continue;
      // The face's triangles (a quad split by the diagonal from its lowest id) and the faces of
      // c's tetrahedra on them.
      const int size = def.face[f].size, ntri = size == 4 ? 2 : 1;
      std::int64_t q[4], tri[2][3];
      for (int k = 0; k < size; ++k) q[k] = mesh.cell(c)[def.face[f].v[k]];
      if (size == 4)
        split_quad(q, tri);
      else
        std::copy(q, q + 3, tri[0]);
      const TetFace* on[2] = {find(mine, face_key_of(tri[0], 3)),
                              ntri == 2 ? find(mine, face_key_of(tri[1], 3)) : nullptr};
      if (!on[0] || (ntri == 2 && !on[1])) return build_topology(s);  // not a face of the tetrahedra
      if (m == kSplitFace) {  // the mesh's own triangles across this quad (of tetrahedra: never split)
        for (const auto& [quad, t0, t1] : base.split_faces) {
          if (quad != cf) continue;
          for (const std::int64_t tf : {t0, t1}) {
            const std::int64_t tc = base.cell_of(tf);
            const Key k = face_key(mesh, tc, static_cast<int>(tf - base.face_offsets[tc]));
            for (int h = 0; h < ntri; ++h)
              if (k == on[h]->key) t.neighbor[on[h]->cf] = first[tc], t.neighbor[scf(tf)] = on[h]->cell;
          }
        }
      } else if (is_split(m)) {  // the tetrahedra across share these triangles (each side sets its own)
        faces_of(m, theirs);
        for (int h = 0; h < ntri; ++h)
          if (const TetFace* o = find(theirs, on[h]->key)) t.neighbor[on[h]->cf] = o->cell;
      } else {  // a whole cell across: its face with the same ids
        const Key k = face_key_of(q, size);
        std::int64_t back = -1;
        for (std::int64_t g = base.face_offsets[m]; g < base.face_offsets[m + 1] && back < 0; ++g)
          if (base.neighbor[g] == c && face_key(mesh, m, static_cast<int>(g - base.face_offsets[m])) == k) back = g;
        if (back < 0) return build_topology(s);  // no face of m with these ids faces c
        for (int h = 0; h < ntri; ++h) t.neighbor[on[h]->cf] = first[m];
        if (size == 3) {
          t.neighbor[scf(back)] = on[0]->cell;
        } else {  // listed in the order of the whole cell's own split of the quad, as build_topology does
          const FaceDef& bf = cell_def(mesh.type(m)).face[back - base.face_offsets[m]];
          std::int64_t bq[4], bt[2][3];
          for (int k = 0; k < 4; ++k) bq[k] = mesh.cell(m)[bf.v[k]];
          split_quad(bq, bt);
          const bool same = face_key_of(bt[0], 3) == on[0]->key;
          t.neighbor[scf(back)] = kSplitFace;
          t.split_faces.push_back({scf(back), same ? on[0]->cf : on[1]->cf, same ? on[1]->cf : on[0]->cf});
        }
      }
    }
  }

  std::int64_t across = 0;
  for (std::int64_t f = 0; f < static_cast<std::int64_t>(t.neighbor.size()); ++f) {
    if (t.neighbor[f] == kBoundary) t.boundary.push_back(f);
    across += t.neighbor[f] >= 0;
  }
  t.shared_faces = across / 2;               // a pair of faces, or a split quad's two triangles, each
  if (!base.seam.empty()) glue_seams(s, t);  // none can appear where the mesh had none
  t.nonmanifold_faces = base.nonmanifold_faces;
  t.first_nonmanifold_cell = base.first_nonmanifold_cell < 0 ? -1 : first[base.first_nonmanifold_cell];
  t.nonplanar_faces = base.nonplanar_faces;
  t.max_nonplanarity = base.max_nonplanarity;
  t.max_relative_nonplanarity = base.max_relative_nonplanarity;
  return t;
}

}  // namespace cellproj
