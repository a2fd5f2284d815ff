#pragma once
// `cellproj render` of a scene with several volumes (docs/scene.md, "Several volumes"). Internal to
// the command line.
#include "render/renderer.hpp"
#include "scene/scene_file.hpp"
#include "tools/render_input.hpp"

namespace cellproj {

// UsageError for what a scene of several volumes does not take (a method other than exact, --iso
// or --field meant for one mesh, time series, progressive levels, MPI).
void check_volume_scene(const RenderArgs& a, const Scene& scene);
// Reads, prepares and renders the volumes of `scene` with the command line's overrides.
int render_volume_scene(const RenderArgs& a, Scene scene, const RenderSettings& settings);

}  // namespace cellproj
