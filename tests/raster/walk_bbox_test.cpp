// SPDX-License-Identifier: MIT
// Bounding-box traversal: the pixel rectangle it visits, the order it emits, and equality with
// the per-centre rule; render()'s fragment order (prim, y, x).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <tuple>
#include <variant>
#include <vector>

#include "rastrules/raster/walk.hpp"
#include "rastrules/scene.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

struct Rect {
  std::int32_t x0, y0, x1, y1;
};

void expect_bounds(const TriangleSetup& t, std::int32_t w, std::int32_t h, Rect r) {
  const raster::PixelRect got = raster::pixel_bounds(t, w, h);
  EXPECT_EQ(got.x0, r.x0);
  EXPECT_EQ(got.y0, r.y0);
  EXPECT_EQ(got.x1, r.x1);
  EXPECT_EQ(got.y1, r.y1);
}

// rule: RASTER.WALK.BBOX
TEST(RasterWalkBbox, FloorDivRoundsTowardMinusInfinity) {
  EXPECT_EQ(rastrules::floor_div(255, 256), 0);
  EXPECT_EQ(rastrules::floor_div(256, 256), 1);
  EXPECT_EQ(rastrules::floor_div(0, 256), 0);
  EXPECT_EQ(rastrules::floor_div(-1, 256), -1);
  EXPECT_EQ(rastrules::floor_div(-256, 256), -1);
  EXPECT_EQ(rastrules::floor_div(-257, 256), -2);
}

// rule: RASTER.WALK.BBOX
TEST(RasterWalkBbox, BoundsAreThePixelsWhoseCentresLieInTheBoundingBox) {
  // Vertices on centres: the box is closed, so the end centres are included.
  expect_bounds(triangle_px({0.5, 0.5}, {3.5, 0.5}, {0.5, 2.5}), 16, 8, {0, 0, 3, 2});
  // One subpixel inside the centres: the end pixels drop out.
  expect_bounds(
      triangle_px({0.50390625, 0.50390625}, {3.49609375, 0.50390625}, {0.50390625, 2.49609375}), 16,
      8, {1, 1, 2, 1});
  // Vertices on pixel corners.
  expect_bounds(triangle_px({1, 1}, {6, 2}, {2, 4}), 16, 8, {1, 1, 5, 3});
  // A box containing no centre is empty.
  EXPECT_TRUE(
      raster::pixel_bounds(triangle_px({1.625, 1.625}, {2.375, 1.625}, {1.625, 2.375}), 16, 8)
          .empty());
}

// rule: RASTER.WALK.BBOX, RASTER.TARGET.CLIP
TEST(RasterWalkBbox, BoundsAreClippedToTheTargetIncludingNegativeCoordinates) {
  // (-5,-5) (2,-5) (-5,3): x centres up to 1.5, y centres up to 2.5.
  expect_bounds(triangle_px({-5, -5}, {2, -5}, {-5, 3}), 16, 8, {0, 0, 1, 2});
  // Bounds at exactly -0.5 px (the centre of pixel -1): clipped to pixel 0.
  expect_bounds(triangle_px({-0.5, -0.5}, {0.5, -0.5}, {-0.5, 0.5}), 16, 8, {0, 0, 0, 0});
  // Beyond the far sides: clipped to width - 1, height - 1.
  expect_bounds(triangle_px({10, 4}, {100, 4}, {10, 50}), 16, 8, {10, 4, 15, 7});
  // Range limits on a 1 x 1 target.
  expect_bounds(triangle_px({-32768, -32768}, {32767.99609375, -32768}, {-32768, 32767.99609375}),
                1, 1, {0, 0, 0, 0});
}

// rule: RASTER.WALK.BBOX
TEST(RasterWalkBbox, EmitsRowByRowLeftToRight) {
  const auto got = walk_pixels(triangle_px({0.5, 0.5}, {6.5, 3.5}, {0.5, 6.5}), 8, 8);
  ASSERT_FALSE(got.empty());
  for (std::size_t i = 1; i < got.size(); ++i) {
    const bool later =
        got[i].y > got[i - 1].y || (got[i].y == got[i - 1].y && got[i].x > got[i - 1].x);
    EXPECT_TRUE(later) << got[i - 1] << " then " << got[i];
  }
}

// rule: RASTER.WALK.BBOX, TRI.COVER.SAMPLE, FIX.BIAS.FORM, FIX.STEP.INCREMENTAL
TEST(RasterWalkBbox, WalkEqualsTheRuleAtEveryCentreForTieHeavyTriangles) {
  const std::array<Px, 3> tris[] = {
      {{{0.5, 0.5}, {7.5, 0.5}, {0.5, 7.5}}},        // edges through centres
      {{{7.5, 0.5}, {7.5, 7.5}, {0.5, 7.5}}},        // the other half
      {{{3.5, 0.5}, {7.5, 4.5}, {3.5, 7.5}}},        // vertices on centres
      {{{0, 0}, {8, 1}, {1, 8}}},                    // corners
      {{{2.25, 1.75}, {6.125, 3.5}, {0.75, 6.875}}}, // arbitrary quarter points
      {{{-3.5, 2.5}, {12.5, 2.5}, {4.5, 10.5}}},     // crossing the target
  };
  for (const auto& v : tris) {
    for (const FillConvention f : kAllConventions) {
      RasterState state;
      state.fill = f;
      const TriangleSetup t = triangle_px(v[0], v[1], v[2], state);
      EXPECT_EQ(walk_pixels(t, 8, 8), centre_pixels(t, 8, 8))
          << "fill " << to_string(f) << " first vertex (" << v[0].x << ", " << v[0].y << ")";
    }
  }
}

// rule: RASTER.WALK.BBOX, SCENE.OUTPUT.FRAGMENTS
TEST(RasterWalkBbox, RenderSortsFragmentsByPrimThenYThenX) {
  // Three overlapping triangles, the last one first on the screen: output is still grouped
  // by primitive in scene order, each in (y, x) order, with mask 1.
  const Scene s = scene_px(
      8, 8, RasterState{},
      {{{{4, 4}, {8, 4}, {4, 8}}}, {{{0, 0}, {8, 0}, {0, 8}}}, {{{0, 0}, {3, 0}, {0, 3}}}});
  const auto r = render(s);
  ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(r));
  const auto& f = std::get<std::vector<Fragment>>(r);
  ASSERT_EQ(f.size(), 6u + 28u + 3u); // 3+2+1, 7+6+...+1, 2+1
  EXPECT_TRUE(std::is_sorted(f.begin(), f.end(), [](const Fragment& a, const Fragment& b) {
    return std::tie(a.prim, a.y, a.x) < std::tie(b.prim, b.y, b.x);
  }));
  EXPECT_EQ(f.front(), (Fragment{0, 4, 4, 1}));
  EXPECT_EQ(f.back(), (Fragment{2, 0, 1, 1}));
  for (const Fragment& x : f)
    EXPECT_EQ(x.mask, 1u);
  EXPECT_EQ(pixels_of(f, 2), (std::vector<Pixel>{{0, 0}, {1, 0}, {0, 1}}));
}

} // namespace
} // namespace rastrules::test
