#include "scene/volume_scene.hpp"

#include "base/error.hpp"

namespace cellproj {

VolumeScene::VolumeScene(const Scene& scene, const std::function<LoadedMesh(const SceneVolume&)>& read,
                         std::optional<bool> draw_volume)
    : prepared_(prepare_volumes(scene, read)), clipped_(prepared_.volumes.size()) {
  // Clipped after preparing: colours and framing are the whole meshes'.
  std::size_t kept = 0;
  for (std::size_t k = 0; k < prepared_.volumes.size(); ++k) {
    Mesh& mesh = prepared_.volumes[k].loaded.mesh;
    if (!scene.clip.empty()) mesh = clip_mesh(mesh, scene.clip, &clipped_[k]);
    kept += mesh.n_cells() > 0;
    if (mesh.n_cells() == 0)
      prepared_.warnings.push_back(where(scene.source, "volumes[" + std::to_string(k) + "] (" + scene.volumes[k].mesh +
                                                           "): nothing of it is on the kept side of the clipping "
                                                           "planes; it is left out"));
  }
  if (kept == 0)
    throw InputError(where(scene.source,
                           "nothing of the volumes is on the kept side of the clipping planes (each "
                           "keeps the side its normal points away from)"));
  volumes_.reserve(kept);  // entries_ point into it
  for (std::size_t k = 0; k < prepared_.volumes.size(); ++k) {
    const PreparedScene& p = prepared_.volumes[k];
    if (p.loaded.mesh.n_cells() == 0) continue;
    volumes_.emplace_back(p.loaded.mesh.view(), VolumeOptions{/*trusted: load_mesh validated it*/ true});
    entries_.push_back({&volumes_.back(), field_of(p.loaded.mesh, p.field), &p.tf, scene.volumes[k].iso,
                        draw_volume.value_or(scene.volumes[k].volume)});
  }
}

}  // namespace cellproj
