// SPDX-License-Identifier: MIT
// The traversal's fast forms: the bias form of the edge test and one-pixel stepping, at the
// extremes of their budgets, compared with direct evaluation.

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/formula/edge.hpp"
#include "rastrules/raster/walk.hpp"
#include "rastrules/triangle.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

__extension__ typedef __int128 Int128;

// rule: FIX.BIAS.FORM
TEST(FixBiasForm, BiasedSignTestEqualsTheRuleAtEveryBoundaryValue) {
  constexpr std::int64_t kLimit = (std::int64_t{1} << 49) - 1; // FIX.BUDGET.EDGE_VALUE
  const std::int64_t values[] = {-kLimit, -kLimit + 1, -65536, -2,         -1,    0,
                                 1,       2,           65536,  kLimit - 1, kLimit};
  for (const std::int64_t e : values) {
    for (const bool inclusive : {false, true}) {
      const std::int64_t bias = formula::edge_bias<std::int64_t>(inclusive);
      const bool rule = e > 0 || (e == 0 && inclusive);
      EXPECT_EQ(e + bias >= 0, rule) << "E = " << e << " inclusive = " << inclusive;
    }
  }
  EXPECT_EQ(formula::edge_bias<std::int64_t>(true), 0);
  EXPECT_EQ(formula::edge_bias<std::int64_t>(false), -1);
}

// rule: FIX.STEP.INCREMENTAL
TEST(FixStepIncremental, OnePixelStepsEqualDirectEvaluationAtTheExtremes) {
  // Edges between opposite corners of the vertex range, stepped across a whole row and down
  // a whole column of the largest target, compared with 128-bit direct evaluation.
  const std::int32_t lo = kMinVertexRaw, hi = kMaxVertexRaw;
  const std::array<std::array<std::int32_t, 4>, 4> edges = {
      {{lo, lo, hi, hi}, {hi, lo, lo, hi}, {lo, hi, hi, hi}, {hi, hi, hi, lo}}};
  for (const auto& ed : edges) {
    const std::int64_t sx = formula::edge_step_x<std::int64_t>(ed[1], ed[3], kSubpixelOne);
    const std::int64_t sy = formula::edge_step_y<std::int64_t>(ed[0], ed[2], kSubpixelOne);
    const auto direct = [&](std::int32_t x, std::int32_t y) {
      const Vec2 p = pixel_center(x, y);
      return (Int128{ed[2]} - ed[0]) * (Int128{p.y.raw()} - ed[1]) -
             (Int128{ed[3]} - ed[1]) * (Int128{p.x.raw()} - ed[0]);
    };
    std::int64_t e = formula::edge_value<std::int64_t>(
        ed[0], ed[1], ed[2], ed[3], pixel_center(0, 0).x.raw(), pixel_center(0, 0).y.raw());
    for (std::int32_t x = 0; x < kMaxTargetSide; ++x) {
      ASSERT_EQ(Int128{e}, direct(x, 0)) << "x = " << x;
      e += sx;
    }
    e = formula::edge_value<std::int64_t>(ed[0], ed[1], ed[2], ed[3],
                                          pixel_center(kMaxTargetSide - 1, 0).x.raw(),
                                          pixel_center(kMaxTargetSide - 1, 0).y.raw());
    for (std::int32_t y = 0; y < kMaxTargetSide; ++y) {
      ASSERT_EQ(Int128{e}, direct(kMaxTargetSide - 1, y)) << "y = " << y;
      e += sy;
    }
  }
}

// rule: FIX.STEP.INCREMENTAL
TEST(FixStepIncremental, StepValuesAreHandComputed) {
  // Edge (1,2) -> (3,7) px: step_x = 256 * (ay - by) raw = 256 * (512 - 1792) = -327680,
  // i.e. -5 px^2 per pixel to the right; step_y = 256 * (768 - 256) = 131072 = 2 px^2.
  EXPECT_EQ(formula::edge_step_x<std::int64_t>(512, 1792, kSubpixelOne), -5 * 65536);
  EXPECT_EQ(formula::edge_step_y<std::int64_t>(256, 768, kSubpixelOne), 2 * 65536);
}

// rule: FIX.STEP.INCREMENTAL, FIX.BIAS.FORM, RASTER.WALK.BBOX
TEST(FixStepIncremental, WalkAcrossTheWidestTargetEqualsTheDirectRule) {
  // A triangle with vertices at the range limits over a 16384 x 4 target: the walk steps
  // 16384 pixels per row in bias form; covers() evaluates each centre directly. Its lower edge
  // runs from (-32768, -2.5) to (32767.99609375, 5.5), about y = 1.5 + x / 8192, so the
  // triangle (above it) covers rows 0 and 1 fully, row 2 from x = 8192 on, row 3 not at all.
  const auto tri = triangle_px({-32768, -2.5}, {32767.99609375, 5.5}, {32767.99609375, -32768});
  const auto walked = walk_pixels(tri, kMaxTargetSide, 4);
  EXPECT_EQ(walked, centre_pixels(tri, kMaxTargetSide, 4));
  EXPECT_EQ(walked.size(), 16384u + 16384u + 8192u);
  // Row 2 (y = 2.5) is crossed at x = 40960 * 65535.99609375 / 65536 - 32768 = 8191.9976.
  EXPECT_FALSE(covers(tri, pixel_center(8191, 2)));
  EXPECT_TRUE(covers(tri, pixel_center(8192, 2)));
}

} // namespace
} // namespace rastrules::test
