#pragma once
// The files of a time series (mesh/time_series.hpp): a ParaView .pvd collection, a numbered
// series (mesh_%04d.vtu) or the time steps of one Exodus file, listed without reading a mesh,
// and the reader that loads one key frame for a SeriesPlayer.
#include <string>

#include "io/read_mesh.hpp"
#include "mesh/time_series.hpp"

namespace cellproj {

// Whether `path` names a series by its form alone: a .pvd collection, or a pattern with one %d
// ("out/mesh_%04d.vtu"). An Exodus file is a series when it has several time steps.
bool is_series_path(const std::string& path);

// InputError unless `pattern`'s file name has exactly one %d (flags and width allowed: %04d) and
// no other %, and its folder none: a pattern safe to give printf.
void check_file_pattern(const std::string& pattern);

// The key frames, reading no mesh: a .pvd's DataSets (timestep and file, relative to the .pvd);
// the files a pattern matches, in the order of their numbers, each its number as time; an Exodus
// file's time steps with their times. InputError naming the file for a malformed collection, a
// missing file, a repeated time, no key frame, or a file that is none of these.
TimeSeries list_series(const std::string& path, const ReadOptions& options);

// The key frames' reader for a SeriesPlayer: load_mesh of the frame's file at its time step.
KeyFrameReader key_frame_reader(ReadOptions options);

}  // namespace cellproj
