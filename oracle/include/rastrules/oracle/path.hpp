// SPDX-License-Identifier: MIT
// 2D paths written a second time, for machines: exact, slow, independent. Written from the
// path definitions (spec/rules/path.md: winding number, fill rules, the boundary convention at
// s + (sx eps, sy delta) with delta << eps, which on lines is s + (sx e, sy e^2), exact area
// coverage) with GMP rationals, Sturm-Tarski queries and a CGAL arrangement; never includes or
// calls kernel code, and shares none of its types: everything is plain integers and strings.
// Implements (as oracle): PATH.GEOMETRY, PATH.CONTOUR.CLOSE, PATH.WINDING, PATH.FILL.RULE,
//   PATH.SAMPLE.TIE, PATH.COVER.SAMPLE, PATH.AREA.EXACT, PATH.DEGENERATE

#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "rastrules/oracle/msaa.hpp"

namespace rastrules::oracle::path {

// A position in raw 16.8 units (1/256 px), y down, already snapped (|raw| <= 2^23).
using Raw2 = std::array<std::int64_t, 2>;

enum class PieceKind { kLine, kQuadratic, kCubic };

// One segment of a contour: `to` holds the control points, then the end point (1, 2 or 3
// points for a line, a quadratic and a cubic Bezier); it starts where the previous one ended.
struct Piece {
  PieceKind kind = PieceKind::kLine;
  std::vector<Raw2> to;
};

// A contour: a start point and its pieces; closed for filling by a straight line from its last
// point back to its start.
struct Contour {
  Raw2 start{};
  std::vector<Piece> pieces;
};

// fill_rule: "nonzero" | "evenodd".
struct Path {
  std::string fill_rule = "nonzero";
  std::vector<Contour> contours;
};

// Returns whether the fill rule ("nonzero" | "evenodd") holds for winding number w; throws
// std::invalid_argument for another string.
bool fills(const std::string& fill_rule, std::int64_t w);

// Returns the winding number of the displaced sample s' = s + (sx eps, sy delta), delta << eps
// (for lines the same as s + (sx e, sy e^2), e -> 0+), with
// (sx, sy) from the fill convention ("top-left" (+1, +1), "top-right" (-1, +1), "bottom-left"
// (+1, -1), "bottom-right" (-1, -1)). Lines are decided by the contract's words (half-open in
// y, the crossing's x at the sample's height strictly right of it, ties to the right only when
// sx = -1); curves by exact root isolation of y(t) = s.y (see path.cpp for the reading of the
// infinitesimals on curves).
std::int64_t winding(const Path& p, const Raw2& s, const std::string& fill);

// The same winding number with every piece, lines included, decided by the curve algorithm
// (exact roots of y(t) - s.y by Sturm-Tarski queries): a second derivation for lines.
std::int64_t winding_by_roots(const Path& p, const Raw2& s, const std::string& fill);

// Returns whether the sample at s is covered: fills(p.fill_rule, winding(p, s, fill)).
bool covers(const Path& p, const Raw2& s, const std::string& fill);

struct SampleMask {
  std::int32_t x = 0;
  std::int32_t y = 0;
  std::uint32_t mask = 0; // bit k: sample k of the pattern
  friend bool operator==(const SampleMask&, const SampleMask&) = default;
};

// Returns every pixel of [0, w) x [0, h) with at least one covered sample, in row order (y, then
// x), by testing every sample of every pixel (positions from msaa::sample_raw).
std::vector<SampleMask> cover_samples(const Path& p, const std::vector<msaa::Offset>& pattern,
                                      const std::string& fill, std::int32_t w, std::int32_t h);

// The exact area (px^2) of {q in the pixel : the fill rule holds at w(q)}, a reduced rational
// written in decimal ("num", "den", den > 0).
struct PixelArea {
  std::int32_t x = 0;
  std::int32_t y = 0;
  std::string num;
  std::string den;
  double approx = 0.0; // for messages only
};

// Returns every pixel of [0, w) x [0, h) with nonzero area, in row order, for a path of lines
// only: a CGAL arrangement of the path's segments and the pixel grid lines, the winding number
// of every face propagated from the unbounded face across edges by the direction of the path
// segments on them, and the exact area of every face where the fill rule holds, summed per
// pixel. Throws std::invalid_argument when the path has a curve.
std::vector<PixelArea> cover_area(const Path& p, std::int32_t w, std::int32_t h);

// The area of a pixel for a path with curves, certified: the exact area of the path with every
// curve replaced by the chords of its 2^depth pieces (de Casteljau at t = 1/2, exact), and a
// bound (px^2) on its distance from the exact area of the curved path: the sum of the hull
// areas of the pieces whose box meets the pixel.
struct PixelAreaBound {
  PixelArea area;
  std::string bound_num;
  std::string bound_den;
  double bound_approx = 0.0;
};

// Returns every pixel of [0, w) x [0, h) with a nonzero area or bound, in row order; for a path
// of lines, the exact areas with bound 0. depth in [0, 16]. The bound shrinks about 8 times per
// level (pieces half as long and a quarter as far from their chords; twice as many).
std::vector<PixelAreaBound> cover_area_bounded(const Path& p, std::int32_t w, std::int32_t h,
                                               int depth);

// Returns whether the path has a quadratic or cubic piece.
bool has_curves(const Path& p);

} // namespace rastrules::oracle::path
