// SPDX-License-Identifier: MIT
// Examples for the POINT.* rules: the square's corners and triangles, ties on pixel centres,
// edges and corners under each fill convention, no culling, and the range limits.

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "point_support.hpp"
#include "rastrules/fixed.hpp"
#include "rastrules/formula/point.hpp"
#include "rastrules/point.hpp"
#include "rastrules/triangle.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

Vec2 raw(std::int32_t x, std::int32_t y) {
  return Vec2{Subpixel::from_raw(x), Subpixel::from_raw(y)};
}

// rule: POINT.SHAPE.SQUARE, POINT.SHAPE.TWO_TRIANGLES
TEST(PointShape, TrianglesAreTheZPatternOfTheUnitSquare) {
  // Centre (1.5, 1.5) px = (384, 384) raw; corners at 1 px and 2 px.
  const auto t = point_triangles(raw(384, 384));
  const Vec2 tl = raw(256, 256), tr = raw(512, 256), bl = raw(256, 512), br = raw(512, 512);
  EXPECT_EQ(t[0], (std::array<Vec2, 3>{tl, tr, bl}));
  EXPECT_EQ(t[1], (std::array<Vec2, 3>{bl, tr, br}));
}

// rule: POINT.SHAPE.TWO_TRIANGLES
TEST(PointShape, BothTrianglesAreClockwiseWithHalfAPixelOfArea) {
  for (const TriangleSetup& s : setup_point(raw(1000, -777), RasterState{})) {
    EXPECT_EQ(s.status, TriangleStatus::kRasterized);
    EXPECT_TRUE(s.clockwise);
    EXPECT_EQ(s.twice_area, 256 * 256); // twice 1/2 px^2, in 1/65536 px^2
  }
}

// rule: POINT.CULL.NONE
TEST(PointCull, CullModesDoNotApplyToPoints) {
  for (const CullMode cull : {CullMode::kNone, CullMode::kBack, CullMode::kFront}) {
    for (const FrontFace ff : {FrontFace::kClockwise, FrontFace::kCounterClockwise}) {
      const RasterState state{cull, ff, FillConvention::kTopLeft};
      for (const TriangleSetup& s : setup_point(sample_px(2.5, 2.5), state)) {
        EXPECT_EQ(s.status, TriangleStatus::kRasterized) << to_string(cull) << " " << to_string(ff);
      }
      EXPECT_EQ(point_pixels(sample_px(2.5, 2.5), 4, 4, state), (std::vector<Pixel>{{2, 2}}));
    }
  }
}

// rule: POINT.COVER.HALF_OPEN
TEST(PointCoverHalfOpen, CentreOnAPixelCentreCoversThatPixel) {
  EXPECT_EQ(point_pixels(sample_px(1.5, 1.5), 4, 4), (std::vector<Pixel>{{1, 1}}));
}

// rule: POINT.COVER.HALF_OPEN, POINT.SHAPE.TWO_TRIANGLES
TEST(PointCoverHalfOpen, CentreOnAPixelCornerCoversTheUpperLeftPixel) {
  // Square [1.5, 2.5) x [1.5, 2.5): the centre (1.5, 1.5) is its top-left corner, inclusive;
  // (2.5, *) and (*, 2.5) lie on the excluded right and bottom sides.
  EXPECT_EQ(point_pixels(sample_px(2.0, 2.0), 4, 4), (std::vector<Pixel>{{1, 1}}));
}

// rule: POINT.COVER.HALF_OPEN
TEST(PointCoverHalfOpen, CentreHalfWayBetweenCentresGoesLeftOrUp) {
  EXPECT_EQ(point_pixels(sample_px(2.0, 1.5), 4, 4), (std::vector<Pixel>{{1, 1}}));
  EXPECT_EQ(point_pixels(sample_px(1.5, 2.0), 4, 4), (std::vector<Pixel>{{1, 1}}));
}

// rule: POINT.COVER.HALF_OPEN
TEST(PointCoverHalfOpen, OneSubpixelPastTheCornerMovesToTheNextPixel) {
  EXPECT_EQ(point_pixels(raw(512 - 1, 512 - 1), 4, 4), (std::vector<Pixel>{{1, 1}}));
  EXPECT_EQ(point_pixels(raw(512 + 1, 512 + 1), 4, 4), (std::vector<Pixel>{{2, 2}}));
  EXPECT_EQ(point_pixels(raw(512 + 1, 512 - 1), 4, 4), (std::vector<Pixel>{{2, 1}}));
}

// rule: POINT.COVER.HALF_OPEN, POINT.SHAPE.TWO_TRIANGLES
TEST(PointCoverHalfOpen, TheOtherConventionsMoveTheInclusiveSides) {
  // Centre on the corner (2, 2): the square's four sides each hold one pixel centre row or
  // column; the convention picks which.
  const struct {
    FillConvention fill;
    Pixel expected;
  } cases[] = {{FillConvention::kTopLeft, {1, 1}},
               {FillConvention::kTopRight, {2, 1}},
               {FillConvention::kBottomLeft, {1, 2}},
               {FillConvention::kBottomRight, {2, 2}}};
  for (const auto& c : cases) {
    const RasterState state{CullMode::kNone, FrontFace::kClockwise, c.fill};
    const auto hits = point_hits(sample_px(2.0, 2.0), 4, 4, state);
    ASSERT_EQ(hits.size(), 1u) << to_string(c.fill);
    EXPECT_EQ(hits.begin()->first, c.expected) << to_string(c.fill);
    EXPECT_EQ(hits.begin()->second, 1) << to_string(c.fill);
  }
}

// rule: POINT.COVER.HALF_OPEN
TEST(PointCoverHalfOpen, TheDiagonalSampleIsCoveredByExactlyOneTriangle) {
  // Centre (1.5, 1.5): the pixel centre (1.5, 1.5) is the middle of the shared diagonal.
  const auto tris = setup_point(sample_px(1.5, 1.5), RasterState{});
  const Vec2 s = pixel_center(1, 1);
  EXPECT_NE(covers(tris[0], s), covers(tris[1], s));
  EXPECT_FALSE(covers(tris[0], s)); // on (TL, TR, BL)'s edge TR -> BL, which runs down: excluded
  EXPECT_TRUE(
      covers(tris[1], s)); // on (BL, TR, BR)'s edge BL -> TR, which runs up: left, inclusive
}

// rule: POINT.RANGE
TEST(PointRange, CentresMustLeaveHalfAPixelInsideTheVertexRange) {
  const auto in_range = [](std::int64_t x, std::int64_t y) {
    return formula::point_centre_in_range<std::int64_t>(x, y, kMinPointRaw, kMaxPointRaw);
  };
  EXPECT_EQ(kMinPointRaw, -8388608 + 128); // -32767.5 px
  EXPECT_EQ(kMaxPointRaw, 8388607 - 128);  // 32767.49609375 px
  EXPECT_TRUE(in_range(kMinPointRaw, kMaxPointRaw));
  EXPECT_TRUE(in_range(0, 0));
  EXPECT_FALSE(in_range(kMinPointRaw - 1, 0));
  EXPECT_FALSE(in_range(0, kMaxPointRaw + 1));
  EXPECT_FALSE(in_range(kMinVertexRaw, kMinVertexRaw));
  // At the limits every corner is still a valid vertex.
  for (const auto& tri : point_triangles(raw(kMinPointRaw, kMaxPointRaw))) {
    for (const Vec2& v : tri) {
      EXPECT_GE(v.x.raw(), kMinVertexRaw);
      EXPECT_LE(v.x.raw(), kMaxVertexRaw);
      EXPECT_GE(v.y.raw(), kMinVertexRaw);
      EXPECT_LE(v.y.raw(), kMaxVertexRaw);
    }
  }
}

// rule: POINT.RANGE, POINT.COVER.HALF_OPEN
TEST(PointRange, PointsOutsideTheTargetCoverNothing) {
  EXPECT_TRUE(point_pixels(sample_px(-0.5, 1.5), 4, 4).empty()); // square [-1, 0): no centre
  EXPECT_EQ(point_pixels(sample_px(0.5, 1.5), 4, 4), (std::vector<Pixel>{{0, 1}}));
  EXPECT_TRUE(point_pixels(raw(kMaxPointRaw, kMaxPointRaw), 4, 4).empty());
}

} // namespace
} // namespace rastrules::test
