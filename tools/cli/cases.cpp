// SPDX-License-Identifier: MIT
// `rastrules cases [DIR]`: the hard-case catalog (spec/cases/, PIPE.CATALOG).
#include <cstdio>
#include <filesystem>
#include <string>

#include "cli.hpp"
#include "rastrules/cases/cases.hpp"

namespace rastrules::cli {

// rule: PIPE.CATALOG
int run_cases(const Args& args) {
  std::string dir = "spec/cases";
  bool dir_given = false;
  for (const std::string& a : args) {
    if (a == "--help" || a == "-h") {
      print_usage(stdout);
      return kExitOk;
    }
    if (!a.empty() && a[0] == '-')
      return usage_error("cases: unexpected option " + shown_value(a));
    if (dir_given)
      return usage_error("cases: more than one directory");
    dir = a;
    dir_given = true;
  }
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    return error(dir + ": not a directory (the catalog is spec/cases in the source tree)");
  const auto scenes = cases::catalog(dir);
  if (scenes.empty())
    return error(dir + ": no case (NAME.json with NAME.expect.json)");
  std::vector<cases::CaseReport> reports;
  for (const auto& s : scenes)
    reports.push_back(cases::check_case(s));
  const std::string text = cases::format_report(reports);
  std::fputs(text.c_str(), stdout);
  for (const auto& r : reports)
    if (!r.ok())
      return kExitDifference;
  return kExitOk;
}

} // namespace rastrules::cli
