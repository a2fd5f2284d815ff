// A solver's post-processing step: its own arrays (here a small hexahedral grid around a moving hot
// spot, with 32-bit ids as many solvers keep them) rendered through cellproj's façade without
// writing a mesh file. The mesh is committed once as a Volume; each time step is a new Field and
// costs no new preparation.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <cellproj.hpp>

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "solver.png";
  const int n = 20;  // cells per axis
  std::vector<double> xyz;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        xyz.insert(xyz.end(), {double(i) / n - 0.5, double(j) / n - 0.5, double(k) / n - 0.5});
  std::vector<std::int32_t> connectivity, offsets{0};
  std::vector<std::uint8_t> types;
  auto id = [&](int i, int j, int k) { return std::int32_t((k * (n + 1) + j) * (n + 1) + i); };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        connectivity.insert(connectivity.end(),
                            {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                             id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
        offsets.push_back(static_cast<std::int32_t>(connectivity.size()));
        types.push_back(12);  // VTK_HEXAHEDRON
      }
  const std::int64_t n_points = static_cast<std::int64_t>(xyz.size() / 3);

  try {
    cellproj::CellArrays cells;
    cells.connectivity = connectivity.data();
    cells.offsets = offsets.data();
    cells.types = types.data();
    cells.n_cells = static_cast<std::int64_t>(types.size());
    cells.ids_32bit = true;
    cells.connectivity_size = static_cast<std::int64_t>(connectivity.size());
    // Validated here (cellproj::InputError names the bad element); the points are read in place.
    const cellproj::Volume volume(xyz.data(), n_points, cells, "solver arrays");

    const cellproj::TransferFunction tf({{0.0, {0.1, 0.2, 0.8}}, {0.5, {0.9, 0.6, 0.2}}, {1.0, {1.0, 1.0, 0.9}}},
                                        {{0.0, 0.0}, {0.2, 1.0}, {1.0, 20.0}});
    cellproj::Camera camera;
    camera.projection = cellproj::Projection::Perspective;
    camera.eye = {1.6, 1.2, 2.0};
    camera.up = {0, 1, 0};
    cellproj::RenderSettings settings;  // cell projection, pt-breakpoints: exact for the canonical tetrahedra
    const auto renderer = cellproj::make_renderer(settings);

    std::vector<double> temperature(static_cast<std::size_t>(n_points));
    for (int step = 0; step < 2; ++step) {  // two time steps of the solver
      const double cx = -0.15 + 0.3 * step;
      for (std::int64_t p = 0; p < n_points; ++p) {
        const double x = xyz[3 * p] - cx, y = xyz[3 * p + 1], z = xyz[3 * p + 2];
        temperature[p] = std::exp(-(x * x + y * y + z * z) / 0.05);
      }
      const cellproj::Field field{temperature.data(), n_points, "temperature"};
      cellproj::RenderReport report;
      const cellproj::Image image = renderer->render(volume, field, tf, camera, {256, 256}, &report);
      const std::string path = step == 0 ? out : out.substr(0, out.rfind('.')) + "_step1.png";
      cellproj::write_png(image, {0, 0, 0}, path);
      std::printf("step %d: wrote %s in %.3f s (preparation %.3f s, preparations so far: %d)\n", step, path.c_str(),
                  report.seconds, report.prepare_seconds, volume.preparations());
    }
    for (const std::string& copy : volume.copies()) std::printf("cellproj copied %s\n", copy.c_str());
    if (volume.preparations() != 1) {
      std::fprintf(stderr, "error: the second time step prepared the mesh again\n");
      return 1;
    }
  } catch (const cellproj::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
