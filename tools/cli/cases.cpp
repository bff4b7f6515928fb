// SPDX-License-Identifier: MIT
// `rastrules cases [DIR]`: the hard-case catalog (spec/cases/, PIPE.CATALOG).
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "parser.hpp"
#include "rastrules/cases/cases.hpp"

namespace rastrules::cli {

// rule: PIPE.CATALOG
int run_cases(const Args& args) {
  CommandLine cl("cases",
                 "Check the hard-case catalog (PIPE.CATALOG): each case run with and without the "
                 "optimizations, its values against the exact oracle's bounds and its "
                 "NAME.expect.json; one line per case (-q: the failures and the last line), exit "
                 "status 1 on a failure.");
  std::vector<std::string> dirs;
  bool as_json = false;
  cl.positionals("DIR", dirs, "the catalog's folder (default spec/cases)");
  cl.flag("--json", as_json, "one JSON document instead of the lines");
  if (const auto stop = cl.parse(args, "cases: "))
    return *stop;
  if (dirs.size() > 1)
    return usage_error("cases: more than one directory");
  const std::string dir = dirs.empty() ? std::string("spec/cases") : dirs.front();
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    return error(dir + ": not a directory (the catalog is spec/cases in the source tree)");
  const auto scenes = cases::catalog(dir);
  if (scenes.empty())
    return error(dir + ": no case (NAME.json with NAME.expect.json)");
  std::vector<cases::CaseReport> reports;
  for (const auto& s : scenes)
    reports.push_back(cases::check_case(s));
  if (as_json) {
    nlohmann::ordered_json j;
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    std::size_t held = 0;
    for (const auto& r : reports) {
      held += r.ok() ? 1u : 0u;
      nlohmann::ordered_json c = {{"name", r.name}, {"ok", r.ok()}, {"rules", r.rules}};
      c["what"] = r.what;
      c["fragments"] = r.fragments;
      c["oracle_checks"] = r.oracle_checks;
      c["failures"] = r.failures;
      list.push_back(std::move(c));
    }
    j["cases"] = list;
    j["hold"] = held;
    j["total"] = reports.size();
    std::fputs((j.dump(2) + "\n").c_str(), stdout);
  } else if (verbosity() == Verbosity::kQuiet) {
    // rule: SCENE.INPUT.ERRORS
    // -q: the failing cases' lines and the last line.
    std::vector<cases::CaseReport> failed;
    for (const auto& r : reports)
      if (!r.ok())
        failed.push_back(r);
    std::string text = cases::format_report(failed);
    text.erase(text.rfind('\n', text.size() - 2) + 1); // the count of the failures alone
    if (failed.empty())
      text.clear();
    std::fputs(text.c_str(), stdout);
    const std::size_t held = reports.size() - failed.size();
    std::printf("%zu of %zu cases hold\n", held, reports.size());
  } else {
    const std::string text = cases::format_report(reports);
    std::fputs(text.c_str(), stdout);
  }
  for (const auto& r : reports)
    if (!r.ok())
      return kExitDifference;
  return kExitOk;
}

} // namespace rastrules::cli
