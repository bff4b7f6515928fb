// SPDX-License-Identifier: MIT
// Antialiased line decision records (rastrules/decision.hpp) against the kernel's
// rasterization: each segment's record holds aa_line_coverage at the pixel, and the pixel has
// a fragment, carrying that coverage, exactly when the record says covered.

#include <gtest/gtest.h>

#include "rastrules/decision.hpp"
#include "rastrules/line_aa.hpp"
#include "rastrules/rules.hpp"
#include "support.hpp"

namespace rastrules {
namespace {

Scene aa_scene(std::vector<Primitive> lines) {
  Scene scene;
  scene.width = 10;
  scene.height = 8;
  for (Primitive& p : lines)
    p.aa = true;
  scene.primitives = std::move(lines);
  return scene;
}

// rule: LINE.AA.FRAGMENT, LINE.AA.COVERAGE, SCENE.OUTPUT.COVERAGE
TEST(LineAADecision, TheRecordCarriesTheFragmentsCoverage) {
  Primitive line;
  line.type = PrimitiveType::kLine;
  line.v = {{0.5f, 2.5f}, {6.5f, 2.5f}};
  const PreparedScene s = test::prepared(aa_scene({line}));
  const PixelDecision d = decide_pixel(s, 0, 3, 2);
  ASSERT_EQ(d.segments.size(), 1u);
  const LineSegmentDecision& g = d.segments[0];
  EXPECT_EQ(g.rule, rules::kLineAAFragment);
  EXPECT_TRUE(g.x_major && g.covered);
  EXPECT_EQ(g.coverage_q16, aa_line_coverage(s.primitives[0].v[0], s.primitives[0].v[1], 3, 2).q16);
  std::optional<std::uint32_t> emitted;
  for (const Fragment& f : rasterize_primitive(s, 0)) {
    if (f.x == 3 && f.y == 2)
      emitted = f.coverage_q16;
  }
  EXPECT_EQ(emitted, std::optional<std::uint32_t>(g.coverage_q16));
  // Four rows below the line, beyond the 3x3 square R4: no coverage, no fragment.
  EXPECT_FALSE(decide_pixel(s, 0, 3, 6).covered);
}

// rule: LINE.AA.FRAGMENT, LINE.AA.ZERO_LENGTH, SCENE.PRIM.LINE_STRIP
TEST(LineAADecision, EveryPixelsRecordAgreesWithTheRasterizedFragments) {
  std::uint32_t seed = 31;
  for (const PrimitiveType type : {PrimitiveType::kLine, PrimitiveType::kLineStrip}) {
    for (const int steps : {2, 8}) {
      const Scene scene = aa_scene(test::tie_heavy_primitives(type, 6, seed++, 10, 8, steps));
      EXPECT_EQ(test::decision_disagreement(test::prepared(scene)), "")
          << to_string(type) << ", grid 1/" << steps << " px";
    }
  }
}

} // namespace
} // namespace rastrules
