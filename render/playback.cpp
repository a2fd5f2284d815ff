#include "render/playback.hpp"

#include <chrono>
#include <cmath>
#include <future>
#include <memory>

#include "base/error.hpp"
#include "base/timing.hpp"

namespace cellproj {

std::vector<double> animation_times(const std::string& text) {
  const auto bad = [&] {
    return InputError("setting 'animate': expected T0:T1:FRAMES (e.g. 0:2.5:60), got '" + text + "'");
  };
  const std::size_t a = text.find(':'), b = a == std::string::npos ? a : text.find(':', a + 1);
  if (b == std::string::npos) throw bad();
  double t0 = 0, t1 = 0;
  int frames = 0;
  try {
    std::size_t u0 = 0, u1 = 0, u2 = 0;
    t0 = std::stod(text.substr(0, a), &u0);
    t1 = std::stod(text.substr(a + 1, b - a - 1), &u1);
    frames = std::stoi(text.substr(b + 1), &u2);
    if (u0 != a || u1 != b - a - 1 || u2 != text.size() - b - 1) throw bad();
  } catch (const std::logic_error&) {
    throw bad();
  }
  if (!std::isfinite(t0) || !std::isfinite(t1)) throw bad();
  if (frames < 1 || frames > 100000)
    throw InputError("setting 'animate': FRAMES must be in [1, 100000], got " + std::to_string(frames));
  std::vector<double> times(static_cast<std::size_t>(frames), t0);
  for (int f = 1; f < frames; ++f) times[f] = f == frames - 1 ? t1 : t0 + (t1 - t0) * f / (frames - 1);
  return times;
}

Playback::Playback(SeriesPlayer& player, SeriesFrame first, std::vector<double> times, bool prefetch,
                   std::vector<ClipPlane> clip)
    : player_(player),
      times_(std::move(times)),
      prefetch_(prefetch),
      clip_(std::move(clip)),
      current_(std::move(first)) {}

Playback::~Playback() {
  if (coming_.valid()) coming_.wait();  // the background thread uses the player
}

SeriesFrame Playback::make(double t) {
  const auto start = std::chrono::steady_clock::now();
  SeriesFrame f = player_.frame_at(t);
  stats_.make_seconds += seconds_since(start);
  return f;
}

void Playback::commit_volume() {
  // Interpolated points may fold a cell the key frames did not: validated unless they are a key frame's.
  const bool trusted = !player_.points_move();
  if (clip_.empty()) {
    volume_ = std::make_unique<Volume>(player_.view(current_), VolumeOptions{trusted});
  } else {
    volume_.reset();  // it views the clipped mesh about to be replaced
    Mesh whole = player_.cells();
    whole.points = *current_.points;
    ClipReport report;
    clipped_mesh_ = clip_mesh(whole, clip_, &report, &clip_weights_);
    if (clipped_mesh_.n_cells() == 0)
      throw InputError(where(player_.series().source, "nothing of the mesh at time " + std::to_string(current_.time) +
                                                          " is on the kept side of the clipping planes"));
    if (stats_.volumes == 0) first_clip_ = report;
    volume_ = std::make_unique<Volume>(clipped_mesh_.view(), VolumeOptions{trusted});
  }
  volume_points_ = current_.points->data();
  ++stats_.volumes;
}

Image Playback::render_next(const Renderer& renderer, const TransferFunction& tf, const Camera& camera, ImageSize size,
                            RenderReport* report, const Progress& progress) {
  if (next_ >= frames()) throw InputError(where(player_.series().source, "every frame of the playback was drawn"));
  if (next_ > 0) {  // frame next_: made in the background while the last one rendered, or now
    const auto wait = std::chrono::steady_clock::now();
    current_ = prefetch_ ? coming_.get() : make(times_[next_]);
    if (prefetch_) stats_.wait_seconds += seconds_since(wait);
  }
  const double t_next = next_ + 1 < frames() ? times_[next_ + 1] : 0.0;
  const bool fetch = prefetch_ && next_ + 1 < frames();
  ++next_;
  if (fetch) coming_ = std::async(std::launch::async, [this, t_next] { return make(t_next); });
  if (!volume_ || current_.points->data() != volume_points_) commit_volume();  // the points moved: anew
  if (!clip_.empty()) clipped_field_ = clip_weights_.apply(current_.field);
  const std::vector<double>& values = clip_.empty() ? current_.field : clipped_field_;
  const Field field{values.data(), static_cast<std::int64_t>(values.size()), player_.field_name(), nullptr, {}};
  return renderer.render(*volume_, field, tf, camera, size, report, progress);
}

PlaybackStats play_series(SeriesPlayer& player, SeriesFrame first, const std::vector<double>& times, bool prefetch,
                          const Renderer& renderer, const TransferFunction& tf,
                          const std::function<Camera(int)>& camera_of, ImageSize size, const FrameDone& done,
                          const std::function<Progress(int)>& progress_of, const std::vector<ClipPlane>& clip,
                          ClipReport* clipped) {
  Playback playback(player, std::move(first), times, prefetch, clip);
  for (int f = 0; f < playback.frames(); ++f) {
    RenderReport report;
    Image image =
        playback.render_next(renderer, tf, camera_of(f), size, &report, progress_of ? progress_of(f) : Progress{});
    if (clipped && f == 0) *clipped = playback.first_clip();
    done(f, std::move(image), report);
  }
  return playback.stats();
}

}  // namespace cellproj
