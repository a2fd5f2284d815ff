#pragma once
// Early ray termination (issue 21): composited front to back, a pixel whose accumulated opacity is
// within kOpaqueWithin of 1 lets nothing behind it show by more than that, so later fragments there
// are dropped, and a cell whose every pixel is such is not projected at all. The mask holds one
// bit per pixel in rows of whole 64-bit words: tiles of whole rows write disjoint words.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace cellproj {

constexpr double kOpaqueWithin = 1e-6;
// The accumulated alpha (float, as the image holds it) from which a pixel counts as opaque.
constexpr float kOpaqueAlpha = static_cast<float>(1.0 - kOpaqueWithin);

class OpaqueMask {
 public:
  OpaqueMask(int width, int height)
      : words_((width + 63) / 64),
        bits_(static_cast<std::size_t>(words_) * static_cast<std::size_t>(height), 0),
        per_row_(static_cast<std::size_t>(height), 0) {}
  void set(int i, int j) {
    std::uint64_t& word = bits_[at(i, j)];
    const std::uint64_t bit = std::uint64_t(1) << (i & 63);
    per_row_[static_cast<std::size_t>(j)] += (word & bit) == 0;
    word |= bit;
  }
  bool opaque(int i, int j) const { return (bits_[at(i, j)] >> (i & 63)) & 1; }
  // Whether every pixel i0 <= i <= i1, j0 <= j <= j1 is opaque (true for an empty box).
  bool all(int i0, int i1, int j0, int j1) const {
    if (i1 < i0) return true;
    for (int j = j0; j <= j1; ++j)  // rows with too few opaque pixels: no word to look at
      if (per_row_[static_cast<std::size_t>(j)] < i1 - i0 + 1) return false;
    const int w0 = i0 >> 6, w1 = i1 >> 6;
    for (int j = j0; j <= j1; ++j) {
      const std::uint64_t* row = &bits_[static_cast<std::size_t>(j) * static_cast<std::size_t>(words_)];
      for (int w = w0; w <= w1; ++w) {
        std::uint64_t want = ~std::uint64_t(0);
        if (w == w0) want &= ~std::uint64_t(0) << (i0 & 63);
        if (w == w1) want &= ~std::uint64_t(0) >> (63 - (i1 & 63));
        if ((row[w] & want) != want) return false;
      }
    }
    return true;
  }

 private:
  std::size_t at(int i, int j) const {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(words_) + static_cast<std::size_t>(i >> 6);
  }
  int words_;
  std::vector<std::uint64_t> bits_;
  std::vector<int> per_row_;  // opaque pixels per row
};

}  // namespace cellproj
