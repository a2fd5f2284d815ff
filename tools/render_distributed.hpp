#pragma once
// `cellproj render` over MPI ranks or from a partition index (docs/parallel.md). Internal to the
// command line.
#include "distributed/communicator.hpp"
#include "render/renderer.hpp"
#include "tools/render_input.hpp"

namespace cellproj {

// Whether the render is distributed: launched on several ranks, or given a partition index.
bool is_distributed(const RenderArgs& a, const Communicator& world);
// UsageError for what a distributed render does not do (several frames, progressive levels, time,
// methods that do not composite in depth order).
void check_distributed(const RenderArgs& a, const RenderSettings& settings);
// Renders input's bricks over the ranks; rank 0 writes the picture and prints --stats.
int render_distributed(const RenderArgs& a, const Input& input, const RenderSettings& settings,
                       const Communicator& world);

}  // namespace cellproj
