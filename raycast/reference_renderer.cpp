#include "raycast/reference_renderer.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <optional>
#include <vector>

#include "base/error.hpp"
#include "base/timing.hpp"
#include "optics/polynomial_segment.hpp"
#include "optics/two_fields.hpp"
#include "view/depth_limit.hpp"

namespace cellproj {
namespace {

// The scalar along a ray through one non-tetrahedral cell, crossing the segments [first, last) of
// its canonical tetrahedra; falls back to their linear value where Newton fails.
struct IsoparametricRun {
  const IsoparametricField& field;
  const double* scalar;
  const Ray& ray;
  const RaySegment* first;
  const RaySegment* last;
  glm::dvec3 xi;
  std::int64_t failures = 0;

  double at(double t) {
    double s;
    if (field.value(scalar, first->cell, ray.origin + t * ray.dir, xi, s)) return s;
    xi = field.centre_guess(first->cell);
    if (field.value(scalar, first->cell, ray.origin + t * ray.dir, xi, s)) return s;
    ++failures;
    xi = field.centre_guess(first->cell);
    const RaySegment* g = first;
    while (g + 1 < last && t > g->t1) ++g;
    const double u = g->t1 > g->t0 ? std::clamp((t - g->t0) / (g->t1 - g->t0), 0.0, 1.0) : 0.0;
    return g->s0 + u * (g->s1 - g->s0);
  }
};

// s along [ta, tb] as the degree-7 Chebyshev interpolant of the isoparametric field, checked
// against the field at three more points; where it is off by more than tol the run is halved.
void integrate_run(const TransferFunction& tf, IsoparametricRun& run, double ta, double tb, double tol, int depth,
                   SegmentLight& acc) {
  if (acc.depth >= kOpaqueDepth) return;
  const double mid = 0.5 * (ta + tb), half = 0.5 * (tb - ta);
  const ScalarPolynomial s = chebyshev_interpolant([&](double x) { return run.at(mid + half * x); });
  bool close = true;
  for (double x : {-0.6, 0.0, 0.6}) close = close && std::abs(s(x) - run.at(mid + half * x)) <= tol;
  if (close || depth >= 12) {
    acc = under(acc, integrate_polynomial_reference(tf, tb - ta, s));
    return;
  }
  integrate_run(tf, run, ta, mid, tol, depth + 1, acc);
  integrate_run(tf, run, mid, tb, tol, depth + 1, acc);
}

// The segments in front of t_max, the one it falls in cut there (the field linear along it: exact
// in a tetrahedron), into `out`; their count.
std::size_t cut_at(double t_max, const RaySegment* seg, std::size_t n, std::vector<RaySegment>& out) {
  out.clear();
  for (std::size_t k = 0; k < n && seg[k].t0 < t_max; ++k) {
    RaySegment g = seg[k];
    if (g.t1 > t_max) g.s1 = g.s0 + (g.s1 - g.s0) * ((t_max - g.t0) / (g.t1 - g.t0)), g.t1 = t_max;
    out.push_back(g);
  }
  return out.size();
}

}  // namespace

ExactRenderer::ExactRenderer(const MeshView& mesh) : local_(mesh), tracer_(local_.view()), n_points_(mesh.n_points) {
  const bool all_tets = std::all_of(mesh.types, mesh.types + mesh.n_cells,
                                    [](std::uint8_t t) { return t == static_cast<std::uint8_t>(CellType::Tetra); });
  if (!all_tets) iso_ = std::make_unique<IsoparametricField>(local_.view(), tracer_.points());
}

Image ExactRenderer::render(const double* scalar, const TransferFunction& tf, const Camera& camera, int width,
                            int height, CellInterpolation interpolation, ExactStats* stats,
                            const std::function<void(double)>& progress, const double* opacity,
                            const OpaqueDepth* opaque) const {
  const auto start = std::chrono::steady_clock::now();
  Image img(width, height);
  const IsoparametricField* iso =
      interpolation == CellInterpolation::isoparametric && scalar && !opacity ? iso_.get() : nullptr;
  std::optional<TwoFieldTransfer> two;
  if (opacity) two.emplace(tf);
  double scalar_tolerance = 0.0;  // largest error of the polynomial s(t) along a ray
  if (iso) {
    const auto [lo, hi] = std::minmax_element(scalar, scalar + n_points_);
    scalar_tolerance = 1e-9 * (*hi - *lo);
  }
  std::optional<PixelRays> rays;  // the opaque depth's rays: t along them is the tracer's (distance from the eye)
  std::optional<DepthLimit> limit;
  if (opaque) rays.emplace(camera, width, height), limit.emplace(*opaque, *rays);
  std::atomic<std::int64_t> segments{0}, failures{0};
  tracer_.trace(
      camera, width, height, scalar,
      [&](int i, int j, const Ray& ray, const RaySegment* seg, std::size_t n) {
        thread_local std::vector<RaySegment> cut;
        if (limit) n = cut_at(limit->t_max(i, j), seg, n, cut), seg = cut.data();
        SegmentLight acc;
        for (std::size_t k = 0; k < n && acc.depth < kOpaqueDepth;) {
          if (two) {  // the colour field traced, the opacity field read at the segment's ends
            const RaySegment& g = seg[k++];
            const double sf = tracer_.value(g.tet, opacity, ray.origin + g.t0 * ray.dir),
                         sb = tracer_.value(g.tet, opacity, ray.origin + g.t1 * ray.dir);
            acc = under(acc, integrate_two_fields_reference(*two, g.t1 - g.t0, g.s0, g.s1, sf, sb));
            continue;
          }
          if (!iso || iso->linear(seg[k].cell)) {
            acc = under(acc, integrate_segment_reference(tf, seg[k].t1 - seg[k].t0, seg[k].s0, seg[k].s1));
            ++k;
            continue;
          }
          std::size_t end = k + 1;  // the adjoining segments of this cell's tetrahedra
          while (end < n && seg[end].cell == seg[k].cell && seg[end].t0 <= seg[end - 1].t1 * (1 + 1e-12) + 1e-300)
            ++end;
          IsoparametricRun run{*iso, scalar, ray, seg + k, seg + end, iso->centre_guess(seg[k].cell)};
          const double ta = seg[k].t0, tb = seg[end - 1].t1;
          integrate_run(tf, run, ta, tb, scalar_tolerance, 0, acc);
          failures.fetch_add(run.failures, std::memory_order_relaxed);
          k = end;
        }
        float* px = img.pixel(i, j);
        px[0] = static_cast<float>(acc.rgb.r);
        px[1] = static_cast<float>(acc.rgb.g);
        px[2] = static_cast<float>(acc.rgb.b);
        px[3] = static_cast<float>(acc.opacity());
        segments.fetch_add(static_cast<std::int64_t>(n), std::memory_order_relaxed);
      },
      progress);
  if (stats) {
    stats->trace_seconds = seconds_since(start);
    stats->segments = segments;
    stats->newton_failures = failures;
  }
  return img;
}

}  // namespace cellproj
