#pragma once
// Playing a time series (libMini's 4D playback, Roettger section 3): each frame renders the field
// interpolated between the two key frames around its time, while a background thread reads the
// next key frame when needed and interpolates the next frame's field.
#include <functional>
#include <future>
#include <memory>
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

// A series played frame by frame, in order: frame f renders the field at times[f] while, with
// `prefetch`, a background thread makes frame f + 1 (reads a key frame when needed and
// interpolates). With `clip` planes every frame is clipped (mesh/clip.hpp): while the points do not
// move, the cells once and each frame's field mapped onto the clipped points. The pictures are the
// same bits with and without prefetch. What a front end iterates (the CLI's frames, Python's
// cellproj.play).
class Playback {
 public:
  // `first`: the frame at times[0], made by the caller. `player` must outlive the playback.
  Playback(SeriesPlayer& player, SeriesFrame first, std::vector<double> times, bool prefetch,
           std::vector<ClipPlane> clip = {});
  ~Playback();  // waits for the background thread
  Playback(const Playback&) = delete;
  Playback& operator=(const Playback&) = delete;

  int frames() const { return static_cast<int>(times_.size()); }
  int next_frame() const { return next_; }  // the frame render_next draws; frames() when done
  double time_of(int frame) const { return times_[static_cast<std::size_t>(frame)]; }
  // The next frame's picture, seen by `camera`. Throws when every frame was drawn.
  Image render_next(const Renderer& renderer, const TransferFunction& tf, const Camera& camera, ImageSize size,
                    RenderReport* report = nullptr, const Progress& progress = {});
  // Without prefetch every frame's making was waited for.
  PlaybackStats stats() const {
    PlaybackStats s = stats_;
    if (!prefetch_) s.wait_seconds = s.make_seconds;
    return s;
  }
  const ClipReport& first_clip() const { return first_clip_; }  // what the planes did to the first frame

 private:
  SeriesFrame make(double t);  // on one thread at a time
  void commit_volume();        // the volume of current_'s points (and the clipped cells)

  SeriesPlayer& player_;
  std::vector<double> times_;
  bool prefetch_;
  std::vector<ClipPlane> clip_;
  PlaybackStats stats_;
  ClipReport first_clip_;
  SeriesFrame current_;
  int next_ = 0;
  std::unique_ptr<Volume> volume_;
  const double* volume_points_ = nullptr;
  Mesh clipped_mesh_;         // with clipping planes: the clipped cells the volume views
  ClipWeights clip_weights_;  // how a frame's field maps onto the clipped points
  std::vector<double> clipped_field_;
  std::future<SeriesFrame> coming_;  // frame next_'s, made in the background; last: waited for first
};

using FrameDone = std::function<void(int frame, Image&& image, const RenderReport& report)>;

// Plays the frames at `times` (Playback) with `renderer`, frame f seen by camera_of(f), and hands
// each to done(f, ...) in order; `clipped` receives what the planes did to the first frame.
PlaybackStats play_series(SeriesPlayer& player, SeriesFrame first, const std::vector<double>& times, bool prefetch,
                          const Renderer& renderer, const TransferFunction& tf,
                          const std::function<Camera(int)>& camera_of, ImageSize size, const FrameDone& done,
                          const std::function<Progress(int)>& progress_of = {}, const std::vector<ClipPlane>& clip = {},
                          ClipReport* clipped = nullptr);

}  // namespace cellproj
