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
