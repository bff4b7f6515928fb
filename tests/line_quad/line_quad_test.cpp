// SPDX-License-Identifier: MIT
// Examples for the LINE.QUAD.* rules: hand-computed corner offsets, 1.4 px against 1.0 px
// lines, ties on pixel centres, direction, zero length and culling.

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/line.hpp"
#include "rastrules/line_quad.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/triangle.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

Vec2 raw(std::int32_t x, std::int32_t y) {
  return Vec2{Subpixel::from_raw(x), Subpixel::from_raw(y)};
}

// Returns the pixels of the quadrilateral line a -> b on a w x h target (kernel triangle path),
// failing the test if a pixel is emitted twice.
std::vector<Pixel> quad_pixels(Vec2 a, Vec2 b, LineMode mode, std::int32_t w, std::int32_t h,
                               const RasterState& state = {}) {
  std::map<Pixel, int> hits;
  for (const TriangleSetup& t : setup_quad_line(a, b, mode, state)) {
    raster::walk_triangle(t, w, h, [&](std::int32_t x, std::int32_t y) { ++hits[Pixel{x, y}]; });
  }
  std::vector<Pixel> out;
  for (const auto& [p, n] : hits) {
    EXPECT_EQ(n, 1) << p << " emitted " << n << " times";
    out.push_back(p);
  }
  return out;
}

// rule: LINE.QUAD.WIDTH, LINE.QUAD.CORNERS
TEST(LineQuadCorners, HandComputedOffsets) {
  const struct {
    std::int64_t dx, dy;
    QuadHalfWidth hw;
    QuadOffset expected;
    const char* why;
  } cases[] = {
      {256, 0, kQuadWideHalfWidth, {0, 179}, "0.7 px = 179.2 raw -> 179"},
      {256, 0, kQuadNarrowHalfWidth, {0, 128}, "0.5 px = 128 raw"},
      {0, -1000, kQuadWideHalfWidth, {179, 0}, "up the screen: offset to +x"},
      {0, 1000, kQuadNarrowHalfWidth, {-128, 0}, "down the screen: offset to -x"},
      {3, 4, kQuadNarrowHalfWidth, {-102, 77}, "128 (-4, 3) / 5 = (-102.4, 76.8)"},
      {300, 400, kQuadWideHalfWidth, {-143, 108}, "179.2 (-4, 3) / 5 = (-143.36, 107.52)"},
      {1, 2, kQuadNarrowHalfWidth, {-114, 57}, "128 (-2, 1) / sqrt 5 = (-114.49, 57.24)"},
      {1, 2, kQuadWideHalfWidth, {-160, 80}, "179.2 (-2, 1) / sqrt 5 = (-160.28, 80.14)"},
      {512, 512, kQuadWideHalfWidth, {-127, 127}, "179.2 / sqrt 2 = 126.71"},
      {-512, -512, kQuadNarrowHalfWidth, {91, -91}, "128 / sqrt 2 = 90.51"},
      {1, 0, kQuadWideHalfWidth, {0, 179}, "the shortest line has the full width"},
  };
  for (const auto& c : cases) {
    EXPECT_EQ(quad_line_offset(c.dx, c.dy, c.hw), c.expected) << c.why;
    // The offset of the reversed line is the negation.
    const QuadOffset rev = quad_line_offset(-c.dx, -c.dy, c.hw);
    EXPECT_EQ(rev, (QuadOffset{-c.expected.x, -c.expected.y})) << c.why;
  }
}

// rule: LINE.QUAD.CORNERS
TEST(LineQuadCorners, RoundingIsToNearestDecidedBySquares) {
  // m * hw / sqrt(len2) with hw = 128: m = 3, len2 = 9 * 4 gives exactly 64; m = 1, len2 = 4
  // gives 64; len2 = 65536 * 4 / 9 is not an integer, so take m = 5, len2 = 25 * 256 -> 8.
  EXPECT_EQ(round_quad_offset(3, 36, kQuadNarrowHalfWidth), 64);
  EXPECT_EQ(round_quad_offset(5, 25 * 256, kQuadNarrowHalfWidth), 8);
  EXPECT_EQ(round_quad_offset(0, 12345, kQuadWideHalfWidth), 0);
  // Exact ties, ties to even: 1 * (num/den) / sqrt(len2) = 2.5 and 3.5 with num/den = 5 / 2.
  EXPECT_EQ(round_quad_offset(1, 1, QuadHalfWidth{5, 2}), 2);
  EXPECT_EQ(round_quad_offset(1, 1, QuadHalfWidth{7, 2}), 4);
  // Just below and above a half: sqrt(len2) slightly off.
  EXPECT_EQ(round_quad_offset(2, 4, QuadHalfWidth{5, 1}), 5);
  EXPECT_EQ(round_quad_offset(100, 100 * 100 + 1, QuadHalfWidth{5, 2}), 2); // 2.49999...
}

// rule: LINE.QUAD.SHAPE
TEST(LineQuadShape, TrianglesAreThePairAroundTheSegment) {
  // Narrow horizontal line (1, 2) -> (4, 2) px: o = (0, 128).
  const auto t = quad_line_triangles(raw(256, 512), raw(1024, 512), LineMode::kQuadNarrow);
  ASSERT_EQ(t.size(), 2u);
  const Vec2 a_minus = raw(256, 384), b_minus = raw(1024, 384), b_plus = raw(1024, 640),
             a_plus = raw(256, 640);
  EXPECT_EQ(t[0], (std::array<Vec2, 3>{a_minus, b_minus, b_plus}));
  EXPECT_EQ(t[1], (std::array<Vec2, 3>{a_minus, b_plus, a_plus}));
}

// rule: LINE.QUAD.WIDTH, LINE.QUAD.SHAPE
TEST(LineQuadWidth, WideLinesReachTheNextRowNarrowLinesDoNot) {
  // (1, 2) -> (4, 2) px. Narrow: y in [1.5, 2.5) holds only the row-1 centres (y = 1.5).
  // Wide: y in [2 - 179/256, 2 + 179/256) = [1.30, 2.70) holds rows 1 and 2.
  // x in [1, 4): centres 1.5, 2.5, 3.5.
  EXPECT_EQ(quad_pixels(sample_px(1, 2), sample_px(4, 2), LineMode::kQuadNarrow, 6, 5),
            pixels_in_picture({"......", ".###..", "......"}));
  EXPECT_EQ(quad_pixels(sample_px(1, 2), sample_px(4, 2), LineMode::kQuadWide, 6, 5),
            pixels_in_picture({"......", ".###..", ".###..", "......"}));
}

// rule: LINE.QUAD.SHAPE
TEST(LineQuadShape, EndpointsOnPixelCentresIncludeTheStartNotTheEnd) {
  // (0.5, 1.5) -> (3.5, 1.5): x in [0.5, 3.5), the end pixel's centre is on the excluded right
  // end. Both widths cover only row 1 (wide: y in [0.80, 2.20)).
  for (const LineMode m : {LineMode::kQuadNarrow, LineMode::kQuadWide}) {
    EXPECT_EQ(quad_pixels(sample_px(0.5, 1.5), sample_px(3.5, 1.5), m, 5, 3),
              pixels_in_picture({".....", "###.."}));
    // Drawn the other way, the same pixels (the ends do not swap roles).
    EXPECT_EQ(quad_pixels(sample_px(3.5, 1.5), sample_px(0.5, 1.5), m, 5, 3),
              pixels_in_picture({".....", "###.."}));
  }
}

// rule: LINE.QUAD.SHAPE, LINE.QUAD.WIDTH
TEST(LineQuadShape, VerticalNarrowLineOnAColumnOfEdges) {
  // (2, 0.5) -> (2, 3.5): o = (-128, 0); x in [1.5, 2.5) holds column 1's centres only.
  EXPECT_EQ(quad_pixels(sample_px(2, 0.5), sample_px(2, 3.5), LineMode::kQuadNarrow, 4, 5),
            pixels_in_picture({".#..", ".#..", ".#..", "...."}));
}

// rule: LINE.QUAD.SHAPE, LINE.QUAD.CORNERS
TEST(LineQuadShape, FortyFiveDegreesMissesTheCentresAtSevenTenthsOfAPixel) {
  // (1, 1) -> (3, 3): the centres (1.5, 2.5) and (2.5, 1.5) lie 1/sqrt 2 = 0.7071 px from the
  // line; the rounded wide offset (127, 127) puts the sides at 127 sqrt 2 / 256 = 0.7016 px,
  // so both stay out, as they would for the exact 0.7 px.
  for (const LineMode m : {LineMode::kQuadNarrow, LineMode::kQuadWide}) {
    EXPECT_EQ(quad_pixels(sample_px(1, 1), sample_px(3, 3), m, 4, 4),
              pixels_in_picture({"....", ".#..", "..#."}));
  }
  // Shifted a quarter pixel down, the centres (1.5, 2.5) and (2.5, 3.5) lie
  // 0.75 / sqrt 2 = 0.53 px from the line, inside its length: the wide line (0.7 px) reaches
  // pixels (1, 2) and (2, 3), the narrow one (0.5 px) does not.
  EXPECT_EQ(quad_pixels(sample_px(1, 1.25), sample_px(3, 3.25), LineMode::kQuadWide, 4, 4),
            pixels_in_picture({"....", ".#..", ".##.", "..#."}));
  EXPECT_EQ(quad_pixels(sample_px(1, 1.25), sample_px(3, 3.25), LineMode::kQuadNarrow, 4, 4),
            pixels_in_picture({"....", ".#..", "..#."}));
}

// rule: LINE.QUAD.ZERO_LENGTH
TEST(LineQuadZeroLength, EqualEndpointsCoverNothing) {
  for (const LineMode m : {LineMode::kQuadNarrow, LineMode::kQuadWide}) {
    EXPECT_TRUE(quad_line_triangles(sample_px(1.5, 1.5), sample_px(1.5, 1.5), m).empty());
    EXPECT_TRUE(setup_quad_line(sample_px(2, 2), sample_px(2, 2), m, RasterState{}).empty());
  }
  // One subpixel long is not zero length: a 1/256 px sliver, 1.4 px tall.
  EXPECT_EQ(quad_line_triangles(raw(384, 384), raw(385, 384), LineMode::kQuadWide).size(), 2u);
}

// rule: LINE.QUAD.NO_CULL
TEST(LineQuadNoCull, CullModesDoNotApply) {
  for (const CullMode cull : {CullMode::kNone, CullMode::kBack, CullMode::kFront}) {
    const RasterState state{cull, FrontFace::kClockwise, FillConvention::kTopLeft};
    const auto setups =
        setup_quad_line(sample_px(0.5, 1.5), sample_px(3.5, 1.5), LineMode::kQuadWide, state);
    ASSERT_EQ(setups.size(), 2u);
    for (const TriangleSetup& s : setups)
      EXPECT_EQ(s.status, TriangleStatus::kRasterized);
    EXPECT_EQ(
        quad_pixels(sample_px(0.5, 1.5), sample_px(3.5, 1.5), LineMode::kQuadWide, 5, 3, state),
        pixels_in_picture({".....", "###.."}));
  }
}

// rule: LINE.QUAD.CORNERS
TEST(LineQuadCorners, CornersNearTheRangeLimitStayRepresentable) {
  const Vec2 a = raw(kMaxVertexRaw, kMaxVertexRaw), b = raw(kMinVertexRaw, kMaxVertexRaw);
  const auto t = quad_line_triangles(a, b, LineMode::kQuadWide);
  ASSERT_EQ(t.size(), 2u);
  // Running -x: o = (0, -179); the corners a + o... lie 179 raw beyond the range in y.
  EXPECT_EQ(t[0][0], raw(kMaxVertexRaw, kMaxVertexRaw + 179));
  EXPECT_EQ(t[1][2], raw(kMaxVertexRaw, kMaxVertexRaw - 179));
}

} // namespace
} // namespace rastrules::test
