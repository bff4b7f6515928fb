// SPDX-License-Identifier: MIT
// Fragments only inside the target: triangles partly or wholly outside, negative coordinates,
// vertices at the range limits.

#include <gtest/gtest.h>

#include <array>
#include <variant>
#include <vector>

#include "rastrules/raster/walk.hpp"
#include "rastrules/scene.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

// Returns the covered centres of t in the window [x0, x0 + w) x [y0, y0 + h), by covers()
// alone, so that clipping can be compared with coverage beyond the target.
std::vector<Pixel> centres_in_window(const TriangleSetup& t, std::int32_t x0, std::int32_t y0,
                                     std::int32_t w, std::int32_t h) {
  std::vector<Pixel> out;
  for (std::int32_t y = y0; y < y0 + h; ++y) {
    for (std::int32_t x = x0; x < x0 + w; ++x) {
      const Vec2 c{Subpixel::from_raw(x * kSubpixelOne + kSubpixelHalf),
                   Subpixel::from_raw(y * kSubpixelOne + kSubpixelHalf)};
      if (covers(t, c))
        out.push_back(Pixel{x, y});
    }
  }
  return out;
}

// rule: RASTER.TARGET.CLIP
TEST(RasterTargetClip, TrianglePartlyRightOfTheTargetIsCutAtItsEdge) {
  // (12,0) (20,0) (12,8) on a 16 x 8 target: right edge x + y = 20 (exclusive).
  const TriangleSetup t = triangle_px({12, 0}, {20, 0}, {12, 8});
  const auto expected = pixels_in_picture({
      "............####",
      "............####",
      "............####",
      "............####",
      "............###.",
      "............##..",
      "............#...",
      "................",
  });
  EXPECT_EQ(walk_pixels(t, 16, 8), expected) << picture(walk_pixels(t, 16, 8), 16, 8);
  // Beyond the target the triangle covers more (e.g. pixel (16, 0)); none of it is emitted.
  const auto beyond = centres_in_window(t, 0, 0, 24, 8);
  EXPECT_GT(beyond.size(), expected.size());
  EXPECT_TRUE(covers(t, sample_px(16.5, 0.5)));
}

// rule: RASTER.TARGET.CLIP
TEST(RasterTargetClip, NegativeCoordinatesAreDrawnOnlyWhereTheyReachTheTarget) {
  // (-4,-4) (6,-4) (-4,6): the right edge x + y = 2 leaves only the centre (0.5, 0.5) inside
  // the target; (1.5, 0.5) and (0.5, 1.5) lie on that edge (a right edge: not covered).
  const TriangleSetup t = triangle_px({-4, -4}, {6, -4}, {-4, 6});
  EXPECT_EQ(walk_pixels(t, 16, 8), (std::vector<Pixel>{{0, 0}}));
  // Beyond the target: pixels (x, y) with x, y >= -4 and x + y <= 0, 9 + 8 + ... + 1 of them.
  EXPECT_EQ(centres_in_window(t, -8, -8, 24, 16).size(), 45u);
}

// rule: RASTER.TARGET.CLIP
TEST(RasterTargetClip, TriangleWhollyOutsideDrawsNothing) {
  for (const auto& v : {std::array<Px, 3>{{{20, 0}, {30, 0}, {20, 8}}},      // right
                        std::array<Px, 3>{{{-10, 0}, {-5, 0}, {-10, 8}}},    // left
                        std::array<Px, 3>{{{0, -10}, {16, -10}, {0, -0.5}}}, // above
                        std::array<Px, 3>{{{0, 8}, {16, 8}, {0, 100}}}}) {   // below (y = 8 edge)
    const TriangleSetup t = triangle_px(v[0], v[1], v[2]);
    ASSERT_EQ(t.status, TriangleStatus::kRasterized);
    EXPECT_TRUE(walk_pixels(t, 16, 8).empty());
    EXPECT_TRUE(raster::pixel_bounds(t, 16, 8).empty());
  }
}

// rule: RASTER.TARGET.CLIP
TEST(RasterTargetClip, TriangleCoveringTheWholeTargetEmitsEachPixelOnce) {
  const TriangleSetup t = triangle_px({-10, -10}, {40, -10}, {-10, 40});
  const auto got = walk_pixels(t, 16, 8);
  EXPECT_EQ(got.size(), 128u);
  EXPECT_EQ(got, centre_pixels(t, 16, 8));
}

// rule: RASTER.TARGET.CLIP, SNAP.VERTEX.RANGE
TEST(RasterTargetClip, TrianglesSpanningTheWholeVertexRangeOnASmallTarget) {
  // m = -32768, M = 32767.99609375. The diagonal from (m, m) to (M, M) is the line y = x and
  // passes through the centres (k + 0.5, k + 0.5).
  const double m = -32768, M = 32767.99609375;
  // Upper-right half: the diagonal is its left edge, so it owns the diagonal centres.
  const TriangleSetup upper = triangle_px({m, m}, {M, M}, {M, m});
  // Lower-left half: the diagonal is its right edge.
  const TriangleSetup lower = triangle_px({m, m}, {m, M}, {M, M});
  const auto up = walk_pixels(upper, 16, 8);
  const auto lo = walk_pixels(lower, 16, 8);
  EXPECT_EQ(up, pixels_in_picture({
                    "################",
                    ".###############",
                    "..##############",
                    "...#############",
                    "....############",
                    ".....###########",
                    "......##########",
                    ".......#########",
                }));
  EXPECT_EQ(up.size() + lo.size(), 128u); // 100 + 28: every pixel exactly once
  for (const Pixel& p : lo)
    EXPECT_GT(p.y, p.x);
  // The anti-diagonal from (M, m) to (m, M) is x + y = -1/256 px: no centre of the target
  // lies on or above-left of it.
  EXPECT_TRUE(walk_pixels(triangle_px({m, m}, {M, m}, {m, M}), 16, 8).empty());
  EXPECT_EQ(walk_pixels(triangle_px({M, m}, {M, M}, {m, M}), 16, 8).size(), 128u);
}

// rule: RASTER.TARGET.CLIP, SCENE.OUTPUT.FRAGMENTS
TEST(RasterTargetClip, RenderNeverEmitsAFragmentOutsideTheTarget) {
  const Scene s =
      scene_px(5, 3, RasterState{},
               {{{{-3, -3}, {9, -3}, {-3, 9}}}, {{{2.5, 1.5}, {100, 1.5}, {2.5, 100}}}});
  const auto r = render(s);
  ASSERT_TRUE(std::holds_alternative<std::vector<Fragment>>(r));
  const auto& f = std::get<std::vector<Fragment>>(r);
  ASSERT_FALSE(f.empty());
  for (const Fragment& x : f) {
    EXPECT_TRUE(x.x >= 0 && x.x < 5 && x.y >= 0 && x.y < 3) << x.x << "," << x.y;
  }
  // Prim 1 starts on the centre (2.5, 1.5): top + left vertex.
  EXPECT_EQ(pixels_of(f, 1), pixels_in_picture({
                                 ".....",
                                 "..###",
                                 "..###",
                             }));
}

} // namespace
} // namespace rastrules::test
