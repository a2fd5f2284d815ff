#pragma once
// A volume to render: a mesh committed once (checked, its face topology, boundary hull and sorter
// planes prepared on first use and kept), rendered with any number of fields, transfer functions,
// cameras and settings. A solver's new time step is a new Field, and costs no preparation.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/validate.hpp"
#include "visibility/methods.hpp"

namespace cellproj {

class ExactRenderer;
class ProjectionRenderer;
class SliceRenderer;

// A caller's cell arrays with 32- or 64-bit ids (connectivity and offsets alike).
struct CellArrays {
  const void* connectivity = nullptr;
  const void* offsets = nullptr;  // n_cells + 1 entries
  const std::uint8_t* types = nullptr;
  std::int64_t n_cells = 0;
  bool ids_32bit = false;               // int32 ids (widened once when the volume is committed), else int64
  std::int64_t connectivity_size = -1;  // entries in connectivity, checked against offsets; -1: unknown
};

// One value per point: a span over the caller's array, read during the render call only.
struct Field {
  const double* values = nullptr;
  std::int64_t size = 0;
  std::string name;  // for messages
  // The extinction from another field (ParaView's separate opacity array), `size` values per point
  // too; the colour then comes from `values` alone (optics/two_fields.hpp). Null: both from values.
  const double* opacity = nullptr;
  std::string opacity_name;
};
Field field_of(const Mesh& mesh, const std::string& name);  // the mesh's field `name` (InputError listing them)
// The same coloured by `name` and opaque by `opacity` (the field itself when empty).
Field field_of(const Mesh& mesh, const std::string& name, const std::string& opacity);

struct VolumeOptions {
  // The caller vouches for the mesh (ids in range, finite points, supported cells): validation is
  // skipped. A bad mesh then gives undefined results, not an error.
  bool trusted = false;
};

class Volume {
 public:
  // Validates the mesh (InputError naming source and element) unless `options.trusted`. Its arrays
  // are not copied and must outlive the volume, except where copies() says so: inverted cells are
  // re-oriented in a copy of the connectivity.
  explicit Volume(const MeshView& mesh, const VolumeOptions& options = {});
  // The same from 32- or 64-bit id arrays; 32-bit ids are widened into a copy.
  Volume(const PointArray& points, std::int64_t n_points, const CellArrays& cells, std::string source,
         const VolumeOptions& options = {});
  Volume(Volume&&) noexcept;
  Volume& operator=(Volume&&) noexcept;
  ~Volume();

  const MeshView& mesh() const;
  const ValidationReport& validation() const;  // empty when trusted
  // What the volume copied, one line each ("connectivity and offsets: 32-bit ids widened to 64
  // bits, 1 MB"): of the caller's arrays at commit, and each preparation's copy of the points
  // recentred on their bounding box (doubles, so huge coordinate offsets lose no precision).
  std::vector<std::string> copies() const;

  // The points moved (a solver's deforming mesh): the same cells over `points` (n_points of them,
  // as many as before), validated again unless `options.trusted`. Every preparation is dropped (face
  // topology, boundary hull, sorter planes: remade on next use); the connectivity and its copies are
  // kept. Not while a render of this volume runs.
  void set_points(const PointArray& points, std::int64_t n_points, const VolumeOptions& options = {});

  // Throws InputError unless `field` has one finite value per point.
  void check(const Field& field) const;

  // The preparations, each made on the first call that needs it (thread-safe) and kept.
  const ProjectionRenderer& projection(Tetrahedralize mode) const;
  const ExactRenderer& exact() const;
  const SliceRenderer& slicing(Tetrahedralize mode) const;
  // How many preparations were made so far: rendering a second field, view or transfer function
  // makes none.
  int preparations() const;

 private:
  struct State;
  void commit(const MeshView& mesh, const VolumeOptions& options);
  std::unique_ptr<State> state_;
};

}  // namespace cellproj
