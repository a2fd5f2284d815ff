#pragma once
// One interface for every way of making a picture of a Volume (docs/architecture.md, "Adding a
// renderer"): cell projection (small cells splatted), the exact ray integrator and slicing; the
// MPI compositor will be a further implementation behind the same call.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "optics/transfer_function.hpp"
#include "render/report.hpp"
#include "render/settings.hpp"
#include "render/volume.hpp"
#include "view/camera.hpp"
#include "view/image.hpp"
#include "view/opaque_depth.hpp"

namespace cellproj {

// The sizes a memory estimate is made from, before the mesh is read (from a file's header) or after.
struct VolumeSize {
  std::int64_t points = 0, cells = 0;
  std::int64_t tets = 0;  // cells after the canonical split (an upper bound: 6 per hexahedron)
};
VolumeSize size_of(const MeshView& mesh);

using Progress = std::function<void(double done)>;  // 0 to 1, from any thread

class Renderer {
 public:
  virtual ~Renderer() = default;
  virtual std::string name() const = 0;  // "pt-breakpoints", "exact", ...
  // Makes the volume's preparation for this renderer now (render() makes it when missing).
  virtual void prepare(const Volume& volume) const = 0;
  // One frame of `field` (Volume::check'ed). Threads: those of the calling task arena.
  Image render(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera,
               ImageSize size, RenderReport* report = nullptr, const Progress& progress = {}) const;
  // The same among opaque geometry (a render window's depth buffer, view/opaque_depth.hpp): each
  // pixel's ray integrated only up to `opaque`'s surface. Cell projection's software back end and
  // the exact renderer draw it; the others throw UnsupportedError, as does a depth of another size
  // than the image (InputError).
  Image render(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera,
               ImageSize size, const OpaqueDepth& opaque, RenderReport* report = nullptr) const;
  // Bytes a frame needs at most (images, per-point and per-tetrahedron arrays, buffers): generous.
  virtual std::uint64_t estimate_bytes(const VolumeSize& volume, ImageSize size) const = 0;

 private:
  // The frame itself; render() checks what every renderer owes (a finite image, CELLPROJ_DCHECK).
  virtual Image frame(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera,
                      ImageSize size, RenderReport* report, const Progress& progress) const = 0;

 protected:
  // The frame among opaque geometry (checked); UnsupportedError unless the renderer draws it.
  virtual Image frame_among(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera,
                            ImageSize size, const OpaqueDepth& opaque, RenderReport* report) const;
};

// The most worker threads a front end may ask for, and the count `asked` gives (0: all cores);
// InputError naming setting 'threads' outside [0, kMaxThreads].
inline constexpr int kMaxThreads = 1024;
int worker_threads(long long asked);

// The largest anti-aliasing factor (RenderSettings::ssaa), and the largest side of the image it
// renders (the image's side times ssaa).
inline constexpr int kMaxSsaa = 16;
inline constexpr int kMaxSupersampledSide = 65536;

// The size a frame of `size` is drawn at for anti-aliasing by `ssaa` (each side ssaa times
// longer); InputError naming the setting beyond kMaxSupersampledSide.
ImageSize supersampled_size(ImageSize size, int ssaa);
// The picture of a frame drawn at supersampled_size: its samples filtered into pixels (the mean of
// each pixel's ssaa x ssaa, or a tent over them: view/image.hpp), and `ssaa` added to the report
// when it is more than 1.
Image resolve_samples(Image samples, int ssaa, SampleFilter filter, RenderReport* report);

// The renderer for `settings`, checked once (InputError for settings that do not go together).
std::unique_ptr<Renderer> make_renderer(const RenderSettings& settings);

// Progressive refinement (slicing): the frame at each plane count of `levels` (increasing), each
// handed to done(level index, slices, image, report) as soon as it is composited (supersampled
// by settings.ssaa as any frame); a level reuses
// the polygons of the previous one's planes where they coincide. InputError unless settings.mode is
// slicing.
using LevelDone = std::function<void(std::size_t level, int slices, const Image&, const RenderReport&)>;
void render_progressive(const Volume& volume, const Field& field, const TransferFunction& tf,
                        const RenderSettings& settings, const Camera& camera, ImageSize size,
                        const std::vector<int>& levels, const LevelDone& done);

// make_renderer(settings)->render(...): one call for one picture.
Image render(const Volume& volume, const Field& field, const TransferFunction& tf, const RenderSettings& settings,
             const Camera& camera, ImageSize size, RenderReport* report = nullptr);

}  // namespace cellproj
