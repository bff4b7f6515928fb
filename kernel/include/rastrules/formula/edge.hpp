// SPDX-License-Identifier: MIT
// Edge-function formulas on raw subpixel integers (format 16.8 in, 32.16 out).
// Generic over Num so that the same source is evaluated with std::int64_t by the kernel and
// with z3::expr terms by the proofs (which is why everything here is branch-free).
// Implements: TRI.EDGE.FUNCTION, TRI.ORIENT.AREA, TRI.FILL.TOP_EDGE, TRI.FILL.LEFT_EDGE,
//             TRI.FILL.CONVENTION, FIX.BIAS.FORM, FIX.STEP.INCREMENTAL

#pragma once

namespace rastrules::formula {

// Returns E_ab(p) = (b - a) x (p - a) for the directed edge (a -> b). In y-down window space
// it is positive when p lies to the right of the edge direction, which is the interior side of
// every edge of a clockwise-on-screen triangle.
// Units: inputs 1/256 px, result 1/65536 px^2.
// rule: TRI.EDGE.FUNCTION
template <class Num> constexpr Num edge_value(Num ax, Num ay, Num bx, Num by, Num px, Num py) {
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

// Returns twice the signed area of triangle (v0, v1, v2): positive when the vertices run
// clockwise on screen (y down), negative counter-clockwise, zero when degenerate.
// rule: TRI.ORIENT.AREA
template <class Num>
constexpr Num twice_signed_area(Num x0, Num y0, Num x1, Num y1, Num x2, Num y2) {
  return edge_value(x0, y0, x1, y1, x2, y2);
}

// Returns whether the directed edge (a -> b) of a clockwise triangle is a top edge: exactly
// horizontal and running in +x, so that the interior lies below it (y down).
// rule: TRI.FILL.TOP_EDGE
template <class Num> constexpr auto is_top_edge(Num ax, Num ay, Num bx, Num by) {
  return (by == ay) && (bx > ax);
}

// Returns whether the directed edge (a -> b) of a clockwise triangle is a left edge: not
// horizontal and running up the screen (-y), so that the interior lies to its right.
// rule: TRI.FILL.LEFT_EDGE
template <class Num> constexpr auto is_left_edge(Num ax, Num ay, Num bx, Num by) {
  (void)ax;
  (void)bx;
  return by < ay;
}

// Returns whether samples exactly on the directed edge (a -> b) of a clockwise triangle are
// inside, under the fill convention chosen by the two flags:
//   TopInclusive:  horizontal edges with the interior below are inclusive (else those above);
//   LeftInclusive: non-horizontal edges with the interior to the right are inclusive (else left).
// <true, true> is D3D's top-left rule.
// rule: TRI.FILL.CONVENTION, TRI.FILL.TOP_LEFT
template <bool TopInclusive, bool LeftInclusive, class Num>
constexpr auto is_inclusive_edge(Num ax, Num ay, Num bx, Num by) {
  const auto horizontal = (by == ay);
  const auto h_ok = TopInclusive ? (bx > ax) : (bx < ax);
  const auto v_ok = LeftInclusive ? (by < ay) : (by > ay);
  return (horizontal && h_ok) || (!horizontal && v_ok);
}

// The bias form used by the traversal: a sample is inside an edge iff E + bias >= 0, where
// bias is 0 for an inclusive edge and -1 (one unit of 1/65536 px^2) otherwise. Equal to
// `E > 0 || (E == 0 && inclusive)` because E is an integer (proofs/tri/bias_form.cpp).
// rule: FIX.BIAS.FORM
template <class Num> constexpr Num edge_bias(bool inclusive) {
  return inclusive ? Num(0) : Num(-1);
}

// One-pixel steps of E: E(p + (256, 0)) = E(p) + step_x, E(p + (0, 256)) = E(p) + step_y.
// rule: FIX.STEP.INCREMENTAL
template <class Num> constexpr Num edge_step_x(Num ay, Num by, Num one) {
  return (ay - by) * one;
}
template <class Num> constexpr Num edge_step_y(Num ax, Num bx, Num one) {
  return (bx - ax) * one;
}

} // namespace rastrules::formula
