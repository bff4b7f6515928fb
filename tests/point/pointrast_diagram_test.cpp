// SPDX-License-Identifier: MIT
// The D3D11.3 point rasterization diagram (shared/reference/img/PointRast.png, "Point
// Rasterization Examples (Single Sample Per Pixel)"), reproduced point by point.
//
// Reading the picture: the grid is 14 x 6 pixels, pixel centres (crosses) at .5; one pixel is
// 40 picture pixels. Each point was read from the outline of its square (1 px wide, so its
// centre is the middle of the outline) and its dot, decoding the PNG: the outlines lie on
// whole, half or quarter pixels, except three squares (I, K, M below) whose outlines sit about
// 0.2 px off the grid; those centres are given to the nearest 1/256 px of the reading, and
// their coverage does not change within +-0.1 px of it. Every square's diagonal runs from the
// lower-left to the upper-right corner (POINT.SHAPE.TWO_TRIANGLES).
//
// The picture shades covered pixels light grey, and one pixel (12, 1) dark grey: the two
// points G and H there have squares that touch along x = 12.5, the centre of that pixel. The
// dark shade marks that tie; the pixel is covered once, by H (its left side is inclusive).
// Points A, B, N (and the centre-free corners) cover nothing: their squares hold no pixel
// centre inside the target or only on excluded sides.

#include <gtest/gtest.h>

#include <map>
#include <string_view>
#include <vector>

#include "point_support.hpp"
#include "rastrules/point.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

struct DiagramPoint {
  char name;
  Px centre;              // as read, in pixels (multiples of 1/256)
  std::string_view where; // how to find it in the picture
};

// clang-format off
const DiagramPoint kPoints[] = {
    {'A', {0.0, 0.0},               "top-left corner of the grid"},
    {'B', {14.0, 0.0},              "top-right corner of the grid"},
    {'C', {1.5, 1.5},               "on the centre of pixel (1, 1)"},
    {'D', {3.5, 2.0},               "column 3, on the line between rows 1 and 2"},
    {'E', {6.0, 1.5},               "on the line between columns 5 and 6, row 1"},
    {'F', {9.0, 2.0},               "on the grid corner (9, 2)"},
    {'G', {12.0, 2.0},              "left of the touching pair, on the grid corner (12, 2)"},
    {'H', {13.0, 2.0},              "right of the touching pair, on the grid corner (13, 2)"},
    {'I', {0.1875, 3.25},           "left border, row 3, square half outside the grid"},
    {'J', {3.5, 4.75},              "column 3, between rows 4 and 5"},
    {'K', {1485.0 / 256, 4.5},      "about (5.8, 4.5): square from x 5.3 to 6.3, rows 4..5"},
    {'M', {2253.0 / 256, 1229.0 / 256}, "about (8.8, 4.8): square about 8.3..9.3 x 4.3..5.3"},
    {'N', {0.0, 6.0},               "bottom-left corner of the grid"},
    {'O', {11.0, 6.0},              "bottom border, on the grid corner (11, 6)"},
    {'P', {14.0, 6.0},              "bottom-right corner of the grid"},
};
// clang-format on

// The covered pixels of the picture (light or dark grey), row 0 at the top.
std::vector<Pixel> covered_in_picture() {
  return pixels_in_picture({
      "..............",
      ".#.#.#..#..##.",
      "..............",
      "#.............",
      "...#.#..#.....",
      "..........#..#",
  });
}

// rule: POINT.SHAPE.SQUARE, POINT.SHAPE.TWO_TRIANGLES, POINT.COVER.HALF_OPEN
TEST(PointDiagram, KernelReproducesThePictureWithEveryPixelCoveredOnce) {
  std::map<Pixel, int> all;
  for (const DiagramPoint& p : kPoints) {
    for (const auto& [px, n] : point_hits(sample_px(p.centre.x, p.centre.y), 14, 6)) {
      EXPECT_EQ(n, 1) << "point " << p.name << " emits " << px << " " << n << " times";
      all[px] += n;
    }
  }
  std::vector<Pixel> got;
  for (const auto& [px, n] : all) {
    EXPECT_EQ(n, 1) << px << " covered by " << n << " points";
    got.push_back(px);
  }
  EXPECT_EQ(got, covered_in_picture()) << picture(got, 14, 6);
}

// rule: POINT.COVER.HALF_OPEN
TEST(PointDiagram, EachPointCoversTheExpectedPixel) {
  // clang-format off
  const std::map<char, std::vector<Pixel>> expected = {
      {'A', {}}, {'B', {}}, {'C', {{1, 1}}}, {'D', {{3, 1}}}, {'E', {{5, 1}}}, {'F', {{8, 1}}},
      {'G', {{11, 1}}}, {'H', {{12, 1}}}, {'I', {{0, 3}}}, {'J', {{3, 4}}}, {'K', {{5, 4}}},
      {'M', {{8, 4}}}, {'N', {}}, {'O', {{10, 5}}}, {'P', {{13, 5}}},
  };
  // clang-format on
  for (const DiagramPoint& p : kPoints) {
    EXPECT_EQ(point_pixels(sample_px(p.centre.x, p.centre.y), 14, 6), expected.at(p.name))
        << "point " << p.name << " (" << p.where << ")";
  }
}

// rule: POINT.COVER.HALF_OPEN
TEST(PointDiagram, ReadingToleranceDoesNotChangeTheOffGridPoints) {
  // I, K and M moved by up to +-0.1 px (25 raw) in each direction cover the same pixel.
  for (const DiagramPoint& p : kPoints) {
    if (p.name != 'I' && p.name != 'K' && p.name != 'M')
      continue;
    const Vec2 c = sample_px(p.centre.x, p.centre.y);
    const auto base = point_pixels(c, 14, 6);
    for (int dx = -25; dx <= 25; dx += 5) {
      for (int dy = -25; dy <= 25; dy += 5) {
        const Vec2 m{Subpixel::from_raw(c.x.raw() + dx), Subpixel::from_raw(c.y.raw() + dy)};
        EXPECT_EQ(point_pixels(m, 14, 6), base)
            << "point " << p.name << " moved by " << dx << ", " << dy << " raw";
      }
    }
  }
}

} // namespace
} // namespace rastrules::test
