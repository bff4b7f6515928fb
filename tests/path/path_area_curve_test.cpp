// SPDX-License-Identifier: MIT
// Examples of area coverage of curves (PATH.AREA.CURVE): a parabolic segment inside one pixel
// (exact, bound 0), a circle of four quadratics whose total is its exact area, interior pixels
// exactly 1, a contour of curves drawn twice (the conflation case: empty under even-odd; its
// boundary pixels hold windings 0 and 2), a ring
// (a glyph-like hole, both fill rules), a cubic with a loop, curves reaching the ends of the
// int32 range, and the 8-bit alpha of curves.

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "path_detail.hpp"
#include "path_support.hpp"
#include "rastrules/path.hpp"

namespace {

using namespace rastrules;
using path::Contour;
using path::FillRule;
using path::Point;
using path::Segment;
using path::SegmentKind;
using Rational = boost::multiprecision::cpp_rational;

// 2^-32 px^2: the bound PATH.AREA.CURVE states for every pixel.
const Rational kMaxBound = Rational(1) / Rational(boost::multiprecision::cpp_int(1) << 32);

Segment quad(Point c, Point e) {
  return Segment{SegmentKind::kQuadratic, {c, e, {}}};
}
Segment cubic(Point c0, Point c1, Point e) {
  return Segment{SegmentKind::kCubic, {c0, c1, e}};
}

// A circle-like contour of four quadratics through (cx +- r, cy) and (cx, cy +- r) (raw), with
// controls at the corners of the square around it; clockwise on the screen unless reversed.
Contour round(std::int32_t cx, std::int32_t cy, std::int32_t r, bool reversed = false) {
  if (!reversed)
    return Contour{{cx + r, cy},
                   {quad({cx + r, cy + r}, {cx, cy + r}), quad({cx - r, cy + r}, {cx - r, cy}),
                    quad({cx - r, cy - r}, {cx, cy - r}), quad({cx + r, cy - r}, {cx + r, cy})}};
  return Contour{{cx + r, cy},
                 {quad({cx + r, cy - r}, {cx, cy - r}), quad({cx - r, cy - r}, {cx - r, cy}),
                  quad({cx - r, cy + r}, {cx, cy + r}), quad({cx + r, cy + r}, {cx + r, cy})}};
}

// Its exact area, raw^2: the square's diamond (2 r^2) and four parabolic segments, each 2/3 of
// its triangle (r^2 / 2).
Rational round_area(std::int64_t r) {
  return Rational(2 * r * r) + 4 * Rational(2, 3) * Rational(r * r, 2);
}

struct Totals {
  Rational area, bound;
  std::size_t pixels = 0;
};

Totals totals(const path::Path& p, std::int32_t w, std::int32_t h) {
  Totals t;
  for (const path::AreaCoverage& a : path::cover_area(p, w, h)) {
    EXPECT_GE(a.area, 0);
    EXPECT_LE(a.area, 1);
    EXPECT_LE(a.error_bound, kMaxBound) << "pixel (" << a.x << ", " << a.y << ")";
    t.area += a.area;
    t.bound += a.error_bound;
    ++t.pixels;
  }
  return t;
}

// rule: PATH.AREA.CURVE
TEST(PathAreaCurve, AParabolicSegmentInsideOnePixelIsExact) {
  // From (10, 10) through control (128, 250) to (250, 10), raw: the region between the arc and
  // its chord is 2/3 of the triangle, 2/3 * 240 * 240 / 2 = 19200 raw^2 = 75/256 px^2.
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const path::Path p{rule, {Contour{{10, 10}, {quad({128, 250}, {250, 10})}}}};
    const std::vector<path::AreaCoverage> a = path::cover_area(p, 2, 2);
    ASSERT_EQ(a.size(), 1u);
    EXPECT_EQ(a[0].x, 0);
    EXPECT_EQ(a[0].y, 0);
    EXPECT_EQ(a[0].area, Rational(75, 256));
    EXPECT_EQ(a[0].error_bound, 0);
  }
}

// rule: PATH.AREA.CURVE
TEST(PathAreaCurve, ACircleOfFourQuadraticsHasItsExactAreaWithinTheBounds) {
  // Radius 3 px about (4, 4) px: 30 px^2.
  const path::Path p{FillRule::kNonZero, {round(1024, 1024, 768)}};
  const Totals t = totals(p, 8, 8);
  EXPECT_EQ(round_area(768) / 65536, 30);
  EXPECT_LE(abs(t.area - 30), t.bound);
  EXPECT_GT(t.bound, 0); // the arcs cross grid lines: those pieces are bounded
  EXPECT_LT(t.bound, Rational(1, std::int64_t{1} << 32));
  // Pixels the arcs do not reach are exactly full, with no bound.
  for (const path::AreaCoverage& a : path::cover_area(p, 8, 8))
    if (a.x >= 3 && a.x <= 4 && a.y >= 2 && a.y <= 5) {
      EXPECT_EQ(a.area, 1) << a.x << ", " << a.y;
      EXPECT_EQ(a.error_bound, 0) << a.x << ", " << a.y;
    }
}

// rule: PATH.AREA.CURVE, PATH.FILL.RULE
TEST(PathAreaCurve, AContourOfCurvesDrawnTwiceIsEmptyUnderEvenOddAndOnceUnderNonzero) {
  // The conflation case with curves: accumulation rasterizers leave a trace on the boundary.
  for (const bool back : {false, true}) {
    const path::Path twice{FillRule::kEvenOdd,
                           {round(1024, 1024, 768), round(1024, 1024, 768, back)}};
    for (const path::AreaCoverage& a : path::cover_area(twice, 8, 8))
      EXPECT_EQ(a.area, 0) << a.x << ", " << a.y;
  }
  const path::Path nonzero{FillRule::kNonZero, {round(1024, 1024, 768), round(1024, 1024, 768)}};
  const path::Path once{FillRule::kNonZero, {round(1024, 1024, 768)}};
  std::map<std::pair<std::int32_t, std::int32_t>, Rational> single;
  for (const path::AreaCoverage& a : path::cover_area(once, 8, 8))
    single[{a.y, a.x}] = a.area;
  for (const path::AreaCoverage& a : path::cover_area(nonzero, 8, 8))
    EXPECT_LE(abs(a.area - single[{a.y, a.x}]), 2 * a.error_bound) << a.x << ", " << a.y;
}

// rule: PATH.AREA.CURVE, PATH.WINDING
TEST(PathAreaCurve, AContourOfCurvesDrawnTwiceHasWindingsZeroAndTwoInItsBoundaryPixels) {
  // Pixel (1, 2) lies across the circle's left arc: outside it w = 0, inside w = 2 (both copies
  // run the same way), and even-odd fills neither, nonzero the part inside.
  for (const FillRule rule : {FillRule::kEvenOdd, FillRule::kNonZero}) {
    const path::Path twice{rule, {round(1024, 1024, 768), round(1024, 1024, 768)}};
    const path::PixelWindings w = path::winding_areas(twice, 1, 2, 8, 8);
    ASSERT_EQ(w.parts.size(), 2u);
    EXPECT_EQ(w.parts[0].winding, 0);
    EXPECT_EQ(w.parts[1].winding, 2);
    EXPECT_EQ(w.parts[0].area + w.parts[1].area, 1);
    EXPECT_EQ(w.parts[1].fills, rule == FillRule::kNonZero);
    EXPECT_LE(w.error_bound, kMaxBound);
    EXPECT_GT(w.parts[1].area, 0);
  }
}

// rule: PATH.AREA.CURVE, PATH.FILL.RULE
TEST(PathAreaCurve, ARingHasTheAreaBetweenItsCircles) {
  // Outer radius 3.5 px, inner 1.5 px, about (4, 4) px: the inner one reversed for nonzero,
  // the same way round for even-odd (a glyph's hole either way).
  const Rational want = (round_area(896) - round_area(384)) / 65536;
  const path::Path nonzero{FillRule::kNonZero,
                           {round(1024, 1024, 896), round(1024, 1024, 384, true)}};
  const path::Path evenodd{FillRule::kEvenOdd, {round(1024, 1024, 896), round(1024, 1024, 384)}};
  for (const path::Path* p : {&nonzero, &evenodd}) {
    const Totals t = totals(*p, 8, 8);
    EXPECT_LE(abs(t.area - want), t.bound);
  }
  // The centre pixels lie in the hole.
  for (const path::AreaCoverage& a : path::cover_area(nonzero, 8, 8))
    EXPECT_FALSE(a.x >= 3 && a.x <= 4 && a.y >= 3 && a.y <= 4 && a.area != 0) << a.x << ", " << a.y;
}

// rule: PATH.AREA.CURVE, PATH.FILL.RULE
TEST(PathAreaCurve, ACubicWithALoopGivesTheSameAreasUnderBothRules) {
  // From (1, 1) px to (7, 1) px with controls beyond each other: the curve crosses itself, and
  // its two lobes (closed by the chord) wind +1 and -1: no pixel holds |w| >= 2.
  const path::Path nz{FillRule::kNonZero,
                      {Contour{{256, 256}, {cubic({3072, 2048}, {-1024, 2048}, {1792, 256})}}}};
  path::Path eo = nz;
  eo.fill_rule = FillRule::kEvenOdd;
  const std::vector<path::AreaCoverage> a = path::cover_area(nz, 8, 8);
  const std::vector<path::AreaCoverage> b = path::cover_area(eo, 8, 8);
  EXPECT_EQ(a, b);
  EXPECT_GT(a.size(), 10u);
  for (const path::AreaCoverage& c : a)
    EXPECT_LE(c.error_bound, kMaxBound);
}

// rule: PATH.AREA.CURVE, PATH.GEOMETRY
TEST(PathAreaCurve, CurvesReachingTheEndsOfTheInt32RangeStayExact) {
  // A parabola from (-R, 1) px through (0, 5) px (control) back to (R, 1) px for R at the end of
  // the snapped range and of int32: over the 4 x 4 target its apex is at 3 px, so the pixels of
  // row 1 are full, those of row 2 full but for a sliver.
  for (const std::int32_t big : {std::int32_t{1} << 23, std::int32_t{2147483647}}) {
    const path::Path p{FillRule::kNonZero, {Contour{{-big, 256}, {quad({0, 1280}, {big, 256})}}}};
    std::map<std::pair<std::int32_t, std::int32_t>, path::AreaCoverage> m;
    for (const path::AreaCoverage& a : path::cover_area(p, 4, 4)) {
      EXPECT_LE(a.error_bound, kMaxBound);
      m[{a.y, a.x}] = a;
    }
    for (std::int32_t x = 0; x < 4; ++x) {
      const path::AreaCoverage& full = m[std::make_pair(1, x)];
      const path::AreaCoverage& under = m[std::make_pair(2, x)];
      EXPECT_EQ(full.area, 1) << big << ": " << x;
      EXPECT_LE(1 - under.area, Rational(1, 1000000) + under.error_bound) << big;
      EXPECT_GT(1 - under.area + under.error_bound, 0) << big; // below the apex
      EXPECT_FALSE(m.contains(std::make_pair(0, x)));
    }
  }
}

// rule: PATH.AREA.CURVE, PATH.AREA.ALPHA
TEST(PathAreaCurve, AlphaOfCurvesIsTheRoundedComputedArea) {
  const path::Path p{FillRule::kNonZero, {round(1024, 1024, 768)}};
  std::vector<std::uint8_t> alpha(64);
  path::cover_area_alpha(p, 8, 8, alpha);
  std::vector<std::uint8_t> want(64, 0);
  for (const path::AreaCoverage& a : path::cover_area(p, 8, 8))
    want[static_cast<std::size_t>(a.y * 8 + a.x)] = path::detail::alpha_of(a.area);
  EXPECT_EQ(alpha, want);
  EXPECT_EQ(alpha[3 * 8 + 3], 255);
  EXPECT_EQ(alpha[0], 0);
}

} // namespace
