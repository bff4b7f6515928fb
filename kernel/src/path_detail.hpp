// SPDX-License-Identifier: MIT
// The path kernel's internal pieces shared by its translation units: the boundary as line
// edges and curves (closing lines added), the tie signs of a fill convention, and one crossing
// of a sample row.

#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rastrules/path.hpp"

namespace rastrules::path::detail {

// The displacement signs of PATH.SAMPLE.TIE: x_right is hx = +1, y_down is hy = +1.
struct Tie {
  bool x_right = true;
  bool y_down = true;
};
[[nodiscard]] Tie tie_of(FillConvention f);

// A directed line edge, raw 16.8.
// contour and segment say which piece of the path it is (segment == the contour's segment count
// for its closing line).
struct Edge {
  std::int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  std::size_t contour = 0, segment = 0;
};

// A quadratic (degree 2, p[0..2]) or cubic (degree 3, p[0..3]) Bézier curve, start point
// first.
struct Curve {
  int degree = 2;
  std::array<Point, 4> p{};
  std::size_t contour = 0, segment = 0;
};

// The boundary of a path: every line segment and closing line (PATH.CONTOUR.CLOSE), and every
// curve, each directed as drawn.
struct Boundary {
  std::vector<Edge> lines;
  std::vector<Curve> curves;
};
[[nodiscard]] Boundary boundary_of(const Path& path);
// The same into b (cleared first; no allocation once b has room).
void boundary_into(const Path& path, Boundary& b);

// One crossing of the displaced horizontal line through a sample row: it counts for a sample
// at raw x iff x <= threshold (PATH.SAMPLE.TIE: x_c > x, or x_c == x and hx = -1); dir is +1
// where the boundary runs down, -1 up.
struct Crossing {
  std::int64_t threshold = 0;
  int dir = 0;
  [[nodiscard]] bool counts_at(std::int64_t x) const { return x <= threshold; }
};

// Returns the crossings of curve c with the line y = sy + hy delta (delta -> 0+), exactly
// (PATH.CURVE.SAMPLE; kernel/src/path_curve.cpp).
[[nodiscard]] std::vector<Crossing> curve_crossings(const Curve& c, std::int64_t sy, Tie t);

// The same by the rational path alone (no integer fast path): curve_crossings must equal it,
// which tests/path checks. fast = false is this; curve_crossings is fast = true.
[[nodiscard]] std::vector<Crossing> curve_crossings_exact(const Curve& c, std::int64_t sy, Tie t);
// Either, into out (cleared first; no allocation once out has room, so the row walk reuses one
// vector); fast chooses whether the integer paths are tried first.
void curve_crossings_into(const Curve& c, std::int64_t sy, Tie t, bool fast,
                          std::vector<Crossing>& out);
// The integer paths alone (no rational path), into out (cleared first): false, with out empty,
// where they leave the row to the rational path. tests/path checks which rows they decide.
[[nodiscard]] bool curve_crossings_integer(const Curve& c, std::int64_t sy, Tie t,
                                           std::vector<Crossing>& out);

// What the crossings of one curve with every row share, computed once (prepare_curve): the
// power coefficients of x and y, x's Lipschitz bound and filter bound (PATH.CURVE.FILTER), the
// cuts of [0, 1] at the estimated roots of y', and the control points' y-range.
struct PreparedCurve {
  const Curve* curve = nullptr;
  std::int64_t ymin = 0, ymax = 0;
  std::array<std::int64_t, 4> y{}, x{};
  std::int64_t x_lipschitz = 0;
  std::int64_t y_abs_rest = 0; // |y1| + |y2| + |y3|, for g's filter bound
  double x_bound = 0.0;
  std::array<double, 4> cut{};
  int cuts = 1;
};
void prepare_curve(const Curve& c, PreparedCurve& p);
// The crossings of curve_crossings_into (fast), from a prepared curve: the same crossings,
// appended to out (scratch: room for the unprepared path, when the estimates give up).
void curve_crossings_prepared(const PreparedCurve& p, std::int64_t sy, Tie t,
                              std::vector<Crossing>& out, std::vector<Crossing>& scratch);

} // namespace rastrules::path::detail
