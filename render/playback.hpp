#pragma once
// Playing a time series (libMini's 4D playback, Roettger section 3): each frame renders the field
// interpolated between the two key frames around its time, while a background thread reads the
// next key frame when needed and interpolates the next frame's field.
#include <functional>
#include <string>
#include <vector>

#include "mesh/clip.hpp"
#include "mesh/time_series.hpp"
#include "optics/transfer_function.hpp"
#include "render/renderer.hpp"
#include "view/camera.hpp"

namespace cellproj {

// "T0:T1:N": N frame times from T0 to T1 inclusive (N = 1: T0); InputError naming setting 'animate'.
std::vector<double> animation_times(const std::string& text);

struct PlaybackStats {
  double make_seconds = 0.0;  // reading key frames and interpolating, on whichever thread did it
  double wait_seconds = 0.0;  // of it, the time the renders waited for (the part not hidden)
  int volumes = 0;            // volumes committed: 1 when the points do not move, one a frame when they do
};

using FrameDone = std::function<void(int frame, Image&& image, const RenderReport& report)>;

// Renders the frames at `times` (the first given as `first`, made by the caller) with `renderer`,
// frame f seen by camera_of(f); done(f, ...) is called in order. With `prefetch`, frame f + 1 is
// made on a background thread while frame f renders; without it, in turn. The pictures are the
// same bits either way. With `clip` planes every frame is clipped (mesh/clip.hpp): while the points
// do not move, the cells once and each frame's field mapped onto the clipped points; `clipped`
// receives what the planes did to the first frame.
PlaybackStats play_series(SeriesPlayer& player, SeriesFrame first, const std::vector<double>& times, bool prefetch,
                          const Renderer& renderer, const TransferFunction& tf,
                          const std::function<Camera(int)>& camera_of, ImageSize size, const FrameDone& done,
                          const std::function<Progress(int)>& progress_of = {}, const std::vector<ClipPlane>& clip = {},
                          ClipReport* clipped = nullptr);

}  // namespace cellproj
