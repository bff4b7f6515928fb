// SPDX-License-Identifier: MIT
// Quadrilateral line decision records (rastrules/decision.hpp) against the kernel's
// rasterization: a line's record holds the two triangles of each segment decided at the pixel
// centre, and says covered exactly when rasterize_primitive emits the pixel, for 1.4 and
// 1.0 px wide lines and line strips on a half-pixel grid.

#include <gtest/gtest.h>

#include "rastrules/decision.hpp"
#include "support.hpp"

namespace rastrules {
namespace {

// rule: LINE.QUAD.WIDTH, LINE.QUAD.NO_CULL, TRI.FILL.TOP_LEFT
TEST(LineQuadDecision, ACentreOnTheDiagonalOfTheRectangleIsCoveredByOneTriangle) {
  // A 1.0 px wide line from (0.5, 2.5) to (6.5, 2.5): the rectangle [0.5, 6.5] x [2, 3]. The
  // centre (3.5, 2.5) of pixel (3, 2) is the rectangle's centre, on the diagonal that splits
  // it into two triangles: exactly one of them covers it.
  Scene scene;
  scene.width = 8;
  scene.height = 5;
  scene.conventions.line_mode = LineMode::kQuadNarrow;
  scene.cull = CullMode::kFront;
  Primitive line;
  line.type = PrimitiveType::kLine;
  line.v = {{0.5f, 2.5f}, {6.5f, 2.5f}};
  scene.primitives = {line};
  const PreparedScene s = test::prepared(scene);
  const PixelDecision d = decide_pixel(s, 0, 3, 2);
  ASSERT_EQ(d.triangles.size(), 2u);
  EXPECT_EQ(d.triangle_seg, (std::vector<std::uint32_t>{0, 0}));
  EXPECT_NE(d.triangles[0].covered, d.triangles[1].covered);
  EXPECT_TRUE(d.covered);
  EXPECT_TRUE(d.segments.empty());
  EXPECT_FALSE(decide_pixel(s, 0, 3, 3).covered);
}

// rule: LINE.QUAD.WIDTH, LINE.QUAD.CORNERS, LINE.QUAD.NO_CULL, TRI.COVER.SAMPLE
TEST(LineQuadDecision, EveryPixelsRecordAgreesWithTheRasterizedFragments) {
  std::uint32_t seed = 21;
  for (const LineMode mode : {LineMode::kQuadWide, LineMode::kQuadNarrow}) {
    for (const PrimitiveType type : {PrimitiveType::kLine, PrimitiveType::kLineStrip}) {
      for (const FillConvention fill : {FillConvention::kTopLeft, FillConvention::kBottomRight}) {
        Scene scene;
        scene.width = 10;
        scene.height = 9;
        scene.conventions.line_mode = mode;
        scene.conventions.fill = fill;
        scene.cull = CullMode::kBack;
        scene.primitives = test::tie_heavy_primitives(type, 6, seed++, 10, 9);
        EXPECT_EQ(test::decision_disagreement(test::prepared(scene)), "")
            << "line_mode " << to_string(mode) << ", " << to_string(type) << ", fill "
            << to_string(fill);
      }
    }
  }
}

} // namespace
} // namespace rastrules
