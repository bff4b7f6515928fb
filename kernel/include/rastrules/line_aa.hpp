// SPDX-License-Identifier: MIT
// Antialiased lines, D3D reference algorithm: per-pixel coverage in fixed point and the
// alpha blend it feeds. rasterize_aa_line (line.hpp) walks the pixels and calls these.
// Implements: LINE.AA.RECT, LINE.AA.COVERAGE, LINE.AA.FRAGMENT, LINE.AA.ZERO_LENGTH,
//             LINE.AA.PRECISION, LINE.AA.BLEND

#pragma once

#include <cstdint>

#include "rastrules/fixed.hpp"
#include "rastrules/line.hpp"

namespace rastrules {

// Coverage of one pixel by an antialiased line.
struct AACoverage {
  // Exact decision (integer arithmetic, no rounding): the exact coverage is > 0, that is the
  // line rectangle and the open 3x3 square R4 overlap in positive area (LINE.AA.FRAGMENT).
  bool positive = false;
  // The coverage in units of 1/65536, within LINE.AA.PRECISION of the exact value; at least 1
  // when `positive`, 0 otherwise.
  std::uint32_t q16 = 0;
};

// Returns the coverage of pixel (px, py) by the antialiased line from a to b (snapped).
// Any pixel position is accepted (the target is not consulted). Zero-length lines cover
// nothing (LINE.AA.ZERO_LENGTH). The result is a function of the line's point set and the
// pixel only: it is identical for b -> a, and mirroring the line and the pixel in x or y
// gives the identical value (the computation runs in a canonical frame).
// rule: LINE.AA.COVERAGE, LINE.AA.FRAGMENT, LINE.AA.PRECISION
[[nodiscard]] AACoverage aa_line_coverage(Vec2 a, Vec2 b, std::int32_t px, std::int32_t py);

// Returns the 8-bit UNORM blend of one colour channel: dst + (src - dst) * alpha with
// alpha = (src_alpha / 255) * (coverage_q16 / 65536), computed exactly and rounded to the
// nearest integer, halves up. coverage_q16 must be <= 65536.
// rule: LINE.AA.BLEND
[[nodiscard]] std::uint8_t aa_blend_unorm8(std::uint8_t src, std::uint8_t src_alpha,
                                           std::uint8_t dst, std::uint32_t coverage_q16);

} // namespace rastrules
