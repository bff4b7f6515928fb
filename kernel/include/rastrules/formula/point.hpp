// SPDX-License-Identifier: MIT
// Point formulas on raw subpixel integers (16.8): the range test and the two triangles of the
// point square in the Z pattern. Generic over Num, branch-free, so that the kernel evaluates it
// with std::int64_t and the proofs (proofs/point/) with z3 terms.
// Implements: POINT.RANGE, POINT.SHAPE.SQUARE, POINT.SHAPE.TWO_TRIANGLES

#pragma once

#include <array>

namespace rastrules::formula {

// Returns whether the snapped centre (cx, cy) lies in [lo, hi] in both coordinates, where
// [lo, hi] is [kMinPointRaw, kMaxPointRaw]: the square around it then lies in SNAP.VERTEX.RANGE.
// rule: POINT.RANGE
template <class Num> constexpr auto point_centre_in_range(Num cx, Num cy, Num lo, Num hi) {
  return (lo <= cx) && (cx <= hi) && (lo <= cy) && (cy <= hi);
}

// A corner (x, y) of the point square, raw 16.8.
template <class Num> using PointCorner = std::array<Num, 2>;
template <class Num> using PointTriangle = std::array<PointCorner<Num>, 3>;

// Returns the two triangles of the point square with centre (cx, cy) and half side `half`
// (kSubpixelHalf: the square is one pixel wide), in the Z pattern of D3D11.3's point diagram:
// the corners in Z order are top-left TL, top-right TR, bottom-left BL, bottom-right BR, the
// shared diagonal runs from BL to TR, and the triangles are (TL, TR, BL) and (BL, TR, BR), both
// clockwise on screen (y down) and non-degenerate.
// Units: raw 16.8 in and out.
// rule: POINT.SHAPE.SQUARE, POINT.SHAPE.TWO_TRIANGLES
template <class Num>
constexpr std::array<PointTriangle<Num>, 2> point_z_triangles(Num cx, Num cy, Num half) {
  const Num left = cx - half;
  const Num right = cx + half;
  const Num top = cy - half;
  const Num bottom = cy + half;
  const PointCorner<Num> tl{left, top};
  const PointCorner<Num> tr{right, top};
  const PointCorner<Num> bl{left, bottom};
  const PointCorner<Num> br{right, bottom};
  return {PointTriangle<Num>{tl, tr, bl}, PointTriangle<Num>{bl, tr, br}};
}

} // namespace rastrules::formula
