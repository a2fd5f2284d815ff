#include "mesh/field_choice.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "base/error.hpp"

namespace cellproj {
namespace {

// Component names in VTK's order: a vector's axes; a symmetric tensor's six (XX YY ZZ XY YZ XZ);
// a full tensor's nine, row by row.
const char* const kVector[] = {"x", "y", "z"};
const char* const kSymmetric[] = {"xx", "yy", "zz", "xy", "yz", "xz"};
const char* const kFull[] = {"xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz"};

const char* component_name(int components, int k) {
  if (components == 2 || components == 3) return kVector[k];
  if (components == 6) return kSymmetric[k];
  if (components == 9) return kFull[k];
  return nullptr;
}

bool has_von_mises(int components) { return components == 6 || components == 9; }

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The component `word` names (case aside) in a field of `components` values, or kWhole when it
// names none.
int component_of(const std::string& word, int components) {
  const std::string w = lower(word);
  if (w == "magnitude" || w == "mag") return FieldChoice::kMagnitude;
  if ((w == "von_mises" || w == "vonmises") && has_von_mises(components)) return FieldChoice::kVonMises;
  if (!w.empty() && w.size() < 4 && std::all_of(w.begin(), w.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    const int k = std::stoi(w);
    return k < components ? k : FieldChoice::kWhole;
  }
  for (int k = 0; k < components; ++k)
    if (const char* n = component_name(components, k); n && w == n) return k;
  return FieldChoice::kWhole;
}

std::string choice_name(const FieldShape& f, int component) {
  if (component == FieldChoice::kMagnitude) return f.name + ":magnitude";
  if (component == FieldChoice::kVonMises) return f.name + ":von_mises";
  const char* n = component_name(f.components, component);
  return f.name + ":" + (n ? std::string(n) : std::to_string(component));
}

FieldChoice whole(const FieldShape& f) {
  if (f.components == 1) return {f.name, FieldChoice::kWhole, f.name, ""};
  return {f.name, FieldChoice::kMagnitude, choice_name(f, FieldChoice::kMagnitude),
          f.name + " has " + std::to_string(f.components) + " components: showing its magnitude (" + f.name +
              ":C picks another, C one of " + component_words(f.components) + ")"};
}

}  // namespace

std::string component_words(int components) {
  std::string words;
  if (component_name(components, 0))
    for (int k = 0; k < components; ++k) words += std::string(component_name(components, k)) + ", ";
  if (has_von_mises(components)) words += "von_mises, ";
  return words + "magnitude or 0.." + std::to_string(components - 1);
}

std::vector<FieldShape> field_shapes(const Mesh& mesh) {
  std::vector<FieldShape> shapes;
  for (const PointField& f : mesh.fields) shapes.push_back({f.name, f.components});
  return shapes;
}

std::string field_list(const std::vector<FieldShape>& fields) {
  std::string list;
  for (const FieldShape& f : fields)
    list += (list.empty() ? "" : ", ") + f.name +
            (f.components == 1 ? "" : " (" + std::to_string(f.components) + " components)");
  return list.empty() ? "(none)" : list;
}

FieldChoice choose_field(const std::vector<FieldShape>& fields, const std::string& spec, const std::string& source) {
  if (spec.empty()) {
    if (fields.size() == 1) return whole(fields.front());
    throw InputError(where(
        source, fields.empty() ? "the mesh has no point fields to render"
                               : "the mesh has several fields, choose one (setting 'field'): " + field_list(fields)));
  }
  for (const FieldShape& f : fields)
    if (f.name == spec) return whole(f);
  // NAME:word, or ParaView's NAME_Word: the longest field name that the spec starts with.
  const FieldShape* base = nullptr;
  for (const FieldShape& f : fields)
    if (spec.size() > f.name.size() + 1 && spec.compare(0, f.name.size(), f.name) == 0 &&
        (spec[f.name.size()] == ':' || spec[f.name.size()] == '_') && (!base || f.name.size() > base->name.size()))
      base = &f;
  if (base && base->components == 1 && spec[base->name.size()] == ':')
    throw InputError(where(source, "field '" + spec + "': " + base->name + " is a scalar (one component)"));
  if (base && base->components > 1) {
    const int k = component_of(spec.substr(base->name.size() + 1), base->components);
    if (k == FieldChoice::kWhole)
      throw InputError(where(source, "field '" + spec + "': " + base->name + " has " +
                                         std::to_string(base->components) + " components; pick " +
                                         component_words(base->components)));
    return {base->name, k, choice_name(*base, k), ""};
  }
  const bool vectors = std::any_of(fields.begin(), fields.end(), [](const FieldShape& f) { return f.components > 1; });
  throw InputError(where(source, "no point field named '" + spec + "'; the fields are: " + field_list(fields) +
                                     (vectors ? " (a vector's component: NAME:x, NAME_X, NAME:magnitude)" : "")));
}

FieldChoice choose_field(const Mesh& mesh, const std::string& spec) {
  return choose_field(field_shapes(mesh), spec, mesh.source);
}

std::vector<double> scalar_values(const PointField& f, int component) {
  return scalar_values(f.values.data(), static_cast<std::int64_t>(f.values.size()) / f.components, f.components,
                       component);
}

std::vector<double> scalar_values(const double* tuples, std::int64_t n, int components, int component) {
  std::vector<double> out(static_cast<std::size_t>(n));
  for (std::int64_t p = 0; p < n; ++p) {
    const double* t = tuples + p * components;
    if (component >= 0) {
      out[p] = t[component];
    } else if (component == FieldChoice::kMagnitude) {
      double s = 0;
      for (int k = 0; k < components; ++k) s += t[k] * t[k];
      out[p] = std::sqrt(s);
    } else if (component == FieldChoice::kVonMises) {
      // The symmetric part's xx yy zz xy yz xz, from six values or nine.
      const bool six = components == 6;
      const double xx = t[0], yy = six ? t[1] : t[4], zz = six ? t[2] : t[8];
      const double xy = six ? t[3] : 0.5 * (t[1] + t[3]), yz = six ? t[4] : 0.5 * (t[5] + t[7]),
                   xz = six ? t[5] : 0.5 * (t[2] + t[6]);
      out[p] = std::sqrt(0.5 * ((xx - yy) * (xx - yy) + (yy - zz) * (yy - zz) + (zz - xx) * (zz - xx)) +
                         3.0 * (xy * xy + yz * yz + xz * xz));
    } else {
      out[p] = t[0];
    }
  }
  return out;
}

PointField& select_field(Mesh& mesh, const std::string& spec, std::string* note) {
  const FieldChoice c = choose_field(mesh, spec);
  if (note) *note = c.note;
  for (PointField& made : mesh.fields)
    if (made.name == c.name) return made;
  const PointField& from = mesh.field(c.field);
  std::string origin =
      from.origin + ", " + c.name.substr(c.field.size() + 1) + " of " + std::to_string(from.components) + " components";
  std::vector<double> values = scalar_values(from, c.component);
  mesh.fields.push_back({c.name, std::move(values), std::move(origin), 1});
  return mesh.fields.back();
}

}  // namespace cellproj
