#pragma once
// Mesh validation. Defects that make a picture wrong or a program crash are errors (InputError);
// defects a renderer can live with are counted in the report and shown as warnings.
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "mesh/mesh.hpp"

namespace cellproj {

struct ValidationReport {
  std::int64_t inverted_cells = 0;    // negative volume: re-oriented by reorient_inverted()
  std::int64_t degenerate_cells = 0;  // zero volume (round-off level): they contribute nothing
  std::int64_t duplicate_points = 0;  // points at the same coordinates as an earlier point
  std::int64_t first_inverted = -1, first_degenerate = -1, first_duplicate = -1;
  std::vector<double> volumes;         // signed volume per cell, as read
  std::vector<std::int64_t> inverted;  // the inverted cells, in order

  std::vector<std::string> warnings(const std::string& source) const;
};

// Throws InputError (naming the source and the first offending element) for: a cell with a wrong
// vertex count, an unsupported or unknown cell type (with the count of each), a point id out of
// range, a NaN or infinite coordinate.
ValidationReport validate(const MeshView& mesh);

// A mesh as read and validated (io/read_mesh.hpp's load_mesh), with what validation found.
struct LoadedMesh {
  Mesh mesh;
  ValidationReport report;
};

// Throws InputError (naming the source) unless offsets[0] is 0 and the offsets never decrease:
// what must hold before the connectivity they index can be read. validate() checks it first.
void check_offsets(const std::string& source, const std::int64_t* offsets, std::int64_t n_cells);

// Cells of types cellproj does not render, tallied per VTK type: how many and the first one.
// throw_if_any() names them all in one InputError of `source` (validate() and the legacy .vtk
// check, which finds polyhedra before VTK's reader would decompose their face streams).
class UnsupportedCellTypes {
 public:
  void add(int vtk_type, std::int64_t cell) { ++types_.try_emplace(vtk_type, 0, cell).first->second.first; }
  void throw_if_any(const std::string& source) const;

 private:
  std::map<int, std::pair<std::int64_t, std::int64_t>> types_;  // type -> (count, first cell)
};

// Throws InputError for the first non-finite value of a field.
void check_finite(const std::string& source, const PointField& field);

// Flips every inverted cell of an owned mesh so its volume is positive; returns how many.
std::int64_t reorient_inverted(Mesh& mesh, const ValidationReport& report);
// The same on writable cell arrays.
std::int64_t reorient_inverted(std::int64_t* connectivity, const std::int64_t* offsets, const std::uint8_t* types,
                               const ValidationReport& report);

}  // namespace cellproj
