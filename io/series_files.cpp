#include "io/series_files.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <regex>

#include <netcdf.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include "base/error.hpp"
#include "base/file_status.hpp"
#include "io/netcdf_check.hpp"
#include "io/vtk_messages.hpp"

namespace fs = std::filesystem;

namespace cellproj {
namespace {

// A ParaView collection: <VTKFile type="Collection"><Collection><DataSet timestep=".." file=".."/>.
std::vector<KeyFrame> pvd_frames(const std::string& path) {
  if (!path_is_file(path)) throw InputError(where(path, "no such file"));
  // A collection lists files: a few hundred bytes a key frame. The parser holds it whole.
  if (const auto bytes = fs::file_size(path); bytes > (64u << 20))
    throw InputError(where(path, "is " + std::to_string(bytes >> 20) +
                                     " MiB: too large for a ParaView collection "
                                     "(a list of files), which this reads whole"));
  vtkSmartPointer<vtkXMLDataElement> root;
  {
    VtkMessages messages;
    root.TakeReference(vtkXMLUtilities::ReadElementFromFile(path.c_str()));
    if (!root) messages.throw_if_failed(path);
  }
  if (!root) throw InputError(where(path, "not an XML file"));
  const char* type = root->GetAttribute("type");
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  if (std::string(root->GetName() ? root->GetName() : "") != "VTKFile" || !type || std::string(type) != "Collection" ||
      !collection)
    throw InputError(where(path,
                           "not a ParaView collection (.pvd): expected <VTKFile type=\"Collection\"> holding "
                           "a <Collection>"));
  std::vector<KeyFrame> frames;
  const fs::path folder = fs::path(path).parent_path();
  for (int k = 0; k < collection->GetNumberOfNestedElements(); ++k) {
    vtkXMLDataElement* d = collection->GetNestedElement(k);
    if (std::string(d->GetName()) != "DataSet") continue;
    const std::string element = "DataSet " + std::to_string(frames.size());
    const char* file = d->GetAttribute("file");
    if (!file || !*file) throw InputError(where(path, element + " has no file attribute"));
    if (const char* part = d->GetAttribute("part"); part && std::string(part) != "0")
      throw InputError(where(path, element + " is part " + part +
                                       " of its time step: collections of several parts per step are not read"));
    double time = static_cast<double>(frames.size());
    if (const char* t = d->GetAttribute("timestep")) {
      char* end = nullptr;
      time = std::strtod(t, &end);
      if (end == t || *end != '\0' || !std::isfinite(time))
        throw InputError(where(path, element + " has timestep=\"" + t + "\", not a finite number"));
    }
    const fs::path p = fs::path(file).is_absolute() ? fs::path(file) : folder / file;
    frames.push_back({time, p.string(), 0});
  }
  return frames;
}

// The prefix and suffix around the one %d of a pattern's file name.
std::pair<std::string, std::string> pattern_parts(const std::string& pattern) {
  const fs::path folder = fs::path(pattern).parent_path();
  const std::string name = fs::path(pattern).filename().string();
  const std::regex conversion("%0?[0-9]*d");
  std::smatch m;
  // The name is a printf format: nothing but its one %d may be a conversion.
  if (!std::regex_search(name, m, conversion) || folder.string().find('%') != std::string::npos ||
      std::count(name.begin(), name.end(), '%') != 1)
    throw InputError(where(pattern,
                           "a numbered series names its files with one %d in the file name and no other %, "
                           "such as mesh_%04d.vtu"));
  return {m.prefix(), m.suffix()};
}

// The files "dir/mesh_%04d.vtu" names, by number: any run of digits that the pattern prints back.
std::vector<KeyFrame> numbered_frames(const std::string& pattern) {
  const fs::path folder = fs::path(pattern).parent_path();
  const std::string name = fs::path(pattern).filename().string();
  const auto [prefix, suffix] = pattern_parts(pattern);
  std::vector<KeyFrame> frames;
  std::error_code ec;
  const fs::path dir = folder.empty() ? fs::path(".") : folder;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string f = entry.path().filename().string();
    if (f.size() <= prefix.size() + suffix.size() || f.compare(0, prefix.size(), prefix) != 0 ||
        f.compare(f.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    const std::string digits = f.substr(prefix.size(), f.size() - prefix.size() - suffix.size());
    if (digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), ::isdigit)) continue;
    const int number = std::stoi(digits);
    char printed[512];
    std::snprintf(printed, sizeof printed, name.c_str(), number);
    if (f == printed) frames.push_back({static_cast<double>(number), (folder / f).string(), 0});
  }
  if (ec) throw InputError(where(pattern, "cannot list its folder: " + ec.message()));
  return frames;
}

// An Exodus file's time steps, from its variable time_whole (netCDF, after the header is checked).
std::vector<KeyFrame> exodus_frames(const std::string& path) {
  check_netcdf_readable(path);
  int id = 0;
  if (int err = nc_open(path.c_str(), NC_NOWRITE, &id); err != NC_NOERR)
    throw InputError(where(path, std::string("not a readable Exodus II file: ") + nc_strerror(err)));
  std::vector<double> times;
  int var = 0, dim = 0, ndims = 0;
  std::size_t steps = 0;
  if (nc_inq_varid(id, "time_whole", &var) == NC_NOERR && nc_inq_varndims(id, var, &ndims) == NC_NOERR && ndims == 1 &&
      nc_inq_vardimid(id, var, &dim) == NC_NOERR && nc_inq_dimlen(id, dim, &steps) == NC_NOERR) {
    times.resize(steps);
    if (steps > 0 && nc_get_var_double(id, var, times.data()) != NC_NOERR) times.clear(), steps = 0;
  }
  nc_close(id);
  std::vector<KeyFrame> frames;
  for (std::size_t k = 0; k < times.size(); ++k) frames.push_back({times[k], path, static_cast<int>(k)});
  if (frames.empty()) frames.push_back({0.0, path, 0});  // no time steps: the one state of the mesh
  return frames;
}

}  // namespace

void check_file_pattern(const std::string& pattern) { pattern_parts(pattern); }

bool is_series_path(const std::string& path) {
  return lower_extension(path) == ".pvd" || fs::path(path).filename().string().find('%') != std::string::npos;
}

TimeSeries list_series(const std::string& path, const ReadOptions& options) {
  TimeSeries s{path, {}};
  const std::string ext = lower_extension(path);
  if (ext == ".pvd")
    s.frames = pvd_frames(path);
  else if (path.find('%') != std::string::npos)
    s.frames = numbered_frames(path);
  else if (options.format == "exodus" || (options.format.empty() && format_for(path) == "exodus"))
    s.frames = exodus_frames(path);
  else
    throw InputError(where(path,
                           "not a time series: give a ParaView collection (.pvd), a numbered series "
                           "(mesh_%04d.vtu) or an Exodus file with time steps"));
  if (s.frames.empty()) throw InputError(where(path, "names no key frame (no file of the series was found)"));
  std::stable_sort(s.frames.begin(), s.frames.end(),
                   [](const KeyFrame& a, const KeyFrame& b) { return a.time < b.time; });
  for (std::size_t k = 1; k < s.frames.size(); ++k)
    if (s.frames[k].time == s.frames[k - 1].time)
      throw InputError(where(path, "two key frames at time " + std::to_string(s.frames[k].time) + " (" +
                                       s.frames[k - 1].path + " and " + s.frames[k].path + ")"));
  return s;
}

KeyFrameReader key_frame_reader(ReadOptions options) {
  return [options](const KeyFrame& frame) {
    ReadOptions o = options;
    o.time_step = frame.time_step;
    return load_mesh(frame.path, o);
  };
}

}  // namespace cellproj
