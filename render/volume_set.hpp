#pragma once
// Several volumes in one picture (a scene's "volumes" list: a fluid and a solid, two solvers'
// outputs), possibly intersecting: each a committed Volume with its field, transfer function and
// iso-surfaces, drawn together on the exact renderer's rays (raycast/volume_union.hpp), exact for the
// model however they overlap. Cell projection and slicing order or cut the cells of one mesh; where
// two meshes overlap, their cells cannot be ordered as whole cells, so those methods are refused.
#include <vector>

#include "optics/transfer_function.hpp"
#include "raycast/iso_options.hpp"
#include "render/renderer.hpp"
#include "render/volume.hpp"

namespace cellproj {

struct VolumeEntry {
  const Volume* volume = nullptr;
  Field field;
  const TransferFunction* tf = nullptr;
  std::vector<IsoSurface> surfaces;
  bool draw_volume = true;  // its transfer function's volume, else its iso-surfaces alone
};

// The picture of the volumes (premultiplied RGBA without background). settings.mode must be exact
// (InputError naming the method otherwise); settings.iso gives the compositing mode and opacity
// model of every volume's surfaces, its own surfaces are not drawn (each entry has its own).
Image render_volumes(const std::vector<VolumeEntry>& volumes, const RenderSettings& settings, const Camera& camera,
                     ImageSize size, RenderReport* report = nullptr, const Progress& progress = {});

// Bytes render_volumes needs at most for volumes of these sizes (as Renderer::estimate_bytes).
std::uint64_t estimate_volumes_bytes(const std::vector<VolumeSize>& volumes, ImageSize size, int ssaa = 1);

}  // namespace cellproj
