#include "test_util.hpp"

#include <random>

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

}  // namespace cellproj::test
