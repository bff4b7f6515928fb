// SPDX-License-Identifier: MIT
// Command-line usage: unknown commands and options, missing arguments, --help.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support.hpp"

namespace {

using rastrules::test::run_cli;

// rule: SCENE.INPUT.ERRORS
TEST(CliUsage, HelpPrintsUsageAndSucceeds) {
  for (const char* flag : {"--help", "-h", "help"}) {
    const auto r = run_cli({flag});
    EXPECT_EQ(r.status, 0) << flag;
    EXPECT_NE(r.out.find("usage: rastrules"), std::string::npos) << flag;
    EXPECT_EQ(r.err, "") << flag;
  }
}

// rule: SCENE.INPUT.ERRORS
TEST(CliUsage, UsageErrorsExitWithStatus2AndPrintUsage) {
  const std::vector<std::vector<std::string>> cases = {
      {},
      {"draw"},
      {"render"},
      {"render", "scene.json"},
      {"render", "scene.json", "--fragments"},
      {"render", "scene.json", "--fragments", "out.json", "--frobnicate"},
      {"render", "a.json", "b.json", "--fragments", "out.json"},
      {"render", "scene.json", "--fragments", "-", "--png", "-"},
      {"explain", "scene.json"},
      {"explain", "--pixel", "1,1"},
      {"showcase", "--out"},
      {"showcase", "--out", "dir", "extra"},
  };
  for (const auto& args : cases) {
    std::string shown;
    for (const auto& a : args)
      shown += a + " ";
    const auto r = run_cli(args);
    EXPECT_EQ(r.status, 2) << shown;
    EXPECT_EQ(r.err.rfind("rastrules: error: ", 0), 0u) << shown << ": " << r.err;
    EXPECT_NE(r.err.find("usage: rastrules"), std::string::npos) << shown;
    EXPECT_EQ(r.out, "") << shown;
  }
}

// A bad value of an option is one line naming it, not the usage (issue 17 item 11).
// rule: SCENE.INPUT.ERRORS
TEST(CliUsage, BadOptionValuesAreOneLine) {
  for (const char* scale : {"0", "x"}) {
    const auto r = run_cli({"render", "scene.json", "--png", "out.png", "--scale", scale});
    EXPECT_EQ(r.status, 2) << scale;
    EXPECT_EQ(r.err,
              std::string("rastrules: error: --scale needs an integer in [1, 4096], got \"") +
                  scale + "\"\n");
    EXPECT_EQ(r.out, "") << scale;
  }
}

// A value a user typed is shown escaped and cut, wherever an error quotes it: a control
// character in an option's value never reaches the terminal as itself.
// rule: SCENE.INPUT.ERRORS
TEST(CliUsage, QuotedValuesAreEscapedAndCut) {
  const std::string esc = "\x1b[2J";
  const struct {
    std::vector<std::string> args;
    std::string want;
  } cases[] = {
      {{"render", "s.json", "--png", "o.png", "--threads", esc},
       "--threads needs an integer in [1, 256], got \"\\x1b[2J\""},
      {{"render", "s.json", "--png", "o.png", "--traversal", esc},
       "--traversal needs \"plain\" or \"fast\", got \"\\x1b[2J\""},
      {{"render", "s.json", "--png", "o.png", "--isa", esc},
       "--isa needs \"scalar\", \"avx2\", \"avx512\" or \"auto\", got \"\\x1b[2J\""},
      {{"render", "s.json", "--png", "o.png", "--" + esc}, "render: unknown option \"--\\x1b[2J\""},
      {{"render", "s.json", "--png", "o.png", "--threads", std::string(100, '7')},
       "--threads needs an integer in [1, 256], got \"" + std::string(40, '7') + "...\""},
  };
  for (const auto& c : cases) {
    const auto r = run_cli(c.args);
    EXPECT_EQ(r.status, 2) << c.want;
    EXPECT_EQ(r.err.substr(0, r.err.find('\n')), "rastrules: error: " + c.want);
  }
}

} // namespace
