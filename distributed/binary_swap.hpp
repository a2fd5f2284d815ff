#pragma once
// Sort-last compositing of the ranks' sub-images over MPI by binary swap (Ma, Painter, Hansen and
// Krogh 1994) for any number of ranks: the ranks beyond the largest power of two first fold their
// image into their neighbour in depth, then log2 rounds each halve the rows a rank owns and swap the
// other half with a partner, "over" in depth order; rank 0 gathers the bands. Each message carries
// only the sender's covered box within the rows it gives (a brick's screen footprint).
#include <vector>

#include "composite/partial_image.hpp"
#include "distributed/communicator.hpp"
#include "view/image.hpp"

namespace cellproj {

// `image` is this rank's premultiplied sub-image (the whole picture's size), zero outside `covered`.
// `back_to_front`: every rank once, the farthest first (the ranks' pieces must be disjoint in depth:
// each is convex, or a union of bricks contiguous in every view order). On return rank 0's image is
// the picture; other ranks' images are left partly composited. Without MPI (one rank) nothing moves.
TrafficStats composite_binary_swap(const Communicator& comm, Image& image, ScreenBox covered,
                                   const std::vector<int>& back_to_front);

}  // namespace cellproj
