// SPDX-License-Identifier: MIT
// The integer expressions of the cell method of exact area coverage (kernel/src/path_area.cpp,
// PATH.AREA.CELLS): where a line edge meets the grid lines of a pixel row, its crossings' positions
// on a cell's border, the tests that two edges meet in a cell or double back, and one edge's
// part of a cell's integral of the winding number. Generic over the integer types I (the
// kernel's std::int64_t) and W (its __int128) and branch-free (`select(c, t, f)` is c ? t : f),
// so that the kernel evaluates them on integers and the proofs (proofs/path/area_budget.cpp) on
// z3 terms, with an obligation that every result fits its type.
// Implements: PATH.AREA.CELLS

#pragma once

#include <array>
#include <cstdint>

#include "rastrules/fixed.hpp"

namespace rastrules::formula {

// A pixel's side in raw units.
inline constexpr std::int64_t kCellSide = kSubpixelOne;

// Returns x at height y of the line edge from (x0, y0) with run (dx, dy), dy != 0, times
// |dy| = dy dir (dir = sgn dy): the edge's x at y is cell_x_numerator / |dy| exactly.
// |.| <= 2^23 2^24 + 2^24 2^24 < 2^49 for |raw| <= 2^23 and y within the edge's y-range.
// rule: PATH.AREA.CELLS
template <class I> constexpr I cell_x_numerator(I x0, I y0, I dx, I dy, I dir, I y) {
  return (x0 * dy + (y - y0) * dx) * dir;
}

// Returns y at x of the edge times |dx| = dx sdx (dx != 0, sdx = sgn dx), as cell_x_numerator
// with the axes exchanged.
// rule: PATH.AREA.CELLS
template <class I> constexpr I cell_y_numerator(I x0, I y0, I dx, I dy, I sdx, I x) {
  return (y0 * dx + (x - x0) * dy) * sdx;
}

// Positions on a cell's border, clockwise from its top-left corner (top side [0, kW], right
// [kW, 2 kW], bottom [2 kW, 3 kW], left [3 kW, 4 kW]), times the crossing's denominator q > 0.
// Cell (col, row) spans x in [col kW, col kW + kW] and y in [top, top + kW].
//
// Top side, at x = xn / q: (x - col kW) q.
// rule: PATH.AREA.CELLS
template <class I> constexpr I cell_top_position(I xn, I col, I q) {
  return xn - col * I(kCellSide) * q;
}
// Right side, at y = yn / q: (kW + y - top) q.
// rule: PATH.AREA.CELLS
template <class I> constexpr I cell_right_position(I yn, I top, I q) {
  return (I(kCellSide) - top) * q + yn;
}
// Bottom side, at x = xn / q: (2 kW + col kW + kW - x) q.
// rule: PATH.AREA.CELLS
template <class I> constexpr I cell_bottom_position(I xn, I col, I q) {
  return (I(2 * kCellSide) + col * I(kCellSide) + I(kCellSide)) * q - xn;
}
// Left side, at y = yn / q: (3 kW + top + kW - y) q.
// rule: PATH.AREA.CELLS
template <class I> constexpr I cell_left_position(I yn, I top, I q) {
  return (I(3 * kCellSide) + top + I(kCellSide)) * q - yn;
}

// Returns whether crossing a precedes crossing b on the border (q, d > 0): its position
// pa / qa first, then, at one position, its tie order sa / da; by cross products in W.
// rule: PATH.AREA.CELLS
template <class W, class I>
constexpr auto cell_border_before(I pa, I qa, I sa, I da, I pb, I qb, I sb, I db) {
  const W lhs = W(pa) * W(qb), rhs = W(pb) * W(qa);
  return lhs < rhs || (lhs == rhs && W(sa) * W(db) < W(sb) * W(da));
}

// Returns whether edges with runs (ex, ey) and (fx, fy) are collinear and point in opposite
// directions (a contour that doubles back). Products |.| <= 2^48 for runs within 2^24.
// rule: PATH.AREA.CELLS
template <class I> constexpr auto cell_doubles_back(I ex, I ey, I fx, I fy) {
  return ex * fy - ey * fx == I(0) && ex * fx + ey * fy < I(0);
}

// The common point of two segments that are not parallel, from the orientations o3, o4 of the
// ends of e (x0, y0) -> (x1, y1) against the other segment's line: e(u) with u = o3 / (o3 - o4),
// as (nx / den, ny / den) with den > 0.
template <class W> struct CellMeetPoint { W nx, ny, den; };
// rule: PATH.AREA.CELLS
template <class W, class Select>
constexpr CellMeetPoint<W> cell_meet_point(W x0, W y0, W x1, W y1, W o3, W o4, Select select) {
  const W den = o3 - o4;
  const W nx = x0 * den + o3 * (x1 - x0);
  const W ny = y0 * den + o3 * (y1 - y0);
  const auto neg = den < W(0);
  return {select(neg, -nx, nx), select(neg, -ny, ny), select(neg, -den, den)};
}
// Whether that point lies in the closed cell [left, left + kW] x [top, top + kW].
// rule: PATH.AREA.CELLS
template <class W> constexpr auto cell_meet_inside(const CellMeetPoint<W>& m, W left, W top) {
  const W side(kCellSide);
  return m.nx >= left * m.den && m.nx <= (left + side) * m.den && m.ny >= top * m.den &&
         m.ny <= (top + side) * m.den;
}

// The integral over y in [ya, ya + h] of max(x(y) - lo, 0), x linear from pa / q to pb / q,
// times 2 q |dx| (adx = |dx| != 0, |pb - pa| = h adx): the edge's part of the ramp at column
// line lo. A cell's part is the ramp at its left line less the ramp at its right line.
// rule: PATH.AREA.CELLS
template <class W, class Select>
constexpr W cell_ramp_integral(W pa, W pb, W q, W h, W adx, W lo, Select select) {
  const W zero(0);
  const W ua = pa - lo * q;
  const W ub = pb - lo * q;
  const W up = select(ua > zero, ua, ub);
  const W trapezoid = h * (ua + ub) * adx;
  const W triangle = up * up;
  return select(ua >= zero && ub >= zero, trapezoid,
                select(ua <= zero && ub <= zero, zero, triangle));
}

} // namespace rastrules::formula
