#include "tools/frame_output.hpp"

#include <cctype>
#include <cstdio>
#include <filesystem>

#include "base/error.hpp"
#include "base/file_status.hpp"

namespace cellproj {

// out.png -> out-64.png: where level `slices` of --progressive goes.
std::string level_path(const std::string& path, int slices) {
  if (path.empty()) return path;
  const std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + "-" + std::to_string(slices) + p.extension().string())).string();
}

// The image into the PNG and the .npy asked for (either path may be empty), saying so with `what`;
// the colour legend drawn on the PNG when given.
void write_outputs(const Image& image, const PngFormat& format, const ColorBar* legend, const std::string& png,
                   const std::string& npy, const std::string& what, std::optional<double> time, const Camera* camera) {
  if (!png.empty()) {
    Figure figure;
    figure.page = format.transparent ? std::nullopt : std::optional<glm::dvec3>(format.background);
    figure.bits = format.bits, figure.caption = format.caption;
    if (legend) figure.legend = *legend;
    if (time && format.time_format) figure.caption.label = time_label(*format.time_format, *time);
    if (camera) figure.annotations = format.annotations, figure.camera = *camera;
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
  const bool png_seq = is_frame_pattern(p.png, "-o"), npy_seq = is_frame_pattern(p.npy, "--npy");
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
    if (paths.sequence)
      create_folders(dir);  // a frame pattern makes its folder
    else if (!dir.empty() && !path_is_folder(dir))
      throw InputError(where(dir, path_exists(dir)
                                      ? "is not a folder: " + out + " cannot be written"
                                      : "no such folder for " + out + " (only a --frames pattern makes its folder)"));
  }
}

}  // namespace cellproj
