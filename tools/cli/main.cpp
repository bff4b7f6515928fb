// SPDX-License-Identifier: MIT
// rastrules: the command line (render, explain, showcase).
// Implements: SCENE.INPUT.ERRORS (exit codes)

#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include "cli.hpp"

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
    if (command == "render")
      return run_render(args);
    if (command == "explain")
      return run_explain(args);
    if (command == "showcase")
      return run_showcase(args);
    if (command == "fuzz")
      return run_fuzz(args);
    if (command == "check")
      return run_check(args);
    if (command == "probe")
      return run_probe(args);
    if (command == "bench")
      return run_bench(args);
    if (command == "cases")
      return run_cases(args);
    return usage_error("unknown command \"" + command + "\"");
  } catch (const std::bad_alloc&) {
    return error("out of memory");
  } catch (const std::exception& e) {
    return error(std::string("internal error: ") + e.what());
  }
}
