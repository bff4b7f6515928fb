// SPDX-License-Identifier: MIT
// The coordinate system: origin at the top-left corner, y down, pixel centres at +0.5.

#include <gtest/gtest.h>

#include "rastrules/fixed.hpp"
#include "rastrules/triangle.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

// rule: COORD.PIXEL.CENTER
TEST(CoordPixelCenter, CentreOfPixelIJIsAtIPlusHalfJPlusHalf) {
  EXPECT_EQ(pixel_center(0, 0), sample_px(0.5, 0.5));
  EXPECT_EQ(pixel_center(3, 2).x.raw(), 3 * 256 + 128);
  EXPECT_EQ(pixel_center(3, 2).y.raw(), 2 * 256 + 128);
  EXPECT_EQ(pixel_center(16383, 16383), sample_px(16383.5, 16383.5));
}

// rule: COORD.PIXEL.CENTER, TRI.COVER.SAMPLE
TEST(CoordPixelCenter, APixelIsCoveredIffItsCentreIs) {
  // A small triangle around the centre of pixel (0,0), a quarter of its area: covered.
  EXPECT_EQ(centre_pixels(triangle_px({0.25, 0.25}, {0.75, 0.25}, {0.5, 0.75}), 2, 2),
            (std::vector<Pixel>{{0, 0}}));
  // Almost half of pixel (0,0), but its diagonal passes 0.0039 px beside the centre: nothing.
  EXPECT_TRUE(centre_pixels(triangle_px({0, 0}, {0.99609375, 0}, {0, 0.99609375}), 2, 2).empty());
  // The same triangle grown by one subpixel reaches the centre exactly: (0,0)-(1,0)-(0,1) has
  // the centre on its right edge, still not covered; grown once more, the centre is inside.
  EXPECT_TRUE(centre_pixels(triangle_px({0, 0}, {1, 0}, {0, 1}), 2, 2).empty());
  EXPECT_EQ(centre_pixels(triangle_px({0, 0}, {1.00390625, 0}, {0, 1.00390625}), 2, 2),
            (std::vector<Pixel>{{0, 0}}));
}

// rule: COORD.PIXEL.ORIGIN
TEST(CoordPixelOrigin, OriginIsTheTopLeftCornerAndYPointsDown) {
  // A triangle hugging the origin covers pixels of row 0 and column 0: the top-left corner.
  EXPECT_EQ(centre_pixels(triangle_px({0, 0}, {3, 0}, {0, 3}), 4, 4), pixels_in_picture({
                                                                          "##..",
                                                                          "#...",
                                                                          "....",
                                                                          "....",
                                                                      }));
  // Increasing y moves coverage down the picture (to later rows).
  EXPECT_EQ(centre_pixels(triangle_px({0, 2}, {3, 2}, {0, 5}), 4, 4), pixels_in_picture({
                                                                          "....",
                                                                          "....",
                                                                          "##..",
                                                                          "#...",
                                                                      }));
  // Pixel (i, j) is the half-open square [i, i+1) x [j, j+1): a triangle over
  // [2, 3) x [1, 2) only contains the centre of pixel (2, 1).
  EXPECT_EQ(centre_pixels(triangle_px({2, 1}, {3.5, 1}, {2, 2.5}), 4, 4),
            (std::vector<Pixel>{{2, 1}}));
}

// rule: TRI.INVARIANCE.TRANSLATION, TRI.COVER.SAMPLE
TEST(TriInvarianceTranslation, WholePixelTranslationMovesCoverageExactly) {
  // A triangle with a top edge, a left edge and a right edge through centres, and a vertex
  // on a centre: every tie of the rule occurs. Moved by (3, 2) px, its coverage moves by
  // (3, 2) pixels, under every convention.
  const Px a{0.5, 0.5}, b{3.5, 0.5}, c{0.5, 3.5};
  for (const FillConvention f : kAllConventions) {
    RasterState state;
    state.fill = f;
    auto moved = centre_pixels(triangle_px(a, b, c, state), 8, 8);
    ASSERT_FALSE(moved.empty());
    for (Pixel& p : moved)
      p = Pixel{p.x + 3, p.y + 2};
    EXPECT_EQ(
        centre_pixels(
            triangle_px({a.x + 3, a.y + 2}, {b.x + 3, b.y + 2}, {c.x + 3, c.y + 2}, state), 8, 8),
        moved)
        << "fill " << to_string(f);
  }
}

} // namespace
} // namespace rastrules::test
