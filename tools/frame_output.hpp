#pragma once
// Where `cellproj render` writes its pictures: one PNG (or EXR) and .npy, a frame pattern, a movie,
// the levels of --progressive. Internal to the command line.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "media/movie.hpp"
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

// The image into the PNG (an EXR by its name: float, premultiplied) and the .npy asked for (either
// path may be empty), saying so with `what`; on the picture the caption above it (labelled with
// `time` when the format says so), the colour legend beside it when given, and the format's
// annotations over it seen by `camera`.
void write_outputs(const Image& image, const PngFormat& format, const ColorBar* legend, const std::string& png,
                   const std::string& npy, const std::string& what, std::optional<double> time = std::nullopt,
                   const Camera* camera = nullptr);

// Where the frames go: one PNG (and .npy), or with a printf pattern (frame_%04d.png) one per frame,
// or a movie (-o turn.mp4, turn.gif) of every frame.
struct FramePaths {
  std::string png, npy;
  bool sequence = false;                            // a pattern: a file a frame
  std::optional<MovieFormat> movie = std::nullopt;  // -o names a movie
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
// .png), patterns checked (a bad one is a usage error); a movie's --npy must be a pattern.
FramePaths frame_paths(const std::string& png, const std::string& npy, const std::string& input, int frames);
// A frame pattern's folders made where missing; a single output's folder must exist. InputError
// naming the folder otherwise (bad output, exit 1).
void make_output_folders(const FramePaths& paths);

// Where a render's frames go as they are made: a sequence's each to its files, a movie's each
// encoded (none held), the one picture of a single output kept for finish() to write with what all
// frames measured.
class FrameWriter {
 public:
  FrameWriter(FramePaths paths, PngFormat format, std::optional<ColorBar> legend, MovieOptions movie = {});
  // Frame f (seen by `camera`; a series' at `time`), saying so with `what` where it is written now.
  void frame(int f, Image&& image, const std::string& what, std::optional<double> time, const Camera& camera);
  // The single picture written, or the movie closed, saying so with `what`.
  void finish(const std::string& what);
  // --progressive's level of `slices` planes, to OUT-64.png (and its .npy), written now.
  void level(int slices, const Image& image, const std::string& what, const Camera& camera) const;
  const FramePaths& paths() const { return paths_; }
  // Each frame written as it comes (a pattern or a movie), not one kept to the end.
  bool streams() const { return paths_.sequence || paths_.movie.has_value(); }

 private:
  FramePaths paths_;
  PngFormat format_;
  std::optional<ColorBar> legend_;
  std::unique_ptr<MovieWriter> movie_;
  struct Kept {
    Image image;
    std::optional<double> time;
    Camera camera;
  };
  std::optional<Kept> first_;
};

}  // namespace cellproj
