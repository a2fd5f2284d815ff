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

PlaybackStats play_series(SeriesPlayer& player, SeriesFrame first, const std::vector<double>& times, bool prefetch,
                          const Renderer& renderer, const TransferFunction& tf,
                          const std::function<Camera(int)>& camera_of, ImageSize size, const FrameDone& done,
                          const std::function<Progress(int)>& progress_of, const std::vector<ClipPlane>& clip,
                          ClipReport* clipped) {
  PlaybackStats stats;
  const auto make = [&player, &stats](double t) {  // runs on one thread at a time
    const auto start = std::chrono::steady_clock::now();
    SeriesFrame f = player.frame_at(t);
    stats.make_seconds += seconds_since(start);
    return f;
  };
  std::unique_ptr<Volume> volume;
  const double* volume_points = nullptr;
  Mesh clipped_mesh;         // with clipping planes: the clipped cells the volume views
  ClipWeights clip_weights;  // how a frame's field maps onto the clipped points
  std::vector<double> clipped_field;
  SeriesFrame current = std::move(first);
  const int n = static_cast<int>(times.size());
  for (int f = 0; f < n; ++f) {
    std::future<SeriesFrame> next;
    if (prefetch && f + 1 < n) next = std::async(std::launch::async, make, times[f + 1]);
    try {
      if (!volume || current.points->data() != volume_points) {  // the points moved: the cells' preparation anew
        // Interpolated points may fold a cell the key frames did not: validate them unless they are a key frame's.
        const bool trusted = !player.points_move();
        if (clip.empty()) {
          volume = std::make_unique<Volume>(player.view(current), VolumeOptions{trusted});
        } else {
          volume.reset();  // it views the clipped mesh about to be replaced
          Mesh whole = player.cells();
          whole.points = *current.points;
          ClipReport report;
          clipped_mesh = clip_mesh(whole, clip, &report, &clip_weights);
          if (clipped_mesh.n_cells() == 0)
            throw InputError(where(player.series().source, "nothing of the mesh at time " +
                                                               std::to_string(current.time) +
                                                               " is on the kept side of the clipping planes"));
          if (clipped && stats.volumes == 0) *clipped = report;
          volume = std::make_unique<Volume>(clipped_mesh.view(), VolumeOptions{trusted});
        }
        volume_points = current.points->data();
        ++stats.volumes;
      }
      if (!clip.empty()) clipped_field = clip_weights.apply(current.field);
      const std::vector<double>& values = clip.empty() ? current.field : clipped_field;
      const Field field{values.data(), static_cast<std::int64_t>(values.size()), player.field_name(), nullptr, {}};
      RenderReport report;
      Image image =
          renderer.render(*volume, field, tf, camera_of(f), size, &report, progress_of ? progress_of(f) : Progress{});
      done(f, std::move(image), report);
    } catch (...) {
      if (next.valid()) next.wait();  // the background thread uses the player: let it finish first
      throw;
    }
    if (f + 1 < n) {
      const auto wait = std::chrono::steady_clock::now();
      current = prefetch ? next.get() : make(times[f + 1]);
      if (prefetch) stats.wait_seconds += seconds_since(wait);
    }
  }
  if (!prefetch) stats.wait_seconds = stats.make_seconds;
  return stats;
}

}  // namespace cellproj
