// SPDX-License-Identifier: MIT
// rastrules showcase: every built-in scene agrees with the exact oracle, and its files are
// what render produces from its scene file.

#include <filesystem>
#include <regex>
#include <set>
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
  std::smatch m;
  const std::regex summary(R"(showcase: (\d+) scenes, (\d+) agree with the oracle, 0 differ; pictures in )");
  ASSERT_TRUE(std::regex_search(r.out, m, summary)) << r.out;
  const int scenes = std::stoi(m[1]);
  EXPECT_EQ(std::stoi(m[2]), scenes);
  EXPECT_GE(scenes, 9);

  std::set<std::string> stems;
  for (const auto& e : std::filesystem::directory_iterator(out)) {
    const std::string name = e.path().filename().string();
    const std::string suffix = ".scene.json";
    if (name.size() > suffix.size() && name.ends_with(suffix)) stems.insert(name.substr(0, name.size() - suffix.size()));
  }
  ASSERT_EQ(stems.size(), static_cast<std::size_t>(scenes));
  for (const std::string& stem : stems) {
    SCOPED_TRACE(stem);
    // The table has a row for the scene that says it agrees.
    EXPECT_TRUE(std::regex_search(r.out, std::regex("\n" + stem + " +[0-9]+ +[0-9]+ .* yes\n"))) << r.out;
    EXPECT_TRUE(rastrules::test::read_png(out / (stem + ".png")).has_value());
    // Rendering the written scene file reproduces the written fragment list byte for byte.
    const auto again = dir / (stem + ".again.json");
    const auto rr = run_cli({"render", (out / (stem + ".scene.json")).string(), "--fragments", again.string()});
    ASSERT_EQ(rr.status, 0) << rr.err;
    EXPECT_EQ(read_file(again), read_file(out / (stem + ".fragments.json")));
  }
}

// rule: SCENE.INPUT.ERRORS
TEST(CliShowcase, MissingOutputDirectoryIsAUsageError) {
  const auto r = run_cli({"showcase"});
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
}

}  // namespace
