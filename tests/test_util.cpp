#include "test_util.hpp"

#include <fstream>
#include <random>

#include "io/read_mesh.hpp"

namespace cellproj::test {

TempDir::TempDir() {
  std::random_device rd;
  path_ = std::filesystem::temp_directory_path() / ("cellproj-test-" + std::to_string(rd()) + std::to_string(rd()));
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

}  // namespace cellproj::test

namespace cellproj::test {

void append(Mesh& a, const Mesh& b) {
  const std::int64_t base = a.n_points();
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for (std::int64_t c = 0; c < b.n_cells(); ++c) {
    std::int64_t ids[8];
    for (std::int64_t k = b.offsets[c]; k < b.offsets[c + 1]; ++k) ids[k - b.offsets[c]] = b.connectivity[k] + base;
    a.add_cell(static_cast<CellType>(b.types[c]), ids);
  }
  if (!a.fields.empty() && !b.fields.empty())
    a.fields[0].values.insert(a.fields[0].values.end(), b.fields[0].values.begin(), b.fields[0].values.end());
}

}  // namespace cellproj::test

namespace cellproj::test {

Mesh with_seam(const Mesh& m, double x) {
  Mesh s = m;
  const std::int64_t n = m.n_points();
  s.points.insert(s.points.end(), m.points.begin(), m.points.end());  // point p's copy is n + p
  for (auto& f : s.fields) f.values.insert(f.values.end(), f.values.begin(), f.values.end());
  for (std::int64_t c = 0; c < m.n_cells(); ++c) {
    double cx = 0.0;
    for (std::int64_t k = m.offsets[c]; k < m.offsets[c + 1]; ++k) cx += m.points[3 * m.connectivity[k]];
    if (cx / static_cast<double>(m.offsets[c + 1] - m.offsets[c]) > x)
      for (std::int64_t k = m.offsets[c]; k < m.offsets[c + 1]; ++k) s.connectivity[k] += n;
  }
  return s;
}

Camera looking_down(double height, const glm::dvec3& target) {
  Camera c;
  c.eye = target + glm::dvec3(0, 0, 5);
  c.target = target;
  c.height = height;
  return c;
}

Camera view_from(const glm::dvec3& eye, Projection projection, double height, double fov_y) {
  Camera c;
  c.projection = projection;
  c.eye = eye;
  c.target = {0, 0, 0};
  c.up = std::abs(glm::normalize(eye).z) > 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 0, 1);
  c.height = height;
  c.fov_y = fov_y;
  return c;
}

Camera perspective(const glm::dvec3& eye, const glm::dvec3& target, double fov_y) {
  Camera c;
  c.projection = Projection::Perspective;
  c.eye = eye;
  c.target = target;
  c.up = {0, 0, 1};
  c.fov_y = fov_y;
  return c;
}

std::vector<Camera> sphere_views(int n, double ortho_distance, double persp_distance, double height, double fov_y) {
  std::vector<Camera> out;
  for (const Projection projection : {Projection::Orthographic, Projection::Perspective})
    for (const glm::dvec3& d : sphere_directions(n)) {
      Camera c;
      c.projection = projection;
      c.eye = (projection == Projection::Perspective ? persp_distance : ortho_distance) * d;
      c.up = up_for(d);
      c.height = height;
      c.fov_y = fov_y;
      out.push_back(c);
    }
  return out;
}

const double* field_values(const Mesh& m, const std::string& field) {
  return (field.empty() ? m.fields.at(0) : m.field(field)).values.data();
}

Image project(const Mesh& m, const std::string& field, const TransferFunction& tf, const Camera& c, int size,
              const ProjectionOptions& options, Tetrahedralize mode, ProjectionStats* stats) {
  return ProjectionRenderer(m.view(), mode).render(field_values(m, field), tf, c, size, size, options, stats);
}

Image exact(const Mesh& m, const std::string& field, const TransferFunction& tf, const Camera& c, int width, int height,
            CellInterpolation interpolation, ExactStats* stats) {
  return ExactRenderer(m.view()).render(field_values(m, field), tf, c, width, height, interpolation, stats);
}

ProjectionOptions with_method(ProjectionMethod method, SortMethod sort) {
  ProjectionOptions o;
  o.method = method;
  o.sort = sort;
  return o;
}

// A deterministic jitter in [-1, 1]^3 per grid point.
glm::dvec3 jitter(const glm::dvec3& u) {
  auto h = [](double x) {
    const double s = std::sin(x) * 43758.5453;
    return 2.0 * (s - std::floor(s)) - 1.0;
  };
  return {h(12.9898 * u.x + 78.233 * u.y + 37.719 * u.z), h(39.3468 * u.x + 11.135 * u.y + 83.155 * u.z),
          h(73.156 * u.x + 52.235 * u.y + 9.151 * u.z)};
}

Mesh warped_hexahedra(int n) {
  const double cell = 2.0 / n;
  Mesh m = make_curvilinear(
      n, n, n,
      [cell](const glm::dvec3& u) {
        const double a = 1.2 * (u.z - 0.5);
        const glm::dvec3 p(2 * u.x - 1, 2 * u.y - 1, 2 * u.z - 1);
        return glm::dvec3(std::cos(a) * p.x - std::sin(a) * p.y, std::sin(a) * p.x + std::cos(a) * p.y, p.z) +
               0.15 * cell * jitter(u);
      },
      false);
  return m;
}

Mesh wavy_grid(int n, bool tetrahedra) {
  Mesh m = make_curvilinear(
      n, n, n,
      [](const glm::dvec3& u) {
        return glm::dvec3(2 * u.x - 1 + 0.15 * std::sin(3 * u.y), 2 * u.y - 1, 2 * u.z - 1 + 0.2 * u.x * u.y);
      },
      tetrahedra);
  set_field(m, "s", [](const glm::dvec3& x) { return std::sin(2 * x.x) * std::cos(1.5 * x.y) + 0.4 * x.z; });
  return m;
}

Camera inside_wavy_grid(Projection projection) {
  Camera c;
  c.projection = projection;
  c.eye = {0.13, -0.41, 0.07};
  c.target = {1.0, 0.3, -0.2};
  c.up = {0, 0, 1};
  c.fov_y = 70;
  c.height = 1.5;
  return c;
}

Mesh twisted_mixed(int n) {
  return make_mixed(n, n, n, [](const glm::dvec3& u) {
    const double a = 1.0 * (u.z - 0.5);
    const glm::dvec3 p(2 * u.x - 1, 2 * u.y - 1, 2 * u.z - 1);
    return glm::dvec3(std::cos(a) * p.x - std::sin(a) * p.y, std::sin(a) * p.x + std::cos(a) * p.y,
                      p.z + 0.1 * p.x * p.y);
  });
}

Mesh delaunay_cube(const TempDir& dir, int points, unsigned seed) {
  const std::string path = dir.file("cloud" + std::to_string(seed) + ".xyzs");
  {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::ofstream out(path);
    out.precision(17);
    for (int k = 0; k < 8; ++k) out << (k & 1 ? 1 : -1) << ' ' << (k & 2 ? 1 : -1) << ' ' << (k & 4 ? 1 : -1) << " 0\n";
    for (int k = 0; k < points; ++k) out << u(rng) << ' ' << u(rng) << ' ' << u(rng) << ' ' << u(rng) << '\n';
  }
  return read_point_cloud(path);
}

}  // namespace cellproj::test
