// SPDX-License-Identifier: MIT
// The D3D11.3 triangle rasterization diagram (shared/reference/img/TriRast.png, "Triangle
// Rasterization Example (Single Sample Per Pixel)"), reproduced triangle by triangle.
//
// Reading the picture: the grid is 16 x 8 pixels, pixel centres (crosses) at .5. Every vertex
// below was read at 1/4 px precision and checked against the picture's pixels: sampling the
// PNG along each edge of each triangle as read gives the darkest path, and moving any vertex
// coordinate by 1/8 px gives a lighter one (a worse fit). All vertices turned out to lie on
// pixel corners, pixel centres or quarter points. The picture shades neighbouring triangles
// light and dark grey only to tell them apart; both mean "covered".
//
// One triangle needs a remark: O's lowest vertex lies below the target, at the bottom border
// of the picture; it reads as (9.5, 9.5) but its exact y is cut off. Its in-target coverage
// (one pixel, decided by a top-left vertex) does not depend on that y.
//
// Every covered pixel of the picture is covered by exactly one triangle, and the kernel
// reproduces the picture exactly.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string_view>
#include <variant>
#include <vector>

#include "rastrules/scene.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

struct DiagramTriangle {
  char name;              // the letter used in kExpected below
  std::array<Px, 3> v;    // as read from the picture, in pixels
  std::string_view where; // how to find it in the picture
};

// clang-format off
constexpr DiagramTriangle kDiagram[] = {
    {'A', {{{5.25, 1.25}, {6.25, 0.25}, {6.25, 1.25}}}, "small right triangle, top middle; no centre inside"},
    {'B', {{{6.5, 1.5}, {7.5, 0.5}, {7.5, 1.5}}}, "small right triangle with vertices on three centres; none covered"},
    {'C', {{{1, 1}, {6, 2}, {2, 4}}}, "large triangle, top left"},
    {'D', {{{9.75, 0.75}, {11.75, 2.5}, {7.75, 2.5}}}, "upper half of the diamond (dark)"},
    {'E', {{{7.75, 2.5}, {11.75, 2.5}, {9.5, 5.25}}}, "lower half of the diamond; owns the shared horizontal edge"},
    {'F', {{{15, 0}, {14.5, 2.5}, {13.5, 1.5}}}, "upper thin triangle, top right; (13,1) on two left edges"},
    {'G', {{{13.5, 1.5}, {14.5, 2.5}, {14.5, 4.5}}}, "lower thin triangle, top right; covers nothing"},
    {'H', {{{1, 6}, {7, 4}, {5, 6}}}, "long sliver of the fan, bottom left (dark)"},
    {'I', {{{7, 4}, {8, 7}, {5, 6}}}, "middle triangle of the fan (light)"},
    {'J', {{{7, 4}, {9.5, 5.5}, {8, 7}}}, "right triangle of the fan (dark)"},
    {'K', {{{11.5, 4.5}, {12.5, 5.5}, {11.5, 6.5}}}, "small arrow pointing right; vertices on centres (dark)"},
    {'M', {{{13.5, 5.5}, {15.5, 5.5}, {13.5, 7.5}}}, "upper-left half of the square, bottom right (light)"},
    {'N', {{{15.5, 5.5}, {15.5, 7.5}, {13.5, 7.5}}}, "lower-right half of the square (dark)"},
    {'O', {{{9.5, 7.5}, {10.5, 7.5}, {9.5, 9.5}}}, "triangle leaving the target at the bottom"},
};

// The covered pixels of the picture, one letter per covering triangle ('.' = not covered).
const std::initializer_list<std::string_view> kExpected = {
    //0123456789012345
    "..............F.",  // 0
    ".CC......DD..FF.",  // 1
    ".CCCC...EEEE....",  // 2
    "..C.....EEE.....",  // 3
    ".....HIJ.E......",  // 4
    "..HHHIIJJ..K.MM.",  // 5
    "......II.....MN.",  // 6
    ".........O......",  // 7
};
// clang-format on

constexpr std::int32_t kWidth = 16;
constexpr std::int32_t kHeight = 8;

Scene diagram_scene(bool reversed) {
  Scene s;
  s.width = kWidth;
  s.height = kHeight;
  for (const DiagramTriangle& t : kDiagram) {
    Primitive p;
    for (std::size_t i = 0; i < 3; ++i) {
      const Px v = t.v[reversed ? 2 - i : i];
      p.v[i] = {static_cast<float>(v.x), static_cast<float>(v.y)};
    }
    s.primitives.push_back(p);
  }
  return s;
}

// rule: TRI.COVER.SAMPLE, TRI.FILL.TOP_LEFT
TEST(TriCoverSampleDiagram, EachTriangleCoversExactlyThePixelsShaded) {
  const auto result = render(diagram_scene(false));
  ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(result));
  const auto& fragments = std::get<std::vector<Fragment>>(result);
  for (std::uint32_t prim = 0; prim < std::size(kDiagram); ++prim) {
    const DiagramTriangle& t = kDiagram[prim];
    const auto expected = pixels_in_picture(kExpected, t.name);
    const auto got = pixels_of(fragments, prim);
    EXPECT_EQ(got, expected) << "triangle " << t.name << " (" << t.where
                             << ")\nexpected:" << picture(expected, kWidth, kHeight)
                             << "\ngot:" << picture(got, kWidth, kHeight);
  }
}

// rule: TRI.COVER.SAMPLE, TRI.ORIENT.NORMALISE
TEST(TriCoverSampleDiagram, ReversedVertexOrderCoversTheSamePixels) {
  const auto forward = render(diagram_scene(false));
  const auto reversed = render(diagram_scene(true));
  ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(forward));
  ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(reversed));
  EXPECT_EQ(std::get<std::vector<Fragment>>(forward), std::get<std::vector<Fragment>>(reversed));
}

// rule: TRI.COVER.SAMPLE
TEST(TriCoverSampleDiagram, NoPixelIsCoveredTwiceAndTheCountMatchesThePicture) {
  const auto result = render(diagram_scene(false));
  ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(result));
  std::vector<Pixel> all;
  for (const Fragment& f : std::get<std::vector<Fragment>>(result))
    all.push_back({f.x, f.y});
  std::sort(all.begin(), all.end());
  EXPECT_EQ(std::adjacent_find(all.begin(), all.end()), all.end());
  // 1 + 6 + 8 + 4 + 4 + 10 + 4 + 1 letters in kExpected.
  EXPECT_EQ(all.size(), 38u);
}

// The tie-breaks the picture illustrates, one sample each (hand-checked on the grid).
// rule: TRI.FILL.TOP_LEFT, TRI.FILL.TOP_EDGE, TRI.FILL.LEFT_EDGE
TEST(TriCoverSampleDiagram, TheDiagramsTieBreaksOneByOne) {
  const auto tri = [](char name) {
    for (const DiagramTriangle& t : kDiagram) {
      if (t.name == name)
        return triangle_px(t.v[0], t.v[1], t.v[2]);
    }
    throw std::logic_error("no such triangle");
  };
  // Diamond: centres on the shared horizontal edge y = 2.5 go to E (top edge), not D (bottom).
  EXPECT_FALSE(covers(tri('D'), sample_px(9.5, 2.5)));
  EXPECT_TRUE(covers(tri('E'), sample_px(9.5, 2.5)));
  // F: (13.5, 1.5) is a vertex joining two left edges: covered.
  EXPECT_TRUE(covers(tri('F'), sample_px(13.5, 1.5)));
  // F: (14.5, 0.5) lies on F's left edge x + y = 15: covered.
  EXPECT_TRUE(covers(tri('F'), sample_px(14.5, 0.5)));
  // G: (14.5, 3.5) lies on G's vertical right edge: not covered.
  EXPECT_FALSE(covers(tri('G'), sample_px(14.5, 3.5)));
  // K: (11.5, 5.5) on the vertical left edge: covered; its vertices (left + right edges): not.
  EXPECT_TRUE(covers(tri('K'), sample_px(11.5, 5.5)));
  EXPECT_FALSE(covers(tri('K'), sample_px(11.5, 4.5)));
  EXPECT_FALSE(covers(tri('K'), sample_px(11.5, 6.5)));
  EXPECT_FALSE(covers(tri('K'), sample_px(12.5, 5.5)));
  // Square: (13.5, 5.5) is a top + left vertex of M: covered; the diagonal belongs to N.
  EXPECT_TRUE(covers(tri('M'), sample_px(13.5, 5.5)));
  EXPECT_FALSE(covers(tri('M'), sample_px(14.5, 6.5)));
  EXPECT_TRUE(covers(tri('N'), sample_px(14.5, 6.5)));
  // Fan: (5.5, 5.5) on the edge shared by H (right edge there) and I (left edge there).
  EXPECT_FALSE(covers(tri('H'), sample_px(5.5, 5.5)));
  EXPECT_TRUE(covers(tri('I'), sample_px(5.5, 5.5)));
  // Fan: (6.5, 6.5) on I's lower edge (5,6)-(8,7), which is a *left* edge: the interior lies
  // on its +x side, even though the edge is nearly horizontal and below the interior.
  EXPECT_TRUE(covers(tri('I'), sample_px(6.5, 6.5)));
  // Fan: (7.5, 5.5) on the edge (7,4)-(8,7) shared by I (right) and J (left).
  EXPECT_FALSE(covers(tri('I'), sample_px(7.5, 5.5)));
  EXPECT_TRUE(covers(tri('J'), sample_px(7.5, 5.5)));
}

} // namespace
} // namespace rastrules::test
