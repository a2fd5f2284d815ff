#pragma once
// The cellproj subcommands. Each registers its options on the CLI11 app and returns the action to
// run once the command line is parsed; the action returns the exit code.
#include <cmath>
#include <functional>
#include <string>

#include <CLI/CLI.hpp>

#include "base/error.hpp"

namespace cellproj {

// Exit codes (docs/cli.md).
constexpr int kExitOk = 0;
constexpr int kExitInput = 1;     // bad input: mesh, scene, transfer function, camera, field
constexpr int kExitUsage = 2;     // bad command line
constexpr int kExitInternal = 3;  // a bug or an exhausted resource

// A bad command-line value (an unknown --method, a malformed --size, an option the method does not
// read): exit code 2, where the same value from a scene file is bad input (1).
class UsageError : public Error {
 public:
  using Error::Error;
};

// Runs f, turning the InputError of a value the command line gave into a UsageError.
template <class F>
auto usage(F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    throw UsageError(e.what());
  }
}

using Action = std::function<int()>;

// A positive number option's check with a one-line message (CLI11's PositiveNumber accepts nan and
// prints its range up to DBL_MAX in full): `what` names the value, e.g. "GiB".
inline CLI::Validator positive_number(const std::string& what) {
  return CLI::Validator(
      [what](std::string& text) -> std::string {
        double v = 0.0;
        const bool ok = CLI::detail::lexical_cast(text, v) && std::isfinite(v) && v > 0.0;
        return ok ? std::string() : "expected a finite number > 0 (" + what + "), got '" + text + "'";
      },
      "NUMBER > 0");
}

// --max-memory GiB: `what` ("Refuse renders") estimated to need more, and the limit of a mesh
// reader's process (default: the memory available now).
inline void add_max_memory_option(CLI::App& cmd, double& gib, const std::string& what) {
  cmd.add_option("--max-memory", gib,
                 what +
                     " estimated to need more than this many GiB, and stop a mesh reader at it (default: the "
                     "memory available now)")
      ->check(positive_number("GiB"));
}

Action add_render(CLI::App& app);
Action add_info(CLI::App& app);
Action add_generate(CLI::App& app);
Action add_sortbench(CLI::App& app);
Action add_compare(CLI::App& app);
Action add_scene(CLI::App& app);
Action add_partition(CLI::App& app);

}  // namespace cellproj
