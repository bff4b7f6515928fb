// SPDX-License-Identifier: MIT
// rastrules: the command line: --version, help [COMMAND], -q/-v, and the commands (each
// parses its own options with CLI11, parser.hpp). Built twice: rastrules-full holds every
// command; rastrules (RASTRULES_CLI_FRONT) holds render and explain, linked against the kernel
// and io alone, and runs rastrules-full beside it for every other command (SCENE.CLI.FRONT).
// Implements: SCENE.INPUT.ERRORS (exit codes), SCENE.CLI.FRONT

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <string_view>

#include "cli.hpp"
#include "rastrules/io/interrupt.hpp"

#ifdef RASTRULES_CLI_FRONT
#include <climits>
#include <unistd.h>
#endif

namespace {

struct Command {
  std::string_view name;
  int (*run)(const rastrules::cli::Args&);
};

constexpr Command kCommands[] = {
    {"render", rastrules::cli::run_render},         {"explain", rastrules::cli::run_explain},
#ifndef RASTRULES_CLI_FRONT
    {"showcase", rastrules::cli::run_showcase},     {"fuzz", rastrules::cli::run_fuzz},
    {"check", rastrules::cli::run_check},           {"probe", rastrules::cli::run_probe},
    {"bench", rastrules::cli::run_bench},           {"cases", rastrules::cli::run_cases},
    {"fuzz-merge", rastrules::cli::run_fuzz_merge}, {"fuzz2d", rastrules::cli::run_fuzz2d},
#ifdef RASTRULES_HAVE_GLYPH
    {"glyph", rastrules::cli::run_glyph},
#endif
#endif
};

#ifdef RASTRULES_CLI_FRONT
// rule: SCENE.CLI.FRONT
// Runs rastrules-full, the program beside this one, with this one's arguments (argv as given:
// the same options, -q/-v included; its exit status and signals are the command's own). Beside:
// in the directory of /proc/self/exe (symbolic links resolved); where /proc is not mounted, of
// argv[0] when it names a path, else rastrules-full is looked for on PATH as rastrules was.
// Returns only when it cannot be started, with the one-line error.
int run_full(char** argv, const std::string& command) {
  constexpr std::string_view kFull = "rastrules-full";
  char self[PATH_MAX];
  const ssize_t n = ::readlink("/proc/self/exe", self, sizeof self - 1);
  const std::string_view path =
      n > 0 ? std::string_view(self, static_cast<std::size_t>(n)) : std::string_view(argv[0]);
  const std::size_t slash = path.rfind('/');
  std::string full(kFull);
  if (slash != std::string_view::npos)
    full = std::string(path.substr(0, slash + 1)) + full;
  argv[0] = full.data();
  if (slash != std::string_view::npos)
    ::execv(full.c_str(), argv);
  else
    ::execvp(full.c_str(), argv);
  const int err = errno;
  return rastrules::cli::error("the command " + rastrules::cli::shown_value(command) +
                               " is run by " + full + ", which cannot be started (" +
                               std::strerror(err) + ")");
}
#endif

} // namespace

namespace {

const Command* find_command(std::string_view name) {
  for (const Command& c : kCommands) {
    if (name == c.name)
      return &c;
  }
  return nullptr;
}

} // namespace

int main(int argc, char** argv) {
  using namespace rastrules::cli;
  Args args(argv + 1, argv + argc);
  // rule: SCENE.INPUT.ERRORS
  // -q/-v before the command apply to it as after it.
  while (!args.empty() && (args.front() == "-q" || args.front() == "--quiet" ||
                           args.front() == "-v" || args.front() == "--verbose")) {
    const bool quiet = args.front() == "-q" || args.front() == "--quiet";
    if (verbosity() != Verbosity::kNormal && (verbosity() == Verbosity::kQuiet) != quiet)
      return usage_error("-q and -v cannot be used together");
    set_verbosity(quiet ? Verbosity::kQuiet : Verbosity::kVerbose);
    args.erase(args.begin());
  }
  if (args.empty())
    return usage_error("missing command");
  const std::string command = args.front();
  args.erase(args.begin());
  try {
    if (command == "--version" || command == "-V") {
      std::printf("rastrules %s (scene format %d)\n", RASTRULES_VERSION, kSceneFormatVersion);
      return kExitOk;
    }
    if (command == "--help" || command == "-h" || (command == "help" && args.empty())) {
      print_usage(stdout);
      return kExitOk;
    }
    if (command == "help") {
      // help COMMAND: the command's own help, as COMMAND --help prints it.
      if (args.size() > 1)
        return usage_error("help: one command only");
      const Command* c = find_command(args.front());
#ifdef RASTRULES_CLI_FRONT
      if (c == nullptr)
        return run_full(argv, args.front());
#endif
      if (c == nullptr)
        return usage_error("help: unknown command " + shown_value(args.front()));
      return c->run({"--help"});
    }
    const Command* c = find_command(command);
#ifdef RASTRULES_CLI_FRONT
    if (c == nullptr)
      return run_full(argv, command);
#endif
    if (c == nullptr)
      return usage_error("unknown command " + shown_value(command));
    // rule: SCENE.INPUT.ERRORS
    // An interrupt removes the temporaries and ends the driver's process group; a campaign
    // then stops after its case and writes what it has, anything else exits at once.
    const bool campaign =
        command == "fuzz" || command == "check" || command == "probe" || command == "fuzz2d";
    rastrules::io::handle_interrupts(campaign ? rastrules::io::OnInterrupt::kRecord
                                              : rastrules::io::OnInterrupt::kExit);
    return c->run(args);
  } catch (const std::bad_alloc&) {
    return error("out of memory");
  } catch (const std::exception& e) {
    return error(std::string("internal error: ") + e.what());
  }
}
