#pragma once
// Where `cellproj render` writes its pictures: one PNG and .npy, a frame pattern, the levels of
// --progressive. Internal to the command line.
#include <cstdio>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "view/caption.hpp"
#include "view/color_bar.hpp"
#include "view/figure.hpp"
#include "view/image.hpp"

namespace cellproj {

// out.png -> out-64.png: where level `slices` of --progressive goes.
std::string level_path(const std::string& path, int slices);

// How a PNG is written: over the background, or transparent (straight alpha, --background none);
// 8 or 16 bits a sample (--png-bits).
struct PngFormat {
  glm::dvec3 background{0.0};
  bool transparent = false;
  int bits = 8;
  Caption caption;                         // its title (and text colour), above the picture
  std::optional<std::string> time_format;  // a time series' frames labelled with their time so
  Annotations annotations;                 // the outline and the axes over the picture, when asked
};

// The image into the PNG and the .npy asked for (either path may be empty), saying so with `what`;
// on the PNG the caption above the picture (labelled with `time` when the format says so), the
// colour legend beside it when given, and the format's annotations over it seen by `camera`.
void write_outputs(const Image& image, const PngFormat& format, const ColorBar* legend, const std::string& png,
                   const std::string& npy, const std::string& what, std::optional<double> time = std::nullopt,
                   const Camera* camera = nullptr);

// Where the frames go: one PNG (and .npy), or with a printf pattern (frame_%04d.png) one per frame.
struct FramePaths {
  std::string png, npy;
  bool sequence = false;
  std::string png_of(int f) const { return sequence ? frame_path(png, f) : png; }
  std::string npy_of(int f) const { return sequence ? frame_path(npy, f) : npy; }
  static std::string frame_path(const std::string& pattern, int f) {
    if (pattern.empty()) return pattern;
    std::vector<char> out(pattern.size() + 32);
    std::snprintf(out.data(), out.size(), pattern.c_str(), f);
    return out.data();
  }
};

// True for a pattern with one %d (flags and width allowed, "%04d"); InputError for any other %.
bool is_frame_pattern(const std::string& path, const char* option);

// The outputs of a render of `frames` frames: -o and --npy as given (by default INPUT's name with
// .png), patterns checked (a bad one is a usage error).
FramePaths frame_paths(const std::string& png, const std::string& npy, const std::string& input, int frames);
// A frame pattern's folders made where missing; a single output's folder must exist. InputError
// naming the folder otherwise (bad output, exit 1).
void make_output_folders(const FramePaths& paths);

}  // namespace cellproj
