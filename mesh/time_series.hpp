#pragma once
// Time series of meshes (libMini's 4D data, Roettger section 3): key frames at increasing times,
// each a file of a ParaView .pvd collection or of a numbered series (mesh_%04d.vtu), or a time
// step of one Exodus file. A SeriesPlayer holds at most two key frames and gives the field (and
// the points, when they move) interpolated linearly between them. The files are listed and read
// by io/series_files.hpp, which hands the player its KeyFrameReader: the player reads no file.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/validate.hpp"

namespace cellproj {

struct KeyFrame {
  double time = 0.0;
  std::string path;   // the file
  int time_step = 0;  // Exodus: the step in `path`
};

struct TimeSeries {
  std::string source;            // the .pvd, the pattern or the Exodus file, for messages
  std::vector<KeyFrame> frames;  // strictly increasing times
};

// Where time t falls: the key frames before and after it and the weight of `after` in [0, 1]
// (at a key frame's own time: that frame, weight 0). InputError outside the series' times.
struct SeriesPosition {
  std::size_t before = 0, after = 0;
  double weight = 0.0;
};
SeriesPosition locate(const TimeSeries& series, double t);

// One frame of the series: the point field interpolated at `time`, and the points (shared with the
// player's cells when the points do not move between key frames).
struct SeriesFrame {
  double time = 0.0;
  SeriesPosition position;
  std::shared_ptr<const std::vector<double>> points;
  std::vector<double> field;
};

// Reads one key frame, validated (io/series_files.hpp: key_frame_reader).
using KeyFrameReader = std::function<LoadedMesh(const KeyFrame&)>;

class SeriesPlayer {
 public:
  // `field`: the point field to interpolate (empty: a key frame's only one).
  SeriesPlayer(TimeSeries series, std::string field, KeyFrameReader read);

  // The frame at time t; reads a key frame only when t leaves the two it holds. Not reentrant:
  // one call at a time (a background thread may make the next frame while another renders the last).
  SeriesFrame frame_at(double t);

  const TimeSeries& series() const { return series_; }
  const std::string& field_name() const { return field_; }
  // The cells every key frame shares (connectivity, offsets, types; no points, no fields); valid
  // after the first frame_at.
  const Mesh& cells() const { return cells_; }
  MeshView view(const SeriesFrame& frame) const;                          // cells() with the frame's points
  const ValidationReport& first_report() const { return first_report_; }  // the first key frame read's
  bool points_move() const { return points_move_; }  // whether a key frame read so far moved a point
  int key_frames_read() const { return reads_; }
  double read_seconds() const { return read_seconds_; }

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  struct Held {
    std::size_t index = kNone;
    std::shared_ptr<const std::vector<double>> points;
    std::vector<double> field;
  };
  const Held& hold(std::size_t index, std::size_t keep);  // reads it unless held, keeping `keep`

  TimeSeries series_;
  std::string field_;
  KeyFrameReader read_;
  Mesh cells_;
  std::shared_ptr<const std::vector<double>> first_points_;
  Held held_[2];
  ValidationReport first_report_;
  bool points_move_ = false;
  int reads_ = 0;
  double read_seconds_ = 0.0;
};

}  // namespace cellproj
