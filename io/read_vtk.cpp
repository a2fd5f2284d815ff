// Readers that go through VTK: XML and legacy VTK files, Exodus II, CGNS and PLOT3D.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <unordered_map>

#include <vtkCGNSReader.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDataObjectTreeIterator.h>
#include <vtkDataReader.h>
#include <vtkDataSet.h>
#include <vtkDataSetReader.h>
#include <vtkExodusIIReader.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkMultiBlockPLOT3DReader.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkStructuredGrid.h>
#include <vtkStructuredGridReader.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkVersion.h>
#include <vtkXMLGenericDataObjectReader.h>

#include "base/error.hpp"
#include "base/file_status.hpp"
#include "base/huge_pages.hpp"
#include "io/legacy_vtk_check.hpp"
#include "io/netcdf_check.hpp"
#include "io/plot3d_header.hpp"
#include "io/read_mesh.hpp"
#include "io/vtk_messages.hpp"
#include "io/vtk_xml_check.hpp"
#include "mesh/geometry.hpp"

namespace fs = std::filesystem;

namespace cellproj {
namespace {

struct Leaf {
  vtkDataSet* data;
  std::string path;  // block names from the root, "/"-joined
};

std::vector<Leaf> leaves_of(vtkDataObject* obj) {
  std::vector<Leaf> out;
  if (auto* ds = vtkDataSet::SafeDownCast(obj)) {
    out.push_back({ds, ""});
    return out;
  }
  auto* tree = vtkDataObjectTree::SafeDownCast(obj);
  if (!tree) return out;
  vtkSmartPointer<vtkDataObjectTreeIterator> it;
  it.TakeReference(tree->NewTreeIterator());
  it->VisitOnlyLeavesOn();
  it->TraverseSubTreeOn();
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem()) {
    auto* ds = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
    if (!ds || ds->GetNumberOfPoints() == 0) continue;
    std::string name;
    if (it->HasCurrentMetaData() && it->GetCurrentMetaData()->Has(vtkCompositeDataSet::NAME()))
      name = it->GetCurrentMetaData()->Get(vtkCompositeDataSet::NAME());
    out.push_back({ds, name});
  }
  return out;
}

// VTK's readers take a cell array's offsets and types as the file gives them, and GetCellPoints
// then reads wherever garbled offsets point: they must start at 0, never decrease and end at the
// connectivity's length, with a type for every cell.
void check_cell_array(vtkDataSet* ds) {
  auto* ug = vtkUnstructuredGrid::SafeDownCast(ds);
  if (!ug || !ug->GetCells()) return;
  vtkCellArray* cells = ug->GetCells();
  vtkDataArray* offsets = cells->GetOffsetsArray();
  const vtkIdType n = cells->GetNumberOfCells(), ids = cells->GetNumberOfConnectivityIds();
  if (n > 0 && (!ug->GetCellTypesArray() || ug->GetCellTypesArray()->GetNumberOfValues() < n))
    throw InputError("the file has " + std::to_string(n) + " cells but " +
                     std::to_string(ug->GetCellTypesArray() ? ug->GetCellTypesArray()->GetNumberOfValues() : 0) +
                     " cell types");
  if (n == 0 || !offsets) return;
  check_offsets([&](std::int64_t c) { return static_cast<std::int64_t>(offsets->GetTuple1(c)); }, n, ids);
}

// Where each leaf's points and cells went in the assembled mesh.
struct LeafMap {
  std::vector<std::int64_t> point;  // leaf point -> mesh point
  std::vector<std::int64_t> cell;   // leaf cell -> mesh cell, or -1 when skipped
};

std::vector<LeafMap> assemble_geometry(const std::vector<Leaf>& leaves, Mesh& mesh) {
  // Blocks of one Exodus file share nodes through their global ids: merge on them.
  bool global_ids = leaves.size() > 1;
  for (const auto& l : leaves) global_ids &= l.data->GetPointData()->GetArray("GlobalNodeId") != nullptr;
  std::unordered_map<std::int64_t, std::int64_t> by_global;

  // The mesh's arrays reserved at once for what the leaves hold (in huge pages): not copied as
  // they grow. A leaf that is not a vtkUnstructuredGrid counts its largest cell for each.
  std::int64_t points = 0, cells = 0, ids_held = 0;
  for (const auto& l : leaves) {
    points += l.data->GetNumberOfPoints(), cells += l.data->GetNumberOfCells();
    auto* ug = vtkUnstructuredGrid::SafeDownCast(l.data);
    ids_held += ug && ug->GetCells() ? ug->GetCells()->GetNumberOfConnectivityIds()
                                     : l.data->GetNumberOfCells() * l.data->GetMaxCellSize();
  }
  reserve_in_huge_pages(mesh.points, static_cast<std::size_t>(mesh.points.size() + 3 * points));
  reserve_in_huge_pages(mesh.connectivity, static_cast<std::size_t>(mesh.connectivity.size() + ids_held));
  reserve_in_huge_pages(mesh.offsets, static_cast<std::size_t>(mesh.offsets.size() + cells));
  reserve_in_huge_pages(mesh.types, static_cast<std::size_t>(mesh.types.size() + cells));

  std::map<std::string, std::int64_t> skipped;
  std::vector<LeafMap> maps(leaves.size());
  auto ids = vtkSmartPointer<vtkIdList>::New();
  std::vector<std::int64_t> v;  // one cell's point ids, reused
  for (std::size_t b = 0; b < leaves.size(); ++b) {
    vtkDataSet* ds = leaves[b].data;
    vtkDataArray* gid = global_ids ? ds->GetPointData()->GetArray("GlobalNodeId") : nullptr;
    LeafMap& map = maps[b];
    map.point.resize(static_cast<std::size_t>(ds->GetNumberOfPoints()));
    for (vtkIdType p = 0; p < ds->GetNumberOfPoints(); ++p) {
      double x[3];
      ds->GetPoint(p, x);
      if (gid) {
        const auto key = static_cast<std::int64_t>(gid->GetTuple1(p));
        auto [it, fresh] = by_global.try_emplace(key, mesh.n_points());
        if (fresh) mesh.add_point({x[0], x[1], x[2]});
        map.point[p] = it->second;
      } else {
        map.point[p] = mesh.add_point({x[0], x[1], x[2]});
      }
    }
    check_cell_array(ds);
    auto* ug = vtkUnstructuredGrid::SafeDownCast(ds);
    vtkCellArray* cell_array = ug ? ug->GetCells() : nullptr;  // read in place, not copied cell by cell
    map.cell.assign(static_cast<std::size_t>(ds->GetNumberOfCells()), -1);
    for (vtkIdType c = 0; c < ds->GetNumberOfCells(); ++c) {
      const int type = ds->GetCellType(c);
      if (const int dim = vtk_type_dimension(type); dim >= 0 && dim < 3) {
        ++skipped[vtk_type_name(type)];
        continue;
      }
      vtkIdType size;
      const vtkIdType* cell_ids;
      if (cell_array) {
        cell_array->GetCellAtId(c, size, cell_ids);
      } else {
        ds->GetCellPoints(c, ids);
        size = ids->GetNumberOfIds(), cell_ids = ids->GetPointer(0);
      }
      v.resize(static_cast<std::size_t>(size));
      for (std::size_t k = 0; k < v.size(); ++k) {
        const vtkIdType id = cell_ids[k];
        if (id < 0 || id >= ds->GetNumberOfPoints())  // VTK's legacy reader lets these through
          throw InputError("cell " + std::to_string(mesh.n_cells()) + " (" + vtk_type_name(type) +
                           ") refers to point " + std::to_string(id) + ", out of range [0, " +
                           std::to_string(ds->GetNumberOfPoints()) + ")");
        v[k] = map.point[id];
      }
      std::uint8_t stored = static_cast<std::uint8_t>(type);
      if (type == 11 && v.size() == 8) {  // voxel -> hexahedron: VTK's voxel numbers its corners (x, y, z) binary
        std::swap(v[2], v[3]);
        std::swap(v[6], v[7]);
        stored = static_cast<std::uint8_t>(CellType::Hexahedron);
      }
      // Unsupported 3D types are kept as read, so that validation names them with their count.
      mesh.connectivity.insert(mesh.connectivity.end(), v.begin(), v.end());
      mesh.offsets.push_back(static_cast<std::int64_t>(mesh.connectivity.size()));
      mesh.types.push_back(stored);
      map.cell[c] = mesh.n_cells() - 1;
    }
  }
  if (!skipped.empty()) {
    std::string what = "skipped cells of dimension < 3 (a volume renderer has nothing to draw for them):";
    for (const auto& [name, n] : skipped) what += " " + name + " x" + std::to_string(n);
    mesh.notes.push_back(what);
  }
  return maps;
}

bool internal_array(const char* name) {
  const std::string n = name ? name : "";
  return n.empty() || n.rfind("vtk", 0) == 0 || n == "GlobalNodeId" || n == "PedigreeNodeId" ||
         n == "GlobalElementId" || n == "PedigreeElementId" || n == "ObjectId";
}

// Tuple i of `a` into out[0 .. components).
void read_tuple(vtkDataArray* a, vtkIdType i, double* out) {
  for (int k = 0; k < a->GetNumberOfComponents(); ++k) out[k] = a->GetComponent(i, k);
}

void assemble_fields(const std::vector<Leaf>& leaves, const std::vector<LeafMap>& maps, Mesh& mesh) {
  struct Source {
    std::vector<vtkDataArray*> per_leaf;
    bool cell;
    std::string array;
  };
  std::map<std::string, Source> sources;  // field name -> array in each leaf
  auto collect = [&](vtkFieldData* fd, std::size_t b, bool cell) {
    for (int i = 0; i < fd->GetNumberOfArrays(); ++i) {
      vtkDataArray* a = vtkDataArray::SafeDownCast(fd->GetAbstractArray(i));
      if (!a || internal_array(a->GetName())) continue;
      std::string name = a->GetName();
      if (cell && sources.count(name) && !sources[name].cell) name += "_cell";
      auto& s = sources[name];
      s.cell = cell;
      s.array = a->GetName();
      s.per_leaf.resize(leaves.size(), nullptr);
      s.per_leaf[b] = a;
    }
  };
  for (std::size_t b = 0; b < leaves.size(); ++b) collect(leaves[b].data->GetPointData(), b, false);
  for (std::size_t b = 0; b < leaves.size(); ++b) collect(leaves[b].data->GetCellData(), b, true);

  for (auto& [name, s] : sources) {
    if (std::find(s.per_leaf.begin(), s.per_leaf.end(), nullptr) != s.per_leaf.end()) {
      mesh.notes.push_back("field '" + name + "' dropped: not present in every block");
      continue;
    }
    const int nc = s.per_leaf[0]->GetNumberOfComponents();
    if (std::any_of(s.per_leaf.begin(), s.per_leaf.end(),
                    [nc](vtkDataArray* a) { return a->GetNumberOfComponents() != nc; })) {
      mesh.notes.push_back("field '" + name + "' dropped: its number of components differs between blocks");
      continue;
    }
    if (!s.cell) {
      PointField& f = mesh.add_field(name, "point data", nc);
      for (std::size_t b = 0; b < leaves.size(); ++b)
        for (std::size_t p = 0; p < maps[b].point.size(); ++p)
          read_tuple(s.per_leaf[b], static_cast<vtkIdType>(p), &f.values[maps[b].point[p] * nc]);
      continue;
    }
    // Cell data kept per cell: mesh/cell_data.hpp draws it constant over each cell or averages it.
    PointField f{name, std::vector<double>(static_cast<std::size_t>(mesh.n_cells() * nc), 0.0),
                 "cell data '" + s.array + "'", nc};
    for (std::size_t b = 0; b < leaves.size(); ++b)
      for (std::size_t lc = 0; lc < maps[b].cell.size(); ++lc)
        if (const std::int64_t c = maps[b].cell[lc]; c >= 0)
          read_tuple(s.per_leaf[b], static_cast<vtkIdType>(lc), &f.values[c * nc]);
    mesh.cell_fields.push_back(std::move(f));
  }
}

Mesh assemble_leaves(std::vector<Leaf> leaves, const std::string& path, const std::string& zone);

Mesh assemble(vtkDataObject* data, const std::string& path, const std::string& zone) {
  try {
    return assemble_leaves(leaves_of(data), path, zone);
  } catch (const InputError& e) {
    const std::string what = e.what();
    throw InputError(what.rfind(path, 0) == 0 ? what : where(path, what));
  }
}

Mesh assemble_leaves(std::vector<Leaf> leaves, const std::string& path, const std::string& zone) {
  if (!zone.empty()) {
    std::vector<Leaf> picked;
    std::vector<std::string> names;
    for (const auto& l : leaves) {
      names.push_back(l.path);
      if (l.path == zone) picked.push_back(l);
    }
    if (picked.empty()) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      throw InputError(where(path, "no zone named '" + zone + "'; the zones are: " + list));
    }
    leaves = picked;
  }
  if (leaves.empty()) throw InputError(where(path, "contains no dataset with points"));
  Mesh mesh;
  const auto maps = assemble_geometry(leaves, mesh);
  assemble_fields(leaves, maps, mesh);
  if (leaves.size() > 1) mesh.notes.push_back("assembled from " + std::to_string(leaves.size()) + " blocks");
  return mesh;
}

// A polyhedron's cell is stored as a face stream, not as the point list the counts below assume;
// such a file is left to the conversion, which names the cell type.
bool has_polyhedra(vtkDataSet* ds) {
  auto* ug = vtkUnstructuredGrid::SafeDownCast(ds);
  if (!ug || !ug->GetCellTypesArray()) return false;
  vtkUnsignedCharArray* types = ug->GetCellTypesArray();
  for (vtkIdType i = 0; i < types->GetNumberOfValues(); ++i)
    if (types->GetValue(i) == VTK_POLYHEDRON) return true;
  return false;
}

// VTK's legacy reader fills a truncated ASCII array with zeros without a word. The values the
// returned dataset holds must all be in the file: count the numbers on its data lines.
void check_legacy_ascii_complete(const std::string& path, vtkDataObject* obj) {
  auto* ds = vtkDataSet::SafeDownCast(obj);
  if (!ds || legacy_file_encoding(path) != LegacyEncoding::ascii) return;
  std::ifstream in(path);
  std::string line;
  for (int i = 0; i < 3 && std::getline(in, line); ++i) {
  }
  std::uintmax_t numbers = 0;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || !(std::isdigit(static_cast<unsigned char>(line[first])) || line[first] == '-' ||
                                        line[first] == '+' || line[first] == '.'))
      continue;  // a keyword line
    std::istringstream words(line);
    for (std::string w; words >> w;) ++numbers;
  }
  std::uintmax_t needed = 0;
  if (vtkPointSet::SafeDownCast(ds)) needed += 3 * static_cast<std::uintmax_t>(ds->GetNumberOfPoints());
  if (auto* ug = vtkUnstructuredGrid::SafeDownCast(ds); ug && ug->GetCells())
    needed += static_cast<std::uintmax_t>(ug->GetCells()->GetNumberOfConnectivityIds() + 2 * ug->GetNumberOfCells());
  for (vtkFieldData* fd :
       {static_cast<vtkFieldData*>(ds->GetPointData()), static_cast<vtkFieldData*>(ds->GetCellData())})
    for (int i = 0; i < fd->GetNumberOfArrays(); ++i)
      if (auto* a = fd->GetAbstractArray(i)) needed += static_cast<std::uintmax_t>(a->GetNumberOfValues());
  if (numbers < needed)
    throw InputError(where(path, "truncated: its arrays need " + std::to_string(needed) + " numbers, the file holds " +
                                     std::to_string(numbers)));
}

// VTK's legacy reader takes a binary file cut inside its last arrays without a word. The file must
// hold at least the bytes of every array it returned, besides its four header lines: cell types
// as 4-byte ints; cells as 4-byte counts and ids before format 5, as offset and connectivity
// arrays of their declared type from 5 on.
void check_legacy_binary_complete(const std::string& path, vtkDataObject* obj) {
  auto* ds = vtkDataSet::SafeDownCast(obj);
  if (!ds || legacy_file_encoding(path) != LegacyEncoding::binary) return;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::uintmax_t needed = 0;  // a lower bound of the file's size
  double version = 0.0;
  for (int i = 0; i < 4 && std::getline(in, line); ++i) {
    needed += line.size() + 1;
    if (i == 0 && line.find("Version") != std::string::npos)
      version = std::atof(line.substr(line.find("Version") + 7).c_str());
  }
  auto bytes = [](vtkAbstractArray* a) {
    return a ? static_cast<std::uintmax_t>(a->GetNumberOfValues()) * static_cast<std::uintmax_t>(a->GetDataTypeSize())
             : 0;
  };
  if (auto* ps = vtkPointSet::SafeDownCast(ds); ps && ps->GetPoints()) needed += bytes(ps->GetPoints()->GetData());
  if (auto* ug = vtkUnstructuredGrid::SafeDownCast(ds); ug && ug->GetCells()) {
    vtkCellArray* cells = ug->GetCells();
    const auto n = static_cast<std::uintmax_t>(ug->GetNumberOfCells());
    needed += version >= 5.0 ? bytes(cells->GetOffsetsArray()) + bytes(cells->GetConnectivityArray())
                             : 4 * (n + static_cast<std::uintmax_t>(cells->GetNumberOfConnectivityIds()));
    needed += 4 * n;
  }
  for (vtkFieldData* fd : {ds->GetFieldData(), static_cast<vtkFieldData*>(ds->GetPointData()),
                           static_cast<vtkFieldData*>(ds->GetCellData())})
    for (int i = 0; fd && i < fd->GetNumberOfArrays(); ++i)
      if (auto* a = fd->GetAbstractArray(i); a && a->GetDataTypeSize() > 0 && !vtkStringArray::SafeDownCast(a))
        needed += bytes(a);
  // The text lines between the arrays are in the file too: keyword lines, and a FIELD block's
  // array lines (the array's name, spaces written %20, then its sizes).
  in.clear();
  in.seekg(0);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto size = static_cast<std::uintmax_t>(text.size());
  std::vector<std::string> starts = {"POINTS ",     "CELLS ",     "OFFSETS ", "CONNECTIVITY ", "CELL_TYPES ",
                                     "POINT_DATA ", "CELL_DATA ", "SCALARS ", "LOOKUP_TABLE ", "VECTORS ",
                                     "NORMALS ",    "TENSORS ",   "FIELD ",   "METADATA",      "INFORMATION ",
                                     "NAME ",       "DATA "};
  for (vtkFieldData* fd : {ds->GetFieldData(), static_cast<vtkFieldData*>(ds->GetPointData()),
                           static_cast<vtkFieldData*>(ds->GetCellData())})
    for (int i = 0; fd && i < fd->GetNumberOfArrays(); ++i)
      if (const char* name = fd->GetAbstractArray(i) ? fd->GetAbstractArray(i)->GetName() : nullptr) {
        std::string encoded;
        for (const char* c = name; *c; ++c) encoded += *c == ' ' ? std::string("%20") : std::string(1, *c);
        starts.push_back(encoded + " ");
      }
  std::sort(starts.begin(), starts.end());
  starts.erase(std::unique(starts.begin(), starts.end()), starts.end());
  for (const std::string& start : starts)
    for (auto at = text.find("\n" + start); at != std::string::npos; at = text.find("\n" + start, at + 1)) {
      const auto end = text.find('\n', at + 1);
      if (end != std::string::npos && end - at < 256) needed += end - at;
    }
  if (size < needed)
    throw InputError(where(path, "truncated: its arrays need at least " + std::to_string(needed) +
                                     " bytes, the file has " + std::to_string(size)));
}

template <class Reader>
Mesh run(Reader* reader, const std::string& path, const VtkMessages& messages, const std::string& zone = "") {
  reader->Update();
  messages.throw_if_failed(path);
  if (!reader->GetOutputDataObject(0)) throw InputError(where(path, "VTK produced no data"));
  return assemble(reader->GetOutputDataObject(0), path, zone);
}

std::string plot3d_q_file(const std::string& xyz, const ReadOptions& o) {
  if (!o.q_file.empty()) {
    if (!path_exists(o.q_file)) throw InputError(where(o.q_file, "PLOT3D solution (q) file not found"));
    return o.q_file;
  }
  const fs::path p(xyz);
  std::string name = p.filename().string();
  const auto at = name.rfind("xyz");
  if (at == std::string::npos) return "";
  name.replace(at, 3, "q");
  const fs::path q = p.parent_path() / name;
  return path_exists(q.string()) ? q.string() : "";
}

// A legacy reader set to read `path` with every scalar, vector and field array, not only the
// first of each kind.
void read_every_array(vtkDataReader* r, const std::string& path) {
  r->SetFileName(path.c_str());
  r->ReadAllScalarsOn();
  r->ReadAllVectorsOn();
  r->ReadAllFieldsOn();
}

// A legacy structured grid is read by its own reader's mesh pass alone: VTK 9.1's pipeline first
// runs a metadata pass (vtkStructuredGridReader::ReadMetaDataSimple) that takes every word of the
// file starting with "field" for a FIELD block, so an array named "field_strength", or bytes of
// the binary coordinates, crashed it on a good file.
Mesh read_legacy_structured_grid(const std::string& path, const VtkMessages& messages) {
  auto r = vtkSmartPointer<vtkStructuredGridReader>::New();
  read_every_array(r, path);
  auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
  r->ReadMeshSimple(path, grid);
  messages.throw_if_failed(path);
  check_legacy_ascii_complete(path, grid);
  check_legacy_binary_complete(path, grid);
  return assemble(grid, path, "");
}

bool all_zero(const Mesh& m, const std::string& field) {
  const auto* f = m.find_field(field);
  return f && std::all_of(f->values.begin(), f->values.end(), [](double v) { return v == 0.0; });
}

}  // namespace

std::string vtk_library_version() { return vtkVersion::GetVTKVersion(); }

Mesh assemble_vtk_object(vtkDataObject* data, const std::string& source) {
  Mesh mesh = assemble(data, source, "");
  mesh.source = source;
  return mesh;
}

Mesh read_vtk_family(const std::string& path, const std::string& format, const ReadOptions& o) {
  VtkMessages messages;
  if (format == "vtk-xml") {
    // VTK does not always notice raw appended data cut short; a whole file ends with </VTKFile>.
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    const std::streamoff size = in.tellg();
    std::string tail(static_cast<std::size_t>(std::min<std::streamoff>(size, 256)), '\0');
    in.seekg(size - static_cast<std::streamoff>(tail.size()));
    in.read(tail.data(), static_cast<std::streamsize>(tail.size()));
    if (tail.find("</VTKFile>") == std::string::npos)
      throw InputError(where(path, "truncated: a VTK XML file ends with </VTKFile>, this one does not"));
    check_vtk_xml(path);
    auto r = vtkSmartPointer<vtkXMLGenericDataObjectReader>::New();
    r->SetFileName(path.c_str());
    Mesh mesh = run(r.Get(), path, messages);
    const auto ext = fs::path(path).extension().string();
    if (ext == ".pvtu" || ext == ".pvts")  // the pieces repeat their interface points
      if (const std::int64_t merged = merge_coincident_points(mesh))
        mesh.notes.push_back(std::to_string(merged) + " coincident points of the pieces merged");
    return mesh;
  }
  if (format == "vtk-legacy") {
    check_legacy_cells(path);
    if (legacy_dataset_is(path, "structured_grid")) return read_legacy_structured_grid(path, messages);
    auto r = vtkSmartPointer<vtkDataSetReader>::New();
    read_every_array(r, path);
    r->Update();
    messages.throw_if_failed(path);
    if (!has_polyhedra(vtkDataSet::SafeDownCast(r->GetOutputDataObject(0)))) {
      check_legacy_ascii_complete(path, r->GetOutputDataObject(0));
      check_legacy_binary_complete(path, r->GetOutputDataObject(0));
    }
    return run(r.Get(), path, messages);
  }
  if (format == "exodus") {
    auto r = vtkSmartPointer<vtkExodusIIReader>::New();
    check_netcdf_readable(path);
    if (!r->CanReadFile(path.c_str())) throw InputError(where(path, "not a readable Exodus II file"));
    r->SetFileName(path.c_str());
    r->UpdateInformation();
    messages.throw_if_failed(path);
    r->SetAllArrayStatus(vtkExodusIIReader::NODAL, 1);
    r->SetAllArrayStatus(vtkExodusIIReader::ELEM_BLOCK, 1);
    r->GenerateGlobalNodeIdArrayOn();
    const int steps = r->GetNumberOfTimeSteps();
    if (o.time_step < 0 || (steps > 0 && o.time_step >= steps) || (steps == 0 && o.time_step != 0))
      throw InputError(where(path, "time step " + std::to_string(o.time_step) + " out of range: the file has " +
                                       std::to_string(steps) + " time steps"));
    r->SetTimeStep(o.time_step);
    return run(r.Get(), path, messages);
  }
  if (format == "cgns") {
    auto r = vtkSmartPointer<vtkCGNSReader>::New();
    if (!r->CanReadFile(path.c_str())) throw InputError(where(path, "not a readable CGNS file"));
    r->SetFileName(path.c_str());
    r->UpdateInformation();
    messages.throw_if_failed(path);
    r->EnableAllBases();
    r->EnableAllPointArrays();
    r->EnableAllCellArrays();
    r->LoadBndPatchOff();
    return run(r.Get(), path, messages, o.zone);
  }
  if (format == "plot3d") {
    // A header no layout of the file fits, or a q file that does not match it, is refused before VTK reads them.
    const std::optional<Plot3dLayout> layout = plot3d_layout(path);
    auto r = vtkSmartPointer<vtkMultiBlockPLOT3DReader>::New();
    r->SetXYZFileName(path.c_str());
    const std::string q = plot3d_q_file(path, o);
    if (layout && !q.empty()) check_plot3d_q(q, *layout);
    if (!q.empty()) r->SetQFileName(q.c_str());
    r->AutoDetectFormatOn();
    if (!q.empty()) {
      r->AddFunction(110);  // pressure
      r->AddFunction(153);  // velocity magnitude
    }
    Mesh m = run(r.Get(), path, messages);
    if (m.n_cells() == 0) throw InputError(where(path, "PLOT3D grid has no 3D cells (wrong format or dimensions?)"));
    if (q.empty())
      m.notes.push_back("PLOT3D grid read without a solution (q) file: no fields");
    else
      m.notes.push_back("PLOT3D solution from " + q);
    if (all_zero(m, "StagnationEnergy")) {  // pressure from zero energy is meaningless
      m.fields.erase(
          std::remove_if(m.fields.begin(), m.fields.end(), [](const PointField& f) { return f.name == "Pressure"; }),
          m.fields.end());
      m.notes.push_back("StagnationEnergy is zero everywhere: derived Pressure omitted");
    }
    return m;
  }
  throw InputError(where(path, "not a VTK-family format: " + format));
}

}  // namespace cellproj

#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include "io/vtk_points.hpp"

namespace cellproj {

Mesh read_vtk_points(const std::string& path) {
  VtkMessages messages;
  auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  r->SetFileName(path.c_str());
  r->Update();
  messages.throw_if_failed(path);
  vtkDataSet* ds = r->GetOutput();
  if (!ds || ds->GetNumberOfPoints() == 0) throw InputError(where(path, "contains no points"));
  Mesh m;
  const std::vector<Leaf> leaves{{ds, ""}};
  assemble_fields(leaves, assemble_geometry(leaves, m), m);
  m.connectivity.clear();  // the polydata's own vertices or polygons are not volume cells
  m.offsets.assign(1, 0);
  m.types.clear();
  m.notes.clear();
  return m;
}

}  // namespace cellproj
