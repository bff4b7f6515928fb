// SPDX-License-Identifier: MIT
// Examples of the SVG path data reader (spec/scene.md SCENE.PATH.DATA).

#include <gtest/gtest.h>

#include <string>
#include <variant>
#include <vector>

#include "rastrules/io/svg_path.hpp"

namespace {

using rastrules::io::parse_svg_path;
using rastrules::io::SvgContour;
using rastrules::io::SvgPathError;
using rastrules::io::SvgSegmentKind;

std::vector<SvgContour> read_ok(const std::string& d) {
  auto r = parse_svg_path(d, 1000);
  if (const auto* e = std::get_if<SvgPathError>(&r)) {
    ADD_FAILURE() << d << ": " << e->what();
    return {};
  }
  return std::get<std::vector<SvgContour>>(r);
}

std::string read_error(const std::string& d, std::size_t max = 1000) {
  auto r = parse_svg_path(d, max);
  if (const auto* e = std::get_if<SvgPathError>(&r))
    return e->what();
  ADD_FAILURE() << d << ": no error";
  return {};
}

// Every point of a contour as "x,y" (start first), for compact comparisons.
std::string points(const SvgContour& c) {
  const auto pt = [](float x, float y) {
    const auto num = [](float v) {
      std::string s = std::to_string(v);
      s.erase(s.find_last_not_of('0') + 1);
      if (s.back() == '.')
        s.pop_back();
      return s;
    };
    return num(x) + "," + num(y);
  };
  std::string out = pt(c.start.x, c.start.y);
  for (const auto& s : c.segments) {
    const int n = s.kind == SvgSegmentKind::kLine        ? 1
                  : s.kind == SvgSegmentKind::kQuadratic ? 2
                                                         : 3;
    out += s.kind == SvgSegmentKind::kLine        ? " L"
           : s.kind == SvgSegmentKind::kQuadratic ? " Q"
                                                  : " C";
    for (int k = 0; k < n; ++k)
      out += " " + pt(s.p[static_cast<std::size_t>(k)].x, s.p[static_cast<std::size_t>(k)].y);
  }
  return out;
}

// rule: SCENE.PATH.DATA
TEST(SvgPath, AbsoluteAndRelativeCommandsGiveTheSamePoints) {
  const auto abs = read_ok("M 1 2 L 4 2 H 6 V 5 Q 7 6 8 5 C 9 4 10 6 11 5 Z");
  const auto rel = read_ok("m1,2 l3,0 h2 v3 q1,1 2,0 c1-1 2,1 3,0 z");
  ASSERT_EQ(abs.size(), 1u);
  ASSERT_EQ(rel.size(), 1u);
  EXPECT_EQ(points(abs[0]), "1,2 L 4,2 L 6,2 L 6,5 Q 7,6 8,5 C 9,4 10,6 11,5");
  EXPECT_EQ(points(rel[0]), points(abs[0]));
}

// rule: SCENE.PATH.DATA
TEST(SvgPath, NumbersFollowSvgGrammar) {
  // "1-2" is two numbers, ".5.5" is .5 and .5, exponents with signs, a leading '+'.
  const auto c = read_ok("M1-2L.5.5 1e1,+2E-1 -.25 3.");
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(points(c[0]), "1,-2 L 0.5,0.5 L 10,0.2 L -0.25,3");
  // Implicit repetition: pairs after M are lines, after L more lines.
  EXPECT_EQ(points(read_ok("M0 0 1 1 2 0")[0]), "0,0 L 1,1 L 2,0");
  // A float32 correctly rounded from the text: 0.1 is 0x3DCCCCCD.
  EXPECT_EQ(read_ok("M0.1 0")[0].start.x, 0.1f);
}

// rule: SCENE.PATH.DATA
TEST(SvgPath, SmoothCurvesReflectThePreviousControlPoint) {
  const auto q = read_ok("M0 0 Q 2 4 4 0 T 8 0");
  EXPECT_EQ(points(q[0]), "0,0 Q 2,4 4,0 Q 6,-4 8,0");
  // T after a line: the control point is the current point.
  EXPECT_EQ(points(read_ok("M0 0 L 4 0 T 8 0")[0]), "0,0 L 4,0 Q 4,0 8,0");
  const auto s = read_ok("M0 0 C 1 2 3 2 4 0 S 7 -2 8 0");
  EXPECT_EQ(points(s[0]), "0,0 C 1,2 3,2 4,0 C 5,-2 7,-2 8,0");
  EXPECT_EQ(points(read_ok("M0 0 S 3 2 4 0")[0]), "0,0 C 0,0 3,2 4,0");
}

// rule: SCENE.PATH.DATA
TEST(SvgPath, ClosingStartsTheNextContourAtTheSameStart) {
  const auto c = read_ok("M 2 2 L 6 2 L 6 6 Z l 0 -2 l -2 0 z M 10 10 l 1 0 z m 1 1 l 1 0");
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(points(c[0]), "2,2 L 6,2 L 6,6");
  EXPECT_EQ(points(c[1]), "2,2 L 2,0 L 0,0");
  EXPECT_EQ(points(c[2]), "10,10 L 11,10");
  EXPECT_EQ(points(c[3]), "11,11 L 12,11"); // 'm' after 'z': relative to the closed start
  EXPECT_TRUE(read_ok("").empty());
  EXPECT_TRUE(read_ok("  \n ").empty());
  EXPECT_EQ(read_ok("M 1 1 M 2 2").size(), 2u); // a contour of one point is kept
}

// rule: SCENE.PATH.DATA, SCENE.INPUT.ERRORS
TEST(SvgPath, BadPathDataNamesThePositionAndTheProblem) {
  EXPECT_EQ(read_error("L 1 1"),
            "at character 0: path data must begin with a move ('M' or 'm'), not 'L'");
  EXPECT_EQ(read_error("M 0 0 A 1 1 0 0 1 2 2"),
            "at character 6: arcs ('A') are not supported; write them as cubic curves");
  EXPECT_EQ(read_error("M 0 0 L 1"), "at character 9: expected a number after 'L', found the end");
  EXPECT_EQ(read_error("M 0 0 L 1 x"), "at character 10: expected a number after 'L', found 'x'");
  EXPECT_EQ(read_error("M 0 0 Z 5"), "at character 8: expected a command letter, not '5'");
  EXPECT_EQ(read_error("M 0 0 L 1e39 0"),
            "at character 8: the number 1e39 is beyond float32 (SCENE.NUMBER.FLOAT32)");
  EXPECT_EQ(read_error("M 3e38 0 l 3e38 0"),
            "at character 11: the point is beyond float32 (a relative coordinate added to the "
            "current point overflowed)");
  EXPECT_EQ(read_error("M 0 0 L 1 1 L 2 2 L 3 3", 3),
            "at character 18: the path has more than 3 segments and moves (SCENE.INPUT.LIMITS)");
  EXPECT_EQ(read_error(std::string("M 0 0 \x01")),
            "at character 6: expected a command letter, not '\\x01'");
}

} // namespace
