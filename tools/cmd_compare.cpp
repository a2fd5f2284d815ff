// cellproj compare A.npy B.npy: how far apart two float images are (the numbers of methods.md).
#include <cstdio>

#include "tools/commands.hpp"
#include "view/image.hpp"

namespace cellproj {

Action add_compare(CLI::App& app) {
  struct Args {
    std::string a, b;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("compare", "Largest and RMS difference of two .npy images written by render --npy");
  cmd->add_option("a", args->a, "First image (.npy)")->required();
  cmd->add_option("b", args->b, "Second image (.npy), e.g. the exact reference")->required();
  return [args] {
    const ImageDifference d = compare(read_npy(args->a), read_npy(args->b));
    std::printf("{\"max_abs\": %.6g, \"rmse\": %.6g}\n", d.max_abs, d.rmse);
    return kExitOk;
  };
}

}  // namespace cellproj
