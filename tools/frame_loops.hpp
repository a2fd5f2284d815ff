#pragma once
// The frame loops of `cellproj render` in one process, one function each: a time series played,
// slicing's progressive levels, and the frames of one mesh (one picture, a turntable or a timing
// run). Each hands its frames to the FrameWriter as they come and returns what it measured.
// Internal to the command line.
#include <string>
#include <vector>

#include "render/playback.hpp"
#include "render/renderer.hpp"
#include "tools/frame_output.hpp"
#include "tools/render_input.hpp"
#include "view/color_bar.hpp"

namespace cellproj {

// The camera of frame f: the prepared one turned by --orbit D spread over the frames; a playback
// keeps its camera; a timing run (--frames without --orbit) turns a degree per frame.
Camera frame_camera(const RenderArgs& a, const PreparedScene& prepared, int f);

// What every loop reads: the arguments, the scene loaded, the renderer, where frames go.
struct FrameJob {
  const RenderArgs& args;
  const Input& input;
  const Renderer& renderer;
  const RenderSettings& settings;
  FrameWriter& writer;

  // "frame 3/36, 512x512, pt-breakpoints, 0.052 s"
  std::string frame_what(int f, double seconds) const;
  Camera camera(int f) const { return frame_camera(args, input.prepared, f); }
};

// What a loop measured.
struct FrameLoop {
  std::vector<double> frame_times;
  double prepare_seconds = 0.0, render_seconds = 0.0;
  RenderReport report;        // the last frame's
  PlaybackStats playback;     // a time series
  ClipReport series_clipped;  // a time series is clipped as it plays
};

FrameLoop play_series_frames(const FrameJob& job);
FrameLoop progressive_levels(const FrameJob& job, const std::vector<int>& levels);
FrameLoop mesh_frames(const FrameJob& job);

}  // namespace cellproj
