#pragma once
// Helpers shared by the tests: small meshes with analytic answers, temporary folders, cameras,
// and one call per renderer over a Mesh's field.
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "frame/projection_renderer.hpp"
#include "mesh/generate.hpp"
#include "optics/transfer_function.hpp"
#include "raycast/reference_renderer.hpp"
#include "view/camera.hpp"

namespace cellproj::test {

// A fresh empty folder under the system's temporary folder, removed at the end of the test.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

// A deterministic jitter in [-1, 1]^3 per grid point (a hash of its position).
glm::dvec3 jitter(const glm::dvec3& u);

// The Delaunay tetrahedra (io/read_mesh's point clouds, CGAL) of the cube [-1, 1]^3's corners
// and `points` random points inside it, each with a random scalar: a convex, irregular mesh. The
// cloud's file is written into `dir`.
Mesh delaunay_cube(const TempDir& dir, int points, unsigned seed);

// The message of the InputError that f() throws ("" when it throws none).
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Constant colour and extinction.
inline TransferFunction constant_tf(double kappa, glm::dvec3 rgb) {
  return TransferFunction({{0.0, rgb}}, {{0.0, kappa}});
}

inline std::string shared_data(const std::string& rel) { return std::string(CELLPROJ_SHARED_DATA) + "/" + rel; }

// Orthographic from +z onto `target`, the image `height` units tall (x to the right, y up).
Camera looking_down(double height, const glm::dvec3& target = {0, 0, 0});
// From `eye` at the origin, up along z (x when looking nearly vertically).
Camera view_from(const glm::dvec3& eye, Projection projection, double height = 3.0, double fov_y = 40.0);
Camera perspective(const glm::dvec3& eye, const glm::dvec3& target, double fov_y);  // up along z
// n directions over the sphere, each orthographic from `ortho_distance` and perspective from
// `persp_distance` (height and fov_y as given).
std::vector<Camera> sphere_views(int n, double ortho_distance, double persp_distance, double height, double fov_y);
// sphere_views framing the meshes of [-1, 1]^3 below (warped_hexahedra, twisted_mixed).
inline std::vector<Camera> views_of_unit_mesh(int n) { return sphere_views(n, 6.0, 4.5, 3.6, 45); }

// The mesh's point field `field` (its only one when empty), rendered by the stage's renderer.
const double* field_values(const Mesh& m, const std::string& field = "");
Image project(const Mesh& m, const std::string& field, const TransferFunction& tf, const Camera& c, int size,
              const ProjectionOptions& options = {}, Tetrahedralize mode = Tetrahedralize::problem,
              ProjectionStats* stats = nullptr);
Image exact(const Mesh& m, const std::string& field, const TransferFunction& tf, const Camera& c, int width, int height,
            CellInterpolation interpolation = CellInterpolation::isoparametric, ExactStats* stats = nullptr);
ProjectionOptions with_method(ProjectionMethod method, SortMethod sort = SortMethod::automatic);

// A twisted, jittered curvilinear grid of n^3 hexahedra: strongly warped faces, a non-convex boundary.
Mesh warped_hexahedra(int n);
// A twisted mixed mesh of n^3 blocks (hexahedra, wedges, pyramids and tetrahedra).
Mesh twisted_mixed(int n);
// An n^3 grid over [-1, 1]^3 sheared and bent (x by sin 3y, z by xy), hexahedra or their canonical
// tetrahedra, with the field "s" = sin 2x cos 1.5y + 0.4z.
Mesh wavy_grid(int n, bool tetrahedra);
// A camera whose eye lies inside wavy_grid's mesh (the cells around it reach behind the eye).
Camera inside_wavy_grid(Projection projection);

}  // namespace cellproj::test

namespace cellproj::test {

// b's points and cells appended to a (fields: the first field of each, concatenated).
void append(Mesh& a, const Mesh& b);

// m with the cells whose centroid lies beyond x on copies of the points (point p's is n + p): two
// blocks with their interface points repeated, a seam (../shared/data: AngularSector, Blunt Fin).
Mesh with_seam(const Mesh& m, double x);

// int_0^L C(t) kappa(t) exp(-int_0^t kappa) dt by composite Simpson (2e5 intervals): an
// independent check on the renderer's integrals.
template <class Kappa, class Colour>
glm::dvec3 simpson_light(double L, Kappa kappa, Colour colour) {
  const int n = 200000;
  const double h = L / n;
  glm::dvec3 sum(0.0);
  double depth = 0.0, k_prev = kappa(0.0);
  for (int i = 0; i <= n; ++i) {
    const double t = i * h, k = kappa(t);
    if (i > 0) depth += 0.5 * h * (k_prev + k);  // trapezoid depth: O(h^2) = 1e-11 for L ~ 1
    k_prev = k;
    sum += double(i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * colour(t) * k * std::exp(-depth);
  }
  return sum * (h / 3);
}

}  // namespace cellproj::test
