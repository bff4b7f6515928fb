// SPDX-License-Identifier: MIT
// 2D paths: contours of lines and quadratic and cubic Bézier curves, filled under the nonzero
// or even-odd rule, with exact sample coverage (every fill convention, every sample pattern)
// and exact area coverage. Rules: spec/rules/path.md.
// Implements: PATH.GEOMETRY, PATH.CONTOUR.CLOSE, PATH.WINDING, PATH.FILL.RULE,
//             PATH.SAMPLE.TIE, PATH.COVER.SAMPLE, PATH.AREA.EXACT, PATH.DEGENERATE,
//             PATH.CURVE.SAMPLE
// Needs, beyond the standard library, Boost.Multiprecision's headers (exact rational areas).

#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

#include "rastrules/msaa.hpp"
#include "rastrules/name_table.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules::path {

// A snapped position: raw 16.8 (1/256 px), y down; |x|, |y| <= 2^23.
// rule: PATH.GEOMETRY
struct Point {
  std::int32_t x = 0, y = 0;
  friend constexpr bool operator==(const Point&, const Point&) = default;
};

enum class SegmentKind { kLine, kQuadratic, kCubic };

// line: p[0] = end; quadratic: p[0] control, p[1] end; cubic: p[0], p[1] controls, p[2] end.
// rule: PATH.GEOMETRY
struct Segment {
  SegmentKind kind = SegmentKind::kLine;
  std::array<Point, 3> p{};
  friend bool operator==(const Segment&, const Segment&) = default;
};

// A start point and segments; closed for filling by a line back to the start
// (PATH.CONTOUR.CLOSE).
struct Contour {
  Point start;
  std::vector<Segment> segments;
  friend bool operator==(const Contour&, const Contour&) = default;
};

// rule: PATH.FILL.RULE
enum class FillRule { kNonZero, kEvenOdd };

struct Path {
  FillRule fill_rule = FillRule::kNonZero;
  std::vector<Contour> contours;
  friend bool operator==(const Path&, const Path&) = default;
};

// Returns whether the fill rule holds for winding number w: w != 0 (nonzero), w odd (evenodd,
// negative w included).
// rule: PATH.FILL.RULE
[[nodiscard]] constexpr bool fill_holds(FillRule rule, std::int64_t w) {
  return rule == FillRule::kNonZero ? w != 0 : (w & 1) != 0;
}

// Returns w(s') of PATH.SAMPLE.TIE for the sample at raw position s: the winding number at s
// displaced by (hx eps, hy delta), delta << eps, (hx, hy) from the fill convention.
// rule: PATH.WINDING, PATH.SAMPLE.TIE
[[nodiscard]] std::int64_t winding_number(const Path& path, Point s, FillConvention fill);

// Returns whether the path covers the sample at raw position s (PATH.SAMPLE.TIE).
// rule: PATH.SAMPLE.TIE, PATH.FILL.RULE
[[nodiscard]] bool covers_sample(const Path& path, Point s, FillConvention fill);

// One pixel with at least one covered sample: bit k of mask is sample k of the pattern.
struct SampleCoverage {
  std::int32_t x = 0, y = 0;
  std::uint32_t mask = 0;
  friend bool operator==(const SampleCoverage&, const SampleCoverage&) = default;
};

// Returns every pixel of [0, w) x [0, h) with at least one covered sample, row by row (y, then
// x). Computes no area. Preconditions: 0 <= w, h <= kMaxTargetSide.
// rule: PATH.COVER.SAMPLE
[[nodiscard]] std::vector<SampleCoverage> cover_samples(const Path& path,
                                                        const SamplePattern& pattern,
                                                        FillConvention fill, std::int32_t w,
                                                        std::int32_t h);

// One pixel with nonzero area: area in px^2 as a reduced rational, exact (error_bound 0) for
// paths of lines; for curves within error_bound of the exact area.
struct AreaCoverage {
  std::int32_t x = 0, y = 0;
  boost::multiprecision::cpp_rational area;
  boost::multiprecision::cpp_rational error_bound;
  friend bool operator==(const AreaCoverage&, const AreaCoverage&) = default;
};

// Returns every pixel of [0, w) x [0, h) with nonzero area under the fill rule, row by row.
// Preconditions: 0 <= w, h <= kMaxTargetSide. Paths with curves are not supported yet: throws
// std::invalid_argument (PATH.AREA.EXACT).
// rule: PATH.AREA.EXACT
[[nodiscard]] std::vector<AreaCoverage> cover_area(const Path& path, std::int32_t w,
                                                   std::int32_t h);

using rastrules::to_string;

} // namespace rastrules::path

namespace rastrules {
template <> struct Names<path::FillRule> {
  static constexpr auto table = in_enum_order<path::FillRule>({"nonzero", "evenodd"});
};
template <> struct Names<path::SegmentKind> {
  static constexpr auto table = in_enum_order<path::SegmentKind>({"line", "quadratic", "cubic"});
};
} // namespace rastrules
