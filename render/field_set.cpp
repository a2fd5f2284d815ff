#include "render/field_set.hpp"

#include <algorithm>
#include <cmath>

#include "base/error.hpp"

namespace cellproj {

void FieldSet::set(const Volume& volume, const std::string& name, const double* values, std::int64_t n_values,
                   int components) {
  const MeshView& m = volume.mesh();
  if (components < 1)
    throw InputError(where(m.source, "field '" + name + "': " + std::to_string(components) + " components"));
  if (components == 1) {
    volume.check({values, n_values, name});
  } else {
    if (!values) throw InputError(where(m.source, "no field given: field '" + name + "' has no values"));
    if (n_values != m.n_points * components)
      throw InputError(where(m.source, "field '" + name + "' has " + std::to_string(n_values) + " values for " +
                                           std::to_string(m.n_points) + " points of " + std::to_string(components) +
                                           " components"));
    for (std::int64_t i = 0; i < n_values; ++i)
      if (!std::isfinite(values[i]))
        throw InputError(where(m.source, "field '" + name + "' is not finite at point " +
                                             std::to_string(i / components) + ", component " +
                                             std::to_string(i % components) + " (" + std::to_string(values[i]) + ")"));
  }
  fields_.erase(std::remove_if(fields_.begin(), fields_.end(), [&](const Entry& e) { return e.name == name; }),
                fields_.end());
  fields_.push_back({name, values, m.n_points, components});
  std::lock_guard<std::mutex> lock(made_lock_);
  made_.clear();  // the choices made of an old field among them
}

void FieldSet::add(const Volume& volume, const Mesh& mesh) {
  for (const PointField& f : mesh.fields)
    set(volume, f.name, f.values.data(), static_cast<std::int64_t>(f.values.size()), f.components);
}

std::vector<FieldShape> FieldSet::shapes() const {
  std::vector<FieldShape> out;
  for (const Entry& e : fields_) out.push_back({e.name, e.components});
  return out;
}

Field FieldSet::stored(const std::string& name) const {
  for (const Entry& e : fields_)
    if (e.name == name) return {e.values, e.n_points, e.name};
  throw InputError("no field named '" + name + "'");
}

Field FieldSet::scalar(const std::string& spec, const std::string& source, std::string* note) const {
  const FieldChoice c = choose_field(shapes(), spec, source);
  if (note) *note = c.note;
  const Entry& e = *std::find_if(fields_.begin(), fields_.end(), [&](const Entry& x) { return x.name == c.field; });
  if (c.component == FieldChoice::kWhole && !c.log) return {e.values, e.n_points, e.name};
  std::lock_guard<std::mutex> lock(made_lock_);
  auto it = made_.find(c.name);
  if (it == made_.end()) it = made_.emplace(c.name, choice_values(e.values, e.n_points, e.components, c, source)).first;
  return {it->second.data(), e.n_points, c.name};
}

}  // namespace cellproj
