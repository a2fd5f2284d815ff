#include "tools/frame_loops.hpp"

#include <chrono>
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "render/volume.hpp"
#include "scene/camera_json.hpp"
#include "scene/report_json.hpp"
#include "tools/progress.hpp"
#include "tools/timing.hpp"

namespace cellproj {
namespace {

std::string bar_label(int f, int frames) {
  return frames > 1 ? "frame " + std::to_string(f + 1) + "/" + std::to_string(frames) : "rendering";
}

// The mesh as a volume, prepared for the renderer (its time measured apart from the frames').
struct PreparedVolume {
  explicit PreparedVolume(const FrameJob& job)
      : volume(job.input.prepared.loaded.mesh.view(), {/*trusted: load_mesh validated it*/ true}),
        field(field_of(job.input.prepared.loaded.mesh, job.input.prepared.field, job.input.prepared.opacity_field)) {
    const auto t = std::chrono::steady_clock::now();
    job.renderer.prepare(volume);
    seconds = seconds_since(t);
  }
  const Volume volume;
  const Field field;
  double seconds = 0.0;
};

}  // namespace

std::string FrameJob::frame_what(int f, double seconds) const {
  char what[128];
  std::snprintf(what, sizeof what, "frame %d/%d, %dx%d, %s, %.3f s", f + 1, args.frames, input.scene.width,
                input.scene.height, renderer.name().c_str(), seconds);
  return what;
}

Camera frame_camera(const RenderArgs& a, const PreparedScene& prepared, int f) {
  const double degrees = a.orbit != 0.0 ? f * a.orbit / a.frames : a.animate.empty() ? f : 0.0;
  return orbit(prepared.camera, degrees, prepared.turn_axis);
}

// Each loop draws one progress bar over all its frames (a movie's, a turntable's), relabelled
// with the frame it is on.
FrameLoop play_series_frames(const FrameJob& job) {
  const Input& in = job.input;
  const ImageSize size{in.scene.width, in.scene.height};
  const int frames = static_cast<int>(in.times.size());
  FrameLoop out;
  auto t_frame = std::chrono::steady_clock::now();
  ProgressBar bar(bar_label(0, frames));
  // Frame f at times[f], the next one made on a background thread while f renders.
  out.playback = play_series(
      *in.player, in.first, in.times, !job.args.no_prefetch, job.renderer, in.prepared.tf,
      [&](int f) { return job.camera(f); }, size,
      [&](int f, Image&& img, const RenderReport& r) {
        out.report = r;
        out.render_seconds += r.seconds;
        out.frame_times.push_back(seconds_since(t_frame));
        t_frame = std::chrono::steady_clock::now();
        char time[64];
        std::snprintf(time, sizeof time, ", time %g", in.times[f]);
        if (job.writer.paths().sequence) bar.clear();
        job.writer.frame(f, std::move(img), job.frame_what(f, r.seconds) + time, in.times[f], job.camera(f));
      },
      [&](int f) -> Progress {
        bar.relabel(bar_label(f, frames));
        return [&bar, f, frames](double d) { bar((f + d) / frames); };
      },
      in.scene.clip, &out.series_clipped);
  return out;
}

FrameLoop progressive_levels(const FrameJob& job, const std::vector<int>& levels) {
  const Input& in = job.input;
  const PreparedVolume v(job);
  FrameLoop out;
  out.prepare_seconds = v.seconds;
  // Each level written as soon as it is done, for the interactive user.
  render_progressive(v.volume, v.field, in.prepared.tf, job.settings, in.prepared.camera,
                     {in.scene.width, in.scene.height}, levels,
                     [&](std::size_t, int slices, const Image& img, const RenderReport& r) {
                       char what[96];
                       std::snprintf(what, sizeof what, "%dx%d, slicing, %d slices, %.3f s", in.scene.width,
                                     in.scene.height, slices, r.seconds);
                       job.writer.level(slices, img, what, in.prepared.camera);
                       if (job.args.stats) {
                         nlohmann::json j = {{"method", job.renderer.name()}, {"level_slices", slices}};
                         j.update(report_json(r));
                         std::fprintf(stderr, "%s\n", j.dump().c_str());
                       }
                       out.report = r;
                     });
  return out;
}

FrameLoop mesh_frames(const FrameJob& job) {
  const Input& in = job.input;
  const PreparedVolume v(job);
  FrameLoop out;
  out.prepare_seconds = v.seconds;
  const int frames = job.args.frames;
  ProgressBar bar(bar_label(0, frames));
  for (int f = 0; f < frames; ++f) {
    const auto t_frame = std::chrono::steady_clock::now();
    bar.relabel(bar_label(f, frames));
    out.report = {};
    const Camera camera = job.camera(f);
    Image img = job.renderer.render(v.volume, v.field, in.prepared.tf, camera, {in.scene.width, in.scene.height},
                                    &out.report, [&](double d) { bar((f + d) / frames); });
    out.render_seconds += out.report.seconds;
    out.frame_times.push_back(seconds_since(t_frame));  // preparation is reported on its own
    if (job.writer.paths().sequence) bar.clear();
    job.writer.frame(f, std::move(img), job.frame_what(f, out.report.seconds), std::nullopt, camera);
  }
  return out;
}

}  // namespace cellproj
