// SPDX-License-Identifier: MIT
// The fill convention as a parameter (TRI.FILL.CONVENTION): the same edge and vertex cases
// under top-left, top-right, bottom-left and bottom-right, and shared edges under each.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <ostream>
#include <string>
#include <vector>

#include "fill_convention_cases.hpp"
#include "rastrules/triangle.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

class TriFillConvention : public ::testing::TestWithParam<ConventionCase> {};

// rule: TRI.FILL.CONVENTION, TRI.FILL.TOP_LEFT
TEST_P(TriFillConvention, SampleOnTheBoundaryFollowsTheConvention) {
  const ConventionCase& c = GetParam();
  const bool expected[] = {c.top_left, c.top_right, c.bottom_left, c.bottom_right};
  for (std::size_t k = 0; k < 4; ++k) {
    RasterState state;
    state.fill = kAllConventions[k];
    const TriangleSetup t = triangle_px(c.tri[0], c.tri[1], c.tri[2], state);
    ASSERT_EQ(t.status, TriangleStatus::kRasterized);
    EXPECT_EQ(covers(t, sample_px(c.sample.x, c.sample.y)), expected[k])
        << "fill " << to_string(state.fill);
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, TriFillConvention, ::testing::ValuesIn(kConventionCases),
                         [](const ::testing::TestParamInfo<ConventionCase>& param_info) {
                           return std::string(param_info.param.name);
                         });

// Two triangles on opposite sides of a shared edge a-b.
struct SharedEdgePair {
  const char* name;
  Px a, b, first_apex, second_apex;
  // Which triangle owns the centres on the shared edge under TL, TR, BL, BR (0 = first).
  std::array<int, 4> owner;
};

// clang-format off
const SharedEdgePair kPairs[] = {
  // Horizontal edge y = 2.5; "first" is above it, "second" below.
  {"Horizontal", {0.5, 2.5}, {6.5, 2.5}, {3.5, 0.5}, {3.5, 4.5}, {1, 1, 0, 0}},
  // Vertical edge x = 2.5; "first" is left of it, "second" right.
  {"Vertical", {2.5, 0.5}, {2.5, 6.5}, {0.5, 3.5}, {4.5, 3.5}, {1, 0, 1, 0}},
  // Diagonal y = x; "first" is above-right, "second" below-left.
  {"Diagonal", {0.5, 0.5}, {4.5, 4.5}, {4.5, 0.5}, {0.5, 4.5}, {0, 1, 0, 1}},
  // Anti-diagonal x + y = 5; "first" is above-left, "second" below-right.
  {"AntiDiagonal", {4.5, 0.5}, {0.5, 4.5}, {0.5, 0.5}, {4.5, 4.5}, {1, 0, 1, 0}},
  // Shallow edge (0,1)-(8,3): no pixel centre on it, checked on the 1/256 grid below.
  {"Shallow", {0, 1}, {8, 3}, {0, 0}, {8, 4}, {-1, -1, -1, -1}},
};
// clang-format on

// Returns every 16.8 grid point strictly between a and b on the segment a-b.
std::vector<Vec2> grid_points_on_open_segment(Vec2 a, Vec2 b) {
  const std::int32_t dx = b.x.raw() - a.x.raw();
  const std::int32_t dy = b.y.raw() - a.y.raw();
  const std::int32_t g = std::gcd(dx, dy);
  std::vector<Vec2> out;
  for (std::int32_t k = 1; k < g; ++k) {
    out.push_back(Vec2{Subpixel::from_raw(a.x.raw() + dx / g * k),
                       Subpixel::from_raw(a.y.raw() + dy / g * k)});
  }
  return out;
}

// rule: TRI.FILL.CONVENTION, TRI.SHARED_EDGE.EXACTLY_ONCE
TEST(TriFillConventionSharedEdge, EveryGridPointOnASharedEdgeIsCoveredExactlyOnce) {
  for (const SharedEdgePair& p : kPairs) {
    for (std::size_t k = 0; k < 4; ++k) {
      RasterState state;
      state.fill = kAllConventions[k];
      // Both windings of each triangle: the owner must not depend on vertex order.
      for (const bool flip : {false, true}) {
        const TriangleSetup first = flip ? triangle_px(p.b, p.a, p.first_apex, state)
                                         : triangle_px(p.a, p.b, p.first_apex, state);
        const TriangleSetup second = flip ? triangle_px(p.a, p.b, p.second_apex, state)
                                          : triangle_px(p.b, p.a, p.second_apex, state);
        const auto points = grid_points_on_open_segment(first.snapped[0], first.snapped[1]);
        ASSERT_FALSE(points.empty());
        for (const Vec2 s : points) {
          const bool in_first = covers(first, s);
          const bool in_second = covers(second, s);
          ASSERT_NE(in_first, in_second)
              << p.name << " fill " << to_string(state.fill) << " sample raw (" << s.x.raw() << ", "
              << s.y.raw() << ")";
          if (p.owner[k] >= 0) {
            EXPECT_EQ(in_second, p.owner[k] == 1) << p.name << " fill " << to_string(state.fill);
          }
        }
      }
    }
  }
}

// rule: TRI.FILL.CONVENTION
TEST(TriFillConventionMirror, MirroringInXTurnsTopLeftIntoTopRight) {
  // The large triangle of the D3D diagram, (1,1) (6,2) (2,4), and its mirror image in the
  // vertical line x = 8 on a 16-pixel-wide target: x -> 16 - x maps pixel i to 15 - i.
  RasterState top_right;
  top_right.fill = FillConvention::kTopRight;
  RasterState bottom_left;
  bottom_left.fill = FillConvention::kBottomLeft;
  RasterState bottom_right;
  bottom_right.fill = FillConvention::kBottomRight;
  // Edges through pixel centres make the convention matter: (0.5,0.5) (6.5,0.5) (0.5,6.5)
  // has a top edge, a left edge and a right edge through centres.
  const Px a{0.5, 0.5}, b{6.5, 0.5}, c{0.5, 6.5};
  const auto mirror_x = [](Px p) { return Px{16 - p.x, p.y}; };
  const auto mirror_y = [](Px p) { return Px{p.x, 8 - p.y}; };
  const auto tl = centre_pixels(triangle_px(a, b, c), 16, 8);
  const auto tr =
      centre_pixels(triangle_px(mirror_x(a), mirror_x(b), mirror_x(c), top_right), 16, 8);
  const auto bl =
      centre_pixels(triangle_px(mirror_y(a), mirror_y(b), mirror_y(c), bottom_left), 16, 8);
  const auto br = centre_pixels(triangle_px(mirror_x(mirror_y(a)), mirror_x(mirror_y(b)),
                                            mirror_x(mirror_y(c)), bottom_right),
                                16, 8);
  EXPECT_EQ(tl, pixels_in_picture({
                    "######..........",
                    "#####...........",
                    "####............",
                    "###.............",
                    "##..............",
                    "#...............",
                    "................",
                    "................",
                }));
  const auto map = [](std::vector<Pixel> v, bool mx, bool my) {
    for (Pixel& p : v) {
      if (mx)
        p.x = 15 - p.x;
      if (my)
        p.y = 7 - p.y;
    }
    std::sort(v.begin(), v.end());
    return v;
  };
  EXPECT_EQ(map(tr, true, false), tl);
  EXPECT_EQ(map(bl, false, true), tl);
  EXPECT_EQ(map(br, true, true), tl);
  // And the mirror image under the wrong convention differs (the ties go the other way).
  const auto tr_as_tl = centre_pixels(triangle_px(mirror_x(a), mirror_x(b), mirror_x(c)), 16, 8);
  EXPECT_NE(map(tr_as_tl, true, false), tl);
}

} // namespace
} // namespace rastrules::test
