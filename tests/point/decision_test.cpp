// SPDX-License-Identifier: MIT
// Point decision records (rastrules/decision.hpp) against the kernel's rasterization: a point's
// record holds its two triangles decided at the pixel centre, and says covered exactly when
// rasterize_primitive emits the pixel, on points whose squares put pixel centres on their
// edges and corners.

#include <gtest/gtest.h>

#include "rastrules/decision.hpp"
#include "rastrules/rules.hpp"
#include "support.hpp"

namespace rastrules {
namespace {

Scene point_scene(std::vector<Primitive> points, FillConvention fill) {
  Scene scene;
  scene.width = 10;
  scene.height = 8;
  scene.conventions.fill = fill;
  scene.cull = CullMode::kBack; // never applied to points (POINT.CULL.NONE)
  scene.primitives = std::move(points);
  return scene;
}

// rule: POINT.SHAPE.TWO_TRIANGLES, POINT.COVER.HALF_OPEN, TRI.FILL.TOP_LEFT
TEST(PointDecision, TheTopLeftCornerOfTheSquareIsCoveredByExactlyOneTriangle) {
  // The square of a point at (2, 2) spans [1.5, 2.5] x [1.5, 2.5]: the centre of pixel (1, 1)
  // is its top-left corner (covered), that of pixel (2, 2) its bottom-right corner (not).
  Primitive point;
  point.type = PrimitiveType::kPoint;
  point.v = {{2.0f, 2.0f}};
  const PreparedScene s = test::prepared(point_scene({point}, FillConvention::kTopLeft));
  const PixelDecision in = decide_pixel(s, 0, 1, 1);
  ASSERT_EQ(in.triangles.size(), 2u);
  EXPECT_NE(in.triangles[0].covered, in.triangles[1].covered);
  EXPECT_TRUE(in.covered);
  for (const TriangleDecision& t : in.triangles)
    EXPECT_FALSE(t.culled);
  const PixelDecision out = decide_pixel(s, 0, 2, 2);
  EXPECT_FALSE(out.triangles[0].covered || out.triangles[1].covered || out.covered);
}

// rule: POINT.SHAPE.TWO_TRIANGLES, POINT.COVER.HALF_OPEN, TRI.COVER.SAMPLE
TEST(PointDecision, EveryPixelsRecordAgreesWithTheRasterizedFragments) {
  std::uint32_t seed = 11;
  for (const FillConvention fill : test::kAllConventions) {
    for (const int steps : {2, 4}) {
      const Scene scene = point_scene(
          test::tie_heavy_primitives(PrimitiveType::kPoint, 10, seed++, 10, 8, steps), fill);
      EXPECT_EQ(test::decision_disagreement(test::prepared(scene)), "")
          << "fill " << to_string(fill) << ", grid 1/" << steps << " px";
    }
  }
}

} // namespace
} // namespace rastrules
