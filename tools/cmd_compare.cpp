// cellproj compare A.npy B.npy: how far apart two float images are (the numbers of methods.md).
#include <cstdio>

#include "base/error.hpp"
#include "media/exr.hpp"
#include "tools/commands.hpp"
#include "view/image.hpp"

namespace cellproj {
namespace {

// A float image by its name: an OpenEXR (render -o x.exr) or a .npy (render --npy).
Image read_float_image(const std::string& path) { return names_exr(path) ? read_exr(path) : read_npy(path); }

}  // namespace

Action add_compare(CLI::App& app) {
  struct Args {
    std::string a, b, diff;
    double scale = 10.0;
    int downsample = 1;
    std::string filter = "box";
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd =
      app.add_subcommand("compare", "Largest and RMS difference of two float images written by render (--npy, .exr)");
  cmd->add_option("a", args->a, "First image (.npy or .exr)")->required();
  cmd->add_option("b", args->b, "Second image (.npy or .exr), e.g. the exact reference")->required();
  cmd->add_option("--diff", args->diff, "Also write |a - b| as a PNG, multiplied by --scale");
  cmd->add_option("--scale", args->scale, "Gain of the --diff image (default 10)")->check(positive_number("a gain"));
  cmd->add_option("--downsample", args->downsample,
                  "Box-filter B down by K first (B rendered at K times A's size: the anti-aliased reference)")
      ->check(CLI::Range(1, 64));
  cmd->add_option("--filter", args->filter,
                  "How --downsample filters: box (default) or tent, as render's --ssaa-filter")
      ->check(CLI::IsMember({"box", "tent"}));
  return [args] {
    const Image a = read_float_image(args->a), b_read = read_float_image(args->b);  // each names its file when it fails
    Image b;
    try {
      b = downsample(b_read, args->downsample, args->filter == "tent" ? SampleFilter::tent : SampleFilter::box);
    } catch (const InputError& e) {  // a size --downsample does not divide: which file
      throw InputError(args->b + ": " + e.what());
    }
    const ImageDifference d = compare(a, b);
    if (!args->diff.empty()) write_png(difference_image(a, b, args->scale), glm::dvec3(0.0), args->diff);
    std::printf("{\"max_abs\": %.6g, \"rmse\": %.6g}\n", d.max_abs, d.rmse);
    return kExitOk;
  };
}

}  // namespace cellproj
