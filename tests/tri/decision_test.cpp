// SPDX-License-Identifier: MIT
// Triangle decision records (rastrules/decision.hpp) against the kernel's rasterization: the
// record of every pixel says covered exactly when rasterize_primitive emits it, under every
// fill convention, cull mode and front face, on tie-heavy triangles (vertices on a half-pixel
// grid, so that pixel centres fall on edges and vertices); and the records of a tie and of a
// culled triangle name the rules that decided.

#include <gtest/gtest.h>

#include "rastrules/decision.hpp"
#include "rastrules/rules.hpp"
#include "support.hpp"

namespace rastrules {
namespace {

// rule: TRI.FILL.TOP_LEFT, TRI.EDGE.FUNCTION, TRI.COVER.SAMPLE
TEST(TriDecision, ACentreOnATopEdgeIsDecidedByTheTopLeftRule) {
  // Clockwise on screen (y down): (0, 0.5) -> (4, 0.5) -> (0, 4.5). The centre (1.5, 0.5) of
  // pixel (1, 0) lies on the horizontal top edge v0 -> v1.
  const PreparedScene s =
      test::prepared(test::scene_px(4, 4, RasterState{}, {{{{0, 0.5}, {4, 0.5}, {0, 4.5}}}}));
  const PixelDecision d = decide_pixel(s, 0, 1, 0);
  ASSERT_EQ(d.triangles.size(), 1u);
  const EdgeDecision& top = d.triangles[0].edges[0];
  EXPECT_EQ(top.from, 0u);
  EXPECT_EQ(top.to, 1u);
  EXPECT_EQ(top.e.raw(), 0);
  EXPECT_TRUE(top.top && top.horizontal && top.inclusive && top.inside);
  EXPECT_EQ(top.rule, rules::kTriFillTopLeft);
  EXPECT_EQ(d.triangles[0].edges[1].rule, rules::kTriEdgeFunction); // E > 0
  EXPECT_EQ(d.triangles[0].rule, rules::kTriCoverSample);
  EXPECT_TRUE(d.covered);

  // Under the bottom-right convention the same tie is broken by TRI.FILL.CONVENTION: outside.
  // rule: TRI.FILL.CONVENTION
  RasterState br;
  br.fill = FillConvention::kBottomRight;
  const PreparedScene t =
      test::prepared(test::scene_px(4, 4, br, {{{{0, 0.5}, {4, 0.5}, {0, 4.5}}}}));
  const PixelDecision e = decide_pixel(t, 0, 1, 0);
  EXPECT_EQ(e.triangles[0].edges[0].rule, rules::kTriFillConvention);
  EXPECT_FALSE(e.triangles[0].edges[0].inside);
  EXPECT_FALSE(e.covered);
}

// rule: TRI.CULL.MODE, SNAP.CULL.AFTER_SNAP, TRI.ORIENT.NORMALISE
TEST(TriDecision, ACulledTriangleIsDecidedByTheCullModeWithItsEdgesForInformation) {
  // Counter-clockwise on screen, back-facing under the default front face, cull back.
  RasterState cull;
  cull.cull = CullMode::kBack;
  const PreparedScene s = test::prepared(test::scene_px(4, 4, cull, {{{{0, 0}, {0, 4}, {4, 0}}}}));
  const PixelDecision d = decide_pixel(s, 0, 0, 0);
  const TriangleDecision& t = d.triangles[0];
  EXPECT_EQ(t.setup.status, TriangleStatus::kCulledBack);
  EXPECT_TRUE(t.culled && t.has_edges);
  EXPECT_EQ(t.rule, rules::kTriCullMode);
  EXPECT_TRUE(t.inside_all_edges); // without culling the centre (0.5, 0.5) would be inside
  EXPECT_EQ(t.edges[0].to, 2u);    // normalised: v1 and v2 swapped
  EXPECT_FALSE(t.covered);
  EXPECT_FALSE(d.covered);
}

// rule: TRI.DEGENERATE.ZERO_AREA
TEST(TriDecision, ADegenerateTriangleIsDecidedByZeroArea) {
  const PreparedScene s =
      test::prepared(test::scene_px(4, 4, RasterState{}, {{{{0, 0.5}, {2, 0.5}, {4, 0.5}}}}));
  const PixelDecision d = decide_pixel(s, 0, 1, 0);
  const TriangleDecision& t = d.triangles[0];
  EXPECT_EQ(t.rule, rules::kTriDegenerateZeroArea);
  EXPECT_FALSE(t.has_edges || t.covered);
}

// rule: TRI.COVER.SAMPLE, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION, TRI.CULL.MODE
TEST(TriDecision, EveryPixelsRecordAgreesWithTheRasterizedFragments) {
  std::uint32_t seed = 1;
  for (const FillConvention fill : test::kAllConventions) {
    for (const CullMode cull : {CullMode::kNone, CullMode::kBack, CullMode::kFront}) {
      for (const FrontFace front : {FrontFace::kClockwise, FrontFace::kCounterClockwise}) {
        Scene scene;
        scene.width = 12;
        scene.height = 10;
        set_raster_state(scene, RasterState{cull, front, fill});
        scene.primitives = test::tie_heavy_primitives(PrimitiveType::kTriangle, 12, seed++,
                                                      scene.width, scene.height);
        EXPECT_EQ(test::decision_disagreement(test::prepared(scene)), "")
            << "fill " << to_string(fill) << ", cull " << to_string(cull) << ", front "
            << to_string(front);
      }
    }
  }
}

} // namespace
} // namespace rastrules
