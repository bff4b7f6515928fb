// SPDX-License-Identifier: MIT
// Command-line usage: unknown commands and options, missing arguments, --help.

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <sys/wait.h>

#include <gtest/gtest.h>

#include <algorithm>

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

// A usage error is one line naming the problem and at most one hint line, never the help
// (issue 19: every usage error printed the 4.7 KB help).
// rule: SCENE.INPUT.ERRORS
TEST(CliUsage, UsageErrorsAreOneLineAndAHintWithStatus2) {
  const struct {
    std::vector<std::string> args;
    std::string error; // the error line after "rastrules: error: "
    std::string hint;  // the second line
  } cases[] = {
      {{}, "missing command", "run 'rastrules --help'"},
      {{"draw"}, "unknown command \"draw\"", "run 'rastrules --help'"},
      {{"help", "draw"}, "help: unknown command \"draw\"", "run 'rastrules --help'"},
      {{"render"}, "render: missing SCENE.json", "run 'rastrules render --help'"},
      {{"render", "scene.json"},
       "render: give --fragments OUT.json, --png OUT.png, --resolve OUT.png, --depth-out "
       "OUT.json or --count OUT.json",
       "run 'rastrules render --help'"},
      {{"render", "scene.json", "--fragments"},
       "--fragments needs a file name",
       "run 'rastrules render --help'"},
      {{"render", "scene.json", "--fragments=", "--png", "p.png"},
       "--fragments needs a file name",
       "run 'rastrules render --help'"},
      {{"render", "scene.json", "--fragments", "out.json", "--frobnicate"},
       "render: unknown option \"--frobnicate\"",
       "run 'rastrules render --help'"},
      {{"render", "a.json", "b.json", "--fragments", "out.json"},
       "render: more than one scene file",
       "run 'rastrules render --help'"},
      {{"render", "scene.json", "--fragments", "-", "--png", "-"},
       "render: only one of --fragments, --png and --resolve can be standard output "
       "(--depth-out counts too)",
       "run 'rastrules render --help'"},
      {{"explain", "scene.json"}, "explain: missing --pixel X,Y", "run 'rastrules explain --help'"},
      {{"explain", "--pixel", "1,1"},
       "explain: missing SCENE.json",
       "run 'rastrules explain --help'"},
      {{"showcase", "--out"}, "--out needs a directory", "run 'rastrules showcase --help'"},
      {{"showcase", "--out", "dir", "extra"},
       "showcase: unexpected argument \"extra\"",
       "run 'rastrules showcase --help'"},
      {{"fuzz", "--driver", "reference", "--frobnicate"},
       "fuzz: unknown option \"--frobnicate\"",
       "run 'rastrules fuzz --help'"},
      {{"probe"}, "--driver is required", "run 'rastrules probe --help'"},
      {{"cases", "a", "b"}, "cases: more than one directory", "run 'rastrules cases --help'"},
      {{"bench", "--quick"},
       "bench: missing --ladder (the only benchmark: bench --ladder [--out DIR] [--quick] [--seed "
       "N] [--threads N])",
       "run 'rastrules bench --help'"},
      {{"render", "s.json", "--png", "p.png", "-q", "-v"},
       "-q and -v cannot be used together",
       "run 'rastrules render --help'"},
  };
  for (const auto& c : cases) {
    std::string shown;
    for (const auto& a : c.args)
      shown += a + " ";
    const auto r = run_cli(c.args);
    EXPECT_EQ(r.status, 2) << shown;
    const auto lines = r.err_lines();
    ASSERT_EQ(lines.size(), 2u) << shown << ": " << r.err;
    EXPECT_EQ(lines[0], "rastrules: error: " + c.error) << shown;
    EXPECT_EQ(lines[1], c.hint) << shown;
    EXPECT_EQ(r.err.find("usage: rastrules"), std::string::npos) << shown;
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

// rule: FUZZ.FAMILIES
TEST(CliUsage, AnUnknownFamilyIsOneLineNamingIt) {
  for (const char* v : {"lines,triangles", "lines,", ""}) {
    const auto r = run_cli({"fuzz", "--driver", "reference", "--families", v});
    EXPECT_EQ(r.status, 2) << v;
    EXPECT_NE(r.err.find("rastrules: error: --families: unknown family \""), std::string::npos)
        << r.err;
    EXPECT_LE(std::count(r.err.begin(), r.err.end(), '\n'), 2) << r.err;
    EXPECT_EQ(r.out, "") << v;
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

// rastrules holds render and explain and runs rastrules-full, beside it, for the rest with the
// same arguments (-q included), whose output and status are then the command's own; through a
// symbolic link too (the program's own path, /proc/self/exe). Alone in a directory it still
// renders, and names the missing program in one line, exit 2, for the other commands.
// rule: SCENE.CLI.FRONT, SCENE.INPUT.ERRORS
TEST(CliFront, OtherCommandsRunTheFullProgramBesideIt) {
  namespace fs = std::filesystem;
  const fs::path front = RASTRULES_CLI;
  const fs::path full = front.parent_path() / "rastrules-full";
  ASSERT_TRUE(fs::exists(full));
  const rastrules::test::TempDir dir;
  const auto run = [&](const fs::path& program, const std::string& args) {
    const fs::path out = dir / "out", err = dir / "err";
    const int raw = std::system(("'" + program.string() + "' " + args + " </dev/null >'" +
                                 out.string() + "' 2>'" + err.string() + "'")
                                    .c_str());
    return rastrules::test::RunResult{raw != -1 && WIFEXITED(raw) ? WEXITSTATUS(raw) : -1,
                                      rastrules::test::read_file(out),
                                      rastrules::test::read_file(err)};
  };
  for (const std::string args : {"help fuzz", "-q cases --help", "fuzz2d --help", "draw"}) {
    SCOPED_TRACE(args);
    const auto a = run(front, args), b = run(full, args);
    EXPECT_EQ(a.status, b.status);
    EXPECT_EQ(a.out, b.out);
    EXPECT_EQ(a.err, b.err);
  }
  EXPECT_EQ(run(front, "draw").err, "rastrules: error: unknown command \"draw\"\n"
                                    "run 'rastrules --help'\n");
  const fs::path scene = dir.write(
      "scene.json", R"({"target": {"width": 4, "height": 4}, "primitives": [{"type": "triangle", )"
                    R"("v": [[0, 0], [4, 0], [0, 4]]}]})");
  // Through a link, the full program is found beside the file it names.
  fs::create_directory(dir / "link");
  fs::create_symlink(front, dir / "link" / "rastrules");
  EXPECT_EQ(run(dir / "link" / "rastrules", "cases --help").out, run(full, "cases --help").out);
  // Alone.
  fs::create_directory(dir / "alone");
  fs::copy_file(front, dir / "alone" / "rastrules");
  fs::permissions(dir / "alone" / "rastrules", fs::perms::owner_exec, fs::perm_options::add);
  const auto rendered =
      run(dir / "alone" / "rastrules", "render '" + scene.string() + "' --count -");
  EXPECT_EQ(rendered.status, 0) << rendered.err;
  EXPECT_NE(rendered.out.find("\"fragments\": 6"), std::string::npos) << rendered.out;
  const auto missing = run(dir / "alone" / "rastrules", "fuzz --help");
  EXPECT_EQ(missing.status, 2);
  EXPECT_EQ(missing.out, "");
  EXPECT_EQ(missing.err, "rastrules: error: the command \"fuzz\" is run by " +
                             fs::weakly_canonical(dir / "alone").string() +
                             "/rastrules-full, which cannot be started (No such file or "
                             "directory)\n");
}

} // namespace
