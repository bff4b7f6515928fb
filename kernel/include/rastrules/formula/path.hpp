// SPDX-License-Identifier: MIT
// The per-edge crossing test of 2D paths on raw subpixel integers (16.8): whether a line edge
// crosses the horizontal line through a displaced sample (PATH.SAMPLE.TIE) and in which
// direction. Generic over Num and branch-free, so that the kernel evaluates it with
// std::int64_t and the proofs (proofs/path/) with z3 terms.
// Implements: PATH.SAMPLE.TIE, PATH.BUDGET.LINE

#pragma once

namespace rastrules::formula {

// Returns whether the line edge from height y0 to height y1 crosses the horizontal line
// y = sy + hy delta (delta -> 0+), where hy = +1 when YDown (top-left, top-right) and -1
// otherwise (bottom-left, bottom-right): half-open in y, [min, max) for YDown, (min, max]
// otherwise. A horizontal edge never crosses.
// Units: raw 16.8.
// rule: PATH.SAMPLE.TIE
template <bool YDown, class Num> constexpr auto path_edge_spans(Num y0, Num y1, Num sy) {
  if constexpr (YDown) {
    return ((y0 <= sy) && (sy < y1)) || ((y1 <= sy) && (sy < y0));
  } else {
    return ((y0 < sy) && (sy <= y1)) || ((y1 < sy) && (sy <= y0));
  }
}

// Returns whether the crossing of an edge running from height y0 to y1 (y0 != y1) lies right
// of the displaced sample s + hx eps, given E = edge_value(edge, s) = (x_c - s.x)(y1 - y0):
// x_c > s.x, or x_c == s.x and hx = -1 (XRight is hx = +1: top-left, bottom-left).
// rule: PATH.SAMPLE.TIE
template <bool XRight, class Num> constexpr auto path_crossing_right(Num e, Num y0, Num y1) {
  const Num zero = e - e;
  if constexpr (XRight) {
    return ((y1 > y0) && (e > zero)) || ((y1 < y0) && (e < zero));
  } else {
    return ((y1 > y0) && (e >= zero)) || ((y1 < y0) && (e <= zero));
  }
}

// Returns N = x_c * (yb - ya) for an edge given top end first, (xa, ya) -> (xb, yb) with
// ya < yb (the kernel orients each edge so before calling): the crossing's x at height sy,
// scaled by D = yb - ya > 0 (exact: x_c = N / D). With it a whole row of samples is tested at
// once: the crossing counts for a sample at raw x iff x * D < N (hx = +1) or x * D <= N
// (hx = -1), that is x <= ceil(N / D) - 1 or x <= floor(N / D).
// Units: raw 16.8 squared; |N| < 2^49 for coordinates in [-2^23, 2^23] (PATH.BUDGET.LINE).
// rule: PATH.BUDGET.LINE
template <class Num> constexpr Num path_crossing_numerator(Num xa, Num ya, Num xb, Num yb, Num sy) {
  return xa * (yb - ya) + (sy - ya) * (xb - xa);
}

} // namespace rastrules::formula
