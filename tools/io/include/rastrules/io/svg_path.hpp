// SPDX-License-Identifier: MIT
// SVG path data ("M 0 0 L 4 4 Q 6 0 8 4 Z") read into contours of float32 control points, for
// path primitives (spec/scene.md SCENE.PATH.DATA). A reader of text, not a rasterizer: the
// points it returns are snapped and filled by the kernel's path rules (PATH.*).
// Implements: SCENE.PATH.DATA

#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace rastrules::io {

// A control point as read: float32 window coordinates, and where its x number begins in the
// text (a character offset from 0, for messages about the point).
struct SvgPoint {
  float x = 0.0f;
  float y = 0.0f;
  std::size_t at = 0;
};

enum class SvgSegmentKind { kLine, kQuadratic, kCubic };

// p[0] the end of a line; p[0] the control and p[1] the end of a quadratic; p[0], p[1] the
// controls and p[2] the end of a cubic.
struct SvgSegment {
  SvgSegmentKind kind = SvgSegmentKind::kLine;
  std::array<SvgPoint, 3> p{};
};

// A contour: its start and its segments. Filling closes every contour (PATH rules), so "Z"
// changes where the next contour starts, not the contour itself.
struct SvgContour {
  SvgPoint start;
  std::vector<SvgSegment> segments;
};

// Bad path data: the character offset where reading stopped and what is wrong there
// ("expected a number after 'L'", "arcs ('A') are not supported", ...).
struct SvgPathError {
  std::size_t at = 0;
  std::string problem;
  // "at character N: problem" (N counted from 0).
  [[nodiscard]] std::string what() const;
};

// Reads path data with the commands M m L l H h V v Q q T t C c S s Z z. Numbers follow SVG's
// grammar (an optional sign, digits with an optional point, an optional exponent; "1-2" and
// "0.5.5" are two numbers each) and are read as float32, correctly rounded from their text
// (SCENE.NUMBER.FLOAT32); a relative coordinate is added to the current point in float32
// arithmetic, and the reflected control point of T and S is 2 * current - previous in float32
// (one rounding each). Fails on arcs, on anything else, on a number that is not finite in
// float32, and when the path has more than max_segments segments. An empty text is a path
// without contours.
// rule: SCENE.PATH.DATA
[[nodiscard]] std::variant<std::vector<SvgContour>, SvgPathError>
parse_svg_path(std::string_view d, std::size_t max_segments);

} // namespace rastrules::io
