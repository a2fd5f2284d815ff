#include "render/volume.hpp"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <mutex>

#include "base/error.hpp"
#include "frame/projection_renderer.hpp"
#include "raycast/reference_renderer.hpp"
#include "slicing/slice_renderer.hpp"

namespace cellproj {

struct Volume::State {
  MeshView mesh;
  ValidationReport validation;
  std::vector<std::int64_t> connectivity, offsets;  // copies, where the caller's could not serve
  std::vector<std::string> copies;
  std::size_t id_copies = 0;  // of copies, those of the caller's ids (kept when the points move)
  std::mutex mutex;
  std::unique_ptr<ProjectionRenderer> projection[3];  // by Tetrahedralize
  std::unique_ptr<ExactRenderer> exact;
  std::unique_ptr<SliceRenderer> slicing[3];  // by Tetrahedralize
  std::atomic<int> preparations{0};

  // The cells validation found inverted, re-oriented in a copy of the connectivity (made now unless
  // the volume has one): the caller's arrays are read-only.
  void reorient_inverted_cells();

  // The preparation in `slot`, made by make() under the lock on first use, counted, and its copy of
  // the mesh listed (what copied() says of it).
  template <class T, class Make, class Copied>
  const T& prepared(std::unique_ptr<T>& slot, Make&& make, Copied&& copied) {
    std::lock_guard<std::mutex> lock(mutex);
    if (!slot) {
      slot = make();
      ++preparations;
      copies.push_back(copied(*slot));
    }
    return *slot;
  }
};

namespace {

std::string megabytes(std::size_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MB", double(bytes) / 1e6);
  return text;
}

std::string points_copy(const MeshView& mesh, const char* what) {
  return std::string("points recentred for ") + what + ", " +
         megabytes(static_cast<std::size_t>(mesh.n_points) * 3 * sizeof(double));
}
}  // namespace

void Volume::State::reorient_inverted_cells() {
  if (validation.inverted.empty()) return;
  if (connectivity.empty()) connectivity.assign(mesh.connectivity, mesh.connectivity + mesh.offsets[mesh.n_cells]);
  reorient_inverted(connectivity.data(), mesh.offsets, mesh.types, validation);
  mesh.connectivity = connectivity.data();
  copies.push_back("connectivity: " + std::to_string(validation.inverted_cells) +
                   " inverted cells re-oriented in a copy, " + megabytes(connectivity.size() * sizeof(std::int64_t)));
}

Field field_of(const Mesh& mesh, const std::string& name) {
  const PointField& f = mesh.field(name);
  return {f.values.data(), static_cast<std::int64_t>(f.values.size()), f.name, nullptr, {}};
}

Field field_of(const Mesh& mesh, const std::string& name, const std::string& opacity) {
  Field f = field_of(mesh, name);
  if (opacity.empty()) return f;
  const PointField& o = mesh.field(opacity);
  f.opacity = o.values.data(), f.opacity_name = o.name;
  return f;
}

Volume::Volume(const MeshView& mesh, const VolumeOptions& options) : state_(std::make_unique<State>()) {
  commit(mesh, options);
}

Volume::Volume(const PointArray& points, std::int64_t n_points, const CellArrays& cells, std::string source,
               const VolumeOptions& options)
    : state_(std::make_unique<State>()) {
  if (cells.n_cells < 0 || !cells.offsets || !cells.types || !cells.connectivity || points.empty())
    throw InputError(where(source, "a null array or a negative cell count"));
  State& s = *state_;
  const auto* offsets = static_cast<const std::int64_t*>(cells.offsets);
  if (cells.ids_32bit) {
    const auto* off = static_cast<const std::int32_t*>(cells.offsets);
    s.offsets.assign(off, off + cells.n_cells + 1);
    offsets = s.offsets.data();
  }
  // The offsets say how much connectivity there is: checked before any of it is read.
  check_offsets(source, offsets, cells.n_cells);
  if (cells.connectivity_size >= 0 && offsets[cells.n_cells] != cells.connectivity_size)
    throw InputError(where(source, "the offsets end at " + std::to_string(offsets[cells.n_cells]) +
                                       " but the connectivity has " + std::to_string(cells.connectivity_size) +
                                       " entries"));
  MeshView v;
  v.points = points;
  v.n_points = n_points;
  v.offsets = offsets;
  v.types = cells.types;
  v.n_cells = cells.n_cells;
  v.source = std::move(source);
  v.connectivity = static_cast<const std::int64_t*>(cells.connectivity);
  if (cells.ids_32bit) {
    const auto* conn = static_cast<const std::int32_t*>(cells.connectivity);
    s.connectivity.assign(conn, conn + offsets[cells.n_cells]);
    v.connectivity = s.connectivity.data();
    s.copies.push_back("connectivity and offsets: 32-bit ids widened to 64 bits, " +
                       megabytes((s.connectivity.size() + s.offsets.size()) * sizeof(std::int64_t)));
  }
  commit(v, options);
}

void Volume::commit(const MeshView& mesh, const VolumeOptions& options) {
  State& s = *state_;
  s.mesh = mesh;
  s.id_copies = s.copies.size();
  if (options.trusted) return;
  s.validation = validate(mesh);
  s.reorient_inverted_cells();
}

void Volume::set_points(const PointArray& points, std::int64_t n_points, const VolumeOptions& options) {
  State& s = *state_;
  if (n_points != s.mesh.n_points || points.empty())
    throw InputError(where(s.mesh.source, "the moved points: expected " + std::to_string(s.mesh.n_points) +
                                              " points, got " + std::to_string(n_points)));
  MeshView moved = s.mesh;
  moved.points = points;
  // Validated before anything is dropped: a bad set of points leaves the volume as it was.
  ValidationReport report = options.trusted ? ValidationReport{} : validate(moved);
  std::lock_guard<std::mutex> lock(s.mutex);
  for (auto& p : s.projection) p.reset();
  for (auto& p : s.slicing) p.reset();
  s.exact.reset();
  s.copies.resize(s.id_copies);
  s.mesh = moved;
  s.validation = std::move(report);
  s.reorient_inverted_cells();
}

Volume::Volume(Volume&&) noexcept = default;
Volume& Volume::operator=(Volume&&) noexcept = default;
Volume::~Volume() = default;

const MeshView& Volume::mesh() const { return state_->mesh; }
const ValidationReport& Volume::validation() const { return state_->validation; }
std::vector<std::string> Volume::copies() const {
  std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->copies;
}
int Volume::preparations() const { return state_->preparations; }

void Volume::check(const Field& f) const {
  const MeshView& m = state_->mesh;
  const auto check = [&](const double* values, const std::string& field_name) {
    const std::string name = field_name.empty() ? "the field" : "field '" + field_name + "'";
    if (!values) throw InputError(where(m.source, "no field given: " + name + " has no values"));
    if (f.size != m.n_points)
      throw InputError(where(
          m.source, name + " has " + std::to_string(f.size) + " values for " + std::to_string(m.n_points) + " points"));
    for (std::int64_t p = 0; p < f.size; ++p)
      if (!std::isfinite(values[p]))
        throw InputError(where(
            m.source, name + " is not finite at point " + std::to_string(p) + " (" + std::to_string(values[p]) + ")"));
  };
  check(f.values, f.name);
  if (f.opacity) check(f.opacity, f.opacity_name.empty() ? "opacity" : f.opacity_name);
}

const ProjectionRenderer& Volume::projection(Tetrahedralize mode) const {
  State& s = *state_;
  return s.prepared(
      s.projection[static_cast<int>(mode)], [&] { return std::make_unique<ProjectionRenderer>(s.mesh, mode); },
      [&](const ProjectionRenderer&) { return points_copy(s.mesh, "projection"); });
}

const ExactRenderer& Volume::exact() const {
  State& s = *state_;
  return s.prepared(
      s.exact, [&] { return std::make_unique<ExactRenderer>(s.mesh); },
      [&](const ExactRenderer&) { return points_copy(s.mesh, "the exact renderer"); });
}

const SliceRenderer& Volume::slicing(Tetrahedralize mode) const {
  State& s = *state_;
  return s.prepared(
      s.slicing[static_cast<int>(mode)], [&] { return std::make_unique<SliceRenderer>(s.mesh, mode); },
      [&](const SliceRenderer& r) {
        const SliceCells& c = r.cells();
        return points_copy(s.mesh, "slicing") + "; the cells to slice (" + std::to_string(c.whole) + " whole, " +
               std::to_string(c.split) + " as tetrahedra), " +
               megabytes(c.ids.size() * sizeof(std::int64_t) + c.offsets.size() * sizeof(std::int64_t) +
                         c.types.size());
      });
}

}  // namespace cellproj
