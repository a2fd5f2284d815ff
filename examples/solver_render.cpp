// A solver's post-processing step: its own arrays (here a small hexahedral grid around a hot spot)
// rendered through cellproj's public API without copying them or writing a mesh file.
#include <cmath>
#include <cstdio>
#include <vector>

#include <cellproj.hpp>

int main(int argc, char** argv) {
  const char* out = argc > 1 ? argv[1] : "solver.png";
  const int n = 20;  // cells per axis
  std::vector<double> xyz, temperature;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const double x = double(i) / n - 0.5, y = double(j) / n - 0.5, z = double(k) / n - 0.5;
        xyz.insert(xyz.end(), {x, y, z});
        temperature.push_back(std::exp(-(x * x + y * y + z * z) / 0.05));
      }
  std::vector<std::int64_t> connectivity, offsets{0};
  std::vector<std::uint8_t> types;
  auto id = [&](int i, int j, int k) { return std::int64_t((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        connectivity.insert(connectivity.end(), {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                                                 id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
        offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
        types.push_back(12);  // VTK_HEXAHEDRON
      }

  cellproj::MeshView mesh;  // a view over the solver's arrays: nothing is copied
  mesh.points = xyz.data();
  mesh.n_points = static_cast<std::int64_t>(temperature.size());
  mesh.connectivity = connectivity.data();
  mesh.offsets = offsets.data();
  mesh.types = types.data();
  mesh.n_cells = static_cast<std::int64_t>(types.size());
  mesh.scalar = temperature.data();
  mesh.source = "solver arrays";
  mesh.field = "temperature";

  try {
    cellproj::validate(mesh);  // throws cellproj::InputError naming the bad element
    const cellproj::TransferFunction tf({{0.0, {0.1, 0.2, 0.8}}, {0.5, {0.9, 0.6, 0.2}}, {1.0, {1.0, 1.0, 0.9}}},
                                        {{0.0, 0.0}, {0.2, 1.0}, {1.0, 20.0}});
    cellproj::Camera camera;
    camera.projection = cellproj::Projection::Perspective;
    camera.eye = {1.6, 1.2, 2.0};
    camera.up = {0, 1, 0};
    // Cell projection (pt-breakpoints by default); cellproj::ExactRenderer is the reference to check it against.
    const cellproj::ProjectionRenderer renderer(mesh);
    const cellproj::Image image = renderer.render(tf, camera, 256, 256);
    cellproj::write_png(image, {0, 0, 0}, out);
  } catch (const cellproj::InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("wrote %s\n", out);
  return 0;
}
