// SPDX-License-Identifier: MIT
// Hand-computed aliased-line cases on each diamond edge and corner, x-major and y-major, in
// both profiles; zero length; strips; order; the explanation of one pixel.
// Pixel (2, 2) has centre (2.5, 2.5) and diamond corners bottom (2.5, 3), top (2.5, 2),
// left (2, 2.5), right (3, 2.5); h = 0.5 px.

#include <vector>

#include <gtest/gtest.h>

#include "line_test_util.hpp"
#include "rastrules/line.hpp"
#include "rastrules/line_aliased.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

constexpr LineMode kD3D = LineMode::kD3DDiamond;
constexpr LineMode kVk = LineMode::kVulkanBresenham;

// Both profiles draw the line from a to b as `expected`.
void expect_both_profiles(Px a, Px b, const std::vector<Pixel>& expected) {
  EXPECT_EQ(line_pixels(a, b, kD3D), expected) << "d3d";
  EXPECT_EQ(line_pixels(a, b, kVk), expected) << "vulkan";
}

// rule: LINE.DIAMOND.GEOMETRY, LINE.D3D.EXIT, LINE.VK.EXIT
TEST(LineExit, CentreToCentreCoversEveryPixelButTheLast) {
  expect_both_profiles({0.5, 0.5}, {3.5, 0.5}, {{0, 0}, {1, 0}, {2, 0}});
}

// rule: LINE.MAJOR.AXIS
TEST(LineMajorAxis, FortyFiveDegreesIsXMajor) {
  EXPECT_TRUE(is_x_major(sample_px(0, 0), sample_px(2, 2)));
  EXPECT_TRUE(is_x_major(sample_px(0, 0), sample_px(2, -2)));
  EXPECT_TRUE(is_x_major(sample_px(0, 0), sample_px(2, 1)));
  EXPECT_FALSE(is_x_major(sample_px(0, 0), sample_px(2, 2.00390625)));
  EXPECT_FALSE(is_x_major(sample_px(0, 0), sample_px(0, 1)));
}

// rule: LINE.D3D.TEST_AREA, LINE.VK.TEST_AREA
TEST(LineBottomCorner, HorizontalLineThroughBottomCornersCoversTheRowAbove) {
  // y = 3 passes the bottom corners of row 2 and the top corners of row 3. D3D includes the
  // bottom corner; Vulkan shifts the line up by e^2 into the row-2 diamonds.
  expect_both_profiles({1.0, 3.0}, {4.0, 3.0}, {{1, 2}, {2, 2}, {3, 2}});
}

// rule: LINE.D3D.TEST_AREA, LINE.VK.TEST_AREA, LINE.VK.D3D.DIFFERENCE
TEST(LineBottomCorner, GrazingTheBottomCornerFromBelowDiffersBetweenProfiles) {
  // Slope 1/2 through (2.5, 3): below pixel (2,2)'s diamond except its bottom corner, and below
  // pixel (2,3)'s diamond except its top corner. D3D: the bottom corner is in T, so (2,2).
  // Vulkan: the line moved by (-e, -e^2) crosses x = 2.5 at y = 3 + e/2 - e^2, just inside the
  // top corner of (2,3).
  const Px a{0.5, 2.0}, b{4.5, 4.0};
  EXPECT_TRUE(covers_px(a, b, kD3D, 2, 2));
  EXPECT_FALSE(covers_px(a, b, kD3D, 2, 3));
  EXPECT_FALSE(covers_px(a, b, kVk, 2, 2));
  EXPECT_TRUE(covers_px(a, b, kVk, 2, 3));
}

// rule: LINE.D3D.EXIT, LINE.VK.EXIT, LINE.VK.D3D.DIFFERENCE
TEST(LineBottomCorner, EndingOnTheBottomCornerDoesNotExitUnderD3D) {
  // Vertical, from the centre of (2,1) down to the bottom corner of (2,2). D3D: the end point
  // is in (2,2)'s test area, so no exit. Vulkan: the end moved to (2.5 - e, 3 - e^2) is
  // outside the open diamond, and the moved segment crosses it.
  EXPECT_EQ(line_pixels({2.5, 1.5}, {2.5, 3.0}, kD3D), (std::vector<Pixel>{{2, 1}}));
  EXPECT_EQ(line_pixels({2.5, 1.5}, {2.5, 3.0}, kVk), (std::vector<Pixel>{{2, 1}, {2, 2}}));
}

// rule: LINE.D3D.TEST_AREA, LINE.VK.TEST_AREA
TEST(LineRightCorner, VerticalLineThroughRightCornersCoversTheLeftColumn) {
  // x = 3 passes the right corners of column 2 and the left corners of column 3. D3D y-major
  // includes the right corner; Vulkan shifts the line left into column 2.
  expect_both_profiles({3.0, 1.0}, {3.0, 4.0}, {{2, 1}, {2, 2}, {2, 3}});
}

// rule: LINE.D3D.TEST_AREA, LINE.MAJOR.AXIS
TEST(LineRightCorner, SteepLineTouchingOnlyTheRightCornerIsCoveredWhenYMajor) {
  // Slope 2 through (3, 2.5) touches (2,2)'s diamond only at its right corner: included for
  // y-major lines. (3,2)'s left corner is the same point: excluded.
  const Px a{2.5, 1.5}, b{3.5, 3.5};
  EXPECT_TRUE(covers_px(a, b, kD3D, 2, 2));
  EXPECT_FALSE(covers_px(a, b, kD3D, 3, 2));
  EXPECT_TRUE(covers_px(a, b, kVk, 2, 2));
}

// rule: LINE.D3D.TEST_AREA, LINE.MAJOR.AXIS, LINE.VK.D3D.DIFFERENCE
TEST(LineUpperRightEdge, FortyFiveDegreeLineAlongUpperRightEdgeMissesUnderD3D) {
  // x - y = 0.5 runs along (2,2)'s upper-right edge from its top corner to its right corner.
  // x-major: the upper edges and the top and right corners are excluded. Vulkan moves the line
  // left, into the open diamond.
  const Px a{2.0, 1.5}, b{3.5, 3.0};
  EXPECT_FALSE(covers_px(a, b, kD3D, 2, 2));
  EXPECT_TRUE(covers_px(a, b, kVk, 2, 2));
}

// rule: LINE.D3D.TEST_AREA, LINE.VK.TEST_AREA
TEST(LineLowerRightEdge, FortyFiveDegreeLineAlongLowerRightEdgeIsCoveredByBoth) {
  // x + y = 5.5 runs along (2,2)'s lower-right edge (included by D3D; Vulkan moves the line
  // up-left into the diamond), and ends outside it.
  const Px a{3.5, 2.0}, b{2.0, 3.5};
  EXPECT_TRUE(covers_px(a, b, kD3D, 2, 2));
  EXPECT_TRUE(covers_px(a, b, kVk, 2, 2));
  // Stopping at the bottom corner: the end point is in D3D's test area (no exit); for Vulkan
  // the moved end (2.5 - e, 3 - e^2) is outside, so the pixel is produced.
  EXPECT_FALSE(covers_px({3.0, 2.5}, {2.5, 3.0}, kD3D, 2, 2));
  EXPECT_TRUE(covers_px({3.0, 2.5}, {2.5, 3.0}, kVk, 2, 2));
}

// rule: LINE.D3D.TEST_AREA, LINE.VK.TEST_AREA, LINE.VK.D3D.DIFFERENCE
TEST(LineLowerLeftEdge, StartingOnTheLowerLeftEdgeAndLeavingDiffers) {
  // (2.25, 2.75) is on (2,2)'s lower-left edge: in D3D's test area, so a line that starts
  // there and leaves exits. Vulkan moves the start to the left, outside; the line then never
  // meets the open diamond. The end (0.25, 2.75) is on (0,2)'s lower-left edge: D3D's end
  // point is in (0,2)'s test area (no exit there); Vulkan's moved end is outside it.
  const Px a{2.25, 2.75}, b{0.25, 2.75};
  EXPECT_TRUE(covers_px(a, b, kD3D, 2, 2));
  EXPECT_FALSE(covers_px(a, b, kVk, 2, 2));
  EXPECT_EQ(line_pixels(a, b, kD3D), (std::vector<Pixel>{{2, 2}, {1, 2}}));
  EXPECT_EQ(line_pixels(a, b, kVk), (std::vector<Pixel>{{1, 2}, {0, 2}}));
}

// rule: LINE.D3D.TEST_AREA, LINE.VK.TEST_AREA, LINE.VK.D3D.DIFFERENCE
TEST(LineUpperRightEdge, StartingAndEndingOnUpperRightEdgesDiffers) {
  // From (2.75, 2.25) on (2,2)'s upper-right edge to (4.75, 2.25) on (4,2)'s. D3D: (2,2) is
  // never entered (excluded edge), (4,2) is exited (its end point is on an excluded edge).
  // Vulkan: the moved start is inside (2,2); the moved end is inside (4,2).
  const Px a{2.75, 2.25}, b{4.75, 2.25};
  EXPECT_EQ(line_pixels(a, b, kD3D), (std::vector<Pixel>{{3, 2}, {4, 2}}));
  EXPECT_EQ(line_pixels(a, b, kVk), (std::vector<Pixel>{{2, 2}, {3, 2}}));
}

// rule: LINE.D3D.TEST_AREA
TEST(LineTopAndLeftCorners, LinesTouchingOnlyTopOrLeftCornersMissUnderD3D) {
  // Horizontal through the top corner (2.5, 2) of (2,2): covered in row 1 instead.
  EXPECT_FALSE(covers_px({1.0, 2.0}, {4.0, 2.0}, kD3D, 2, 2));
  EXPECT_TRUE(covers_px({1.0, 2.0}, {4.0, 2.0}, kD3D, 2, 1));
  // Vertical through the left corner (2, 2.5): covered in column 1 (its right corner).
  EXPECT_FALSE(covers_px({2.0, 1.0}, {2.0, 4.0}, kD3D, 2, 2));
  EXPECT_TRUE(covers_px({2.0, 1.0}, {2.0, 4.0}, kD3D, 1, 2));
}

// rule: LINE.VK.TEST_AREA, LINE.VK.D3D.DIFFERENCE
TEST(LineTopAndLeftCorners, VulkanEntersThroughTheTopCornerOnlyInSomeDirections) {
  // Slope 1/2 through the top corner (2.5, 2) continuing to the right: moved left by e, the
  // line cuts the diamond just below its top corner. D3D: the top corner is excluded.
  EXPECT_TRUE(covers_px({1.5, 1.5}, {3.5, 2.5}, kVk, 2, 2));
  EXPECT_FALSE(covers_px({1.5, 1.5}, {3.5, 2.5}, kD3D, 2, 2));
  // Stopping at the corner, horizontal through it, or vertical through the left corner: no.
  EXPECT_FALSE(covers_px({1.5, 1.5}, {2.5, 2.0}, kVk, 2, 2));
  EXPECT_FALSE(covers_px({1.0, 2.0}, {4.0, 2.0}, kVk, 2, 2));
  EXPECT_FALSE(covers_px({2.0, 1.0}, {2.0, 4.0}, kVk, 2, 2));
}

// rule: LINE.ZERO_LENGTH
TEST(LineZeroLength, CoversNothingInEitherProfile) {
  for (const Px p : {Px{2.5, 2.5}, Px{3.0, 2.5}, Px{2.5, 3.0}, Px{2.25, 2.75}, Px{2.125, 2.375}}) {
    EXPECT_TRUE(line_pixels(p, p, kD3D).empty());
    EXPECT_TRUE(line_pixels(p, p, kVk).empty());
  }
}

// rule: LINE.TARGET.CLIP
TEST(LineTargetClip, OnlyTargetPixelsAndNoGeometricClipping) {
  // From far left of the target to its middle, along row 1's centres.
  EXPECT_EQ(line_pixels({-100.5, 1.5}, {2.5, 1.5}, kD3D, 4, 4),
            (std::vector<Pixel>{{0, 1}, {1, 1}}));
  // The same line on a 2-pixel-wide target: the end pixel (2,1) is outside, not "clipped in".
  EXPECT_EQ(line_pixels({-100.5, 1.5}, {2.5, 1.5}, kD3D, 2, 4),
            (std::vector<Pixel>{{0, 1}, {1, 1}}));
  EXPECT_TRUE(line_pixels({0.5, 0.5}, {3.5, 0.5}, kD3D, 0, 4).empty());
}

// rule: LINE.ORDER.TRAVEL
TEST(LineOrder, PixelsComeFromStartToEnd) {
  EXPECT_EQ(line_pixels({3.5, 0.5}, {0.5, 0.5}, kD3D),
            (std::vector<Pixel>{{3, 0}, {2, 0}, {1, 0}}));
  EXPECT_EQ(line_pixels({0.5, 3.5}, {0.5, 0.5}, kVk), (std::vector<Pixel>{{0, 3}, {0, 2}, {0, 1}}));
}

// rule: LINE.STRIP.SEQUENCE
TEST(LineStrip, DrawsAsItsIndependentLinesInOrder) {
  const std::vector<Vec2> strip = {sample_px(0.5, 0.5), sample_px(3.5, 0.5), sample_px(3.5, 3.5)};
  std::vector<Pixel> got;
  rasterize_aliased_line_strip(strip, kD3D, 8, 8, [&](std::int32_t x, std::int32_t y) {
    got.push_back({x, y});
  });
  EXPECT_EQ(got, (std::vector<Pixel>{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}}));
  got.clear();
  rasterize_aliased_line_strip({sample_px(0.5, 0.5)}, kD3D, 8, 8,
                               [&](std::int32_t x, std::int32_t y) {
                                 got.push_back({x, y});
                               });
  EXPECT_TRUE(got.empty());
}

// rule: LINE.VK.BRESENHAM_CENTRES
TEST(LineVulkanBresenham, RowBoundaryTiesFollowTheSlope) {
  // (0.5, 0.5) -> (2.5, 1.5): at column 1's centre the line is at y = 1.0, a row boundary.
  // Positive slope: the row below (1).
  EXPECT_EQ(line_pixels({0.5, 0.5}, {2.5, 1.5}, kVk), (std::vector<Pixel>{{0, 0}, {1, 1}}));
  // Negative slope: the row above (0).
  EXPECT_EQ(line_pixels({0.5, 1.5}, {2.5, 0.5}, kVk), (std::vector<Pixel>{{0, 1}, {1, 0}}));
  // y-major: a column boundary goes to the column on the left.
  EXPECT_EQ(line_pixels({0.5, 0.5}, {1.5, 2.5}, kVk), (std::vector<Pixel>{{0, 0}, {0, 1}}));
}

// rule: LINE.D3D.EXIT, LINE.VK.EXIT
TEST(LineExplain, NamesTheFeaturesAndTheDecision) {
  const Vec2 a = sample_px(2.75, 2.25), b = sample_px(4.75, 2.25);
  const LineDiamondDecision d3d = explain_aliased_line_pixel(a, b, kD3D, 2, 2);
  EXPECT_TRUE(d3d.x_major);
  EXPECT_EQ(d3d.met_features, static_cast<std::uint32_t>(kFeatureEdgeUpperRight));
  EXPECT_FALSE(d3d.entered);
  EXPECT_FALSE(d3d.covered);
  EXPECT_EQ(to_string(kFeatureEdgeUpperRight), "upper-right edge");
  const LineDiamondDecision vk = explain_aliased_line_pixel(a, b, kVk, 2, 2);
  EXPECT_TRUE(vk.entered);
  EXPECT_FALSE(vk.end_inside);
  EXPECT_TRUE(vk.covered);
  const LineDiamondDecision end = explain_aliased_line_pixel(a, b, kVk, 4, 2);
  EXPECT_TRUE(end.end_inside);
  EXPECT_FALSE(end.covered);
  EXPECT_EQ(to_string(LineMode::kD3DDiamond), "d3d");
  EXPECT_EQ(to_string(LineMode::kVulkanBresenham), "vulkan-bresenham");
}

} // namespace
} // namespace rastrules::test
