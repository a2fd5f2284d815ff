// cellproj: direct volume rendering of unstructured and curvilinear grids.
#include <cstdio>
#include <filesystem>
#include <new>
#include <string>

#include "base/error.hpp"
#include "base/huge_pages.hpp"
#include "distributed/communicator.hpp"
#include "media/movie.hpp"
#include "tools/commands.hpp"
#include "tools/terminal_text.hpp"

int main(int argc, char** argv) {
  using namespace cellproj;
  keep_frame_arrays_in_heap();         // a frame's arrays of a few MB reused, not mapped anew (base/huge_pages.hpp)
  const MpiSession mpi(&argc, &argv);  // MPI only when launched by mpirun
  quiet_ffmpeg_messages();             // a movie's encoder says what goes wrong, not how it went
  // Under mpirun every rank meets the same error (agree() makes them one): rank 0 reports it.
  const bool report_errors = Communicator::world().rank == 0;
  CLI::App app{"cellproj: direct volume rendering of unstructured and curvilinear grids by cell projection"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "cellproj 0.1.0");
  const Action render = add_render(app), info = add_info(app), generate = add_generate(app),
               sortbench = add_sortbench(app), compare = add_compare(app), scene = add_scene(app),
               partition = add_partition(app);
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
    if (app.got_subcommand("partition")) return partition();
    return generate();
  } catch (const UsageError& e) {
    if (report_errors) std::fprintf(stderr, "cellproj: error: %s\n", cli_words(e.what()).c_str());
    return kExitUsage;
  } catch (const InputError& e) {
    if (report_errors) std::fprintf(stderr, "cellproj: error: %s\n", cli_words(e.what()).c_str());
    return kExitInput;
  } catch (const ResourceError& e) {
    if (report_errors) std::fprintf(stderr, "cellproj: error: %s\n", cli_words(e.what()).c_str());
    return kExitInternal;
  } catch (const std::bad_alloc&) {
    std::string command;
    for (int i = 1; i < argc; ++i) command += std::string(i > 1 ? " " : "") + argv[i];
    std::fprintf(stderr,
                 "cellproj: error: out of memory in 'cellproj %s': use a smaller --size or mesh, or lower "
                 "--max-memory so that the estimate refuses it up front\n",
                 command.c_str());
    return kExitInternal;
  } catch (const std::filesystem::filesystem_error& e) {  // a path the checks above did not look up first
    if (report_errors)
      std::fprintf(stderr, "cellproj: error: %s\n",
                   printable(where(e.path1().string(), "cannot be used (" + e.code().message() + ")")).c_str());
    return kExitInput;
  } catch (const std::exception& e) {
    if (report_errors) std::fprintf(stderr, "cellproj: internal error: %s\n", cli_words(e.what()).c_str());
    return kExitInternal;
  }
}
