// SPDX-License-Identifier: MIT
// rastrules glyph: a glyph of a font file as a path scene that renders and checks (built with
// FreeType, RASTRULES_FONT_DEJAVU from tools/io).

#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support.hpp"

#ifdef RASTRULES_FONT_DEJAVU
namespace {

using rastrules::test::run_cli;
using rastrules::test::TempDir;

// rule: PATH.GLYPH.SOURCE, SCENE.PRIM.PATH
TEST(CliGlyph, AGlyphBecomesAPathSceneThatRenders) {
  const TempDir dir;
  const std::string scene = (dir / "o.json").string();
  const auto g =
      run_cli({"glyph", RASTRULES_FONT_DEJAVU, "--char", "o", "--size", "16", "--out", scene});
  ASSERT_EQ(g.status, 0) << g.err;
  const auto doc = nlohmann::json::parse(rastrules::test::read_file(scene));
  const auto& p = doc["primitives"][0];
  EXPECT_EQ(p["type"], "path");
  EXPECT_EQ(p["fill_rule"], "nonzero");
  EXPECT_EQ(p["contours"].size(), 2u); // the outside and the hole
  const auto r = run_cli({"render", scene, "--fragments", (dir / "f.json").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  // The same code point by U+XXXX gives the same scene.
  const auto u = run_cli({"glyph", RASTRULES_FONT_DEJAVU, "--char", "U+006F", "--size", "16"});
  ASSERT_EQ(u.status, 0) << u.err;
  EXPECT_EQ(u.out, rastrules::test::read_file(scene));
}

// rule: PATH.GLYPH.ERRORS
TEST(CliGlyph, BadFontsCharactersAndSizesAreOneLineErrors) {
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"glyph", "/nonexistent.ttf", "--char", "a"},
           {"glyph", RASTRULES_FONT_DEJAVU, "--char", "ab"},
           {"glyph", RASTRULES_FONT_DEJAVU, "--char", "U+110000"},
           {"glyph", RASTRULES_FONT_DEJAVU, "--char", "a", "--size", "0"},
           {"glyph", RASTRULES_FONT_DEJAVU, "--char", "a", "--coverage", "alpha"}}) {
    const auto r = run_cli(args);
    EXPECT_EQ(r.status, 2) << args[3];
    EXPECT_EQ(r.err.find("rastrules: error: "), 0u) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  }
}

} // namespace
#endif
