// SPDX-License-Identifier: MIT
// The lines of D3D11.3's aliased-line diagram (D3D11_3_LineRast.png), reproduced under the
// d3d profile. The diagram is a 17 x 16 pixel grid; end points were read off the
// picture (dot = start or strip interior, square = end; every coordinate a multiple of 1/8 px)
// and the covered pixels are the grey cells next to each line. kDiagramGrey is the picture's
// grey map, row by row, so that every expectation is also checked against the picture itself.
//
// Transcribed: every line and strip of the picture except the six very short lines clustered
// around pixel (12, 3), whose directions cannot be read at the picture's resolution (they cover
// nothing there). Together the transcribed lines claim exactly the picture's grey cells.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "line_test_util.hpp"
#include "rastrules/line.hpp"
#include "rastrules/line_aliased.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

constexpr std::int32_t kW = 17, kH = 16;

// '#' = grey (covered) in the picture.
const std::vector<std::string> kDiagramGrey = {
    "#..#.#.#.#.#..#..", // 0
    "..........#......", // 1
    ".#..##....#......", // 2
    "..#...##.#.......", // 3
    ".#.#.#...#.......", // 4
    "#....#...#..#..#.", // 5
    ".............#...", // 6
    "..##..#...##.....", // 7
    ".#..#..#.....#...", // 8
    "..#.....#.#......", // 9
    ".#..#..#...#.....", // 10
    "..#..#..#..#.#.#.", // 11
    "...#....#.#..#.#.", // 12
    "..#...#.....#.#..", // 13
    ".#.#.#..###.#..#.", // 14
    "...#.........#...", // 15
};

struct DiagramLine {
  const char* what;
  std::vector<Px> vertices;    // two for an independent line, more for a strip
  std::vector<Pixel> expected; // in the order the line travels
};

const std::vector<DiagramLine>& diagram_lines() {
  static const std::vector<DiagramLine> lines = {
      {"row 0: centre to the right, down", {{0.5, 0.5}, {1.5, 0.75}}, {{0, 0}}},
      {"row 0: steep from above the target", {{3.75, -0.125}, {3.875, 1.125}}, {{3, 0}}},
      {"row 0: y-major from a right corner", {{6.0, 0.5}, {6.125, 0.875}}, {{5, 0}}},
      {"row 0: x-major from a bottom corner", {{7.5, 1.0}, {7.875, 0.875}}, {{7, 0}}},
      {"row 0: vertical from a lower-left edge", {{9.25, 0.75}, {9.25, 1.25}}, {{9, 0}}},
      {"row 0: vertical from a lower-right edge", {{11.75, 0.75}, {11.75, 1.25}}, {{11, 0}}},
      {"row 0: 45 degrees along an upper-left edge", {{13.125, 0.375}, {13.375, 0.125}}, {}},
      {"row 0: short horizontal through a diamond", {{14.25, 0.125}, {14.75, 0.125}}, {{14, 0}}},
      {"row 0: 45 degrees along an upper-right edge", {{15.625, 0.125}, {15.875, 0.375}}, {}},
      {"row 1: zero length", {{12.25, 1.375}, {12.25, 1.375}}, {}},
      {"row 1: along a lower-left edge, ending in it", {{13.375, 1.875}, {13.125, 1.625}}, {}},
      {"row 1: along a lower-right edge, ending in it", {{15.875, 1.625}, {15.625, 1.875}}, {}},
      {"row 2: up-left to a centre row", {{1.5, 2.75}, {0.5, 2.5}}, {{1, 2}}},
      {"rows 3-5: strip up and down 45 degrees, along lower edges",
       {{0.5, 6.0}, {2.5, 4.0}, {4.5, 6.0}},
       {{0, 5}, {1, 4}, {2, 3}, {3, 4}}},
      {"rows 4-6: vertical strip through right corners (y-major)",
       {{6.0, 4.5}, {6.0, 5.5}, {6.0, 6.5}},
       {{5, 4}, {5, 5}}},
      {"rows 7-9: strip up and down from left corners",
       {{1.0, 9.5}, {3.0, 7.5}, {5.0, 9.5}},
       {{1, 8}, {2, 7}, {3, 7}, {4, 8}}},
      {"rows 9-11: 45 degrees up along lower-right edges",
       {{1.0, 11.5}, {3.0, 9.5}},
       {{1, 10}, {2, 9}}},
      {"rows 10-12: 45 degrees down along lower-left edges",
       {{4.0, 10.5}, {6.0, 12.5}},
       {{4, 10}, {5, 11}}},
      {"rows 7-11: strip down-right then down-left from a bottom corner",
       {{6.5, 8.0}, {8.5, 10.0}, {6.5, 12.0}},
       {{6, 7}, {7, 8}, {8, 9}, {7, 10}}},
      {"row 11: horizontal between left and right corners", {{9.0, 11.5}, {8.0, 11.5}}, {{8, 11}}},
      {"row 12: horizontal between left and right corners", {{8.0, 12.5}, {9.0, 12.5}}, {{8, 12}}},
      {"rows 11-13: 45 degrees from a bottom corner to a bottom corner",
       {{2.5, 12.0}, {4.5, 14.0}},
       {{2, 11}, {3, 12}}},
      {"rows 13-15: 45 degrees from a right corner",
       {{7.0, 13.5}, {5.0, 15.5}},
       {{6, 13}, {5, 14}}},
      {"rows 13-15: 45 degrees down-left to a bottom corner",
       {{2.5, 14.0}, {0.5, 16.0}},
       {{2, 13}, {1, 14}}},
      {"rows 14-15: strip up from the bottom edge, then up a lower-right edge",
       {{3.5, 16.0}, {3.5, 15.0}, {4.0, 14.5}},
       {{3, 15}, {3, 14}}},
      {"rows 2-3: through a bottom corner, ending on one",
       {{4.0, 2.5}, {8.5, 4.0}},
       {{4, 2}, {5, 2}, {6, 3}, {7, 3}}},
      {"rows 1-6: y-major through a right corner",
       {{10.5, 2.0}, {9.0, 6.5}},
       {{10, 1}, {10, 2}, {9, 3}, {9, 4}, {9, 5}}},
      {"rows 2-3: 45 degrees from an upper-left edge, away", {{14.25, 3.25}, {13.875, 2.875}}, {}},
      {"row 3: from an upper-right edge to an upper-left edge",
       {{14.625, 3.125}, {15.125, 3.375}},
       {}},
      {"row 2: short horizontal between diamonds", {{15.25, 2.875}, {14.875, 2.875}}, {}},
      {"rows 2-3: short vertical between diamonds", {{15.875, 3.125}, {15.875, 2.875}}, {}},
      {"row 4: along a lower-left edge to the bottom corner", {{14.0, 4.5}, {14.5, 5.0}}, {}},
      {"row 5: along a lower-right edge to the right corner",
       {{12.5, 6.0}, {13.0, 5.5}},
       {{12, 5}}},
      {"row 6: vertical from bottom corner to top corner", {{13.5, 7.0}, {13.5, 6.0}}, {{13, 6}}},
      {"rows 5-6: down-left from a bottom corner", {{15.5, 6.0}, {15.0, 6.5}}, {{15, 5}}},
      {"row 7: strip along bottom corners",
       {{11.5, 8.0}, {10.5, 8.0}, {9.5, 8.0}},
       {{11, 7}, {10, 7}}},
      {"rows 7-8: along an upper-left edge to a bottom corner", {{15.0, 8.5}, {15.5, 8.0}}, {}},
      {"rows 8-9: along an upper-right edge", {{13.0, 9.5}, {12.5, 9.0}}, {}},
      {"rows 8-9: vertical from a bottom corner to a bottom corner",
       {{13.5, 9.0}, {13.5, 10.0}},
       {{13, 8}}},
      {"rows 9-13: strip of two 45-degree lines along lower edges",
       {{10.0, 9.5}, {12.0, 11.5}, {10.0, 13.5}},
       {{10, 9}, {11, 10}, {11, 11}, {10, 12}}},
      {"rows 10-13: y-major down-left",
       {{14.125, 10.75}, {12.25, 13.875}},
       {{13, 11}, {13, 12}, {12, 13}}},
      {"rows 10-14: y-major ending on a right corner",
       {{16.125, 10.75}, {14.0, 14.5}},
       {{15, 11}, {15, 12}, {14, 13}}},
      {"rows 14-15: y-major ending inside a diamond",
       {{15.875, 14.125}, {15.125, 15.5}},
       {{15, 14}}},
      {"rows 14-15: strip along a centre row, then down a lower-left edge",
       {{8.0, 14.5}, {10.0, 14.5}, {11.0, 15.5}},
       {{8, 14}, {9, 14}, {10, 14}}},
      {"rows 14-15: strip from the bottom edge",
       {{13.5, 16.0}, {12.5, 15.0}, {12.0, 15.0}},
       {{13, 15}, {12, 14}}},
  };
  return lines;
}

std::vector<Pixel> draw(const DiagramLine& l) {
  std::vector<Vec2> vs;
  for (const Px& p : l.vertices)
    vs.push_back(sample_px(p.x, p.y));
  std::vector<Pixel> out;
  rasterize_aliased_line_strip(vs, LineMode::kD3DDiamond, kW, kH,
                               [&](std::int32_t x, std::int32_t y) {
                                 out.push_back({x, y});
                               });
  return out;
}

// rule: LINE.D3D.EXIT, LINE.D3D.TEST_AREA, LINE.MAJOR.AXIS, LINE.STRIP.SEQUENCE, LINE.ZERO_LENGTH
TEST(LineRastDiagram, EveryTranscribedLineCoversItsGreyPixels) {
  for (const DiagramLine& l : diagram_lines()) {
    SCOPED_TRACE(l.what);
    EXPECT_EQ(draw(l), l.expected);
  }
}

// rule: LINE.D3D.EXIT
TEST(LineRastDiagram, ExpectationsAreGreyInThePicture) {
  // Guards the transcription: each expected pixel is grey in the picture's map, and the grey
  // cells next to the transcribed lines are all claimed by exactly one of them.
  std::vector<std::string> claimed(kDiagramGrey.size(), std::string(kW, '.'));
  for (const DiagramLine& l : diagram_lines()) {
    for (const Pixel& p : l.expected) {
      ASSERT_EQ(kDiagramGrey[static_cast<std::size_t>(p.y)][static_cast<std::size_t>(p.x)], '#')
          << l.what << " " << p;
      EXPECT_EQ(claimed[static_cast<std::size_t>(p.y)][static_cast<std::size_t>(p.x)], '.') << p;
      claimed[static_cast<std::size_t>(p.y)][static_cast<std::size_t>(p.x)] = '#';
    }
  }
  // Every grey cell of the picture is claimed.
  for (std::size_t y = 0; y < kDiagramGrey.size(); ++y) {
    EXPECT_EQ(kDiagramGrey[y], claimed[y]) << "row " << y;
  }
}

} // namespace
} // namespace rastrules::test
