// SPDX-License-Identifier: MIT
// The command line's parser (CLI11, tools/cli/parser.hpp): --version, help COMMAND and
// COMMAND --help for every command, --opt=value, -q/-v, and the --json outputs of probe,
// showcase and cases (issue 19).

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support.hpp"

namespace rastrules::test {
namespace {

const char* kScene = R"({"version": 1, "target": {"width": 8, "height": 6},
  "primitives": [{"type": "triangle", "v": [[0, 0], [8, 0], [0, 6]]}]})";

// The text without the lines of a fuzz summary's table that hold times ("| 5 | ...").
std::string untimed(const std::string& text) {
  std::string out;
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = text.find('\n', at);
    const std::string line = text.substr(at, end == std::string::npos ? end : end - at + 1);
    if (!(line.size() > 2 && line[0] == '|' && line[2] >= '0' && line[2] <= '9'))
      out += line;
    at = end == std::string::npos ? text.size() : end + 1;
  }
  return out;
}

std::vector<std::string> commands() {
  std::vector<std::string> c = {"render", "explain", "showcase", "fuzz",      "check",
                                "probe",  "bench",   "cases",    "fuzz-merge"};
#ifdef RASTRULES_FONT_DEJAVU
  c.emplace_back("glyph");
#endif
  return c;
}

// rule: SCENE.INPUT.ERRORS
TEST(CliParser, VersionNamesTheProjectAndSceneFormat) {
  for (const char* flag : {"--version", "-V"}) {
    const RunResult r = run_cli({flag});
    EXPECT_EQ(r.status, 0) << flag;
    EXPECT_EQ(r.out, std::string("rastrules ") + RASTRULES_VERSION + " (scene format 1)\n");
    EXPECT_EQ(r.err, "");
  }
}

// Every command has its own help, the same through `help COMMAND`, `COMMAND --help` and
// `COMMAND -h`, and none is the overview of all commands.
// rule: SCENE.INPUT.ERRORS
TEST(CliParser, EveryCommandHasItsOwnHelp) {
  const RunResult overview = run_cli({"--help"});
  ASSERT_EQ(overview.status, 0);
  for (const std::string& c : commands()) {
    const RunResult help = run_cli({"help", c});
    EXPECT_EQ(help.status, 0) << c << ": " << help.err;
    EXPECT_EQ(help.err, "") << c;
    EXPECT_NE(help.out.find("Usage: rastrules " + c + " [OPTIONS]"), std::string::npos)
        << c << ": " << help.out;
    EXPECT_NE(help.out.find("--help"), std::string::npos) << c;
    EXPECT_NE(help.out.find("-q,--quiet"), std::string::npos) << c;
    EXPECT_NE(help.out, overview.out) << c;
    EXPECT_EQ(help.out.find("usage: rastrules [-q|-v] <command>"), std::string::npos) << c;
    for (const char* flag : {"--help", "-h"}) {
      const RunResult own = run_cli({c, flag});
      EXPECT_EQ(own.status, 0) << c << " " << flag << ": " << own.err;
      EXPECT_EQ(own.out, help.out) << c << " " << flag;
    }
    // --help wins over anything else on the line, even a bad option.
    const RunResult mixed = run_cli({c, "--frobnicate", "--help"});
    EXPECT_EQ(mixed.status, 0) << c;
    EXPECT_EQ(mixed.out, help.out) << c;
  }
  // The options of each command are in its help.
  EXPECT_NE(run_cli({"render", "--help"}).out.find("--max-work N"), std::string::npos);
  EXPECT_NE(run_cli({"fuzz", "--help"}).out.find("--cases N"), std::string::npos);
  EXPECT_NE(run_cli({"probe", "--help"}).out.find("--json"), std::string::npos);
}

// --opt=value is --opt value.
// rule: SCENE.INPUT.ERRORS
TEST(CliParser, OptEqualsValueIsOptValue) {
  TempDir dir;
  const auto scene = dir.write("s.json", kScene).string();
  const RunResult spaced = run_cli({"render", scene, "--fragments", (dir / "a.json").string(),
                                    "--threads", "2", "--traversal", "plain"});
  const RunResult joined = run_cli({"render", scene, "--fragments=" + (dir / "b.json").string(),
                                    "--threads=2", "--traversal=plain"});
  ASSERT_EQ(spaced.status, 0) << spaced.err;
  ASSERT_EQ(joined.status, 0) << joined.err;
  EXPECT_EQ(read_file(dir / "a.json"), read_file(dir / "b.json"));

  const RunResult e1 = run_cli({"explain", scene, "--pixel", "1,1"});
  const RunResult e2 = run_cli({"explain", scene, "--pixel=1,1"});
  EXPECT_EQ(e1.status, 0) << e1.err;
  EXPECT_EQ(e1.out, e2.out);

  const RunResult f1 =
      run_cli({"fuzz", "--driver", "imprecise", "--cases", "5", "--seed", "3", "--no-progress"});
  const RunResult f2 = run_cli({"fuzz", "--driver=imprecise", "--cases=5", "--seed=3",
                                "--profile=d3d11", "--mode=exact", "--no-progress"});
  EXPECT_EQ(f1.status, f2.status);
  EXPECT_EQ(untimed(f1.out), untimed(f2.out));

  // A bad value given either way is the same one-line error naming option and value.
  const RunResult b1 = run_cli({"render", scene, "--png", "p.png", "--scale", "0"});
  const RunResult b2 = run_cli({"render", scene, "--png", "p.png", "--scale=0"});
  EXPECT_EQ(b1.status, 2);
  EXPECT_EQ(b1.err, "rastrules: error: --scale needs an integer in [1, 4096], got \"0\"\n");
  EXPECT_EQ(b2.err, b1.err);
}

// -q drops the summary and progress text, never a result or an error; -v adds detail.
// rule: SCENE.INPUT.ERRORS
TEST(CliParser, QuietAndVerbose) {
  TempDir dir;
  const auto scene = dir.write("s.json", kScene).string();
  const auto out = (dir / "f.json").string();
  const RunResult normal = run_cli({"render", scene, "--fragments", out});
  ASSERT_EQ(normal.status, 0) << normal.err;
  EXPECT_NE(normal.out.find("render: 1 primitives"), std::string::npos) << normal.out;
  const std::string fragments = read_file(out);
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"render", scene, "--fragments", out, "-q"},
        std::vector<std::string>{"-q", "render", scene, "--fragments", out},
        std::vector<std::string>{"render", "--quiet", scene, "--fragments", out}}) {
    const RunResult quiet = run_cli(args);
    EXPECT_EQ(quiet.status, 0) << quiet.err;
    EXPECT_EQ(quiet.out, "");
    EXPECT_EQ(quiet.err, "");
    EXPECT_EQ(read_file(out), fragments);
  }
  // An error is still printed under -q.
  const RunResult bad = run_cli({"-q", "render", scene, "--png", "p.png", "--scale", "x"});
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err_lines().size(), 1u) << bad.err;

  // fuzz: -v draws the progress even when standard error is no terminal; -q never.
  const std::vector<std::string> fuzz = {"fuzz", "--driver", "imprecise", "--cases", "4"};
  auto with = [&](const std::string& flag) {
    std::vector<std::string> a = fuzz;
    a.push_back(flag);
    return run_cli(a);
  };
  const RunResult verbose = with("-v");
  EXPECT_NE(verbose.err.find("[##############################] 4/4 cases"), std::string::npos)
      << verbose.err;
  const RunResult quiet = with("-q");
  EXPECT_EQ(quiet.err.find('['), std::string::npos) << quiet.err;
  EXPECT_NE(quiet.out.find("result "), std::string::npos) << "the result stays";

  // cases: -q keeps the last line (and any failure) only.
  const std::string catalog = std::string(RASTRULES_SOURCE_DIR) + "/spec/cases";
  const RunResult all = run_cli({"cases", catalog});
  ASSERT_EQ(all.status, 0) << all.out << all.err;
  const RunResult few = run_cli({"cases", catalog, "-q"});
  EXPECT_EQ(few.status, 0);
  EXPECT_EQ(few.out, all.out.substr(all.out.rfind('\n', all.out.size() - 2) + 1));
  EXPECT_NE(few.out.find(" cases hold\n"), std::string::npos) << few.out;
}

// -q: the showcase's summary line alone when every scene agrees.
// rule: SCENE.INPUT.ERRORS
TEST(CliParser, ShowcaseQuietPrintsTheSummaryLine) {
  TempDir dir;
  const RunResult q = run_cli({"showcase", "--out", (dir / "q").string(), "-q"});
  ASSERT_EQ(q.status, 0) << q.err;
  EXPECT_EQ(q.out.find('\n'), q.out.size() - 1) << q.out;
  EXPECT_EQ(q.out.rfind("showcase: ", 0), 0u) << q.out;
}

// rule: FUZZ.PROBE
TEST(CliParser, ProbeJson) {
  const RunResult r = run_cli({"probe", "--driver", "reference", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["driver"], "reference");
  EXPECT_EQ(j["fill"]["convention"], "top-left");
  EXPECT_TRUE(j["fill"]["top"].get<bool>());
  EXPECT_FALSE(j["fill"]["bottom"].get<bool>());
  EXPECT_EQ(j["subpixel_bits"], 8);
  EXPECT_TRUE(j["snapping"]["rounding"].is_string());
  EXPECT_TRUE(j["line_mode"].is_string());
  EXPECT_TRUE(j["point_rule"].is_string());
  ASSERT_TRUE(j["samples_4x"].is_array());
  EXPECT_EQ(j["samples_4x"].size(), 4u);
  // The text says the same.
  const RunResult text = run_cli({"probe", "--driver", "reference"});
  EXPECT_NE(text.out.find(j["fill"]["convention"].get<std::string>()), std::string::npos);
}

// rule: SCENE.OUTPUT.FRAGMENTS
TEST(CliParser, ShowcaseJson) {
  TempDir dir;
  const RunResult r = run_cli({"showcase", "--out", (dir / "s").string(), "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j["scenes"].is_array());
  EXPECT_GT(j["scenes"].size(), 20u);
  EXPECT_EQ(j["agree"], j["scenes"].size());
  EXPECT_EQ(j["differ"], 0);
  for (const auto& s : j["scenes"]) {
    EXPECT_TRUE(s["agree"].get<bool>()) << s["name"];
    EXPECT_TRUE(std::filesystem::exists(dir / "s" / (s["name"].get<std::string>() + ".png")));
    EXPECT_FALSE(s["oracles"].empty()) << s["name"];
  }
}

// rule: PIPE.CATALOG
TEST(CliParser, CasesJson) {
  const std::string catalog = std::string(RASTRULES_SOURCE_DIR) + "/spec/cases";
  const RunResult r = run_cli({"cases", catalog, "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j["cases"].is_array());
  EXPECT_GT(j["total"].get<int>(), 0);
  EXPECT_EQ(j["hold"], j["total"]);
  EXPECT_EQ(j["cases"].size(), j["total"].get<std::size_t>());
  for (const auto& c : j["cases"]) {
    EXPECT_TRUE(c["ok"].get<bool>()) << c["name"];
    EXPECT_TRUE(c["failures"].empty());
    EXPECT_FALSE(c["rules"].empty()) << c["name"];
  }
}

} // namespace
} // namespace rastrules::test
