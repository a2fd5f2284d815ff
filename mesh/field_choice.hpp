#pragma once
// The scalar a picture shows, chosen from a mesh's fields by the words a user writes: a field's
// name; for a vector or tensor, one component, its magnitude or its von Mises stress, spelt
// `NAME:x|y|z|magnitude|von_mises|N` or as ParaView does (`NAME_X`, `NAME_Magnitude`). A vector
// named alone means its magnitude. On a log scale the scalar is `log10(SPEC)` (or
// `log10(max(SPEC, FLOOR))`): the log of the values at the points, interpolated linearly inside
// the cells like any field, so that every method integrates it exactly as it does any other and the
// exact renderer stays the reference. Every front end (command line, scene files, Python, C, time
// series, MPI bricks) picks through here, so one file gives one field whichever door it came in by.
#include <optional>
#include <string>

#include "mesh/mesh.hpp"

namespace cellproj {

struct FieldChoice {
  static constexpr int kWhole = -1;      // a scalar field as it is
  static constexpr int kMagnitude = -2;  // the vector's length
  static constexpr int kVonMises = -3;   // a symmetric tensor's von Mises stress

  std::string field;  // the stored field's name
  int component = kWhole;
  std::string name;             // the scalar's name ("Velocity:x"), as a legend shows it and a spec repeats it
  std::string note;             // what was chosen without being asked ("Velocity has 3 components: ..."), or ""
  bool log = false;             // log10 of the scalar
  std::optional<double> floor;  // with log: values below it are taken as it (> 0)
  std::string scalar;           // with log: the scalar's name before the log ("p"), else `name`
};

// The spec of `spec`'s scalar on a log scale: log10(SPEC), or log10(max(SPEC, FLOOR)) with a floor
// (InputError unless it is finite and positive).
std::string log_spec(const std::string& spec, std::optional<double> floor);
// Whether a scalar's name (a choice's) is of a log scale: log10(...); and the scalar inside it
// (its floor, when it has one, into `floor`).
bool log_scale_name(const std::string& name);
std::string log_scale_scalar(const std::string& name, std::optional<double>* floor = nullptr,
                             const std::string& source = "");

// A field as choosing sees it: its name and how many values each point has.
struct FieldShape {
  std::string name;
  int components = 1;
};
std::vector<FieldShape> field_shapes(const Mesh& mesh);
std::string field_list(const std::vector<FieldShape>& fields);  // "p, Velocity (3 components)" or "(none)"

// What `spec` names among `fields` (of the mesh or arrays `source`); an empty spec is the only
// field. InputError naming the source, the spec and what would be understood (the fields and their
// components) when nothing matches.
FieldChoice choose_field(const std::vector<FieldShape>& fields, const std::string& spec, const std::string& source);
FieldChoice choose_field(const Mesh& mesh, const std::string& spec);

// The scalar field `spec` chooses: a stored scalar as it is, or one made from a vector or tensor
// and kept in `mesh.fields` under the choice's name (so asking again costs nothing). `note`, when
// given, receives the choice's note.
PointField& select_field(Mesh& mesh, const std::string& spec, std::string* note = nullptr);

// The scalar `choice` makes of n tuples (`components` values each): its component, magnitude or
// von Mises stress, and on a log scale the log of that. A log of a value not above 0 (without a
// floor) is an InputError naming `source`, the scalar, how many values and the smallest.
std::vector<double> choice_values(const double* tuples, std::int64_t n, int components, const FieldChoice& choice,
                                  const std::string& source);

// One value per tuple of n (`components` values each): component k (FieldChoice::component), the
// magnitude or the von Mises stress.
std::vector<double> scalar_values(const double* tuples, std::int64_t n, int components, int component);
std::vector<double> scalar_values(const PointField& field, int component);
// The values `field` shows named alone (choose_field): a scalar's own, a vector's magnitude.
std::vector<double> shown_values(const PointField& field);

// "x, y, z, magnitude or 0..2": the words that pick from a field of `components` values.
std::string component_words(int components);

}  // namespace cellproj
