// SPDX-License-Identifier: MIT
// Antialiased-line formulas, branch-free and generic over Num so that the same source is
// evaluated on integers by the kernel (kernel/src/line_aa.cpp) and on Z3 terms by the proofs
// (proofs/line_aa/).
// Implements: LINE.AA.FRAGMENT (exact comparison with a square root), LINE.AA.BLEND

#pragma once

namespace rastrules::formula {

// Returns whether v * sqrt(D) < w, for D > 0 and w >= 0, without the square root: when v < 0
// the left side is negative and the right side is not; otherwise both sides are >= 0 and the
// comparison survives squaring. Used with v, w, D such that v^2 D and w^2 fit the type.
// rule: LINE.AA.FRAGMENT
template <class Num> constexpr auto times_sqrt_less(Num v, Num w, Num D) {
  return (v < 0) || (v * v * D < w * w);
}

// Returns N = dst * den + (src - dst) * src_alpha * coverage: with den = 255 * 65536, N / den is
// the blended value dst + (src - dst) * (src_alpha / 255) * (coverage / 65536) in units of
// 1/255 (8-bit UNORM), exactly.
// rule: LINE.AA.BLEND
template <class Num>
constexpr Num aa_blend_numerator(Num src, Num src_alpha, Num dst, Num coverage, Num den) {
  return dst * den + (src - dst) * src_alpha * coverage;
}

} // namespace rastrules::formula
