#include "mesh/generate.hpp"

#include <cmath>

#include <glm/geometric.hpp>

#include "base/error.hpp"
#include "mesh/tetrahedralize.hpp"

namespace cellproj {

Mesh make_curvilinear(int nx, int ny, int nz, const std::function<glm::dvec3(const glm::dvec3&)>& map,
                      bool tetrahedra) {
  if (nx < 1 || ny < 1 || nz < 1) throw InputError("grid resolution must be at least 1 cell per axis");
  Mesh m;
  auto id = [&](int i, int j, int k) { return (static_cast<std::int64_t>(k) * (ny + 1) + j) * (nx + 1) + i; };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) m.add_point(map({double(i) / nx, double(j) / ny, double(k) / nz}));
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        m.add_cell(CellType::Hexahedron,
                   {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                    id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  if (!tetrahedra) return m;
  Mesh t;
  t.points = m.points;
  const MeshView hexes = m.view();
  for (std::int64_t c = 0; c < m.n_cells(); ++c) {
    Tet tets[kMaxTetsPerCell];
    const int n = canonical_tetrahedra(hexes, c, tets);
    for (int k = 0; k < n; ++k) t.add_cell(CellType::Tetra, tets[k].data());
  }
  return t;
}

Mesh make_mixed(int nx, int ny, int nz, const std::function<glm::dvec3(const glm::dvec3&)>& map) {
  Mesh grid = make_curvilinear(nx, ny, nz, map, false);
  Mesh m;
  m.points = grid.points;
  const CellDef& hex = cell_def(CellType::Hexahedron);
  const MeshView gv = grid.view();
  for (std::int64_t c = 0; c < grid.n_cells(); ++c) {
    const std::int64_t* v = gv.cell(c);  // hexahedron vertices, 0-3 the bottom
    const int i = static_cast<int>(c % nx), j = static_cast<int>(c / nx % ny);
    switch ((i + j) % 3) {
      case 0: m.add_cell(CellType::Hexahedron, v); break;
      case 1:  // two wedges, every cell of the column split by the same diagonal 0-2 of its quads
        m.add_cell(CellType::Wedge, {v[0], v[2], v[1], v[4], v[6], v[5]});
        m.add_cell(CellType::Wedge, {v[0], v[3], v[2], v[4], v[7], v[6]});
        break;
      default: {  // pyramids on the four side faces, tetrahedra on the split top and bottom
        glm::dvec3 centre(0.0);
        for (int k = 0; k < 8; ++k) centre += gv.point(v[k]) / 8.0;
        const std::int64_t apex = m.add_point(centre);
        for (int f = 0; f < hex.faces; ++f) {
          const std::uint8_t* fv = hex.face[f].v;  // outward: the base of a pyramid turns inward
          const std::int64_t q[4] = {v[fv[0]], v[fv[1]], v[fv[2]], v[fv[3]]};
          if (f < 4) {
            m.add_cell(CellType::Pyramid, {q[0], q[3], q[2], q[1], apex});
            continue;
          }
          std::int64_t tri[2][3];
          split_quad(q, tri);
          for (const auto& t : tri) m.add_cell(CellType::Tetra, {t[0], t[2], t[1], apex});
        }
      }
    }
  }
  return m;
}

Mesh make_box(int nx, int ny, int nz, const glm::dvec3& lo, const glm::dvec3& hi, bool tetrahedra) {
  return make_curvilinear(
      nx, ny, nz, [&](const glm::dvec3& u) { return lo + u * (hi - lo); }, tetrahedra);
}

void set_field(Mesh& mesh, const std::string& name, const std::function<double(const glm::dvec3&)>& f) {
  PointField* field = nullptr;
  for (auto& existing : mesh.fields)
    if (existing.name == name) field = &existing;
  if (!field) field = &mesh.add_field(name, "generated");
  field->values.resize(static_cast<std::size_t>(mesh.n_points()));
  for (std::int64_t p = 0; p < mesh.n_points(); ++p)
    field->values[p] = f({mesh.points[3 * p], mesh.points[3 * p + 1], mesh.points[3 * p + 2]});
}

namespace {

constexpr double kPi = 3.14159265358979323846;

// Three quarters of a thick ring: a curvilinear grid with a hole and a cut, so its boundary is
// not convex, carrying a field with two hot filaments that wind around the ring.
Mesh swirl(int n, bool tets) {
  Mesh m = make_curvilinear(
      3 * n, n, n,
      [](const glm::dvec3& u) {
        const double theta = 1.5 * kPi * (1.0 - u.x), r = 0.45 + 0.55 * u.y, z = 0.7 * (u.z - 0.5);
        const double twist = 0.25 * std::sin(theta);  // gently warped faces: a curvilinear grid
        return glm::dvec3(r * std::cos(theta), r * std::sin(theta), z + twist * (r - 0.7));
      },
      tets);
  set_field(m, "temperature", [](const glm::dvec3& x) {
    const double r = std::hypot(x.x, x.y), theta = std::atan2(x.y, x.x);
    double t = 0.25 * (r - 0.45) / 0.55;  // a gentle outward gradient
    for (int f = 0; f < 2; ++f) {         // two filaments winding about the ring's core
      const double phase = theta * 2.0 + f * kPi;
      const double rc = 0.72 + 0.13 * std::cos(phase), zc = 0.13 * std::sin(phase);
      t += std::exp(-((r - rc) * (r - rc) + (x.z - zc) * (x.z - zc)) / 0.004);
    }
    return t;
  });
  return m;
}

// The growth ratio r of n geometric cells from `first` to a total of 1: first (r^n - 1) / (r - 1) = 1.
double growth_ratio(int n, double first) {
  if (n * first >= 1.0) return 1.0;
  double lo = 1.0, hi = 2.0;
  auto total = [&](double r) { return first * (std::pow(r, n) - 1.0) / (r - 1.0); };
  while (total(hi) < 1.0) hi *= 2.0;
  for (int k = 0; k < 200; ++k) (total(0.5 * (lo + hi)) < 1.0 ? lo : hi) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi);
}

}  // namespace

Mesh make_graded(int n, double first, bool tetrahedra) {
  const double r = growth_ratio(n, first);
  auto axis = [&](double u) {  // u in [0, 1] at the nodes k / (2n): 2n cells, the smallest at 0.5
    const double t = std::abs(2.0 * u - 1.0);
    const double x = r == 1.0 ? t : (std::pow(r, n * t) - 1.0) / (std::pow(r, n) - 1.0);
    return u < 0.5 ? -x : x;
  };
  Mesh m = make_curvilinear(
      2 * n, 2 * n, 2 * n, [&](const glm::dvec3& u) { return glm::dvec3(axis(u.x), axis(u.y), 2.0 * u.z - 1.0); },
      tetrahedra);
  // A hot filament along the z axis, 0.004 in radius (about a pixel wide at 512 x 512) and
  // brightening upwards, over a gentle background: only the cells thinner than a pixel resolve it.
  set_field(m, "scalar", [](const glm::dvec3& x) {
    const double d2 = x.x * x.x + x.y * x.y, sigma = 0.004;
    return 0.2 * (1.0 - glm::dot(x, x) / 3.0) + (0.55 + 0.25 * x.z) * std::exp(-d2 / (2.0 * sigma * sigma));
  });
  return m;
}

std::string generated_kinds() {
  return "box (hexahedra), box-tets (6 tetrahedra per hexahedron), swirl (non-convex curvilinear ring, hexahedra), "
         "swirl-tets, mixed (twisted box of hexahedra, wedges, pyramids and tetrahedra), graded (hexahedra of "
         "[-1, 1]^3 thinning geometrically to 1e-4 towards the z axis, a hot filament along it), graded-tets, shells "
         "(hexahedra of [-1, 1]^3, cos(3 pi r) inside the unit ball: iso-value 0 on the nested "
         "spheres r = 1/6, 1/2, 5/6), shells-tets";
}

Mesh generate(const std::string& kind, int n) {
  if (n < 1) throw InputError("generate: resolution must be at least 1");
  Mesh m;
  if (kind == "box" || kind == "box-tets") {
    m = make_box(n, n, n, glm::dvec3(-1), glm::dvec3(1), kind == "box-tets");
    set_field(m, "scalar", [](const glm::dvec3& x) { return 1.0 - glm::dot(x, x) / 3.0; });
  } else if (kind == "mixed") {
    m = make_mixed(n, n, n, [](const glm::dvec3& u) {
      const double a = 0.6 * (u.z - 0.5);  // twisted about z: the side faces are not planar
      const glm::dvec3 p = 2.0 * u - 1.0;
      return glm::dvec3(p.x * std::cos(a) - p.y * std::sin(a), p.x * std::sin(a) + p.y * std::cos(a), p.z);
    });
    set_field(m, "scalar", [](const glm::dvec3& x) { return 1.0 - glm::dot(x, x) / 3.0 + 0.3 * x.x * x.y * x.z; });
  } else if (kind == "graded" || kind == "graded-tets") {
    m = make_graded(n, kGradedFirstCell, kind == "graded-tets");
  } else if (kind == "shells" || kind == "shells-tets") {
    m = make_box(n, n, n, glm::dvec3(-1), glm::dvec3(1), kind == "shells-tets");
    set_field(m, "scalar", [](const glm::dvec3& x) { return shells_field(glm::length(x)); });
  } else if (kind == "swirl" || kind == "swirl-tets") {
    m = swirl(n, kind == "swirl-tets");
  } else {
    throw InputError("generate: unknown kind '" + kind + "'; the kinds are: " + generated_kinds());
  }
  m.source = "generated " + kind;
  return m;
}

}  // namespace cellproj
