// cellproj: direct volume rendering of unstructured and curvilinear grids.
#include <cstdio>
#include <new>
#include <string>

#include "base/error.hpp"
#include "tools/commands.hpp"

int main(int argc, char** argv) {
  using namespace cellproj;
  CLI::App app{"cellproj: direct volume rendering of unstructured and curvilinear grids by cell projection"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "cellproj 0.1.0");
  const Action render = add_render(app), info = add_info(app), generate = add_generate(app),
               sortbench = add_sortbench(app), compare = add_compare(app), scene = add_scene(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitUsage;
  }
  try {
    if (app.got_subcommand("render")) return render();
    if (app.got_subcommand("info")) return info();
    if (app.got_subcommand("sortbench")) return sortbench();
    if (app.got_subcommand("compare")) return compare();
    if (app.got_subcommand("scene")) return scene();
    return generate();
  } catch (const UsageError& e) {
    std::fprintf(stderr, "cellproj: error: %s\n", e.what());
    return kExitUsage;
  } catch (const InputError& e) {
    std::fprintf(stderr, "cellproj: error: %s\n", e.what());
    return kExitInput;
  } catch (const ResourceError& e) {
    std::fprintf(stderr, "cellproj: error: %s\n", e.what());
    return kExitInternal;
  } catch (const std::bad_alloc&) {
    std::string command;
    for (int i = 1; i < argc; ++i) command += std::string(i > 1 ? " " : "") + argv[i];
    std::fprintf(stderr,
                 "cellproj: error: out of memory in 'cellproj %s': use a smaller --size or mesh, or lower "
                 "--max-memory so that the estimate refuses it up front\n",
                 command.c_str());
    return kExitInternal;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cellproj: internal error: %s\n", e.what());
    return kExitInternal;
  }
}
