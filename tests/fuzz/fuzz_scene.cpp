// libFuzzer harness for scene files: the input is a scene JSON beside a small generated mesh,
// loaded and prepared as `cellproj render` does (the mesh read, the field and transfer function
// checked against it, the camera chosen; a scene of several volumes each clipped and committed).
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#include "base/error.hpp"
#include "fuzz_folder.hpp"
#include "io/write_mesh.hpp"
#include "mesh/generate.hpp"
#include "scene/prepare.hpp"
#include "scene/scene_file.hpp"
#include "scene/volume_scene.hpp"

namespace {

const std::string& folder() {  // one per fuzzing process, holding box.vtu for the scenes to name
  static const std::string dir = [] {
    const std::string name = make_fuzz_folder();
    cellproj::write_vtu(cellproj::generate("box-tets", 2), name + "/box.vtu");
    return name;
  }();
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = folder() + "/scene.json";
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  try {
    cellproj::Scene scene = cellproj::load_scene(path);
    scene.reader.max_memory_gib = 0.125;
    if (scene.volumes.size() > 1) {  // a scene of several volumes, made ready as render makes it
      const cellproj::VolumeScene volumes(scene, [](const cellproj::SceneVolume& v) {
        cellproj::ReadOptions reader = v.reader;
        reader.max_memory_gib = 0.125;
        return cellproj::load_mesh(v.mesh, reader);
      });
    } else {
      cellproj::prepare_scene(scene);
    }
  } catch (const cellproj::InternalError&) {
    std::abort();
  } catch (const cellproj::Error&) {
  }
  return 0;
}
