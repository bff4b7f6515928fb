// SPDX-License-Identifier: MIT
// The bad-input catalog (tests/bad_input/): every file makes `rastrules render` and
// `rastrules explain` fail with exit status 2, exactly one line on standard error containing
// the expected text, and no output file.

#include <filesystem>
#include <fstream>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support.hpp"

namespace {

using rastrules::test::run_cli;
using rastrules::test::TempDir;

struct BadInput {
  std::string file;
  std::string expected; // substring of the error line
};

std::vector<BadInput> catalog() {
  std::vector<BadInput> cases;
  std::ifstream in(std::string(RASTRULES_BAD_INPUT_DIR) + "/expected.tsv");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#')
      continue;
    const std::size_t tab = line.find('\t');
    if (tab == std::string::npos)
      continue;
    cases.push_back({line.substr(0, tab), line.substr(tab + 1)});
  }
  return cases;
}

// Test names show the catalog file (CTest's discovery puts the printed parameter in the name).
void PrintTo(const BadInput& c, std::ostream* os) {
  *os << c.file;
}

class BadInputCatalog : public testing::TestWithParam<BadInput> {};

void expect_one_error_line(const rastrules::test::RunResult& r, const std::string& expected) {
  EXPECT_EQ(r.status, 2);
  const auto lines = r.err_lines();
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_EQ(lines[0].rfind("rastrules: error: ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find(expected), std::string::npos)
      << "expected \"" << expected << "\" in: " << lines[0];
  EXPECT_EQ(r.err.back(), '\n');
}

// rule: SCENE.INPUT.ERRORS, SCENE.FORMAT.V1, SCENE.TARGET.LIMITS, SNAP.VERTEX.INVALID
TEST_P(BadInputCatalog, RenderFailsWithOneLineAndWritesNothing) {
  const BadInput& c = GetParam();
  const TempDir dir;
  const auto scene = std::filesystem::path(RASTRULES_BAD_INPUT_DIR) / c.file;
  ASSERT_TRUE(std::filesystem::exists(scene)) << scene;
  const auto r = run_cli({"render", scene.string(), "--fragments", (dir / "out.json").string(),
                          "--png", (dir / "out.png").string()});
  expect_one_error_line(r, c.expected);
  EXPECT_EQ(r.out, "");
  EXPECT_TRUE(std::filesystem::is_empty(dir.path())) << "an output file was left in " << dir.path();
}

// rule: SCENE.INPUT.ERRORS
TEST_P(BadInputCatalog, ExplainAndStandardInputFailTheSameWay) {
  const BadInput& c = GetParam();
  const auto scene = std::filesystem::path(RASTRULES_BAD_INPUT_DIR) / c.file;
  const auto r = run_cli({"explain", scene.string(), "--pixel", "0,0"});
  expect_one_error_line(r, c.expected);
  EXPECT_EQ(r.out, "");
  const auto s = run_cli({"render", "-", "--fragments", "-"}, scene.string());
  // Parse errors name <stdin> instead of the file; the problem text is the same.
  expect_one_error_line(s, c.expected);
  EXPECT_EQ(s.out, "");
}

INSTANTIATE_TEST_SUITE_P(Catalog, BadInputCatalog, testing::ValuesIn(catalog()));

TEST(BadInputCatalogFiles, EveryCatalogFileHasAnExpectedMessageAndNoneIsMissing) {
  std::set<std::string> listed, present;
  for (const BadInput& c : catalog()) {
    EXPECT_TRUE(listed.insert(c.file).second) << "listed twice: " << c.file;
    EXPECT_FALSE(c.expected.empty()) << c.file;
  }
  for (const auto& e : std::filesystem::directory_iterator(RASTRULES_BAD_INPUT_DIR)) {
    if (e.path().extension() == ".json")
      present.insert(e.path().filename().string());
  }
  EXPECT_EQ(listed, present);
  EXPECT_GE(listed.size(), 40u);
}

// rule: SCENE.INPUT.ERRORS
TEST(BadInput, FilesLargerThanTheLimitAreRefusedBeforeParsing) {
  const TempDir dir;
  const auto big = dir / "big.json";
  {
    std::ofstream out(big, std::ios::binary);
    const std::string chunk(1 << 20, ' ');
    for (int i = 0; i < 65; ++i)
      out << chunk; // 65 MiB of whitespace
  }
  const auto r = run_cli({"render", big.string(), "--fragments", (dir / "out.json").string()});
  expect_one_error_line(r, "is larger than 64 MiB");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.json"));
}

// rule: SCENE.INPUT.ERRORS
TEST(BadInput, MissingSceneFileIsReported) {
  const TempDir dir;
  const auto r =
      run_cli({"render", (dir / "nope.json").string(), "--fragments", (dir / "out.json").string()});
  expect_one_error_line(r, "nope.json: cannot open");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.json"));
}

} // namespace
