#pragma once
// The ordered batch pipeline (MWSC section 7, on oneTBB): items already in visibility order (cells,
// slice polygons, splats) are cut into batches; worker threads turn batches into fragments in
// parallel, kept by band of image rows (FragmentBands), and the batches are blended in order,
// "over", each batch's bands in parallel: a pixel sees its fragments in the items' order, and a
// band's rows stay in cache. Compositing runs in the order alone, so 1 and N threads give the same
// image bit for bit, and the blend is not a serial stage: its share does not grow with threads.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/concurrent_queue.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include "composite/fragment.hpp"
#include "view/image.hpp"

namespace cellproj {

// What turns the k-th item of the order into fragments. A Source provides
//   Scratch   per-token working memory, kept from batch to batch (default-constructible);
//   Counters  per-batch counts, value-initialised, merged with `void add(const Counters&)`;
//   void fragments(std::size_t k, FragmentBands& out, Scratch&, Counters&) const
//             appends item k's fragments (called from many threads at once);
//   void composite(std::size_t k, Image& image, Scratch&, Counters&) const
//             draws item k straight onto the image, "over" (called in order from the compositor).
struct PipelineLimits {
  std::size_t batch_items = 0;  // items per token; 0: about 16 tokens per thread, 64 to 2048
  // A token also closes once its items' footprints add up to this many pixels, so that its
  // fragments (20 bytes each, at most one per covered pixel and item) stay near 4 MB: a token's
  // buffer is then reused by the frame's later batches instead of growing into fresh pages, a page
  // fault each (at 5e6, 100 MB per token, pt-linear on 10k tetrahedra at 1024² took 1.6 times as
  // long: docs/methods.md, "Fresh pages").
  double batch_pixels = 2e5;
  // An item covering more is not buffered: the compositor draws it itself, in order, straight onto
  // the image (a few huge cells in a large image would otherwise buffer gigabytes of fragments).
  double direct_pixels = 1e6;
};

// Items per token: the limit, or enough tokens to keep every thread busy on small inputs (a few
// large cells cover most pixels there) without per-token overhead on large ones.
inline std::size_t batch_size(std::size_t option, std::size_t items) {
  if (option > 0) return option;
  const std::size_t per = items / (16 * static_cast<std::size_t>(tbb::this_task_arena::max_concurrency()));
  return std::clamp<std::size_t>(per, 64, 2048);
}

// The bands of the blend: 2^shift rows, about 2 bands per thread, at least 4 rows; one band below
// 4 threads. The serial blend of one band is 10% of pt-linear's work on the 1M box (3.6 ns a
// fragment), hidden behind the projection on 2 threads, where bands cost 10% more (docs/methods.md,
// "Threads"); Amdahl caps one band at 6.4x on 16 threads and 8.8x on 64.
inline int band_shift(int height) {
  const int threads = tbb::this_task_arena::max_concurrency();
  if (threads < 4) return 30;
  const int rows = height / (2 * threads);
  int shift = 2;
  while ((2 << shift) <= rows) ++shift;
  return shift;
}

// Composites items [0, n) of the order onto `image`; footprint(k) is the number of pixels item k
// may cover (its image bounding box). Threads: those of the calling task arena. Returns the sum of
// the batches' counters.
// `blend_seconds`, when given, receives the time the blend stage took (the serial share with one
// band; its bands' parallel loops included otherwise).
template <class Source, class Footprint>
typename Source::Counters composite_in_order(Image& image, std::size_t n, const Footprint& footprint,
                                             const PipelineLimits& limits, const Source& source,
                                             double* blend_seconds = nullptr) {
  const int shift = band_shift(image.height);
  struct Batch {
    std::size_t begin = 0, end = 0;
    FragmentBands fragments{0, 0, 0};
    // The items left to the compositor: their positions in the order, and each band's fragments
    // emitted before each of them (direct.size() x bands).
    std::vector<std::size_t> direct, direct_at;
    typename Source::Counters counters{};
    typename Source::Scratch scratch{};
  };
  typename Source::Counters total{};
  const std::size_t batch = batch_size(limits.batch_items, n);
  const int tokens = 2 * tbb::this_task_arena::max_concurrency();
  std::vector<Batch> batches(static_cast<std::size_t>(tokens));
  tbb::concurrent_bounded_queue<Batch*> free;  // batches are reused, keeping their fragment buffers
  for (auto& b : batches) {
    b.fragments.reset(image.width, image.height, shift);
    free.push(&b);
  }
  const std::size_t bands = batches.front().fragments.bands();
  std::size_t next = 0;
  auto cut = [&](tbb::flow_control& fc) -> Batch* {
    if (next >= n) {
      fc.stop();
      return nullptr;
    }
    Batch* b = nullptr;
    free.pop(b);
    b->begin = next;
    double pixels = 0;
    for (const std::size_t last = std::min(n, next + batch); next < last && pixels < limits.batch_pixels; ++next) {
      const double a = footprint(next);
      if (a <= limits.direct_pixels) pixels += a;
    }
    b->end = next;
    return b;
  };
  auto project = [&](Batch* b) {
    b->fragments.clear();
    b->direct.clear();
    b->direct_at.clear();
    b->counters = {};
    for (std::size_t k = b->begin; k < b->end; ++k) {
      if (footprint(k) > limits.direct_pixels) {
        b->direct.push_back(k);
        for (std::size_t band = 0; band < bands; ++band) b->direct_at.push_back(b->fragments.band(band).size());
      } else {
        source.fragments(k, b->fragments, b->scratch, b->counters);
      }
    }
    return b;
  };
  std::vector<std::size_t> done(bands);  // each band's fragments blended so far (the blend stage's own)
  // Each band's fragments up to upto[band] (or all) "over" the image, the bands in parallel.
  auto blend_bands = [&](const Batch& b, const std::size_t* upto) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, bands), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t band = r.begin(); band != r.end(); ++band) {
        const Fragments& f = b.fragments.band(band);
        const std::size_t to = upto ? upto[band] : f.size();
        composite_over(image, f.data() + done[band], to - done[band]);
        done[band] = to;
      }
    });
  };
  double blending = 0.0;
  auto blend = [&](Batch* b) {
    const auto t0 = std::chrono::steady_clock::now();
    std::fill(done.begin(), done.end(), 0);
    for (std::size_t d = 0; d < b->direct.size(); ++d) {  // the direct items go in between, in order
      blend_bands(*b, b->direct_at.data() + d * bands);
      source.composite(b->direct[d], image, b->scratch, b->counters);
    }
    blend_bands(*b, nullptr);
    total.add(b->counters);
    free.push(b);
    blending += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  tbb::parallel_pipeline(static_cast<std::size_t>(tokens),
                         tbb::make_filter<void, Batch*>(tbb::filter_mode::serial_in_order, cut) &
                             tbb::make_filter<Batch*, Batch*>(tbb::filter_mode::parallel, project) &
                             tbb::make_filter<Batch*, void>(tbb::filter_mode::serial_in_order, blend));
  if (blend_seconds) *blend_seconds = blending;
  return total;
}

}  // namespace cellproj
