// The classic sorting-benchmark tetrahedral text format (.off) and x y z s point lists.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include "base/error.hpp"
#include "io/read_mesh.hpp"
#include "io/text_scanner.hpp"
#include "io/vtk_points.hpp"

namespace cellproj {

Mesh read_off(const std::string& path) {
  {  // Geomview's OFF (a surface of polygons) shares the extension: say so, not "not a number"
    std::ifstream head(path);
    std::string word;
    while (head >> word && word[0] == '#') std::getline(head, word);
    if (word.size() >= 3 && word.compare(word.size() - 3, 3, "OFF") == 0)
      throw InputError(where(path, "line 1: '" + word.substr(0, 8) +
                                       "' starts a Geomview OFF surface (polygons); cellproj's .off is the tetrahedral "
                                       "format of the sorting benchmarks ('nverts ntets', then 'x y z s' and 'a b c d' "
                                       "lines): tetrahedralize the surface first (e.g. TetGen's .node/.ele)"));
  }
  TextScanner in(path);
  const std::int64_t nv = in.integer("the vertex count"), nt = in.integer("the tetrahedron count");
  if (nv < 4 || nt < 1)
    throw InputError(where(path, "header says " + std::to_string(nv) + " vertices and " + std::to_string(nt) +
                                     " tetrahedra; expected 'nverts ntets' with at least 4 and 1"));
  // Reserved no further than the file can hold (four numbers a vertex, 2 bytes at least each), so
  // that a garbled count ends as "truncated" at the end of the file rather than in the allocator.
  const auto held = static_cast<std::int64_t>(std::filesystem::file_size(path)) / 8;
  Mesh m;
  m.points.reserve(static_cast<std::size_t>(3 * std::min(nv, held)));
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(std::min(nv, held)));
  for (std::int64_t v = 0; v < nv; ++v) {
    const double x = in.number("a vertex x"), y = in.number("a vertex y"), z = in.number("a vertex z");
    m.add_point({x, y, z});
    values.push_back(in.number("a vertex scalar"));
  }
  m.add_field("scalar", "point data").values = std::move(values);
  for (std::int64_t t = 0; t < nt; ++t) {
    std::int64_t ids[4];
    for (auto& id : ids) id = in.integer("a tetrahedron vertex index");
    m.add_cell(CellType::Tetra, ids);
  }
  if (!in.at_end())
    throw InputError(where(path, "unexpected data after " + std::to_string(nt) + " tetrahedra (line " +
                                     std::to_string(in.line()) + "): header counts wrong?"));
  return m;
}

namespace {

// Tetrahedralizes the points of m with CGAL's 3D Delaunay triangulation (coincident points are
// inserted once; the later copies stay unused).
void delaunay(Mesh& m, const std::string& path) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::int64_t, K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb>;
  using Delaunay = CGAL::Delaunay_triangulation_3<K, Tds>;
  std::vector<std::pair<K::Point_3, std::int64_t>> pts;
  pts.reserve(static_cast<std::size_t>(m.n_points()));
  for (std::int64_t p = 0; p < m.n_points(); ++p) {
    const glm::dvec3 x(m.points[3 * p], m.points[3 * p + 1], m.points[3 * p + 2]);
    if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z))
      throw InputError(where(path, "point " + std::to_string(p) + " has a non-finite coordinate"));
    pts.emplace_back(K::Point_3(x.x, x.y, x.z), p);
  }
  Delaunay dt(pts.begin(), pts.end());
  if (dt.dimension() < 3)
    throw InputError(where(path, "the " + std::to_string(m.n_points()) +
                                     " points are coplanar, collinear or fewer than 4: no volume to tetrahedralize"));
  for (auto c : dt.finite_cell_handles()) {
    std::int64_t ids[4];
    for (int k = 0; k < 4; ++k) ids[k] = c->vertex(k)->info();
    m.add_cell(CellType::Tetra, ids);  // CGAL's positive orientation is VTK's
  }
  const auto unused = m.n_points() - static_cast<std::int64_t>(dt.number_of_vertices());
  m.notes.push_back("point cloud tetrahedralized by CGAL's Delaunay triangulation: " + std::to_string(m.n_cells()) +
                    " tetrahedra" + (unused ? ", " + std::to_string(unused) + " coincident points left unused" : ""));
}

}  // namespace

Mesh read_point_cloud(const std::string& path) {
  Mesh m;
  if (std::filesystem::path(path).extension() == ".vtp") {
    m = read_vtk_points(path);
  } else {
    TextScanner in(path);
    std::vector<double> values;
    while (!in.at_end()) {
      const double x = in.number("x"), y = in.number("y"), z = in.number("z");
      m.add_point({x, y, z});
      values.push_back(in.number("the scalar s (lines are 'x y z s')"));
    }
    m.add_field("scalar", "point data").values = std::move(values);
  }
  for (const auto& f : m.fields) check_finite(path, f);
  delaunay(m, path);
  return m;
}

}  // namespace cellproj
