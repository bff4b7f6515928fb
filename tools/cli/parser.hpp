// SPDX-License-Identifier: MIT
// The parser of one rastrules command: CLI11 (Debian's libcli11-dev) with the project's
// conventions. Options take "--opt VALUE" and "--opt=VALUE" (the last one given wins), every
// command has -h/--help (its own help on standard output, exit 0) and -q/-v, and a usage error
// is one line "rastrules: error: ..." plus the hint "run 'rastrules COMMAND --help'", exit 2.
// Values are taken as text and checked by the command, whose one-line errors name the option
// and show the value (shown_value()).
// Implements: SCENE.INPUT.ERRORS (usage errors)

#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli.hpp"

namespace rastrules::cli {

class CommandLine {
public:
  // `command`: the name after "rastrules"; `summary`: its help's first paragraph.
  CommandLine(const std::string& command, const std::string& summary);

  CLI::App& app() { return app_; }

  // --NAME VALUE (or --NAME=VALUE) into `slot`; `missing`: the error when no value follows (one
  // line when it ends "got nothing" like every bad value, else a usage error with the hint).
  CLI::Option* value(const std::string& flags, std::optional<std::string>& slot,
                     const std::string& type, const std::string& help, const std::string& missing);
  // A flag without a value.
  CLI::Option* flag(const std::string& flags, bool& slot, const std::string& help);
  // Every argument that is no option, in order (the command checks how many it takes).
  CLI::Option* positionals(const std::string& name, std::vector<std::string>& slot,
                           const std::string& help);
  // positionals() for the scene file of render, explain and check (take_scene_argument()).
  CLI::Option* scene_files(std::vector<std::string>& slot);

  // Parses the arguments. Returns nullopt to go on, else the exit status: 0 after the help,
  // kExitBadInput after a usage error (printed). An argument that looks like an option and is
  // none is reported as "PREFIXunknown option "ARG"" (unknown_prefix: "render: ", ...).
  std::optional<int> parse(const Args& args, const std::string& unknown_prefix = "");

private:
  // The error of option `name` given no value (printed), or nullopt for an unknown name.
  std::optional<int> missing_value(const std::string& name) const;

  CLI::App app_;
  std::string command_;
  std::map<std::string, std::string> missing_; // option name -> "needs a value" error
  bool quiet_ = false, verbose_ = false;
};

} // namespace rastrules::cli
