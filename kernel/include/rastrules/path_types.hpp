// SPDX-License-Identifier: MIT
// The geometry of 2D paths (spec/rules/path.md): snapped points, segments, contours, the fill
// rule and the coverage kind a path primitive asks for. Standard library only: the scene model
// holds these; the rasterizer of paths is rastrules/path.hpp.
// Implements: PATH.GEOMETRY, PATH.FILL.RULE, SCENE.PRIM.PATH

#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "rastrules/name_table.hpp"

namespace rastrules::path {

// A snapped position: raw 16.8 (1/256 px), y down; |x|, |y| <= 2^23.
// rule: PATH.GEOMETRY
struct Point {
  std::int32_t x = 0, y = 0;
  friend constexpr bool operator==(const Point&, const Point&) = default;
};

enum class SegmentKind { kLine, kQuadratic, kCubic };

// Returns the number of points a segment of kind k gives after its start: 1, 2 or 3.
[[nodiscard]] constexpr std::size_t point_count(SegmentKind k) {
  return k == SegmentKind::kLine ? 1 : k == SegmentKind::kQuadratic ? 2 : 3;
}

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

// What a path primitive's fragments carry: the samples it covers (PATH.COVER.SAMPLE), or the
// exact area of each pixel it covers (PATH.AREA.EXACT).
// rule: SCENE.PRIM.PATH
enum class Coverage { kSamples, kArea };

// Returns whether the fill rule holds for winding number w: w != 0 (nonzero), w odd (evenodd,
// negative w included).
// rule: PATH.FILL.RULE
[[nodiscard]] constexpr bool fill_holds(FillRule rule, std::int64_t w) {
  return rule == FillRule::kNonZero ? w != 0 : (w & 1) != 0;
}

} // namespace rastrules::path

namespace rastrules {
template <> struct Names<path::FillRule> {
  static constexpr auto table = in_enum_order<path::FillRule>({"nonzero", "evenodd"});
};
template <> struct Names<path::SegmentKind> {
  static constexpr auto table = in_enum_order<path::SegmentKind>({"line", "quadratic", "cubic"});
};
template <> struct Names<path::Coverage> {
  static constexpr auto table = in_enum_order<path::Coverage>({"samples", "area"});
};
} // namespace rastrules
