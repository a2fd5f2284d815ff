#include "python/numpy_mesh.hpp"

#include <algorithm>

#include "base/error.hpp"
#include "mesh/field_choice.hpp"
#include "mesh/validate.hpp"

namespace cellproj::python {
namespace {

std::string dtype_name(const py::array& a) { return py::str(a.dtype()).cast<std::string>(); }

// `a` as a C-contiguous array of T, converting (and saying so) unless it already is one.
template <class T>
py::array as(py::array a, const char* what, std::vector<std::string>& conversions) {
  if (a.dtype().kind() == 'c')  // numpy would drop the imaginary part with a warning only
    throw InputError(std::string(what) + ": complex values (dtype " + py::str(a.dtype()).cast<std::string>() +
                     ") are not coordinates, ids or field values");
  if (py::isinstance<py::array_t<T>>(a) && (a.flags() & py::array::c_style)) return a;
  const std::string from = dtype_name(a);
  py::array out = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!out)
    throw InputError(std::string(what) + ": cannot convert dtype " + from + " to " +
                     py::str(py::dtype::of<T>()).cast<std::string>());
  conversions.push_back(std::string(what) + ": " + from + (a.flags() & py::array::c_style ? "" : " (not contiguous)") +
                        " copied as " + py::str(py::dtype::of<T>()).cast<std::string>());
  return out;
}

void need_1d(const py::array& a, const char* what) {
  if (a.ndim() != 1)
    throw InputError(std::string(what) + ": expected a 1-D array, got " + std::to_string(a.ndim()) + " dimensions");
}

// Integer ids as int64 or int32 (both arrays alike), anything else converted to int64.
bool ids_32bit(py::array& connectivity, py::array& offsets, std::vector<std::string>& conversions) {
  const bool c32 = py::isinstance<py::array_t<std::int32_t>>(connectivity),
             o32 = py::isinstance<py::array_t<std::int32_t>>(offsets);
  for (const py::array* a : {&connectivity, &offsets})
    if (a->dtype().kind() != 'i' && a->dtype().kind() != 'u')
      throw InputError(std::string(a == &connectivity ? "connectivity" : "offsets") +
                       ": expected integer ids, got dtype " + dtype_name(*a));
  if (c32 && o32) {
    connectivity = as<std::int32_t>(connectivity, "connectivity", conversions);
    offsets = as<std::int32_t>(offsets, "offsets", conversions);
    return true;
  }
  connectivity = as<std::int64_t>(connectivity, "connectivity", conversions);
  offsets = as<std::int64_t>(offsets, "offsets", conversions);
  return false;
}

// Points as they are when float64 or float32 with packed x, y, z in each row; else `points` becomes
// a float64 copy (said in `conversions`).
PointArray points_of(py::array& points, std::vector<std::string>& conversions) {
  const bool row_packed = points.ndim() == 2 && points.strides(1) == points.itemsize() && points.strides(0) > 0;
  if (py::isinstance<py::array_t<double>>(points) && row_packed)
    return PointArray::strided(static_cast<const double*>(points.data()), points.strides(0));
  if (py::isinstance<py::array_t<float>>(points) && row_packed)
    return PointArray::strided(static_cast<const float*>(points.data()), points.strides(0));
  points = as<double>(points, "points", conversions);
  return PointArray(static_cast<const double*>(points.data()));
}

}  // namespace

NumpyMesh::NumpyMesh(py::array points, py::array connectivity, py::array offsets, py::array types, py::object scalars,
                     std::string source) {
  if (points.ndim() != 2 || points.shape(1) != 3) {
    std::string shape;
    for (py::ssize_t d = 0; d < points.ndim(); ++d) shape += (d ? ", " : "") + std::to_string(points.shape(d));
    throw InputError(where(source, "points: expected shape (N, 3), got (" + shape + ")"));
  }
  need_1d(connectivity, "connectivity");
  need_1d(offsets, "offsets");
  need_1d(types, "types");
  if (offsets.shape(0) != types.shape(0) + 1)
    throw InputError(where(source, "offsets: expected one more entry than types (" +
                                       std::to_string(types.shape(0) + 1) + "), got " +
                                       std::to_string(offsets.shape(0)) +
                                       " (VTK's layout: cell c is connectivity[offsets[c]:offsets[c+1]])"));
  const PointArray point_array = points_of(points, conversions_);
  if (types.dtype().kind() != 'u' && types.dtype().kind() != 'i')
    throw InputError(where(source, "types: expected VTK cell type codes (uint8), got dtype " + dtype_name(types)));
  if (!py::isinstance<py::array_t<std::uint8_t>>(types)) {
    const py::array_t<std::int64_t> wide = py::array_t<std::int64_t, py::array::forcecast>::ensure(types);
    const auto* t = wide.data();
    for (py::ssize_t c = 0; c < wide.size(); ++c)
      if (t[c] < 0 || t[c] > 255)
        throw InputError(where(source, "types: cell " + std::to_string(c) + " has type " + std::to_string(t[c]) +
                                           ", not a VTK cell type code"));
  }
  types = as<std::uint8_t>(types, "types", conversions_);
  const bool narrow = ids_32bit(connectivity, offsets, conversions_);
  keep_ = {points, connectivity, offsets, types};
  CellArrays cells;
  cells.connectivity = connectivity.data();
  cells.offsets = offsets.data();
  cells.types = static_cast<const std::uint8_t*>(types.data());
  cells.n_cells = types.shape(0);
  cells.ids_32bit = narrow;
  cells.connectivity_size = connectivity.shape(0);
  volume_ = std::make_unique<Volume>(point_array, points.shape(0), cells, source);
  if (py::isinstance<py::dict>(scalars)) {
    for (const auto& [name, values] : scalars.cast<py::dict>())
      add_field(py::str(name).cast<std::string>(), py::array::ensure(values));
  } else if (!scalars.is_none()) {
    add_field("scalars", py::array::ensure(scalars));
  }
}

NumpyMesh::NumpyMesh(std::shared_ptr<const Mesh> read, bool trusted) : read_(std::move(read)) {
  volume_ = std::make_unique<Volume>(read_->view(), VolumeOptions{trusted});
  fields_.add(*volume_, *read_);
}

void NumpyMesh::add_field(const std::string& name, py::array values) {
  const std::string what = "field '" + name + "'";
  if (!values) throw InputError(what + ": expected an array of one value per point");
  if (values.ndim() != 1 && values.ndim() != 2)
    throw InputError(what + ": expected shape (N,) or (N, k) for k components, got " + std::to_string(values.ndim()) +
                     " dimensions");
  const int components = values.ndim() == 2 ? static_cast<int>(values.shape(1)) : 1;
  if (components < 1 || components > 9)
    throw InputError(what + ": expected 1 to 9 components per point, got " + std::to_string(values.shape(1)));
  py::array v = as<double>(values, what.c_str(), conversions_);
  fields_.set(*volume_, name, static_cast<const double*>(v.data()), static_cast<std::int64_t>(v.size()), components);
  arrays_[name] = v;
}

void NumpyMesh::set_points(py::array points) {
  const std::int64_t n = view().n_points;
  if (!points || points.ndim() != 2 || points.shape(0) != n || points.shape(1) != 3)
    throw InputError(where(view().source, "points: expected shape (" + std::to_string(n) + ", 3), the mesh's points"));
  std::vector<std::string> conversions;
  const PointArray p = points_of(points, conversions);
  volume_->set_points(p, n);  // validated: a refused move leaves the mesh as it was
  moved_points_ = points;
  for (std::string& c : conversions) conversions_.push_back(std::move(c));
}

std::vector<double> NumpyMesh::point_coordinates() const {
  const MeshView& v = view();
  std::vector<double> xyz(static_cast<std::size_t>(v.n_points) * 3);
  for (std::int64_t p = 0; p < v.n_points; ++p) {
    const glm::dvec3 x = v.point(p);
    for (int k = 0; k < 3; ++k) xyz[static_cast<std::size_t>(p) * 3 + k] = x[k];
  }
  return xyz;
}

std::string NumpyMesh::stored_name(const std::string& spec) const {
  return choose_field(fields_.shapes(), spec, view().source).field;
}

py::array NumpyMesh::field_array(const std::string& spec, py::handle owner) const {
  const std::vector<FieldShape> shapes = fields_.shapes();
  const auto stored = std::find_if(shapes.begin(), shapes.end(), [&](const FieldShape& f) { return f.name == spec; });
  const int k = stored == shapes.end() ? 1 : stored->components;
  const Field f = k == 1 ? field(spec) : fields_.stored(spec);
  py::array a = k == 1 ? py::array(py::dtype::of<double>(), {f.size}, {sizeof(double)}, f.values, owner)
                       : py::array(py::dtype::of<double>(), {f.size, py::ssize_t(k)},
                                   {py::ssize_t(k * sizeof(double)), py::ssize_t(sizeof(double))}, f.values, owner);
  return read_only(a);
}

py::array read_only(py::array a) {
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

std::vector<std::string> NumpyMesh::copies() const {
  std::vector<std::string> out = conversions_;
  for (const auto& c : volume_->copies()) out.push_back(c);
  return out;
}

namespace {

// `a` (n,) or (n, k) as a field of n tuples, copied as float64.
PointField field_of_array(const std::string& name, py::handle a, std::int64_t n, const char* per,
                          const std::string& source) {
  const auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!v || (v.ndim() != 1 && v.ndim() != 2) || v.shape(0) != n)
    throw InputError(where(source, "field '" + name + "': expected " + std::to_string(n) + " values, one per " + per +
                                       " (or (" + std::to_string(n) + ", k) for k components)"));
  const int k = v.ndim() == 2 ? static_cast<int>(v.shape(1)) : 1;
  return {name, std::vector<double>(v.data(), v.data() + v.size()), std::string(per) + " data", k};
}

}  // namespace

std::shared_ptr<const Mesh> mesh_with_cell_data(py::array points, py::array connectivity, py::array offsets,
                                                py::array types, const py::dict& point_fields,
                                                const py::dict& cell_fields, CellData cell_data, std::string source) {
  const auto p = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points);
  const auto c = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(connectivity);
  const auto o = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(offsets);
  const auto t = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(types);
  if (!p || p.ndim() != 2 || p.shape(1) != 3) throw InputError(where(source, "points: expected shape (N, 3)"));
  if (!c || !o || !t || c.ndim() != 1 || o.ndim() != 1 || t.ndim() != 1 || o.shape(0) != t.shape(0) + 1)
    throw InputError(
        where(source, "connectivity, offsets and types: expected 1-D arrays, offsets one longer than types"));
  Mesh m;
  m.source = std::move(source);
  m.points.assign(p.data(), p.data() + p.size());
  m.connectivity.assign(c.data(), c.data() + c.size());
  m.offsets.assign(o.data(), o.data() + o.size());
  m.types.assign(t.data(), t.data() + t.size());
  if (m.offsets.front() != 0 || m.offsets.back() != static_cast<std::int64_t>(m.connectivity.size()))
    throw InputError(where(m.source, "offsets: expected 0 first and the connectivity's length last"));
  for (const auto& [name, a] : point_fields)
    m.fields.push_back(field_of_array(py::str(name), a, m.n_points(), "point", m.source));
  for (const auto& [name, a] : cell_fields)
    m.cell_fields.push_back(field_of_array(py::str(name), a, m.n_cells(), "cell", m.source));
  const ValidationReport report = validate(m.view());
  reorient_inverted(m, report);
  apply_cell_data(m, cell_data);
  return std::make_shared<const Mesh>(std::move(m));
}

}  // namespace cellproj::python
