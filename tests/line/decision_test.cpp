// SPDX-License-Identifier: MIT
// Aliased line decision records (rastrules/decision.hpp, LineDiamondDecision) against the
// kernel's rasterization: each segment's record says covered exactly when rasterize_primitive
// emits the pixel for that segment, for D3D and Bresenham lines and line strips on grids that
// put endpoints and segments on diamond corners and edges; and the record names the rule that
// decided, from the rule table.

#include <gtest/gtest.h>

#include "rastrules/decision.hpp"
#include "rastrules/rules.hpp"
#include "support.hpp"

namespace rastrules {
namespace {

PreparedScene line_scene(float y) {
  Scene scene;
  scene.width = 8;
  scene.height = 5;
  Primitive line;
  line.type = PrimitiveType::kLine;
  line.v = {{0.5f, y}, {6.5f, y}};
  scene.primitives = {line};
  return test::prepared(scene);
}

// rule: LINE.D3D.EXIT, LINE.D3D.TEST_AREA
TEST(LineDecision, EachReasonNamesTheRuleThatDecided) {
  // A horizontal line through the pixel centres of row 2, from (0.5, 2.5) to (6.5, 2.5).
  const PreparedScene centres = line_scene(2.5f);
  const LineSegmentDecision crosses = decide_pixel(centres, 0, 3, 2).segments.at(0);
  EXPECT_TRUE(crosses.covered);
  EXPECT_EQ(crosses.rule, rules::kLineD3DExit);
  EXPECT_EQ(crosses.diamond.reason, "the line crosses the diamond's interior and exits");
  const LineSegmentDecision ends = decide_pixel(centres, 0, 6, 2).segments.at(0);
  EXPECT_FALSE(ends.covered);
  EXPECT_EQ(ends.rule, rules::kLineD3DExit);
  EXPECT_EQ(ends.diamond.reason, "the end point lies in the test area: the line does not exit");
  // At y = 2 the line runs through the top corners of row 2's diamonds, which an x-major
  // line's test area excludes.
  const LineSegmentDecision corner = decide_pixel(line_scene(2.0f), 0, 3, 2).segments.at(0);
  EXPECT_FALSE(corner.covered);
  EXPECT_EQ(corner.rule, rules::kLineD3DTestArea);
  EXPECT_EQ(corner.diamond.reason,
            "the segment meets only excluded edges or corners (LINE.D3D.TEST_AREA)");
}

// rule: LINE.ZERO_LENGTH
TEST(LineDecision, AZeroLengthLineIsDecidedByTheZeroLengthRule) {
  Scene scene;
  scene.width = 4;
  scene.height = 4;
  Primitive line;
  line.type = PrimitiveType::kLine;
  line.v = {{1.5f, 1.5f}, {1.5f, 1.5f}};
  scene.primitives = {line};
  const LineSegmentDecision g = decide_pixel(test::prepared(scene), 0, 1, 1).segments.at(0);
  EXPECT_FALSE(g.covered);
  EXPECT_EQ(g.rule, rules::kLineZeroLength);
  EXPECT_EQ(g.diamond.reason, "zero-length line: covers nothing (LINE.ZERO_LENGTH)");
}

// rule: LINE.D3D.EXIT, LINE.VK.EXIT, LINE.STRIP.SEQUENCE
TEST(LineDecision, EveryPixelsRecordAgreesWithTheRasterizedFragments) {
  std::uint32_t seed = 51;
  for (const LineMode mode : {LineMode::kD3DDiamond, LineMode::kVulkanBresenham}) {
    for (const PrimitiveType type : {PrimitiveType::kLine, PrimitiveType::kLineStrip}) {
      for (const int steps : {2, 4}) {
        Scene scene;
        scene.width = 10;
        scene.height = 8;
        scene.conventions.line_mode = mode;
        scene.primitives = test::tie_heavy_primitives(type, 8, seed++, 10, 8, steps);
        EXPECT_EQ(test::decision_disagreement(test::prepared(scene)), "")
            << "line_mode " << to_string(mode) << ", " << to_string(type) << ", grid 1/" << steps
            << " px";
      }
    }
  }
}

} // namespace
} // namespace rastrules
