#include "mesh/field_choice.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

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
  if (f.components == 1) return {f.name, FieldChoice::kWhole, f.name, "", false, {}, f.name};
  return {f.name,
          FieldChoice::kMagnitude,
          choice_name(f, FieldChoice::kMagnitude),
          f.name + " has " + std::to_string(f.components) + " components: showing its magnitude (" + f.name +
              ":C picks another, C one of " + component_words(f.components) + ")",
          false,
          {},
          choice_name(f, FieldChoice::kMagnitude)};
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

bool log_scale_name(const std::string& name) {
  return name.size() >= 7 && name.compare(0, 6, "log10(") == 0 && name.back() == ')';
}

std::string log_scale_scalar(const std::string& name, std::optional<double>* floor, const std::string& source) {
  std::string inner = name.substr(6, name.size() - 7);
  const std::size_t comma = inner.rfind(", ");
  if (inner.rfind("max(", 0) != 0 || inner.back() != ')' || comma == std::string::npos) return inner;
  const std::string number = inner.substr(comma + 2, inner.size() - comma - 3);
  char* end = nullptr;
  const double f = std::strtod(number.c_str(), &end);
  if (end != number.c_str() + number.size() || number.empty())
    throw InputError(where(source, "field '" + name + "': '" + number + "' is not a number"));
  if (floor) *floor = f;
  return inner.substr(4, comma - 4);
}

std::string log_spec(const std::string& spec, std::optional<double> floor) {
  if (!floor) return "log10(" + spec + ")";
  if (!(*floor > 0) || !std::isfinite(*floor))
    throw InputError("setting 'log-floor': expected a positive number, got " + std::to_string(*floor));
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", *floor);
  return "log10(max(" + spec + ", " + text + "))";
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
  if (log_scale_name(spec)) {
    std::optional<double> floor;
    FieldChoice c = choose_field(fields, log_scale_scalar(spec, &floor, source), source);
    c.log = true, c.floor = floor, c.scalar = c.name;
    c.name = log_spec(c.name, floor);
    return c;
  }
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
    return {base->name, k, choice_name(*base, k), "", false, {}, choice_name(*base, k)};
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

std::vector<double> shown_values(const PointField& f) {
  return scalar_values(f, whole({f.name, f.components}).component);
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

std::vector<double> choice_values(const double* tuples, std::int64_t n, int components, const FieldChoice& choice,
                                  const std::string& source) {
  std::vector<double> v = scalar_values(tuples, n, components, choice.component);
  if (!choice.log) return v;
  if (choice.floor) {
    for (double& x : v) x = std::log10(std::max(x, *choice.floor));
    return v;
  }
  std::int64_t bad = 0, smallest = -1;
  for (std::int64_t p = 0; p < n; ++p)
    if (!(v[p] > 0)) {
      ++bad;
      if (smallest < 0 || v[p] < v[smallest]) smallest = p;
    }
  if (bad)
    throw InputError(where(source, "field '" + choice.scalar + "' on a log scale: " + std::to_string(bad) + " of " +
                                       std::to_string(n) + " values are not above 0 (the smallest " +
                                       std::to_string(v[smallest]) + ", at point " + std::to_string(smallest) +
                                       "); give a floor below which values count as it (setting 'log-floor')"));
  for (double& x : v) x = std::log10(x);
  return v;
}

PointField& select_field(Mesh& mesh, const std::string& spec, std::string* note) {
  const FieldChoice c = choose_field(mesh, spec);
  if (note) *note = c.note;
  for (PointField& made : mesh.fields)
    if (made.name == c.name) return made;
  const PointField& from = mesh.field(c.field);
  std::string origin = from.origin;
  if (!from.scalar()) origin += ", " + c.scalar + " of " + std::to_string(from.components) + " components";
  if (c.log) origin += ", on a log scale";
  const std::int64_t n = static_cast<std::int64_t>(from.values.size()) / from.components;
  std::vector<double> values = choice_values(from.values.data(), n, from.components, c, mesh.source);
  mesh.fields.push_back({c.name, std::move(values), std::move(origin), 1, from.per_cell});
  return mesh.fields.back();
}

}  // namespace cellproj
