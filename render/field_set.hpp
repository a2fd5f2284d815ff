#pragma once
// The named fields a front end holds over one volume's points (a C or Python caller's arrays, or a
// read mesh's), not copied, and the scalars chosen from them by mesh/field_choice.hpp's words: a
// vector's component or magnitude is made on first use and kept, once per field and choice.
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "mesh/field_choice.hpp"
#include "render/volume.hpp"

namespace cellproj {

class FieldSet {
 public:
  // `values` holds `components` finite values per point of `volume` (InputError naming the field
  // and the first bad value otherwise); a field of the same name is replaced.
  void set(const Volume& volume, const std::string& name, const double* values, std::int64_t n_values,
           int components = 1);
  void add(const Volume& volume, const Mesh& mesh);  // every field of a read mesh

  std::vector<FieldShape> shapes() const;
  // The field `name` as it is stored: `size` points of its components, interleaved.
  Field stored(const std::string& name) const;
  bool empty() const { return fields_.empty(); }
  // The scalar `spec` chooses (InputError listing the fields when none), `note` as choose_field's.
  // Safe from several threads at once, as long as no set() runs beside it.
  Field scalar(const std::string& spec, const std::string& source, std::string* note = nullptr) const;

 private:
  struct Entry {
    std::string name;
    const double* values;
    std::int64_t n_points;
    int components;
  };
  std::vector<Entry> fields_;
  mutable std::mutex made_lock_;
  mutable std::map<std::string, std::vector<double>> made_;  // a choice's name -> its scalars
};

}  // namespace cellproj
