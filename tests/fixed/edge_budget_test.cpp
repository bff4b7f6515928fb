// SPDX-License-Identifier: MIT
// Bit budgets: edge values at the extremes of the vertex range are exact in int64_t.
// Each value is compared with an independent 128-bit computation written here.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <type_traits>

#include "rastrules/fixed.hpp"
#include "rastrules/formula/edge.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules {
namespace {

__extension__ typedef __int128 Int128;

// Returns E_ab(p) in 128-bit arithmetic, written from the spec's formula.
Int128 edge_value_128(Int128 ax, Int128 ay, Int128 bx, Int128 by, Int128 px, Int128 py) {
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

// rule: FIX.BUDGET.EDGE_VALUE
TEST(FixBudgetEdgeValue, StaticBudgetsAreTheSpecsNumbers) {
  static_assert(kVertexMagBits == 23);
  static_assert(kMinVertexRaw == -(1 << 23) && kMaxVertexRaw == (1 << 23) - 1);
  static_assert(kEdgeValueMagBits == 49); // 2 * (23 + 1) + 1
  static_assert(kEdgeValueMagBits <= 63);
  static_assert(std::is_same_v<EdgeValue::rep, std::int64_t> && EdgeValue::kFracBits == 16);
  static_assert(std::is_same_v<Subpixel::rep, std::int32_t>);
  // Pixel centres of the largest target are inside the vertex range.
  static_assert(kMaxTargetSide == 16384);
  static_assert(pixel_center(kMaxTargetSide - 1, kMaxTargetSide - 1).x.raw() == 4194176);
  SUCCEED();
}

// rule: FIX.BUDGET.EDGE_VALUE, TRI.EDGE.FUNCTION
TEST(FixBudgetEdgeValue, EveryCombinationOfExtremeCoordinatesIsExact) {
  // Each of the six coordinates takes each of these values: 5^6 = 15625 edge values.
  const std::array<std::int32_t, 5> values = {kMinVertexRaw, kMinVertexRaw + 1, 0,
                                              kMaxVertexRaw - 1, kMaxVertexRaw};
  Int128 largest = 0;
  for (const auto ax : values)
    for (const auto ay : values)
      for (const auto bx : values)
        for (const auto by : values)
          for (const auto px : values)
            for (const auto py : values) {
              const std::int64_t e = formula::edge_value<std::int64_t>(ax, ay, bx, by, px, py);
              const Int128 exact = edge_value_128(ax, ay, bx, by, px, py);
              ASSERT_EQ(Int128{e}, exact)
                  << ax << " " << ay << " " << bx << " " << by << " " << px << " " << py;
              largest = std::max(largest, exact < 0 ? -exact : exact);
            }
  // The largest magnitude is (2^24 - 1)^2: twice the area of half the range square.
  EXPECT_EQ(largest, Int128{281474943156225});
  EXPECT_LT(largest, Int128{1} << 49);
}

// rule: FIX.BUDGET.EDGE_VALUE, TRI.ORIENT.AREA
TEST(FixBudgetEdgeValue, TwiceTheAreaOfTheLargestTriangleIsExact) {
  // (-32768, -32768), (32767.99609375, -32768), (-32768, 32767.99609375): A = d * d with
  // d = 2^24 - 1 raw, positive (clockwise on screen).
  const Vec2 a{Subpixel::from_raw(kMinVertexRaw), Subpixel::from_raw(kMinVertexRaw)};
  const Vec2 b{Subpixel::from_raw(kMaxVertexRaw), Subpixel::from_raw(kMinVertexRaw)};
  const Vec2 c{Subpixel::from_raw(kMinVertexRaw), Subpixel::from_raw(kMaxVertexRaw)};
  const TriangleSetup t = setup_triangle({a, b, c}, RasterState{});
  EXPECT_EQ(t.twice_area, std::int64_t{281474943156225});
  const TriangleSetup r = setup_triangle({a, c, b}, RasterState{});
  EXPECT_EQ(r.twice_area, -std::int64_t{281474943156225});
  // Evaluated at the far corner of the largest target through the typed API.
  const Vec2 s = pixel_center(kMaxTargetSide - 1, kMaxTargetSide - 1);
  for (const EdgeSetup& e : t.edges) {
    EXPECT_EQ(Int128{e.value_at(s).raw()}, edge_value_128(e.a.x.raw(), e.a.y.raw(), e.b.x.raw(),
                                                          e.b.y.raw(), s.x.raw(), s.y.raw()));
  }
}

} // namespace
} // namespace rastrules
