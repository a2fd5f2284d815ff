#include "grid/mesh.hpp"

#include "grid/error.hpp"

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
  std::string known;
  for (const auto& f : fields) known += (known.empty() ? "" : ", ") + f.name;
  throw InputError(where(source, "no point field named '" + name + "'; the fields are: " +
                                     (known.empty() ? "(none)" : known)));
}

PointField& Mesh::add_field(std::string name, std::string origin) {
  fields.push_back({std::move(name), std::vector<double>(static_cast<std::size_t>(n_points())), std::move(origin)});
  return fields.back();
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

MeshView Mesh::view(const std::string& field_name) const {
  MeshView v = view();
  v.scalar = field(field_name).values.data();
  v.field = field_name;
  return v;
}

}  // namespace cellproj
