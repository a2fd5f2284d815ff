#pragma once
// A time series behind cellproj.Series (libMini's 4D data, Roettger section 3): its key frames
// listed without reading a mesh, a key frame read whole, a frame at any time between them, and the
// playback that renders frames in order while the next one is made on a background thread
// (render/playback.hpp, as `cellproj render --animate`). Internal to the module.
#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

#include "io/read_mesh.hpp"
#include "mesh/time_series.hpp"

namespace cellproj::python {

namespace py = pybind11;

class NumpyMesh;

class Series {
 public:
  // Lists the key frames of a .pvd, a numbered pattern or an Exodus file's time steps.
  Series(const std::string& path, const ReadOptions& reader);

  const TimeSeries& listed() const { return listed_; }
  const ReadOptions& reader() const { return reader_; }
  std::vector<double> times() const;
  // Key frame i (negative from the end) read whole, every field, as cellproj.read reads a file.
  std::unique_ptr<NumpyMesh> key_frame(std::ptrdiff_t i) const;
  // The frame at t: the cells, the points at t and the scalar `spec` at t, its one field.
  std::unique_ptr<NumpyMesh> at(double t, const std::string& spec);

 private:
  TimeSeries listed_;
  ReadOptions reader_;
  std::string spec_;                      // the player's field
  std::unique_ptr<SeriesPlayer> player_;  // made for spec_
};

// A mesh of the player's cells with a frame's points and field (validated when the points move
// between key frames: interpolated points may fold a cell).
std::unique_ptr<NumpyMesh> frame_mesh(const SeriesPlayer& player, const SeriesFrame& frame);

// cellproj.Series and the playback behind cellproj.play.
void bind_series(py::module_& m);

}  // namespace cellproj::python
