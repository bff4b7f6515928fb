// SPDX-License-Identifier: MIT
// Culling (cull mode x front face x winding), zero-area triangles, needles and slivers.

#include <gtest/gtest.h>

#include <ostream>
#include <stdexcept>
#include <string>

#include "rastrules/scene.hpp"
#include "rastrules/triangle.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

enum class Winding { kClockwise, kCounterClockwise, kZeroArea };

TriangleSetup triangle_with(Winding w, const RasterState& state) {
  switch (w) {
  case Winding::kClockwise:
    return triangle_px({0.5, 0.5}, {4.5, 0.5}, {0.5, 4.5}, state);
  case Winding::kCounterClockwise:
    return triangle_px({0.5, 0.5}, {0.5, 4.5}, {4.5, 0.5}, state);
  case Winding::kZeroArea:
    return triangle_px({0.5, 0.5}, {2.5, 2.5}, {4.5, 4.5}, state);
  }
  throw std::logic_error("winding");
}

struct CullCase {
  Winding winding;
  CullMode cull;
  FrontFace front;
  bool front_facing;
  TriangleStatus status;
};

// clang-format off
constexpr CullCase kCullCases[] = {
  // winding                     cull              front face                    front? status
  {Winding::kClockwise,        CullMode::kNone,  FrontFace::kClockwise,        true,  TriangleStatus::kRasterized},
  {Winding::kClockwise,        CullMode::kBack,  FrontFace::kClockwise,        true,  TriangleStatus::kRasterized},
  {Winding::kClockwise,        CullMode::kFront, FrontFace::kClockwise,        true,  TriangleStatus::kCulledFront},
  {Winding::kClockwise,        CullMode::kNone,  FrontFace::kCounterClockwise, false, TriangleStatus::kRasterized},
  {Winding::kClockwise,        CullMode::kBack,  FrontFace::kCounterClockwise, false, TriangleStatus::kCulledBack},
  {Winding::kClockwise,        CullMode::kFront, FrontFace::kCounterClockwise, false, TriangleStatus::kRasterized},
  {Winding::kCounterClockwise, CullMode::kNone,  FrontFace::kClockwise,        false, TriangleStatus::kRasterized},
  {Winding::kCounterClockwise, CullMode::kBack,  FrontFace::kClockwise,        false, TriangleStatus::kCulledBack},
  {Winding::kCounterClockwise, CullMode::kFront, FrontFace::kClockwise,        false, TriangleStatus::kRasterized},
  {Winding::kCounterClockwise, CullMode::kNone,  FrontFace::kCounterClockwise, true,  TriangleStatus::kRasterized},
  {Winding::kCounterClockwise, CullMode::kBack,  FrontFace::kCounterClockwise, true,  TriangleStatus::kRasterized},
  {Winding::kCounterClockwise, CullMode::kFront, FrontFace::kCounterClockwise, true,  TriangleStatus::kCulledFront},
  // Zero area: back-facing whatever the front face; never draws (status reports the cause).
  {Winding::kZeroArea,         CullMode::kNone,  FrontFace::kClockwise,        false, TriangleStatus::kDegenerate},
  {Winding::kZeroArea,         CullMode::kBack,  FrontFace::kClockwise,        false, TriangleStatus::kDegenerate},
  {Winding::kZeroArea,         CullMode::kFront, FrontFace::kClockwise,        false, TriangleStatus::kDegenerate},
  {Winding::kZeroArea,         CullMode::kNone,  FrontFace::kCounterClockwise, false, TriangleStatus::kDegenerate},
  {Winding::kZeroArea,         CullMode::kBack,  FrontFace::kCounterClockwise, false, TriangleStatus::kDegenerate},
  {Winding::kZeroArea,         CullMode::kFront, FrontFace::kCounterClockwise, false, TriangleStatus::kDegenerate},
};
// clang-format on

// Names the case in gtest output instead of dumping its bytes.
void PrintTo(const CullCase& c, std::ostream* os) {
  *os << "winding " << static_cast<int>(c.winding) << ", cull " << to_string(c.cull) << ", front "
      << to_string(c.front);
}

class TriCullMode : public ::testing::TestWithParam<CullCase> {};

// rule: TRI.CULL.MODE, TRI.DEGENERATE.ZERO_AREA
TEST_P(TriCullMode, FacingAndCullingFollowTheWindingAndTheState) {
  const CullCase& c = GetParam();
  RasterState state;
  state.cull = c.cull;
  state.front_face = c.front;
  const TriangleSetup t = triangle_with(c.winding, state);
  EXPECT_EQ(t.front_facing, c.front_facing);
  EXPECT_EQ(t.status, c.status) << to_string(t.status);
  // Drawn triangles cover the same 10 centres whatever the winding (4 + 3 + 2 + 1, the
  // diagonal x + y = 5 being a right edge); culled and degenerate ones cover none.
  const auto covered = walk_pixels(t, 8, 8);
  EXPECT_EQ(covered.size(), c.status == TriangleStatus::kRasterized ? 10u : 0u);
}

INSTANTIATE_TEST_SUITE_P(Table, TriCullMode, ::testing::ValuesIn(kCullCases),
                         [](const ::testing::TestParamInfo<CullCase>& param_info) {
                           const CullCase& c = param_info.param;
                           const char* w = c.winding == Winding::kClockwise          ? "Cw"
                                           : c.winding == Winding::kCounterClockwise ? "Ccw"
                                                                                     : "ZeroArea";
                           const char* cull = c.cull == CullMode::kNone   ? "None"
                                              : c.cull == CullMode::kBack ? "Back"
                                                                          : "Front";
                           const char* front =
                               c.front == FrontFace::kClockwise ? "FrontCw" : "FrontCcw";
                           return std::string(w) + "Cull" + cull + front;
                         });

// rule: TRI.CULL.MODE
TEST(TriCullMode, SceneWithBothWindingsKeepsOnlyTheChosenOnes) {
  // Two triangles side by side: prim 0 clockwise, prim 1 counter-clockwise.
  const auto scene = [](CullMode cull) {
    RasterState state;
    state.cull = cull;
    return scene_px(8, 4, state, {{{{0, 0}, {4, 0}, {0, 4}}}, {{{4, 0}, {4, 4}, {8, 0}}}});
  };
  const auto prims = [](const std::variant<std::vector<Fragment>, SceneError>& r) {
    std::vector<std::uint32_t> out;
    for (const Fragment& f : std::get<std::vector<Fragment>>(r)) {
      if (out.empty() || out.back() != f.prim)
        out.push_back(f.prim);
    }
    return out;
  };
  EXPECT_EQ(prims(render(scene(CullMode::kNone))), (std::vector<std::uint32_t>{0, 1}));
  EXPECT_EQ(prims(render(scene(CullMode::kBack))), (std::vector<std::uint32_t>{0}));
  EXPECT_EQ(prims(render(scene(CullMode::kFront))), (std::vector<std::uint32_t>{1}));
}

// rule: TRI.DEGENERATE.ZERO_AREA
TEST(TriDegenerateZeroArea, CollinearVerticesThroughPixelCentresCoverNothing) {
  // All three vertices on the row of centres y = 0.5, under every convention: an edge and its
  // reverse are never both inclusive, but the rule does not even get there.
  for (const FillConvention f : kAllConventions) {
    RasterState state;
    state.fill = f;
    const TriangleSetup t = triangle_px({0.5, 0.5}, {7.5, 0.5}, {3.5, 0.5}, state);
    EXPECT_EQ(t.status, TriangleStatus::kDegenerate);
    EXPECT_FALSE(t.front_facing);
    EXPECT_FALSE(covers(t, sample_px(2.5, 0.5)));
    EXPECT_TRUE(walk_pixels(t, 8, 8).empty());
  }
}

// rule: TRI.DEGENERATE.ZERO_AREA
TEST(TriDegenerateZeroArea, RepeatedVerticesCoverNothing) {
  EXPECT_EQ(triangle_px({1.5, 1.5}, {1.5, 1.5}, {5.5, 3.5}).status, TriangleStatus::kDegenerate);
  EXPECT_EQ(triangle_px({1.5, 1.5}, {5.5, 3.5}, {5.5, 3.5}).status, TriangleStatus::kDegenerate);
  EXPECT_EQ(triangle_px({2.5, 2.5}, {2.5, 2.5}, {2.5, 2.5}).status, TriangleStatus::kDegenerate);
  // A diagonal zero-area triangle through the centres (0.5,0.5), (1.5,1.5), ...
  const TriangleSetup d = triangle_px({0.5, 0.5}, {7.5, 7.5}, {3.5, 3.5});
  EXPECT_EQ(d.status, TriangleStatus::kDegenerate);
  EXPECT_TRUE(centre_pixels(d, 8, 8).empty());
}

// rule: TRI.COVER.SAMPLE, TRI.FILL.TOP_LEFT
TEST(TriNeedle, VerticalNeedleOnItsLeftEdgeCoversAColumnAndItsMirrorNothing) {
  // 1/256 px wide, 8 px tall. Left edge x = 2.5 through the centres of column 2.
  const TriangleSetup right_of_line = triangle_px({2.5, 0}, {2.50390625, 0}, {2.5, 8});
  EXPECT_EQ(walk_pixels(right_of_line, 8, 8),
            (std::vector<Pixel>{{2, 0}, {2, 1}, {2, 2}, {2, 3}, {2, 4}, {2, 5}, {2, 6}, {2, 7}}));
  // Its mirror image has x = 2.5 as a right edge.
  const TriangleSetup left_of_line = triangle_px({2.49609375, 0}, {2.5, 0}, {2.5, 8});
  EXPECT_TRUE(walk_pixels(left_of_line, 8, 8).empty());
}

// rule: TRI.COVER.SAMPLE, TRI.FILL.TOP_LEFT
TEST(TriNeedle, HorizontalSliverOnItsTopEdgeCoversARowAndItsMirrorNothing) {
  const TriangleSetup below_line = triangle_px({0, 2.5}, {8, 2.5}, {8, 2.50390625});
  EXPECT_EQ(walk_pixels(below_line, 8, 8), pixels_in_picture({
                                               "........",
                                               "........",
                                               "########",
                                           }));
  const TriangleSetup above_line = triangle_px({0, 2.5}, {8, 2.49609375}, {8, 2.5});
  EXPECT_TRUE(walk_pixels(above_line, 8, 8).empty());
}

// rule: TRI.COVER.SAMPLE, TRI.FILL.TOP_LEFT
TEST(TriNeedle, DiagonalNeedleCoversTheDiagonalOnlyOnItsLeftSide) {
  // Needle from (0,0) to (8,8), 1/256 px wide at the far end. On the +x side of the diagonal
  // the diagonal is a left edge: the 8 centres (k+0.5, k+0.5) are covered.
  EXPECT_EQ(walk_pixels(triangle_px({0, 0}, {8, 8}, {8.00390625, 8}), 8, 8),
            (std::vector<Pixel>{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}, {5, 5}, {6, 6}, {7, 7}}));
  EXPECT_TRUE(walk_pixels(triangle_px({0, 0}, {8, 8}, {7.99609375, 8}), 8, 8).empty());
}

// rule: TRI.COVER.SAMPLE
TEST(TriNeedle, LongNeedleBetweenRowsOfCentresCoversNothing) {
  // 16 px long, at most 1/8 px tall, between y = 0.25 and y = 0.375: no centre inside.
  EXPECT_TRUE(walk_pixels(triangle_px({0, 0.25}, {16, 0.25}, {16, 0.375}), 16, 4).empty());
  EXPECT_EQ(triangle_px({0, 0.25}, {16, 0.25}, {16, 0.375}).status, TriangleStatus::kRasterized);
}

} // namespace
} // namespace rastrules::test
