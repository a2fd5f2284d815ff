#include "render/volume_set.hpp"

#include <chrono>
#include <string>

#include "base/error.hpp"
#include "base/timing.hpp"
#include "raycast/reference_renderer.hpp"
#include "raycast/volume_union.hpp"

namespace cellproj {

Image render_volumes(const std::vector<VolumeEntry>& volumes, const RenderSettings& settings, const Camera& camera,
                     ImageSize size, RenderReport* report, const Progress& progress) {
  if (settings.mode != RenderMode::exact)
    throw InputError(
        "several volumes are drawn together by setting 'method' exact only: cell projection and slicing order "
        "or cut the cells of one mesh, and cells of overlapping meshes cannot be ordered as whole cells");
  if (volumes.empty()) throw InputError("render_volumes: no volume to draw");
  check(settings.iso);
  std::vector<VolumePart> parts;
  std::int64_t surfaces = 0;
  const auto t_prepare = std::chrono::steady_clock::now();
  int prepared_before = 0, prepared_after = 0;
  for (const VolumeEntry& v : volumes) {
    if (!v.volume || !v.tf) throw InputError("render_volumes: a volume without its mesh or transfer function");
    v.volume->check(v.field);
    check(IsoOptions{v.surfaces});
    prepared_before += v.volume->preparations();
    const ExactRenderer& exact = v.volume->exact();
    prepared_after += v.volume->preparations();
    parts.push_back({&exact.tracer(), v.field.values, v.field.size, v.tf, v.surfaces, v.draw_volume});
    surfaces += static_cast<std::int64_t>(v.surfaces.size());
  }
  if (report && prepared_after != prepared_before) report->prepare_seconds += seconds_since(t_prepare);
  IsoStats st;
  const ImageSize drawn = supersampled_size(size, settings.ssaa);
  Image image = render_volume_union(parts, settings.iso.mode, settings.iso.opacity, camera, drawn.width, drawn.height,
                                    &st, progress);

  if (report) {
    report->seconds = st.seconds;
    report->phase_seconds = {{"trace, merge and integrate the volumes", st.seconds}};
    report->add("volumes", static_cast<std::int64_t>(volumes.size()));
    report->add("interpolation", CellInterpolation::canonical_tets);
    report->add("iso_surfaces", surfaces);
    report->add("iso_mode", settings.iso.mode);
    report->add("iso_opacity", settings.iso.opacity);
    report->add_counters(st);
    report->add("overlap_pieces", st.overlap_pieces);

    if (settings.iso.opacity == IsoOpacity::spectrum_fit) {
      report->add("spectrum_fit_max_error", st.fit_max_error);
      report->add("spectrum_fit_exponents", st.fit_exponents);
    }
  }
  return resolve_samples(std::move(image), settings.ssaa, settings.ssaa_filter, report);
}

std::uint64_t estimate_volumes_bytes(const std::vector<VolumeSize>& volumes, ImageSize size, int ssaa) {
  RenderSettings settings;
  settings.mode = RenderMode::exact;
  settings.ssaa = ssaa;
  const auto exact = make_renderer(settings);
  std::uint64_t bytes = 0;
  for (const VolumeSize& v : volumes) bytes += exact->estimate_bytes(v, size);
  return bytes;
}

}  // namespace cellproj
