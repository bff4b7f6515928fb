// SPDX-License-Identifier: MIT
// rastrules: the command line (render, explain, showcase).
// Implements: SCENE.INPUT.ERRORS (exit codes)

#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <string_view>

#include "cli.hpp"
#include "rastrules/io/interrupt.hpp"

namespace {

struct Command {
  std::string_view name;
  int (*run)(const rastrules::cli::Args&);
};

constexpr Command kCommands[] = {
    {"render", rastrules::cli::run_render},         {"explain", rastrules::cli::run_explain},
    {"showcase", rastrules::cli::run_showcase},     {"fuzz", rastrules::cli::run_fuzz},
    {"check", rastrules::cli::run_check},           {"probe", rastrules::cli::run_probe},
    {"bench", rastrules::cli::run_bench},           {"cases", rastrules::cli::run_cases},
    {"fuzz-merge", rastrules::cli::run_fuzz_merge},
#ifdef RASTRULES_HAVE_GLYPH
    {"glyph", rastrules::cli::run_glyph},
#endif
};

} // namespace

int main(int argc, char** argv) {
  using namespace rastrules::cli;
  Args args(argv + 1, argv + argc);
  if (args.empty())
    return usage_error("missing command");
  const std::string command = args.front();
  args.erase(args.begin());
  try {
    if (command == "--help" || command == "-h" || command == "help") {
      print_usage(stdout);
      return kExitOk;
    }
    // rule: SCENE.INPUT.ERRORS
    // An interrupt removes the temporaries and ends the driver's process group; a campaign
    // then stops after its case and writes what it has, anything else exits at once.
    const bool campaign = command == "fuzz" || command == "check" || command == "probe";
    rastrules::io::handle_interrupts(campaign ? rastrules::io::OnInterrupt::kRecord
                                              : rastrules::io::OnInterrupt::kExit);
    for (const Command& c : kCommands) {
      if (command == c.name)
        return c.run(args);
    }
    return usage_error("unknown command \"" + command + "\"");
  } catch (const std::bad_alloc&) {
    return error("out of memory");
  } catch (const std::exception& e) {
    return error(std::string("internal error: ") + e.what());
  }
}
