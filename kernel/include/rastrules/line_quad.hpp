// SPDX-License-Identifier: MIT
// Quadrilateral lines (helpers of rastrules/line.hpp's quad_line_triangles): the exact,
// integer-only rounding of the rectangle's corner offsets to 16.8.
// Implements: LINE.QUAD.WIDTH, LINE.QUAD.CORNERS, LINE.QUAD.NO_CULL

#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/line.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules {

// Half the width of a quadrilateral line in raw 16.8 units, as the exact fraction num / den:
// 1.4 px wide -> 0.7 px = 179.2 raw = 896 / 5; 1.0 px wide -> 0.5 px = 128 / 1.
// rule: LINE.QUAD.WIDTH
struct QuadHalfWidth {
  std::int64_t num = 0;
  std::int64_t den = 1;
};
inline constexpr QuadHalfWidth kQuadWideHalfWidth{7 * kSubpixelOne / 2, 5}; // 896 / 5
inline constexpr QuadHalfWidth kQuadNarrowHalfWidth{kSubpixelHalf, 1};      // 128 / 1

// The corner offset o of the quadrilateral line from a to b (raw 16.8): the exact offset is
// (w/2) * (-dy, dx) / |d| with d = b - a; each component is rounded to the nearest integer
// (LINE.QUAD.CORNERS).
struct QuadOffset {
  std::int32_t x = 0;
  std::int32_t y = 0;
  friend constexpr bool operator==(const QuadOffset&, const QuadOffset&) = default;
};

namespace detail {
__extension__ typedef __int128 QuadWide; // 128-bit products of squares (GCC/Clang)
} // namespace detail

// Returns the integer nearest to the exact real m * hw.num / (hw.den * sqrt(len2)), ties to even,
// decided only by exact comparisons of squares in 128-bit integers (no floating point, no
// square root). Preconditions: 0 <= m, m * m <= len2, 0 < len2 < 2^50, hw.num, hw.den > 0 and
// hw.num / hw.den <= 256. The result lies in [0, hw.num / hw.den + 1/2].
// rule: LINE.QUAD.CORNERS
[[nodiscard]] constexpr std::int32_t round_quad_offset(std::int64_t m, std::int64_t len2,
                                                       QuadHalfWidth hw) {
  using W = detail::QuadWide;
  // target = (m * num)^2; candidate n is <= the exact value v iff (n * den)^2 * len2 <= target.
  const W mn = W{m} * W{hw.num};
  const W target = mn * mn;
  const W den2_len2 = W{hw.den} * W{hw.den} * W{len2};
  // floor(v) by bisection on [0, 512): v <= 256 by the preconditions.
  std::int64_t lo = 0, hi = 512; // invariant: lo <= v < hi
  while (hi - lo > 1) {
    const std::int64_t mid = (lo + hi) / 2;
    if (W{mid} * W{mid} * den2_len2 <= target) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  // Compare v with lo + 1/2: 2v vs 2 lo + 1, squared (both sides >= 0).
  const W twice_lo_plus_1 = W{2 * lo + 1};
  const W lhs = W{4} * target;                                 // (2v)^2 * den^2 * len2
  const W rhs = twice_lo_plus_1 * twice_lo_plus_1 * den2_len2; // (2 lo + 1)^2 * den^2 * len2
  std::int64_t n = lo;
  if (lhs > rhs || (lhs == rhs && lo % 2 != 0))
    n = lo + 1;
  return static_cast<std::int32_t>(n);
}

// Returns the rounded corner offset of the quadrilateral line with direction d = (dx, dy)
// (raw 16.8, not both zero) and half width hw: (-sgn(dy) * R(|dy|), sgn(dx) * R(|dx|)) with
// R(m) = round_quad_offset(m, dx^2 + dy^2, hw). Rounding half to even is symmetric, so this is
// the nearest integer to each component of the exact offset, and offset(-d) == -offset(d).
// rule: LINE.QUAD.CORNERS
[[nodiscard]] constexpr QuadOffset quad_line_offset(std::int64_t dx, std::int64_t dy,
                                                    QuadHalfWidth hw) {
  const std::int64_t len2 = dx * dx + dy * dy;
  const std::int32_t rx = round_quad_offset(dy < 0 ? -dy : dy, len2, hw);
  const std::int32_t ry = round_quad_offset(dx < 0 ? -dx : dx, len2, hw);
  return QuadOffset{dy > 0 ? -rx : rx, dx < 0 ? -ry : ry};
}

// Hand-checkable instances (LINE.QUAD.CORNERS): horizontal lines get the full half width,
// 0.7 px rounds 179.2 down to 179; 45-degree lines get 179.2 / sqrt(2) = 126.71... -> 127 and
// 128 / sqrt(2) = 90.50966... -> 91.
static_assert(quad_line_offset(256, 0, kQuadWideHalfWidth) == QuadOffset{0, 179});
static_assert(quad_line_offset(-256, 0, kQuadNarrowHalfWidth) == QuadOffset{0, -128});
static_assert(quad_line_offset(0, 5, kQuadWideHalfWidth) == QuadOffset{-179, 0});
static_assert(quad_line_offset(3, 3, kQuadWideHalfWidth) == QuadOffset{-127, 127});
static_assert(quad_line_offset(-7, 7, kQuadNarrowHalfWidth) == QuadOffset{-91, -91});

// Returns the set-up triangles of the quadrilateral line from a to b (quad_line_triangles):
// culling off whatever state.cull says, the state's fill convention. Empty when a == b.
// rule: LINE.QUAD.NO_CULL
[[nodiscard]] std::vector<TriangleSetup> setup_quad_line(Vec2 a, Vec2 b, LineMode mode,
                                                         const RasterState& state);

} // namespace rastrules
