#pragma once
// A scene of several volumes (Scene::volumes) ready to render: each mesh read, its field and
// transfer function prepared, clipped by the scene's planes, committed as a Volume, with the
// common camera. One setup for every front end (the CLI, the Python module).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "mesh/clip.hpp"
#include "render/volume_set.hpp"
#include "scene/prepare.hpp"

namespace cellproj {

class VolumeScene {
 public:
  // read(volume) reads each mesh (e.g. load_mesh). draw_volume, when given, replaces every volume's
  // "volume" (as setting volume). InputError when the clipping planes keep nothing of any volume.
  VolumeScene(const Scene& scene, const std::function<LoadedMesh(const SceneVolume&)>& read,
              std::optional<bool> draw_volume = std::nullopt);
  VolumeScene(const VolumeScene&) = delete;  // entries point into it
  VolumeScene& operator=(const VolumeScene&) = delete;

  const std::vector<VolumeEntry>& entries() const { return entries_; }  // the volumes clipping kept
  const Camera& camera() const { return prepared_.camera; }
  const PreparedVolumes& prepared() const { return prepared_; }        // every volume, in the scene's order
  const std::vector<ClipReport>& clipped() const { return clipped_; }  // per volume, in the scene's order
  const std::vector<std::string>& warnings() const { return prepared_.warnings; }

 private:
  PreparedVolumes prepared_;
  std::vector<ClipReport> clipped_;
  std::vector<Volume> volumes_;
  std::vector<VolumeEntry> entries_;
};

}  // namespace cellproj
