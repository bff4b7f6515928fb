// SPDX-License-Identifier: MIT
// The top-left rule (D3D11.3 3.4.2.1) on hand-drawn triangles: top and left edges by the
// spec's words, samples on one edge, samples on two edges (vertices), pixel centres.
// Every triangle is small enough to draw on squared paper; coordinates are in pixels.

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "rastrules/triangle.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

// The reference triangle of most cases: clockwise on screen (y down), with a top edge
// (0,0)-(4,0), a vertical left edge (0,4)-(0,0) and a right edge (4,0)-(0,4) (the diagonal).
//
//   (0,0) +-------+ (4,0)
//         |     /
//         |   /
//         | /
//   (0,4) +
TriangleSetup upper_left_half() {
  return triangle_px({0, 0}, {4, 0}, {0, 4});
}

// rule: TRI.FILL.TOP_EDGE
TEST(TriFillTopEdge, HorizontalEdgeAboveTheThirdVertexIsTop) {
  const TriangleSetup t = upper_left_half();
  ASSERT_EQ(t.status, TriangleStatus::kRasterized);
  // Normalised clockwise edges: (0,0)->(4,0), (4,0)->(0,4), (0,4)->(0,0).
  EXPECT_TRUE(t.edges[0].is_top);
  EXPECT_FALSE(t.edges[1].is_top);
  EXPECT_FALSE(t.edges[2].is_top);
}

// rule: TRI.FILL.TOP_EDGE
TEST(TriFillTopEdge, HorizontalEdgeBelowTheThirdVertexIsNotTop) {
  // Horizontal edge (0,4)-(4,4) with the third vertex (2,0) above it: a bottom edge.
  const TriangleSetup t = triangle_px({2, 0}, {4, 4}, {0, 4});
  ASSERT_EQ(t.status, TriangleStatus::kRasterized);
  for (const EdgeSetup& e : t.edges)
    EXPECT_FALSE(e.is_top);
}

// rule: TRI.FILL.TOP_EDGE
TEST(TriFillTopEdge, AlmostHorizontalEdgeIsNotTop) {
  // (0,0)-(4, 1/256): not exactly horizontal after snapping, so never a top edge.
  const TriangleSetup t = triangle_px({0, 0}, {4, 0.00390625}, {0, 4});
  ASSERT_EQ(t.status, TriangleStatus::kRasterized);
  for (const EdgeSetup& e : t.edges)
    EXPECT_FALSE(e.is_top);
  EXPECT_TRUE(t.edges[0].is_left || t.edges[1].is_left || t.edges[2].is_left);
}

// rule: TRI.FILL.LEFT_EDGE
TEST(TriFillLeftEdge, ATriangleCanHaveOneOrTwoLeftEdges) {
  const TriangleSetup one = upper_left_half();
  EXPECT_EQ(int{one.edges[0].is_left} + int{one.edges[1].is_left} + int{one.edges[2].is_left}, 1);
  EXPECT_TRUE(one.edges[2].is_left); // (0,4)->(0,0): interior on its +x side
  // Arrow pointing left: the left vertex (0,2) joins two left edges.
  const TriangleSetup two = triangle_px({4, 0}, {4, 4}, {0, 2});
  ASSERT_EQ(two.status, TriangleStatus::kRasterized);
  EXPECT_FALSE(two.edges[0].is_left); // (4,0)->(4,4): interior on its -x side (a right edge)
  EXPECT_TRUE(two.edges[1].is_left);  // (4,4)->(0,2)
  EXPECT_TRUE(two.edges[2].is_left);  // (0,2)->(4,0)
}

// rule: TRI.FILL.LEFT_EDGE, TRI.ORIENT.NORMALISE
TEST(TriFillLeftEdge, ClassificationDoesNotDependOnTheInputVertexOrder) {
  // The same triangle given counter-clockwise: normalisation swaps v1 and v2, so the edges
  // and their classification are those of the clockwise form.
  const TriangleSetup cw = triangle_px({4, 0}, {4, 4}, {0, 2});
  const TriangleSetup ccw = triangle_px({4, 0}, {0, 2}, {4, 4});
  ASSERT_EQ(ccw.status, TriangleStatus::kRasterized);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(cw.edges[i].a, ccw.edges[i].a);
    EXPECT_EQ(cw.edges[i].b, ccw.edges[i].b);
    EXPECT_EQ(cw.edges[i].is_left, ccw.edges[i].is_left);
    EXPECT_EQ(cw.edges[i].is_top, ccw.edges[i].is_top);
  }
}

// rule: TRI.FILL.LEFT_EDGE
TEST(TriFillLeftEdge, NearlyHorizontalEdgeBelowTheInteriorIsLeftWhenTheInteriorIsOnItsPlusXSide) {
  // (0,0), (8,1), (8,0)... given clockwise as (0,0) -> (8,0) -> (8,1): the long edge
  // (8,1) -> (0,0) runs up the screen and the third vertex (8,0) is on its +x side: left.
  const TriangleSetup t = triangle_px({0, 0}, {8, 0}, {8, 1});
  ASSERT_EQ(t.status, TriangleStatus::kRasterized);
  EXPECT_TRUE(t.edges[0].is_top);   // (0,0)->(8,0)
  EXPECT_FALSE(t.edges[1].is_left); // (8,0)->(8,1): right edge
  EXPECT_TRUE(t.edges[2].is_left);  // (8,1)->(0,0)
}

// rule: TRI.FILL.TOP_LEFT
TEST(TriFillTopLeft, SampleOnTopEdgeIsCovered) {
  EXPECT_TRUE(covers(upper_left_half(), sample_px(1.5, 0)));
}

// rule: TRI.FILL.TOP_LEFT
TEST(TriFillTopLeft, SampleOnBottomEdgeIsNotCovered) {
  // (0,4) -> (4,0) -> (4,4) is clockwise; (4,4)-(0,4) is a bottom edge.
  const TriangleSetup t = triangle_px({0, 4}, {4, 0}, {4, 4});
  EXPECT_FALSE(covers(t, sample_px(2.5, 4)));
  EXPECT_TRUE(covers(t, sample_px(2.5, 3.99609375))); // 1/256 px above it
}

// rule: TRI.FILL.TOP_LEFT
TEST(TriFillTopLeft, SampleOnLeftEdgeIsCovered) {
  EXPECT_TRUE(covers(upper_left_half(), sample_px(0, 1.5)));
}

// rule: TRI.FILL.TOP_LEFT
TEST(TriFillTopLeft, SampleOnRightEdgeIsNotCovered) {
  const TriangleSetup t = upper_left_half();
  EXPECT_FALSE(covers(t, sample_px(2, 2)));          // on the diagonal x + y = 4
  EXPECT_TRUE(covers(t, sample_px(2, 1.99609375)));  // 1/256 px inside
  EXPECT_FALSE(covers(t, sample_px(2.00390625, 2))); // 1/256 px outside
}

// rule: TRI.FILL.TOP_LEFT
TEST(TriFillTopLeft, VertexJoiningTwoLeftEdgesIsCovered) {
  // Arrow pointing left: (0,2) joins (4,4)->(0,2) and (0,2)->(4,0), both left edges.
  EXPECT_TRUE(covers(triangle_px({4, 0}, {4, 4}, {0, 2}), sample_px(0, 2)));
}

// rule: TRI.FILL.TOP_LEFT
TEST(TriFillTopLeft, VertexJoiningALeftAndARightEdgeIsNotCovered) {
  // Apex (2,0) of (2,0), (4,4), (0,4): left edge (0,4)->(2,0), right edge (2,0)->(4,4).
  EXPECT_FALSE(covers(triangle_px({2, 0}, {4, 4}, {0, 4}), sample_px(2, 0)));
  // Bottom apex (2,4) of (0,0), (4,0), (2,4).
  EXPECT_FALSE(covers(triangle_px({0, 0}, {4, 0}, {2, 4}), sample_px(2, 4)));
}

// rule: TRI.FILL.TOP_LEFT
TEST(TriFillTopLeft, VertexJoiningTopAndLeftEdgesIsCovered) {
  EXPECT_TRUE(covers(upper_left_half(), sample_px(0, 0)));
}

// rule: TRI.FILL.TOP_LEFT
TEST(TriFillTopLeft, VertexJoiningTopAndRightEdgesIsNotCovered) {
  EXPECT_FALSE(covers(upper_left_half(), sample_px(4, 0)));
}

// rule: TRI.FILL.TOP_LEFT
TEST(TriFillTopLeft, VertexJoiningTwoRightEdgesIsNotCovered) {
  // Arrow pointing right: (4,2) joins (0,0)->(4,2) and (4,2)->(0,4), both right edges.
  EXPECT_FALSE(covers(triangle_px({0, 0}, {4, 2}, {0, 4}), sample_px(4, 2)));
}

// rule: TRI.FILL.TOP_LEFT, TRI.COVER.SAMPLE
TEST(TriFillTopLeft, PixelCentresOfATriangleWithEdgesThroughCentres) {
  // (0.5,0.5) -> (4.5,0.5) -> (0.5,4.5): top edge, left edge and diagonal all run through
  // pixel centres. Top and left centres are in; diagonal centres (x + y = 5) are out.
  const TriangleSetup t = triangle_px({0.5, 0.5}, {4.5, 0.5}, {0.5, 4.5});
  const auto expected = pixels_in_picture({
      "####..",
      "###...",
      "##....",
      "#.....",
      "......",
  });
  EXPECT_EQ(centre_pixels(t, 6, 5), expected) << picture(centre_pixels(t, 6, 5), 6, 5);
}

// rule: TRI.FILL.TOP_LEFT, TRI.SHARED_EDGE.EXACTLY_ONCE
TEST(TriFillTopLeft, TwoHalvesOfASquareShareTheirDiagonalExactlyOnce) {
  // Square (0.5,0.5)-(4.5,4.5) cut along x + y = 5. The lower-right half has the diagonal as
  // a left edge, a right edge x = 4.5 and a bottom edge y = 4.5, so it owns the diagonal's
  // centres except its two ends, which are vertices with a right or a bottom edge.
  const TriangleSetup upper = triangle_px({0.5, 0.5}, {4.5, 0.5}, {0.5, 4.5});
  const TriangleSetup lower = triangle_px({4.5, 0.5}, {4.5, 4.5}, {0.5, 4.5});
  EXPECT_EQ(centre_pixels(lower, 6, 6), pixels_in_picture({
                                            "......",
                                            "...#..",
                                            "..##..",
                                            ".###..",
                                            "......",
                                            "......",
                                        }));
  std::vector<Pixel> both = centre_pixels(upper, 6, 6);
  for (const Pixel& p : centre_pixels(lower, 6, 6)) {
    EXPECT_FALSE(covers(upper, pixel_center(p.x, p.y))) << "covered twice: " << p;
    both.push_back(p);
  }
  std::sort(both.begin(), both.end());
  // Together they cover the square's pixels (centres in [0.5, 4.5) x [0.5, 4.5)) once.
  EXPECT_EQ(both, pixels_in_picture({
                      "####..",
                      "####..",
                      "####..",
                      "####..",
                      "......",
                      "......",
                  }));
}

} // namespace
} // namespace rastrules::test
