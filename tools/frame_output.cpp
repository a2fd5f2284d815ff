#include "tools/frame_output.hpp"

#include <cctype>
#include <cstdio>
#include <filesystem>

#include "base/error.hpp"
#include "base/file_status.hpp"
#include "media/exr.hpp"

namespace cellproj {

// out.png -> out-64.png: where level `slices` of --progressive goes.
std::string level_path(const std::string& path, int slices) {
  if (path.empty()) return path;
  const std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + "-" + std::to_string(slices) + p.extension().string())).string();
}

namespace {

// The figure of a frame: the format's page, caption (with `time` when labelled), annotations seen
// by `camera`, and the legend when given.
Figure figure_of(const PngFormat& format, const ColorBar* legend, std::optional<double> time, const Camera* camera) {
  Figure figure;
  figure.page = format.transparent ? std::nullopt : std::optional<glm::dvec3>(format.background);
  figure.bits = format.bits, figure.caption = format.caption;
  if (legend) figure.legend = *legend;
  if (time && format.time_format) figure.caption.label = time_label(*format.time_format, *time);
  if (camera) figure.annotations = format.annotations, figure.camera = *camera;
  return figure;
}

}  // namespace

void write_outputs(const Image& image, const PngFormat& format, const ColorBar* legend, const std::string& png,
                   const std::string& npy, const std::string& what, std::optional<double> time, const Camera* camera) {
  if (!png.empty()) {
    const Figure figure = figure_of(format, legend, time, camera);
    if (names_exr(png))
      write_exr(premultiplied(figure_pixels(image, figure)), png);
    else
      write_figure(image, figure, png);
  }
  if (!npy.empty()) write_npy(image, npy);
  for (const std::string& out : {png, npy})
    if (!out.empty()) std::printf("wrote %s (%s)\n", out.c_str(), what.c_str());
  std::fflush(stdout);
}

// True for a pattern with one %d (flags and width allowed, "%04d"); InputError for any other %.
bool is_frame_pattern(const std::string& path, const char* option) {
  int conversions = 0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i] != '%') continue;
    std::size_t j = i + 1;
    while (j < path.size() && (std::isdigit(static_cast<unsigned char>(path[j])) || path[j] == '0')) ++j;
    if (j >= path.size() || path[j] != 'd' || ++conversions > 1)
      throw InputError(std::string(option) + ": '" + path +
                       "': a frame pattern takes one %d (e.g. frame_%04d.png) and no other %");
    i = j;
  }
  return conversions == 1;
}

FramePaths frame_paths(const std::string& png, const std::string& npy, const std::string& input, int frames) {
  FramePaths p{png, npy};
  if (p.png.empty() && p.npy.empty()) p.png = std::filesystem::path(input).stem().string() + ".png";
  if (!p.png.empty()) p.movie = movie_format(p.png);
  const bool png_seq = is_frame_pattern(p.png, "-o"), npy_seq = is_frame_pattern(p.npy, "--npy");
  if (p.movie) {
    if (png_seq) throw InputError("-o: '" + p.png + "': a movie is one file, with no %d in its name");
    if (!p.npy.empty() && !npy_seq)
      throw InputError("--npy: with a movie in -o, give a frame pattern (frame_%04d.npy) for the frames' arrays");
    p.sequence = npy_seq;
    return p;
  }
  if (!p.png.empty() && !p.npy.empty() && png_seq != npy_seq)
    throw InputError("-o and --npy: give both as frame patterns (frame_%04d.png, frame_%04d.npy) or neither");
  p.sequence = png_seq || npy_seq;
  if (p.sequence && frames < 2) throw InputError("a frame pattern in -o or --npy needs --frames N (N >= 2)");
  return p;
}

void make_output_folders(const FramePaths& paths) {
  for (const std::string& out : {paths.png, paths.npy}) {
    if (out.empty()) continue;
    const std::string dir = std::filesystem::path(out).parent_path().string();
    if (paths.sequence && is_frame_pattern(out, "-o"))
      create_folders(dir);  // a frame pattern makes its folder
    else if (!dir.empty() && !path_is_folder(dir))
      throw InputError(where(dir, path_exists(dir)
                                      ? "is not a folder: " + out + " cannot be written"
                                      : "no such folder for " + out + " (only a --frames pattern makes its folder)"));
  }
}

FrameWriter::FrameWriter(FramePaths paths, PngFormat format, std::optional<ColorBar> legend, MovieOptions movie)
    : paths_(std::move(paths)), format_(std::move(format)), legend_(std::move(legend)) {
  const std::string picture = paths_.movie ? "a movie" : names_exr(paths_.png) ? "an EXR" : "";
  if (!picture.empty() && format_.bits != 8)
    throw InputError("--png-bits: " + paths_.png + " is " + picture + ", not a PNG" +
                     (paths_.movie ? " (its frames are 8-bit)" : " (its samples are 32-bit floats)"));
  if (paths_.movie && format_.transparent)
    throw InputError(paths_.png +
                     ": a movie has no alpha; give --background a colour (--background none is for "
                     "PNGs and EXRs)");
  if (paths_.movie) movie_ = std::make_unique<MovieWriter>(paths_.png, movie);
}

void FrameWriter::frame(int f, Image&& image, const std::string& what, std::optional<double> time,
                        const Camera& camera) {
  const ColorBar* legend = legend_ ? &*legend_ : nullptr;
  if (movie_) {
    movie_->add(figure_rgb8(image, figure_of(format_, legend, time, &camera)));
    if (paths_.sequence) write_outputs(image, format_, legend, "", paths_.npy_of(f), what, time, &camera);
  } else if (paths_.sequence) {
    write_outputs(image, format_, legend, paths_.png_of(f), paths_.npy_of(f), what, time, &camera);
  } else if (!first_) {
    first_ = Kept{std::move(image), time, camera};
  }
}

void FrameWriter::level(int slices, const Image& image, const std::string& what, const Camera& camera) const {
  write_outputs(image, format_, legend_ ? &*legend_ : nullptr, level_path(paths_.png, slices),
                level_path(paths_.npy, slices), what, std::nullopt, &camera);
}

void FrameWriter::finish(const std::string& what) {
  if (movie_) {
    movie_->finish();
    std::printf("wrote %s (%d frame%s, %s)\n", paths_.png.c_str(), movie_->frames(), movie_->frames() == 1 ? "" : "s",
                what.c_str());
    std::fflush(stdout);
  } else if (first_) {
    write_outputs(first_->image, format_, legend_ ? &*legend_ : nullptr, paths_.png, paths_.npy, what, first_->time,
                  &first_->camera);
  }
}

}  // namespace cellproj
