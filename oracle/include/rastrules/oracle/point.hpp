// SPDX-License-Identifier: MIT
// Points and quadrilateral lines written a second time, for machines: exact, slow,
// independent. Written from spec/rules/point.md and spec/rules/line_quad.md with GMP integers
// and rationals; never includes or calls kernel code, and shares none of its types.
// Implements (as oracle): POINT.RANGE, POINT.SHAPE.SQUARE, POINT.COVER.HALF_OPEN,
//   LINE.QUAD.WIDTH, LINE.QUAD.CORNERS, LINE.QUAD.SHAPE, LINE.QUAD.ZERO_LENGTH

#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace rastrules::oracle {

// A position in raw 16.8 units (1/256 px), y down.
using Raw2 = std::array<std::int64_t, 2>;

// Returns whether a point centre (raw) lies in the range POINT.RANGE states in pixels:
// [-32767.5, 32767.49609375] in both coordinates.
bool point_in_range(const Raw2& centre);

// Returns whether the point with snapped centre c covers the sample s (both raw), decided on
// the exact square [cx - 1/2, cx + 1/2] x [cy - 1/2, cy + 1/2] px with the sides the fill
// convention (spelled as in spec/scene.md: "top-left", ...) makes inclusive: left side for
// *-left, right side for *-right, top side for top-*, bottom side for bottom-*.
bool point_covers(const Raw2& c, const Raw2& s, const std::string& fill);

// Returns the rounded corner offset of the quadrilateral line a -> b in mode "quad-wide"
// (width 7/5 px) or "quad-narrow" (1 px): each component of (w/2) (-dy, dx) / |d| rounded to
// the nearest integer (raw), ties to even, found with GMP integer square roots.
// Preconditions: a != b.
Raw2 quad_line_offset(const Raw2& a, const Raw2& b, const std::string& mode);

// Returns the four corners a - o, b - o, b + o, a + o (clockwise, y down) of the
// quadrilateral line a -> b, or nothing when a == b.
std::vector<Raw2> quad_line_corners(const Raw2& a, const Raw2& b, const std::string& mode);

// Returns whether the quadrilateral line a -> b covers sample s: s inside the parallelogram of
// quad_line_corners, with each side classified top / bottom / left / right by the spec's
// words and the fill convention deciding which sides include their samples. False when a == b.
bool quad_line_covers(const Raw2& a, const Raw2& b, const std::string& mode, const Raw2& s,
                      const std::string& fill);

} // namespace rastrules::oracle
