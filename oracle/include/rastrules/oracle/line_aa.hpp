// SPDX-License-Identifier: MIT
// The antialiased-line rule written a second time, for machines: exact, slow, independent.
// Written from spec/rules/line_aa.md (LINE.AA.RECT, LINE.AA.COVERAGE, LINE.AA.FRAGMENT,
// LINE.AA.ZERO_LENGTH, LINE.AA.BLEND) with exact arithmetic in the field Q(sqrt(D)),
// D = |b - a|^2 in raw units; never includes or calls kernel code, and shares none of its types.
// Implements (as oracle): LINE.AA.RECT, LINE.AA.COVERAGE, LINE.AA.FRAGMENT,
//   LINE.AA.ZERO_LENGTH, LINE.AA.PRECISION, LINE.AA.BLEND

#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace rastrules::oracle {

// Raw 16.8 integers (value * 256), as snapped.
using AARaw = std::array<std::int64_t, 2>;

// The exact coverage of pixel (px, py) by the line a -> b, compared with a kernel value.
struct AACheck {
  bool positive = false;     // exact coverage > 0
  bool within_bound = false; // |q16 / 65536 - exact| <= 1 / 65536 (LINE.AA.PRECISION)
  // |q16 - 65536 * exact| <= 1/2 + 1/1024: rounding to nearest plus the internal error budget
  // (the tighter statement inside LINE.AA.PRECISION; false where the floor of 1 applies).
  bool nearest = false;
  double approx = 0.0; // exact coverage rounded to double, for messages only
};

// Returns the exact coverage of pixel (px, py) checked against q16.
AACheck aa_check(const AARaw& a, const AARaw& b, std::int32_t px, std::int32_t py,
                 std::uint32_t q16);

// Returns the sign of (exact coverage of pixel (px, py)) - num / den, den > 0.
int aa_compare(const AARaw& a, const AARaw& b, std::int32_t px, std::int32_t py, std::int64_t num,
               std::int64_t den);

// Returns every pixel (x, y) of the target [0, w) x [0, h) whose exact coverage is > 0, in row
// order (y, then x), found by testing every pixel of the target.
std::vector<std::array<std::int32_t, 2>> aa_pixels(const AARaw& a, const AARaw& b, std::int32_t w,
                                                   std::int32_t h);

// Returns the exact blend dst + (src - dst) * (sa / 255) * (cov / 65536) compared with a
// kernel result: true when out is that value rounded to nearest with halves rounded up.
bool aa_blend_ok(std::uint32_t src, std::uint32_t sa, std::uint32_t dst, std::uint32_t cov,
                 std::uint32_t out);

} // namespace rastrules::oracle
