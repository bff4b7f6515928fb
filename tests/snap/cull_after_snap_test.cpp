// SPDX-License-Identifier: MIT
// Orientation, zero-area detection and culling are decided on the snapped vertices.
// The float inputs below are exact binary fractions, so the arithmetic is checkable by hand;
// raw values are in 1/256 px.

#include <gtest/gtest.h>

#include "rastrules/triangle.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

// rule: SNAP.CULL.AFTER_SNAP, TRI.DEGENERATE.ZERO_AREA
TEST(SnapCullAfterSnap, NonZeroFloatAreaThatSnapsToZeroIsDegenerate) {
  // (0,0), (10,0), (5, 0.375/256): float area 10 * 0.375/256 / 2 > 0, but y = 0.375 raw
  // snaps to 0, so all three snapped vertices lie on y = 0.
  const TriangleSetup t = triangle_px({0, 0}, {10, 0}, {5, 0.375 / 256});
  EXPECT_EQ(t.snapped[2].y.raw(), 0);
  EXPECT_EQ(t.twice_area, 0);
  EXPECT_EQ(t.status, TriangleStatus::kDegenerate);
  EXPECT_FALSE(t.front_facing);
  // The float triangle would contain the sample (5, 0.125/256); the snapped one covers nothing.
  EXPECT_TRUE(walk_pixels(t, 16, 1).empty());
}

// rule: SNAP.CULL.AFTER_SNAP, TRI.ORIENT.AREA
TEST(SnapCullAfterSnap, WindingThatFlipsBySnappingIsTheSnappedWinding) {
  // v0 = (0,0), v1 = (1, 0.375/256), v2 = (4, 0.625/256). In raw units before rounding:
  // A = 256 * 0.625 - 0.375 * 1024 = 160 - 384 = -224 < 0: counter-clockwise as floats.
  // Snapped: v1.y = 0 (0.375 rounds down), v2.y = 1 (0.625 rounds up):
  // A = 256 * 1 - 0 * 1024 = 256 > 0: clockwise.
  const Px v0{0, 0}, v1{1, 0.375 / 256}, v2{4, 0.625 / 256};
  const TriangleSetup none = triangle_px(v0, v1, v2);
  EXPECT_EQ(none.twice_area, 256);
  EXPECT_TRUE(none.clockwise);
  EXPECT_TRUE(none.front_facing); // front face clockwise (default)

  RasterState back;
  back.cull = CullMode::kBack;
  EXPECT_EQ(triangle_px(v0, v1, v2, back).status, TriangleStatus::kRasterized);
  RasterState front;
  front.cull = CullMode::kFront;
  EXPECT_EQ(triangle_px(v0, v1, v2, front).status, TriangleStatus::kCulledFront);
  RasterState back_ccw = back;
  back_ccw.front_face = FrontFace::kCounterClockwise;
  EXPECT_EQ(triangle_px(v0, v1, v2, back_ccw).status, TriangleStatus::kCulledBack);
}

// rule: SNAP.CULL.AFTER_SNAP
TEST(SnapCullAfterSnap, TheSnappedTriangleDecidesCoverageToo) {
  // Float vertex (2.5 + 0.375/256, 0.5) snaps to (2.5, 0.5) exactly, so the top edge from
  // (0.5,0.5) ends on the centre (2.5, 0.5), a top + right vertex, which is not covered; the
  // float triangle would have contained that centre.
  const TriangleSetup t = triangle_px({0.5, 0.5}, {2.5 + 0.375 / 256, 0.5}, {0.5, 2.5});
  EXPECT_EQ(t.snapped[1], sample_px(2.5, 0.5));
  EXPECT_EQ(walk_pixels(t, 4, 4), (std::vector<Pixel>{{0, 0}, {1, 0}, {0, 1}}));
}

} // namespace
} // namespace rastrules::test
