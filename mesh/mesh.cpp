#include "mesh/mesh.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

#include "base/error.hpp"
#include "mesh/field_choice.hpp"

namespace cellproj {

std::int64_t Mesh::add_point(const glm::dvec3& p) {
  points.insert(points.end(), {p.x, p.y, p.z});
  return n_points() - 1;
}

void Mesh::add_cell(CellType type, const std::int64_t* ids) {
  const int n = cell_def(type).vertices;
  connectivity.insert(connectivity.end(), ids, ids + n);
  offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
  types.push_back(static_cast<std::uint8_t>(type));
}

const PointField* Mesh::find_field(const std::string& name) const {
  for (const auto& f : fields)
    if (f.name == name) return &f;
  return nullptr;
}

const PointField& Mesh::field(const std::string& name) const {
  if (const auto* f = find_field(name)) return *f;
  throw InputError(
      where(source, "no point field named '" + name + "'; the fields are: " + field_list(field_shapes(*this))));
}

PointField& Mesh::add_field(std::string name, std::string origin, int components) {
  fields.push_back({std::move(name), std::vector<double>(static_cast<std::size_t>(n_points() * components)),
                    std::move(origin), components});
  return fields.back();
}

PointField gather(const PointField& f, const std::vector<std::int64_t>& points) {
  PointField g{f.name, {}, f.origin, f.components, f.per_cell};
  g.values.reserve(points.size() * static_cast<std::size_t>(f.components));
  for (std::int64_t p : points) g.append_tuple(f, p);
  return g;
}

MeshView Mesh::view() const {
  MeshView v;
  v.points = points.data();
  v.n_points = n_points();
  v.connectivity = connectivity.data();
  v.offsets = offsets.data();
  v.types = types.data();
  v.n_cells = n_cells();
  v.source = source;
  return v;
}

std::int64_t merge_coincident_points(Mesh& mesh) {
  const std::int64_t n = mesh.n_points();
  std::vector<std::int64_t> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  auto coords = [&](std::int64_t p) {
    return std::tie(mesh.points[3 * p], mesh.points[3 * p + 1], mesh.points[3 * p + 2]);
  };
  std::sort(order.begin(), order.end(),
            [&](std::int64_t a, std::int64_t b) { return coords(a) < coords(b) || (coords(a) == coords(b) && a < b); });
  std::vector<std::int64_t> keep_as(static_cast<std::size_t>(n));  // point -> the first of its coincident group
  for (std::size_t i = 0; i < order.size(); ++i)
    keep_as[order[i]] = i > 0 && coords(order[i]) == coords(order[i - 1]) ? keep_as[order[i - 1]] : order[i];
  std::vector<std::int64_t> new_id(static_cast<std::size_t>(n), -1);
  std::int64_t kept = 0;
  for (std::int64_t p = 0; p < n; ++p) {
    if (keep_as[p] != p) continue;
    new_id[p] = kept;
    for (int k = 0; k < 3; ++k) mesh.points[3 * kept + k] = mesh.points[3 * p + k];
    for (auto& f : mesh.fields)
      std::copy_n(f.values.begin() + p * f.components, f.components, f.values.begin() + kept * f.components);
    ++kept;
  }
  if (kept == n) return 0;
  mesh.points.resize(static_cast<std::size_t>(3 * kept));
  for (auto& f : mesh.fields) f.values.resize(static_cast<std::size_t>(kept * f.components));
  for (auto& id : mesh.connectivity) id = new_id[keep_as[id]];
  return n - kept;
}

}  // namespace cellproj
