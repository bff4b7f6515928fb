// SPDX-License-Identifier: MIT
// rastrules showcase: every built-in scene agrees with the exact oracle, and its files are
// what render produces from its scene file.

#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "support.hpp"

namespace {

using rastrules::test::read_file;
using rastrules::test::run_cli;
using rastrules::test::TempDir;

// rule: SCENE.OUTPUT.FRAGMENTS, SCENE.INPUT.ERRORS
TEST(CliShowcase, EverySceneAgreesWithTheOracleAndItsFilesAreConsistent) {
  const TempDir dir;
  const auto out = dir / "pictures";
  const auto r = run_cli({"showcase", "--out", out.string()});
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(r.err, "");
  // The last line: "showcase: N scenes, N agree with the oracle, 0 differ; pictures in DIR".
  // (std::regex is avoided: GCC 12 warns inside <regex> under the sanitizers.)
  const std::size_t at = r.out.rfind("showcase: ");
  ASSERT_NE(at, std::string::npos) << r.out;
  int scenes = -1, agreeing = -1, differing = -1;
  ASSERT_EQ(std::sscanf(r.out.c_str() + at,
                        "showcase: %d scenes, %d agree with the oracle, %d differ;", &scenes,
                        &agreeing, &differing),
            3)
      << r.out;
  EXPECT_EQ(agreeing, scenes);
  EXPECT_EQ(differing, 0);
  EXPECT_GE(scenes, 9);

  std::set<std::string> stems;
  for (const auto& e : std::filesystem::directory_iterator(out)) {
    const std::string name = e.path().filename().string();
    const std::string suffix = ".scene.json";
    if (name.size() > suffix.size() && name.ends_with(suffix))
      stems.insert(name.substr(0, name.size() - suffix.size()));
  }
  ASSERT_EQ(stems.size(), static_cast<std::size_t>(scenes));
  for (const std::string& stem : stems) {
    SCOPED_TRACE(stem);
    // The table has a row for the scene that says it agrees.
    std::istringstream table(r.out);
    bool row_agrees = false;
    for (std::string line; std::getline(table, line);) {
      if (line.rfind(stem + " ", 0) == 0)
        row_agrees = line.size() > 5 && line.ends_with("  yes");
    }
    EXPECT_TRUE(row_agrees) << r.out;
    EXPECT_TRUE(rastrules::test::read_png(out / (stem + ".png")).has_value());
    // Rendering the written scene file reproduces the written fragment list byte for byte.
    const auto again = dir / (stem + ".again.json");
    const auto rr =
        run_cli({"render", (out / (stem + ".scene.json")).string(), "--fragments", again.string()});
    ASSERT_EQ(rr.status, 0) << rr.err;
    EXPECT_EQ(read_file(again), read_file(out / (stem + ".fragments.json")));
  }
}

// Points, lines and antialiased lines are checked by their own oracles, and the summary says
// which oracle checked each scene.
// rule: SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP
// rule: SCENE.LINE_MODE, SCENE.OUTPUT.COVERAGE
TEST(CliShowcase, PointAndLineScenesNameTheOracleThatCheckedThem) {
  const TempDir dir;
  const auto r = run_cli({"showcase", "--out", (dir / "pictures").string()});
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const std::size_t at = r.out.find("oracles used:\n");
  ASSERT_NE(at, std::string::npos) << r.out;
  const std::string used = r.out.substr(at);
  for (const char* line :
       {"  fan: triangle oracle (render)\n", "  points: point oracle (point_covers)\n",
        "  lines-d3d: line oracle (aliased_line_pixels)\n",
        "  lines-vulkan: line oracle (aliased_line_pixels)\n",
        "  line-strip: line oracle (aliased_line_pixels)\n",
        "  lines-aa: AA-line oracle (aa_pixels, aa_check within 1/65536)\n",
        "  quad-lines-1.4: quad-line oracle (quad_line_covers)\n",
        "  quad-lines-1.0: quad-line oracle (quad_line_covers)\n"}) {
    EXPECT_NE(used.find(line), std::string::npos) << line << "in:\n" << used;
  }
  // The strip scene draws pixels twice (once per segment) and the AA scene writes coverage.
  const std::string strip = read_file(dir / "pictures" / "line-strip.fragments.json");
  EXPECT_NE(strip.find("\"seg\": 2"), std::string::npos);
  const std::string aa = read_file(dir / "pictures" / "lines-aa.fragments.json");
  EXPECT_NE(aa.find("\"coverage\": 0."), std::string::npos);
}

// rule: SCENE.INPUT.ERRORS
TEST(CliShowcase, MissingOutputDirectoryIsAUsageError) {
  const auto r = run_cli({"showcase"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
}

} // namespace
