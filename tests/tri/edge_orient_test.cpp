// SPDX-License-Identifier: MIT
// Edge functions, orientation and normalisation on hand-computed values.
// Units: raw 16.8 positions (1/256 px), edge values in 1/65536 px^2 (1 px^2 = 65536).

#include <gtest/gtest.h>

#include <cstdint>

#include "rastrules/formula/edge.hpp"
#include "rastrules/triangle.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

constexpr std::int64_t kPx2 = 65536; // one square pixel in edge-value units

// rule: TRI.EDGE.FUNCTION
TEST(TriEdgeFunction, ValueIsTwiceTheSignedAreaInUnitsOf1Over65536SquarePixels) {
  // Edge (0,0) -> (4,0), sample (1,1): E = (4 - 0)(1 - 0) - (0 - 0)(1 - 0) = 4 px^2.
  EdgeSetup e;
  e.a = sample_px(0, 0);
  e.b = sample_px(4, 0);
  EXPECT_EQ(e.value_at(sample_px(1, 1)).raw(), 4 * kPx2);
  // Edge (1,2) -> (3,7), sample (6,2.5): E = (2)(0.5) - (5)(5) = -24 px^2.
  e.a = sample_px(1, 2);
  e.b = sample_px(3, 7);
  EXPECT_EQ(e.value_at(sample_px(6, 2.5)).raw(), -24 * kPx2);
  // One subpixel step off the line gives the smallest non-zero magnitudes: (0,0)->(1,0) at
  // (0, 1/256): E = (256)(1) - 0 = 256 raw units.
  e.a = sample_px(0, 0);
  e.b = sample_px(1, 0);
  EXPECT_EQ(e.value_at(sample_px(0, 0.00390625)).raw(), 256);
  EXPECT_EQ(formula::edge_value<std::int64_t>(0, 0, 1, 0, 0, 1), 1); // raw units throughout
}

// rule: TRI.EDGE.FUNCTION, COORD.PIXEL.ORIGIN
TEST(TriEdgeFunction, PositiveOnTheRightOfTheDirectionInYDownSpace) {
  // Walking from (0,0) to (4,0) (to the right on screen), the right-hand side is +y (down).
  EdgeSetup e;
  e.a = sample_px(0, 0);
  e.b = sample_px(4, 0);
  EXPECT_GT(e.value_at(sample_px(2, 1)).raw(), 0);  // below the edge on screen
  EXPECT_LT(e.value_at(sample_px(2, -1)).raw(), 0); // above
  EXPECT_EQ(e.value_at(sample_px(7, 0)).raw(), 0);  // on the line, beyond b
  // Reversing the direction negates the value.
  std::swap(e.a, e.b);
  EXPECT_EQ(e.value_at(sample_px(2, 1)).raw(), -4 * kPx2);
}

// rule: TRI.ORIENT.AREA
TEST(TriOrientArea, ClockwiseOnScreenIsPositive) {
  // (0,0) -> (4,0) -> (0,4): right, then down-left: clockwise on a y-down screen.
  const TriangleSetup cw = triangle_px({0, 0}, {4, 0}, {0, 4});
  EXPECT_EQ(cw.twice_area, 16 * kPx2);
  EXPECT_TRUE(cw.clockwise);
  const TriangleSetup ccw = triangle_px({0, 0}, {0, 4}, {4, 0});
  EXPECT_EQ(ccw.twice_area, -16 * kPx2);
  EXPECT_FALSE(ccw.clockwise);
  // Triangle C of the D3D diagram, (1,1) (6,2) (2,4): A = (5)(3) - (1)(1) = 14 px^2.
  EXPECT_EQ(triangle_px({1, 1}, {6, 2}, {2, 4}).twice_area, 14 * kPx2);
}

// rule: TRI.ORIENT.AREA
TEST(TriOrientArea, CollinearOrRepeatedVerticesGiveZero) {
  EXPECT_EQ(triangle_px({0, 0}, {2, 2}, {5, 5}).twice_area, 0);
  EXPECT_EQ(triangle_px({1, 1}, {1, 1}, {3, 5}).twice_area, 0);
  EXPECT_EQ(triangle_px({3, 2}, {3, 2}, {3, 2}).twice_area, 0);
  EXPECT_EQ(triangle_px({0, 0.5}, {8, 0.5}, {3, 0.5}).twice_area, 0);
}

// rule: TRI.ORIENT.NORMALISE
TEST(TriOrientNormalise, CounterClockwiseInputIsSwappedToClockwiseEdges) {
  const TriangleSetup t = triangle_px({0, 0}, {0, 4}, {4, 0}); // counter-clockwise
  ASSERT_EQ(t.status, TriangleStatus::kRasterized);
  // Edges (v0 v2), (v2 v1), (v1 v0) of the input: (0,0)->(4,0), (4,0)->(0,4), (0,4)->(0,0).
  EXPECT_EQ(t.edges[0].a, sample_px(0, 0));
  EXPECT_EQ(t.edges[0].b, sample_px(4, 0));
  EXPECT_EQ(t.edges[1].a, sample_px(4, 0));
  EXPECT_EQ(t.edges[1].b, sample_px(0, 4));
  EXPECT_EQ(t.edges[2].a, sample_px(0, 4));
  EXPECT_EQ(t.edges[2].b, sample_px(0, 0));
  // The snapped vertices are kept as given.
  EXPECT_EQ(t.snapped[1], sample_px(0, 4));
  // Interior samples are positive on every normalised edge.
  for (const EdgeSetup& e : t.edges)
    EXPECT_GT(e.value_at(sample_px(1, 1)).raw(), 0);
}

// rule: TRI.ORIENT.NORMALISE, TRI.COVER.SAMPLE
TEST(TriOrientNormalise, AllSixVertexOrdersCoverTheSamePixels) {
  const Px v[3] = {{0.5, 0.5}, {6.5, 2.5}, {2.5, 5.5}};
  const auto reference = centre_pixels(triangle_px(v[0], v[1], v[2]), 8, 8);
  ASSERT_FALSE(reference.empty());
  const int orders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (const auto& o : orders) {
    for (const FillConvention f : kAllConventions) {
      RasterState state;
      state.fill = f;
      EXPECT_EQ(centre_pixels(triangle_px(v[o[0]], v[o[1]], v[o[2]], state), 8, 8),
                centre_pixels(triangle_px(v[0], v[1], v[2], state), 8, 8))
          << "order " << o[0] << o[1] << o[2] << " fill " << to_string(f);
    }
  }
}

} // namespace
} // namespace rastrules::test
