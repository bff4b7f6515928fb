// SPDX-License-Identifier: MIT
// The parser of one rastrules command (parser.hpp).
// Implements: SCENE.INPUT.ERRORS (usage errors)

#include "parser.hpp"

#include <algorithm>
#include <cstdio>

#include "rastrules/io/scene_json.hpp"

namespace rastrules::cli {

namespace {

// The text broken into lines of at most 80 characters, at spaces.
std::string wrapped(const std::string& text) {
  std::string out, line;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t space = text.find(' ', at);
    const std::string word = text.substr(at, space == std::string::npos ? space : space - at);
    at = space == std::string::npos ? text.size() : space + 1;
    if (!line.empty() && line.size() + 1 + word.size() > 80) {
      out += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  return out + line;
}

} // namespace

CommandLine::CommandLine(const std::string& command, const std::string& summary)
    : app_(wrapped(summary), "rastrules " + command), command_(command) {
  set_current_command(command);
  app_.allow_extras();
  // rule: SCENE.INPUT.ERRORS
  // As before CLI11: an option given twice keeps its last value.
  app_.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  app_.set_help_flag("-h,--help", "show this help and exit");
  app_.get_formatter()->column_width(32);
  app_.footer("-q: errors and results only; -v: more detail where the command has it.\n"
              "exit status: 0 success, 1 a difference was found (showcase, fuzz, check,\n"
              "fuzz-merge, cases; with --baseline: one it does not list), 2 bad input or usage,\n"
              "or a driver failure, 130 interrupted (SCENE.INPUT.ERRORS).");
  app_.add_flag("-q,--quiet", quiet_, "errors and results only: no progress or summary text");
  app_.add_flag("-v,--verbose", verbose_, "more detail (e.g. a campaign's progress)");
}

CLI::Option* CommandLine::value(const std::string& flags, std::optional<std::string>& slot,
                                const std::string& type, const std::string& help,
                                const std::string& missing) {
  CLI::Option* o = app_.add_option_function<std::string>(
      flags, [&slot](const std::string& v) { slot = v; }, help);
  o->type_name(type);
  missing_[o->get_name()] = missing;
  return o;
}

CLI::Option* CommandLine::flag(const std::string& flags, bool& slot, const std::string& help) {
  return app_.add_flag(flags, slot, help);
}

CLI::Option* CommandLine::positionals(const std::string& name, std::vector<std::string>& slot,
                                      const std::string& help) {
  return app_.add_option(name, slot, help)->type_name("");
}

CLI::Option* CommandLine::scene_files(std::vector<std::string>& slot) {
  return positionals("SCENE.json", slot, "the scene file (\"-\": standard input)");
}

// rule: SCENE.INPUT.ERRORS
std::optional<int> CommandLine::missing_value(const std::string& name) const {
  const auto it = missing_.find(name);
  if (it == missing_.end())
    return std::nullopt;
  // A value error that shows the value ("..., got nothing", shown_value()) is one line like
  // every bad value; "--NAME needs a file name" is a usage error (with the hint).
  const std::string nothing = "got " + shown_value(std::nullopt);
  const std::string& text = it->second;
  const bool value_error = text.size() >= nothing.size() &&
                           text.compare(text.size() - nothing.size(), nothing.size(), nothing) == 0;
  return value_error ? error(text) : usage_error(text);
}

// rule: SCENE.INPUT.ERRORS
std::optional<int> CommandLine::parse(const Args& args, const std::string& unknown_prefix) {
  // "--NAME=" with nothing after it: CLI11 would take the empty text as an argument.
  for (const std::string& a : args) {
    if (a.size() > 3 && a.rfind("--", 0) == 0 && a.back() == '=') {
      if (const auto status = missing_value(a.substr(0, a.size() - 1)))
        return status;
    }
  }
  std::vector<std::string> reversed(args.rbegin(), args.rend()); // CLI11 takes them last first
  try {
    app_.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    std::string help = app_.help();
    if (!help.empty() && help.back() != '\n')
      help += '\n';
    std::fputs(help.c_str(), stdout);
    return kExitOk;
  } catch (const CLI::ArgumentMismatch& e) {
    // "--NAME: 1 required TYPE missing": the option's own words.
    const std::string what = e.what();
    if (const auto status = missing_value(what.substr(0, what.find(':'))))
      return status;
    return usage_error(command_ + ": " + io::printable(what, 200));
  } catch (const CLI::ParseError& e) {
    return usage_error(command_ + ": " + io::printable(e.what(), 200));
  }
  for (const std::string& a : app_.remaining()) {
    if (a == "--")
      continue;
    if (a.size() > 1 && a[0] == '-')
      return usage_error(unknown_prefix + "unknown option " + shown_value(a));
    return usage_error(unknown_prefix + "unexpected argument " + shown_value(a));
  }
  if (quiet_ && verbose_)
    return usage_error("-q and -v cannot be used together");
  if (quiet_)
    set_verbosity(Verbosity::kQuiet);
  else if (verbose_)
    set_verbosity(Verbosity::kVerbose);
  return std::nullopt;
}

} // namespace rastrules::cli
