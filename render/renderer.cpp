#include "render/renderer.hpp"

#include <chrono>

#include <tbb/info.h>

#include "base/check.hpp"
#include "base/error.hpp"
#include "base/timing.hpp"
#include "frame/projection_renderer.hpp"
#include "mesh/tetrahedralize.hpp"
#include "optics/two_fields.hpp"
#include "raycast/iso_layers.hpp"
#include "raycast/iso_surfaces.hpp"
#include "raycast/ray_reduction.hpp"
#include "raycast/reference_renderer.hpp"
#include "slicing/slice_renderer.hpp"

namespace cellproj {
namespace {

// Bytes every renderer needs: the float image and its copy kept for output, 8-bit PNG rows, and
// a fixed allowance for triangle and fragment buffers and thread stacks.
std::uint64_t common_bytes(ImageSize size) {
  const std::uint64_t pixels = static_cast<std::uint64_t>(size.width) * static_cast<std::uint64_t>(size.height);
  return pixels * (16 * 2 + 4) + (576ull << 20);
}

// The volume's preparation that `get` returns, its time added to the report when this call made it.
template <class Get>
decltype(auto) timed_preparation(const Volume& volume, RenderReport* report, Get&& get) {
  const int before = volume.preparations();
  const auto t = std::chrono::steady_clock::now();
  decltype(auto) prepared = get();
  if (report && volume.preparations() != before) report->prepare_seconds += seconds_since(t);
  return prepared;
}

// How far apart the mesh's consecutive cells lie and whether the renderer drew a copy of them
// renumbered for locality (mesh/cell_order.hpp).
void add_numbering(RenderReport& r, double spread, bool renumbered) {
  r.add("cell_numbering_spread", spread);
  r.add("cells_renumbered", std::int64_t{renumbered});
}

// What the small cells' rule found and the splats did, as report counters.
void add_splats(RenderReport& r, SmallCells mode, double threshold, const SplatCounters& c) {
  r.add("small_cells_mode", mode);
  r.add("splat_threshold", threshold);
  r.add_counters(c);
  if (c.refused_degenerate + c.refused_inverted > 0)
    r.warnings.push_back(std::to_string(c.refused_degenerate + c.refused_inverted) + " small cells have no splat (" +
                         std::to_string(c.refused_degenerate) + " of zero volume, " +
                         std::to_string(c.refused_inverted) + " inverted) and add nothing to the picture");
}

// UnsupportedError for a field whose extinction comes from another field, where `renderer` cannot draw it.
void refuse_opacity_field(const Field& field, const std::string& renderer) {
  if (field.opacity) throw two_fields_refused(field.opacity_name, renderer);
}

class ProjectionMode final : public Renderer {
 public:
  ProjectionMode(const ProjectionOptions& options, Tetrahedralize mode) : options_(options), mode_(mode) {
    check_options(options);
  }
  std::string name() const override { return name_of(options_.method); }
  void prepare(const Volume& volume) const override { volume.projection(mode_); }

  Image frame(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera,
              ImageSize size, RenderReport* report, const Progress&) const override {
    return draw(volume, field, tf, camera, size, nullptr, report);
  }
  Image frame_among(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera,
                    ImageSize size, const OpaqueDepth& opaque, RenderReport* report) const override {
    return draw(volume, field, tf, camera, size, &opaque, report);
  }

  std::uint64_t estimate_bytes(const VolumeSize& v, ImageSize size) const override {
    // Per point: coordinates (twice: recentred), screen positions, optics. Per tetrahedron:
    // connectivity, faces and neighbours, sorter planes and centroids, and 40 for the cells'
    // renumbered copy (mesh/cell_order.hpp; a hexahedron's 73 bytes are within its tetrahedra's).
    return common_bytes(size) + static_cast<std::uint64_t>(v.points) * 120 + static_cast<std::uint64_t>(v.tets) * 360;
  }

 private:
  Image draw(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera, ImageSize size,
             const OpaqueDepth* opaque, RenderReport* report) const {
    volume.check(field);
    const ProjectionRenderer& renderer =
        timed_preparation(volume, report, [&]() -> const ProjectionRenderer& { return volume.projection(mode_); });
    ProjectionStats st;
    Image image =
        renderer.render(field.values, tf, camera, size.width, size.height, options_, &st, field.opacity, opaque);
    if (report) fill(*report, st);
    return image;
  }

  void fill(RenderReport& r, const ProjectionStats& p) const {
    r.seconds = p.seconds;
    r.phase_seconds = p.phase_seconds;
    r.add("backend", options_.backend);
    add_numbering(r, p.cell_numbering_spread, p.cells_renumbered);
    r.add_counters(p);
    r.add("gaps_from", p.sort.method == SortMethod::mpvo_abuffer ? ReportValue(p.sort.gaps_from) : ReportValue());
    add_fragment_rates(r, p);
    add_splats(r, p.small_cells, p.splat_threshold, p.splat);
    if (p.small_cells == SmallCells::splat) r.add("splat_stencil_tiles", p.splat_stencil_tiles);
    if (!p.gl_renderer.empty()) r.add("gl_renderer", p.gl_renderer);
    warn(r, p);
  }

  // Wall time per fragment of the projection and compositing phase, and with the stream compositor
  // the memory traffic of the fragments: each written to its batch (20 bytes), read back by the
  // blend (20), and its pixel read and written (16 + 16): 72 bytes, against what the machine's
  // memory moves (docs/methods.md). Tiles store no fragment, and their pixels stay in cache.
  static void add_fragment_rates(RenderReport& r, const ProjectionStats& p) {
    double seconds = 0.0;
    for (const auto& [phase, s] : p.phase_seconds)
      if (phase == "project and composite") seconds = s;
    const double n = static_cast<double>(p.counters.fragments);
    const bool rated = n > 0 && seconds > 0;
    r.add("ns_per_fragment", rated ? ReportValue(1e9 * seconds / n) : ReportValue());
    r.add("fragments_per_second", rated ? ReportValue(n / seconds) : ReportValue());
    const bool stream = rated && p.tiles == 0;
    r.add("fragment_traffic_gb_per_second", stream ? ReportValue(72.0 * n / seconds / 1e9) : ReportValue());
    r.add("blend_seconds", stream ? ReportValue(p.blend_seconds) : ReportValue());
  }

  void warn(RenderReport& r, const ProjectionStats& p) const {
    // The software back end ray casts the tetrahedra reaching behind the eye; OpenGL cannot draw
    // them, nor can whole cells be projected there.
    if (p.counters.behind_eye > 0 && (is_opengl(options_.backend) || mode_ == Tetrahedralize::none))
      r.warnings.push_back(
          std::to_string(p.counters.behind_eye) +
          " cells reach behind the eye and were not drawn (the camera is inside or too close to the "
          "mesh); use setting 'backend' software with setting 'tetrahedralize' problem or all, which ray casts them");
    if (mode_ == Tetrahedralize::none && p.problem_cells > 0)
      r.warnings.push_back(
          std::to_string(p.problem_cells) +
          " cells have a face folded in this view and were projected whole (setting 'tetrahedralize' none): "
          "the order and the picture may be wrong there");
    if (p.sort.cycles.empty()) return;
    std::int64_t cells = 0;
    for (const VisibilityCycle& c : p.sort.cycles) cells += c.size;
    const std::size_t n = p.sort.cycles.size();
    r.warnings.push_back(
        "the visibility sort met " + std::to_string(n) + " visibility cycle" + (n == 1 ? "" : "s") + " (" +
        std::to_string(cells) +
        " cells) and broke each at one relation: those cells have no back-to-front order (cells that "
        "overlap, or warped faces), so the picture may be wrong where they cover each other; setting 'method' "
        "exact is exact there, and the overlaps check of `cellproj info` tells whether cells overlap");
  }

  ProjectionOptions options_;
  Tetrahedralize mode_;
};

// The field checked and the exact renderer's preparation, made (and timed) on first use.
const ExactRenderer& checked_exact(const Volume& volume, const Field& field, RenderReport* report) {
  volume.check(field);
  const ExactRenderer& exact =
      timed_preparation(volume, report, [&]() -> const ExactRenderer& { return volume.exact(); });
  if (report) add_numbering(*report, exact.local_cells().spread(), exact.local_cells().renumbered());
  return exact;
}

class ExactMode final : public Renderer {
 public:
  explicit ExactMode(CellInterpolation interpolation, IsoOptions iso = {})
      : interpolation_(interpolation), iso_(std::move(iso)) {
    check(iso_);
  }
  std::string name() const override { return "exact"; }
  void prepare(const Volume& volume) const override { volume.exact(); }

  Image frame(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera,
              ImageSize size, RenderReport* report, const Progress& progress) const override {
    const ExactRenderer& renderer = checked_exact(volume, field, report);
    if (!iso_.surfaces.empty()) {
      refuse_opacity_field(field, "iso-surfaces");
      return render_surfaces(renderer, field, tf, camera, size, report, progress);
    }
    return draw(renderer, field, tf, camera, size, nullptr, report, progress);
  }
  Image frame_among(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera,
                    ImageSize size, const OpaqueDepth& opaque, RenderReport* report) const override {
    if (!iso_.surfaces.empty()) return Renderer::frame_among(volume, field, tf, camera, size, opaque, report);
    return draw(checked_exact(volume, field, report), field, tf, camera, size, &opaque, report, {});
  }

  std::uint64_t estimate_bytes(const VolumeSize& v, ImageSize size) const override {
    // Per point: coordinates (twice: recentred), isoparametric data. Per tetrahedron: the
    // tracer's planes and tile bins, and the cells' renumbered copy (40, as projection's).
    return common_bytes(size) + static_cast<std::uint64_t>(v.points) * 120 + static_cast<std::uint64_t>(v.tets) * 440;
  }

 private:
  Image draw(const ExactRenderer& renderer, const Field& field, const TransferFunction& tf, const Camera& camera,
             ImageSize size, const OpaqueDepth* opaque, RenderReport* report, const Progress& progress) const {
    ExactStats st;
    Image image = renderer.render(field.values, tf, camera, size.width, size.height, interpolation_, &st, progress,
                                  field.opacity, opaque);
    if (report) {
      report->seconds = st.trace_seconds;
      report->phase_seconds = {{"trace and integrate", st.trace_seconds}};
      report->add("interpolation", interpolation_);
      report->add_counters(st);
    }
    return image;
  }

  // Iso-surfaces with the volume (raycast/iso_surfaces.hpp), in the mode asked for.
  Image render_surfaces(const ExactRenderer& renderer, const Field& field, const TransferFunction& tf,
                        const Camera& camera, ImageSize size, RenderReport* report, const Progress& progress) const {
    IsoStats st;
    Image image = render_iso_surfaces(renderer.tracer(), field.values, field.size, tf, camera, size.width, size.height,
                                      iso_, &st, progress);
    if (report) {
      report->seconds = st.seconds;
      report->phase_seconds = {{"trace, integrate and blend surfaces", st.seconds}};
      report->add("iso_surfaces", static_cast<std::int64_t>(iso_.surfaces.size()));
      report->add("iso_mode", iso_.mode);
      report->add("iso_opacity", iso_.opacity);
      report->add("volume", std::string(iso_.volume ? "on" : "off"));
      report->add_counters(st);
      if (iso_.opacity == IsoOpacity::spectrum_fit) {
        report->add("spectrum_fit_max_error", st.fit_max_error);
        report->add("spectrum_fit_exponents", st.fit_exponents);
      }
    }
    return image;
  }

  CellInterpolation interpolation_;
  IsoOptions iso_;
};

// MIP, MinIP and the mean along each ray, on the exact renderer's tracer (prepared once, shared).
class ReductionMode final : public Renderer {
 public:
  explicit ReductionMode(RayReduction reduction) : reduction_(reduction) {}
  std::string name() const override {
    return reduction_ == RayReduction::maximum ? "mip" : reduction_ == RayReduction::minimum ? "minip" : "average";
  }
  void prepare(const Volume& volume) const override { volume.exact(); }

  Image frame(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera,
              ImageSize size, RenderReport* report, const Progress& progress) const override {
    refuse_opacity_field(field, name());
    const ExactRenderer& renderer = checked_exact(volume, field, report);
    ReductionStats st;
    Image image =
        reduce_rays(renderer.tracer(), field.values, tf, camera, size.width, size.height, reduction_, &st, progress);
    if (report) {
      report->seconds = st.seconds;
      report->phase_seconds = {{"trace and reduce", st.seconds}};
      report->add_counters(st);
    }
    return image;
  }

  std::uint64_t estimate_bytes(const VolumeSize& v, ImageSize size) const override {
    return ExactMode(CellInterpolation::canonical_tets).estimate_bytes(v, size);  // the same tracer
  }

 private:
  RayReduction reduction_;
};

// Volumetric depth peeling (Nagy and Klein) on the exact renderer's tracer: the n-th crossings of
// an iso-value, blended, with silhouettes.
class LayersMode final : public Renderer {
 public:
  explicit LayersMode(const LayerOptions& options) : options_(options) { check(options); }
  std::string name() const override { return "layers"; }
  void prepare(const Volume& volume) const override { volume.exact(); }

  Image frame(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera,
              ImageSize size, RenderReport* report, const Progress& progress) const override {
    refuse_opacity_field(field, name());
    const ExactRenderer& renderer = checked_exact(volume, field, report);
    LayerStats st;
    Image image = render_layers(renderer.tracer(), field.values, field.size, tf, camera, size.width, size.height,
                                options_, &st, progress);
    if (report) {
      report->seconds = st.seconds;
      report->phase_seconds = {{"trace and peel", st.seconds}};
      report->add("iso", options_.iso);
      report->add("silhouettes", options_.silhouettes);
      report->add_counters(st);
    }
    return image;
  }

  std::uint64_t estimate_bytes(const VolumeSize& v, ImageSize size) const override {
    return ExactMode(CellInterpolation::canonical_tets).estimate_bytes(v, size);  // the same tracer
  }

 private:
  LayerOptions options_;
};

// The slicing stats as a report.
void fill(RenderReport& r, const SlicingStats& st, const SlicingOptions& o) {
  r.seconds = st.seconds;
  r.phase_seconds = st.phase_seconds;
  r.add("backend", o.backend);
  r.add("slice_integral", o.integral);
  r.add_counters(st);
  if (!st.gl_renderer.empty()) r.add("gl_renderer", st.gl_renderer);
  add_splats(r, st.small_cells, st.splat_threshold, st.splat);
  if (st.cells_between_planes > 0)
    r.warnings.push_back(std::to_string(st.cells_between_planes) +
                         " cells (or tetrahedra of split cells) lie between two planes and add nothing to the picture; "
                         "more setting 'slices' catch them");
  if (st.slices == 0)
    r.warnings.push_back(
        "no slice plane lies in front of the eye: the picture is empty (the camera is inside the "
        "mesh or beyond it); use setting 'slice-axis' view or more setting 'slices'");
  if (st.rays_along_planes > 0)
    r.warnings.push_back(std::to_string(st.rays_along_planes) +
                         " pixels' rays run along the slice planes or away from them (an axis-aligned stack in "
                         "perspective, the camera near or inside the mesh): their slices are composited out of order; "
                         "use setting 'slice-axis' view or auto");
  if (st.overlapping_fragments > 0)
    r.warnings.push_back(
        std::to_string(st.overlapping_fragments) +
        " pixels were covered twice by one slice: cells overlap (the overlaps check of `cellproj info`), and "
        "only one of them shows there");
}

class SlicingMode final : public Renderer {
 public:
  SlicingMode(const SlicingOptions& options, Tetrahedralize mode) : options_(options), mode_(mode) {
    check_options(options);
  }
  std::string name() const override { return "slicing"; }
  void prepare(const Volume& volume) const override { volume.slicing(mode_); }

  Image frame(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera,
              ImageSize size, RenderReport* report, const Progress&) const override {
    Image image;
    render_levels(volume, field, tf, camera, size, {options_.slices},
                  [&](std::size_t, int, Image&& i, RenderReport&& r) {
                    image = std::move(i);
                    if (report) *report = std::move(r);
                  });
    return image;
  }

  // Each level's image and report, the callee's to keep.
  using Taken = std::function<void(std::size_t level, int slices, Image&&, RenderReport&&)>;
  void render_levels(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera,
                     ImageSize size, const std::vector<int>& levels, const Taken& done) const {
    refuse_opacity_field(field, "slicing");
    volume.check(field);
    RenderReport first;
    const SliceRenderer& renderer =
        timed_preparation(volume, &first, [&]() -> const SliceRenderer& { return volume.slicing(mode_); });
    renderer.render_levels(field.values, tf, camera, size.width, size.height, options_, levels,
                           [&](std::size_t level, int slices, Image&& image, const SlicingStats& st) {
                             CELLPROJ_DCHECK(finite_pixels(image), "slicing made a pixel that is not finite");
                             RenderReport r;
                             if (level == 0) r.prepare_seconds = first.prepare_seconds;
                             fill(r, st, options_);
                             r.add("tetrahedralize", mode_);
                             add_numbering(r, renderer.local_cells().spread(), renderer.local_cells().renumbered());
                             done(level, slices, std::move(image), std::move(r));
                           });
  }

  std::uint64_t estimate_bytes(const VolumeSize& v, ImageSize size) const override {
    // Per point: coordinates (twice: recentred), screen attributes and height. Per tetrahedron:
    // the slice cells' ids and the cells' renumbered copy (40, as projection's). Per pixel: the
    // chunk's slice images (64 MB), lengths and layers.
    const std::uint64_t pixels = static_cast<std::uint64_t>(size.width) * static_cast<std::uint64_t>(size.height);
    return common_bytes(size) + static_cast<std::uint64_t>(v.points) * 112 + static_cast<std::uint64_t>(v.tets) * 88 +
           pixels * 8 + (64ull << 20) + (512ull << 20);
  }

 private:
  SlicingOptions options_;
  Tetrahedralize mode_;
};

// Anti-aliasing (RenderSettings::ssaa): the frame of the renderer it wraps, drawn n times larger on
// each side, each pixel the mean of its n x n samples (a box filter over the pixel's square) or a
// tent over them (the same weights for colour and opacity, premultiplied).
class Supersampled final : public Renderer {
 public:
  Supersampled(std::unique_ptr<Renderer> inner, int n, SampleFilter filter)
      : inner_(std::move(inner)), n_(n), filter_(filter) {}
  std::string name() const override { return inner_->name(); }
  void prepare(const Volume& volume) const override { inner_->prepare(volume); }
  std::uint64_t estimate_bytes(const VolumeSize& v, ImageSize size) const override {
    const std::uint64_t pixels = static_cast<std::uint64_t>(size.width) * static_cast<std::uint64_t>(size.height);
    return inner_->estimate_bytes(v, {size.width * n_, size.height * n_}) + pixels * 16;
  }

 private:
  Image frame(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera,
              ImageSize size, RenderReport* report, const Progress& progress) const override {
    return resolve_samples(inner_->render(volume, field, tf, camera, supersampled_size(size, n_), report, progress), n_,
                           filter_, report);
  }

  std::unique_ptr<Renderer> inner_;
  int n_;
  SampleFilter filter_;
};

// The renderer of the settings' mode, not supersampled.
std::unique_ptr<Renderer> mode_renderer(const RenderSettings& s) {
  switch (s.mode) {
    case RenderMode::projection: return std::make_unique<ProjectionMode>(s.projection, s.tetrahedralize);
    case RenderMode::exact: return std::make_unique<ExactMode>(s.interpolation, s.iso);
    case RenderMode::slicing: return std::make_unique<SlicingMode>(s.slicing, s.tetrahedralize);
    case RenderMode::reduction: return std::make_unique<ReductionMode>(s.reduction);
    case RenderMode::layers: return std::make_unique<LayersMode>(s.layers);
  }
  throw InputError("unknown render mode " + std::to_string(static_cast<int>(s.mode)));
}

}  // namespace

int worker_threads(long long asked) {
  if (asked < 0 || asked > kMaxThreads)
    throw InputError("setting 'threads': expected 0 (all cores) to " + std::to_string(kMaxThreads) + ", got " +
                     std::to_string(asked));
  return asked > 0 ? static_cast<int>(asked) : tbb::info::default_concurrency();
}

ImageSize supersampled_size(ImageSize size, int ssaa) {
  if (ssaa < 1 || ssaa > kMaxSsaa)
    throw InputError("setting 'ssaa': expected an integer in [1, " + std::to_string(kMaxSsaa) + "], got " +
                     std::to_string(ssaa));
  if (size.width > kMaxSupersampledSide / ssaa || size.height > kMaxSupersampledSide / ssaa)
    throw InputError("setting 'ssaa' " + std::to_string(ssaa) + " draws a " + std::to_string(size.width) + "x" +
                     std::to_string(size.height) + " image " + std::to_string(ssaa) +
                     " times larger on each side, beyond the " + std::to_string(kMaxSupersampledSide) +
                     " pixels a side a frame may have: lower it or the image size");
  return {size.width * ssaa, size.height * ssaa};
}

Image resolve_samples(Image samples, int ssaa, SampleFilter filter, RenderReport* report) {
  if (ssaa == 1) return samples;
  if (report) report->add("ssaa", std::int64_t{ssaa});
  return downsample(samples, ssaa, filter);
}

Image Renderer::render(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera,
                       ImageSize size, RenderReport* report, const Progress& progress) const {
  Image image = frame(volume, field, tf, camera, size, report, progress);
  CELLPROJ_DCHECK(finite_pixels(image), name() + " made a pixel that is not finite");
  return image;
}

Image Renderer::render(const Volume& volume, const Field& field, const TransferFunction& tf, const Camera& camera,
                       ImageSize size, const OpaqueDepth& opaque, RenderReport* report) const {
  check_opaque_depth(opaque, size.width, size.height, "opaque geometry");
  Image image = frame_among(volume, field, tf, camera, size, opaque, report);
  CELLPROJ_DCHECK(finite_pixels(image), name() + " made a pixel that is not finite");
  return image;
}

Image Renderer::frame_among(const Volume&, const Field&, const TransferFunction&, const Camera&, ImageSize,
                            const OpaqueDepth&, RenderReport*) const {
  throw UnsupportedError(
      "opaque geometry (a depth buffer) is drawn among by setting 'method' exact and the cell "
      "projection methods with setting 'backend' software and no anti-aliasing, not by " +
      name());
}

void render_progressive(const Volume& volume, const Field& field, const TransferFunction& tf,
                        const RenderSettings& settings, const Camera& camera, ImageSize size,
                        const std::vector<int>& levels, const LevelDone& done) {
  if (settings.mode != RenderMode::slicing)
    throw InputError("progressive refinement is a slicing feature: use setting 'method' slicing");
  const int n = settings.ssaa;
  SlicingMode(settings.slicing, settings.tetrahedralize)
      .render_levels(volume, field, tf, camera, supersampled_size(size, n), levels,
                     [&](std::size_t level, int slices, Image&& image, RenderReport&& report) {
                       const Image picture = resolve_samples(std::move(image), n, settings.ssaa_filter, &report);
                       done(level, slices, picture, report);
                     });
}

VolumeSize size_of(const MeshView& mesh) {
  VolumeSize v{mesh.n_points, mesh.n_cells, 0};
  for (std::int64_t c = 0; c < mesh.n_cells; ++c) v.tets += mesh.type(c) == CellType::Tetra ? 1 : kMaxTetsPerCell;
  return v;
}

std::unique_ptr<Renderer> make_renderer(const RenderSettings& s) {
  supersampled_size({1, 1}, s.ssaa);  // the factor checked now
  std::unique_ptr<Renderer> renderer = mode_renderer(s);
  if (s.ssaa == 1) return renderer;
  return std::make_unique<Supersampled>(std::move(renderer), s.ssaa, s.ssaa_filter);
}

Image render(const Volume& volume, const Field& field, const TransferFunction& tf, const RenderSettings& settings,
             const Camera& camera, ImageSize size, RenderReport* report) {
  return make_renderer(settings)->render(volume, field, tf, camera, size, report);
}

}  // namespace cellproj
