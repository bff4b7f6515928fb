// SPDX-License-Identifier: MIT
// Behaviour that scripts/coverage found no other test exercising: prepare()'s own vertex-count
// checks (the scene reader rejects such scenes first), the kernel's names for line modes,
// diamond features and snap statuses, and the cases where a rasterizer draws nothing (a
// triangle wholly outside the target, an empty target, a quadrilateral mode handed to the
// aliased-line rasterizer).

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "rastrules/line.hpp"
#include "rastrules/line_aliased.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/scene.hpp"
#include "rastrules/snap.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules {
namespace {

Vec2 px(std::int32_t x, std::int32_t y) {
  return Vec2{Subpixel::from_int(x), Subpixel::from_int(y)};
}

std::string prepare_error(PrimitiveType type, std::size_t vertices) {
  Scene s;
  s.width = 8;
  s.height = 8;
  Primitive p;
  p.type = type;
  p.v.assign(vertices, FloatPoint{1.0f, 1.0f});
  s.primitives.push_back(p);
  const auto r = prepare(s);
  if (!std::holds_alternative<SceneError>(r))
    return "accepted";
  return std::get<SceneError>(r).what();
}

// rule: SCENE.PRIM.POINT, SCENE.PRIM.LINE, SCENE.PRIM.LINE_STRIP
TEST(CoverageGaps, PrepareChecksVertexCountsOnItsOwn) {
  EXPECT_EQ(prepare_error(PrimitiveType::kTriangle, 4),
            "primitives[0].v: a triangle must have exactly 3 vertices [x, y], got 4");
  EXPECT_EQ(prepare_error(PrimitiveType::kPoint, 2),
            "primitives[0].v: a point must have exactly 1 vertex [x, y], got 2");
  EXPECT_EQ(prepare_error(PrimitiveType::kLine, 3),
            "primitives[0].v: a line must have exactly 2 vertices [x, y], got 3");
  EXPECT_EQ(prepare_error(PrimitiveType::kLineStrip, 1),
            "primitives[0].v: a line_strip must have at least 2 vertices [x, y], got 1");
  EXPECT_EQ(prepare_error(PrimitiveType::kLineStrip, 0),
            "primitives[0].v: a line_strip must have at least 2 vertices [x, y], got 0");
  // The counts each type needs are accepted.
  EXPECT_EQ(prepare_error(PrimitiveType::kTriangle, 3), "accepted");
  EXPECT_EQ(prepare_error(PrimitiveType::kPoint, 1), "accepted");
  EXPECT_EQ(prepare_error(PrimitiveType::kLine, 2), "accepted");
  EXPECT_EQ(prepare_error(PrimitiveType::kLineStrip, 5), "accepted");
}

// rule: SCENE.LINE_MODE
TEST(CoverageGaps, LineModeNames) {
  EXPECT_EQ(to_string(LineMode::kD3DDiamond), "d3d");
  EXPECT_EQ(to_string(LineMode::kVulkanBresenham), "vulkan-bresenham");
  EXPECT_EQ(to_string(LineMode::kQuadWide), "quad-wide");
  EXPECT_EQ(to_string(LineMode::kQuadNarrow), "quad-narrow");
}

// rule: LINE.DIAMOND.GEOMETRY
TEST(CoverageGaps, DiamondFeatureNamesOneBitEachAndNoneForSeveral) {
  EXPECT_EQ(to_string(kFeatureInterior), "interior");
  EXPECT_EQ(to_string(kFeatureEdgeLowerRight), "lower-right edge");
  EXPECT_EQ(to_string(kFeatureEdgeLowerLeft), "lower-left edge");
  EXPECT_EQ(to_string(kFeatureEdgeUpperRight), "upper-right edge");
  EXPECT_EQ(to_string(kFeatureEdgeUpperLeft), "upper-left edge");
  EXPECT_EQ(to_string(kFeatureCornerBottom), "bottom corner");
  EXPECT_EQ(to_string(kFeatureCornerRight), "right corner");
  EXPECT_EQ(to_string(kFeatureCornerTop), "top corner");
  EXPECT_EQ(to_string(kFeatureCornerLeft), "left corner");
  EXPECT_EQ(to_string(static_cast<DiamondFeature>(0)), "");
  EXPECT_EQ(to_string(static_cast<DiamondFeature>(kFeatureCornerTop | kFeatureEdgeUpperLeft)), "");
}

// rule: SNAP.VERTEX.INVALID
TEST(CoverageGaps, SnapStatusNames) {
  EXPECT_EQ(to_string(SnapStatus::kOk), "ok");
  EXPECT_EQ(to_string(SnapStatus::kNaN), "NaN");
  EXPECT_EQ(to_string(SnapStatus::kInfinite), "infinite");
  EXPECT_EQ(to_string(snap_to_subpixel(1.0f).status), "ok");
}

// rule: RASTER.TARGET.CLIP
TEST(CoverageGaps, TriangleWhollyOutsideTheTargetVisitsNoPixel) {
  // Clockwise on screen (y down) and well formed, but right of and below an 8x8 target.
  for (const auto& v : {std::array<Vec2, 3>{px(20, 2), px(30, 2), px(20, 6)},
                        std::array<Vec2, 3>{px(2, 20), px(6, 20), px(2, 30)},
                        std::array<Vec2, 3>{px(-30, -30), px(-20, -30), px(-30, -20)}}) {
    const TriangleSetup t = setup_triangle(v, RasterState{});
    ASSERT_EQ(t.status, TriangleStatus::kRasterized);
    int visited = 0;
    raster::walk_triangle(t, 8, 8, [&](std::int32_t, std::int32_t) { ++visited; });
    EXPECT_EQ(visited, 0);
    // The same triangle on a target large enough to hold it is drawn.
    const TriangleSetup big =
        setup_triangle({Vec2{v[0].x + Subpixel::from_int(40), v[0].y + Subpixel::from_int(40)},
                        Vec2{v[1].x + Subpixel::from_int(40), v[1].y + Subpixel::from_int(40)},
                        Vec2{v[2].x + Subpixel::from_int(40), v[2].y + Subpixel::from_int(40)}},
                       RasterState{});
    raster::walk_triangle(big, 128, 128, [&](std::int32_t, std::int32_t) { ++visited; });
    EXPECT_GT(visited, 0);
  }
}

// rule: LINE.TARGET.CLIP
TEST(CoverageGaps, LinesOnAnEmptyTargetDrawNothing) {
  int n = 0;
  const PixelEmit count = [&](std::int32_t, std::int32_t) { ++n; };
  const AAEmit count_aa = [&](std::int32_t, std::int32_t, std::uint32_t) { ++n; };
  for (const auto& wh : {std::array<std::int32_t, 2>{0, 8}, std::array<std::int32_t, 2>{8, 0}}) {
    rasterize_aliased_line(px(1, 1), px(6, 3), LineMode::kD3DDiamond, wh[0], wh[1], count);
    rasterize_aliased_line(px(1, 1), px(6, 3), LineMode::kVulkanBresenham, wh[0], wh[1], count);
    rasterize_aa_line(px(1, 1), px(6, 3), wh[0], wh[1], count_aa);
  }
  EXPECT_EQ(n, 0);
  // The same lines on an 8x8 target are drawn.
  rasterize_aliased_line(px(1, 1), px(6, 3), LineMode::kD3DDiamond, 8, 8, count);
  const int aliased = n;
  EXPECT_GT(aliased, 0);
  rasterize_aa_line(px(1, 1), px(6, 3), 8, 8, count_aa);
  EXPECT_GT(n, aliased);
}

// rule: LINE.QUAD.SHAPE
TEST(CoverageGaps, AliasedRasterizerDrawsNothingInAQuadrilateralMode) {
  // Quadrilateral lines are triangles (quad_line_triangles); the aliased rasterizer takes
  // only the two aliased modes and draws nothing for the others.
  int n = 0;
  const PixelEmit count = [&](std::int32_t, std::int32_t) { ++n; };
  rasterize_aliased_line(px(1, 1), px(6, 3), LineMode::kQuadWide, 8, 8, count);
  rasterize_aliased_line(px(1, 1), px(6, 3), LineMode::kQuadNarrow, 8, 8, count);
  EXPECT_EQ(n, 0);
  EXPECT_EQ(quad_line_triangles(px(1, 1), px(6, 3), LineMode::kQuadWide).size(), 2u);
}

// rule: LINE.VK.TEST_AREA
TEST(CoverageGaps, VulkanExplainsATouchAtACornerThatThePerturbationMisses) {
  // A horizontal line along y = 1 touches the closed diamond of pixel (3, 1) only at its top
  // corner (3.5, 1). Vulkan's endpoint perturbation (-e, -e^2) moves the line up, off that
  // corner and into the open diamond of pixel (3, 0) above it.
  const LineDiamondDecision below =
      explain_aliased_line_pixel(px(0, 1), px(8, 1), LineMode::kVulkanBresenham, 3, 1);
  EXPECT_EQ(below.met_features, std::uint32_t{kFeatureCornerTop});
  EXPECT_FALSE(below.entered);
  EXPECT_FALSE(below.covered);
  EXPECT_EQ(below.reason, "the perturbed segment misses the open diamond (LINE.VK.TEST_AREA)");
  EXPECT_FALSE(aliased_line_covers(px(0, 1), px(8, 1), LineMode::kVulkanBresenham, 3, 1));
  const LineDiamondDecision above =
      explain_aliased_line_pixel(px(0, 1), px(8, 1), LineMode::kVulkanBresenham, 3, 0);
  EXPECT_TRUE(above.covered);
  EXPECT_TRUE(aliased_line_covers(px(0, 1), px(8, 1), LineMode::kVulkanBresenham, 3, 0));
}

} // namespace
} // namespace rastrules
