// SPDX-License-Identifier: MIT
// Examples for barycentrics, interpolation and depth: exact sums, perspective against linear,
// the horizon, saturation, format conversion with its rounding, the compare functions, and
// depth bias.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "rastrules/pipeline.hpp"

namespace rastrules::pipe {
namespace {

Vec2 px(double x, double y) {
  return Vec2{Subpixel::from_raw(static_cast<std::int32_t>(std::lround(x * 256))),
              Subpixel::from_raw(static_cast<std::int32_t>(std::lround(y * 256)))};
}

// rule: PIPE.BARY.EXACT, PIPE.BARY.SUM
TEST(PipeBary, EdgeValuesAreExactAndSumToTheArea) {
  const std::array<Vec2, 3> v{px(0, 0), px(8, 0), px(0, 4)}; // counter-clockwise on screen
  const Barycentrics at0 = barycentrics(v, v[0]);
  EXPECT_EQ(at0.e[0], at0.area);
  EXPECT_EQ(at0.e[1], 0);
  EXPECT_EQ(at0.e[2], 0);
  const Barycentrics mid = barycentrics(v, px(2, 1));
  // lambda = (1 - 2/8 - 1/4, 2/8, 1/4) = (1/2, 1/4, 1/4).
  EXPECT_EQ(mid.e[0] * 2, mid.area);
  EXPECT_EQ(mid.e[1] * 4, mid.area);
  EXPECT_EQ(mid.e[2] * 4, mid.area);
  EXPECT_EQ(mid.e[0] + mid.e[1] + mid.e[2], mid.area);
  // Far outside, at the corners of the vertex range, the sum still holds exactly.
  const std::array<Vec2, 3> big{px(-32768, -32768), px(32767.99609375, -32768),
                                px(-32768, 32767.99609375)};
  const Barycentrics b = barycentrics(big, px(32767.99609375, 32767.99609375));
  EXPECT_EQ(b.e[0] + b.e[1] + b.e[2], b.area);
}

// rule: PIPE.INTERP.LINEAR
TEST(PipeInterp, LinearIsTheAreaWeightedMean) {
  const std::array<Vec2, 3> v{px(0, 0), px(8, 0), px(0, 4)};
  EXPECT_EQ(interpolate_linear(barycentrics(v, px(2, 1)), {4.0f, 8.0f, 16.0f}), 8.0f);
  // Extrapolated outside: lambda = (-1, 1, 1) at (8, 4).
  EXPECT_EQ(interpolate_linear(barycentrics(v, px(8, 4)), {4.0f, 8.0f, 16.0f}), 20.0f);
}

// rule: PIPE.INTERP.PERSPECTIVE
TEST(PipeInterp, PerspectiveWeighsByOneOverW) {
  const std::array<Vec2, 3> v{px(0, 0), px(8, 0), px(0, 4)};
  const Barycentrics b = barycentrics(v, px(4, 0)); // lambda = (1/2, 1/2, 0)
  // (0.5 * 0 / 1 + 0.5 * 12 / 3) / (0.5 / 1 + 0.5 / 3) = 2 / (2/3) = 3.
  EXPECT_EQ(interpolate_perspective(b, {0.0f, 12.0f, 100.0f}, {1.0f, 3.0f, 5.0f}, -1.0f), 3.0f);
  // With equal w it equals linear interpolation.
  EXPECT_EQ(interpolate_perspective(b, {0.0f, 12.0f, 100.0f}, {2.0f, 2.0f, 2.0f}, -1.0f), 6.0f);
  // The winding of the triangle does not matter.
  const std::array<Vec2, 3> cw{v[0], v[2], v[1]};
  EXPECT_EQ(interpolate_perspective(barycentrics(cw, px(4, 0)), {0.0f, 100.0f, 12.0f},
                                    {1.0f, 5.0f, 3.0f}, -1.0f),
            3.0f);
}

// rule: PIPE.INTERP.HORIZON
TEST(PipeInterp, BeyondTheHorizonTakesTheFlatValueAndNothingIsNaN) {
  const std::array<Vec2, 3> v{px(0, 0), px(8, 0), px(0, 8)};
  // w grows a million-fold towards vertex 1: far outside on that side, sum(lambda_i / w_i) < 0.
  const Barycentrics b = barycentrics(v, px(-16, 0)); // lambda = (3, -2, 0)
  EXPECT_EQ(interpolate_perspective(b, {1.0f, 2.0f, 3.0f}, {1e6f, 1.0f, 1.0f}, 7.0f), 7.0f);
  // Huge attribute values extrapolated beyond float32 saturate.
  const Barycentrics out = barycentrics(v, px(32, 0)); // lambda = (-3, 4, 0)
  const float max = std::numeric_limits<float>::max();
  EXPECT_EQ(interpolate_linear(out, {-max, max, 0.0f}), max);
  EXPECT_EQ(interpolate_perspective(out, {-max, max, 0.0f}, {1.0f, 1.0f, 1.0f}, 0.0f), max);
  // A zero-length line (area 0) gives the flat value.
  EXPECT_EQ(interpolate_perspective(Barycentrics{{0, 0, 0}, 0}, {1, 2, 3}, {1, 1, 1}, 9.0f), 9.0f);
}

// rule: PIPE.DEPTH.INTERP
TEST(PipeDepth, DepthIsLinearInScreenSpace) {
  const std::array<Vec2, 3> v{px(0, 0), px(8, 0), px(0, 4)};
  EXPECT_EQ(interpolate_depth(barycentrics(v, px(2, 1)), {0.0f, 0.5f, 1.0f}),
            0.5 * 0.0 + 0.25 * 0.5 + 0.25 * 1.0);
}

// rule: PIPE.DEPTH.CLAMP, PIPE.DEPTH.FORMAT
TEST(PipeDepth, FormatsRoundToNearestAfterTheClamp) {
  EXPECT_EQ(to_depth_format(0.5, 0, 1, DepthFormat::kD16).unorm, 32768u); // 32767.5 + 0.5
  EXPECT_EQ(to_depth_format(1.0, 0, 1, DepthFormat::kD16).unorm, 65535u);
  EXPECT_EQ(to_depth_format(1.0, 0, 1, DepthFormat::kD24).unorm, 16777215u);
  EXPECT_EQ(to_depth_format(0.0, 0, 1, DepthFormat::kD24).unorm, 0u);
  // Half a step below 1 / 16777215 rounds down, half a step above rounds up.
  EXPECT_EQ(to_depth_format(0.49 / 16777215.0, 0, 1, DepthFormat::kD24).unorm, 0u);
  EXPECT_EQ(to_depth_format(0.51 / 16777215.0, 0, 1, DepthFormat::kD24).unorm, 1u);
  // Clamped to the viewport's depth range, whatever the interpolated value.
  EXPECT_EQ(to_depth_format(-3.0, 0.25f, 0.75f, DepthFormat::kD16).unorm,
            to_depth_format(0.25, 0, 1, DepthFormat::kD16).unorm);
  EXPECT_EQ(to_depth_format(1e30, 0.25f, 0.75f, DepthFormat::kD32F).f, 0.75f);
  // d32f rounds to nearest, ties to even.
  EXPECT_EQ(to_depth_format(0.1, 0, 1, DepthFormat::kD32F).f, 0.1f);
}

// rule: PIPE.DEPTH.TEST
TEST(PipeDepth, EveryCompareFunction) {
  const DepthValue lo{100, 0.25f}, hi{200, 0.5f};
  struct Case {
    CompareFunc f;
    bool lt, eq, gt;
  };
  for (const Case c :
       {Case{CompareFunc::kNever, false, false, false},
        Case{CompareFunc::kLess, true, false, false}, Case{CompareFunc::kEqual, false, true, false},
        Case{CompareFunc::kLessEqual, true, true, false},
        Case{CompareFunc::kGreater, false, false, true},
        Case{CompareFunc::kNotEqual, true, false, true},
        Case{CompareFunc::kGreaterEqual, false, true, true},
        Case{CompareFunc::kAlways, true, true, true}}) {
    for (const DepthFormat fmt : {DepthFormat::kD24, DepthFormat::kD32F}) {
      EXPECT_EQ(depth_test(c.f, lo, hi, fmt), c.lt) << to_string(c.f);
      EXPECT_EQ(depth_test(c.f, lo, lo, fmt), c.eq) << to_string(c.f);
      EXPECT_EQ(depth_test(c.f, hi, lo, fmt), c.gt) << to_string(c.f);
    }
  }
}

// rule: PIPE.DEPTH.BIAS
TEST(PipeDepth, BiasFollowsD3D) {
  const std::array<Vec2, 3> v{px(0, 0), px(8, 0), px(0, 4)};
  const std::array<float, 3> flat{0.5f, 0.5f, 0.5f};
  EXPECT_EQ(depth_bias(v, flat, DepthBias{}, DepthFormat::kD24), 0.0f);
  // Constant bias: r = 1 / (2^n - 1) in float32.
  EXPECT_EQ(depth_bias(v, flat, DepthBias{3, 0, 0}, DepthFormat::kD16),
            3.0f * static_cast<float>(1.0 / 65535.0));
  // d32f: r = 2^(exponent(max |z|) - 23); max |z| = 0.5 = 2^-1.
  EXPECT_EQ(depth_bias(v, flat, DepthBias{1, 0, 0}, DepthFormat::kD32F), std::ldexp(1.0f, -24));
  // Slope: z rises by 1 over 8 px in x and by 0.5 over 4 px in y: max slope 0.125.
  const std::array<float, 3> slope{0.0f, 1.0f, 0.5f};
  EXPECT_EQ(depth_bias(v, slope, DepthBias{0, 2.0f, 0}, DepthFormat::kD24), 0.25f);
  // Clamp: positive clamps from above, negative from below, zero does nothing.
  EXPECT_EQ(depth_bias(v, slope, DepthBias{0, 2.0f, 0.1f}, DepthFormat::kD24), 0.1f);
  EXPECT_EQ(depth_bias(v, slope, DepthBias{0, -2.0f, -0.1f}, DepthFormat::kD24), -0.1f);
}

} // namespace
} // namespace rastrules::pipe
