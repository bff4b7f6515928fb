// SPDX-License-Identifier: MIT
// Exact area coverage of paths of lines (PATH.AREA.EXACT): a square and its reverse, partial
// pixels as exact rationals, the conflation cases (a path drawn twice inside one pixel under
// even-odd, a doubled-back diagonal), the star, a glyph-like shape with a hole, paths reaching
// beyond the target and the coordinate range, and the areas of simple polygons against the
// shoelace formula.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <utility>
#include <vector>

#include "path_support.hpp"
#include "rastrules/path.hpp"

namespace rastrules::test {
namespace {

using path::FillRule;
using Q = boost::multiprecision::cpp_rational;

// Returns the sum of the areas of every listed pixel.
Q total(const std::vector<path::AreaCoverage>& v) {
  Q s = 0;
  for (const path::AreaCoverage& c : v) {
    EXPECT_GT(c.area, 0);
    EXPECT_LE(c.area, 1);
    EXPECT_EQ(c.error_bound, 0);
    s += c.area;
  }
  return s;
}

// Returns twice the signed area (shoelace) of a polygon in px^2, exact.
Q shoelace(const path::Contour& c) {
  std::vector<path::Point> pts{c.start};
  for (const path::Segment& s : c.segments)
    pts.push_back(s.p[0]);
  Q a = 0;
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const path::Point& p = pts[k];
    const path::Point& q = pts[(k + 1) % pts.size()];
    a += Q(std::int64_t{p.x} * q.y - std::int64_t{q.x} * p.y);
  }
  return a / 65536;
}

// rule: PATH.AREA.EXACT
TEST(PathArea, SquareOnHalfPixelsHasExactQuartersAndHalves) {
  const path::Contour c = polygon({{0.5, 0.5}, {2.5, 0.5}, {2.5, 2.5}, {0.5, 2.5}});
  for (const path::Path& p :
       {make_path(FillRule::kNonZero, {c}), make_path(FillRule::kEvenOdd, {reversed(c)})}) {
    const auto m = area_map(path::cover_area(p, 4, 4));
    ASSERT_EQ(m.size(), 9u);
    EXPECT_EQ(m.at({0, 0}), Q(1, 4));
    EXPECT_EQ(m.at({0, 1}), Q(1, 2));
    EXPECT_EQ(m.at({1, 1}), Q(1));
    EXPECT_EQ(m.at({2, 2}), Q(1, 4));
    EXPECT_EQ(m.at({1, 2}), Q(1, 2));
  }
}

// rule: PATH.AREA.EXACT
TEST(PathArea, SlantedTriangleAreasAreExactRationals) {
  // (0,0) (3,1) (1,3) in pixels: area 4 px^2; pixels cut by slanted edges get rationals.
  const path::Contour c = polygon({{0, 0}, {3, 1}, {1, 3}});
  const auto v = path::cover_area(make_path(FillRule::kNonZero, {c}), 4, 4);
  EXPECT_EQ(total(v), Q(4));
  EXPECT_EQ(shoelace(c), Q(8)); // twice the area, clockwise on screen
  const auto m = area_map(v);
  // Pixel (0, 0) lies between the edges y = x/3 and y = 3x: 1 - 1/6 - 1/6.
  EXPECT_EQ(m.at({0, 0}), Q(2, 3));
  EXPECT_EQ(m.at({1, 1}), Q(1));
}

// A path drawn twice inside one pixel: under even-odd the area is 0 everywhere, not the 0.5
// (twice the area, folded) that signed-area accumulation shows; under nonzero it is the area
// once, not twice.
// rule: PATH.AREA.EXACT, PATH.FILL.RULE
TEST(PathArea, ConflationPathDrawnTwiceInsideOnePixel) {
  const path::Contour c = polygon({{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}});
  EXPECT_TRUE(path::cover_area(make_path(FillRule::kEvenOdd, {c, c}), 2, 2).empty());
  const auto nz = path::cover_area(make_path(FillRule::kNonZero, {c, c}), 2, 2);
  ASSERT_EQ(nz.size(), 1u);
  EXPECT_EQ(nz[0].area, Q(1, 4));
  // A triangle drawn twice across four pixels, and its reverse added: even-odd empty, nonzero
  // the area once.
  const path::Contour t = polygon({{0.5, 0.25}, {1.75, 1}, {0.25, 1.75}});
  EXPECT_TRUE(path::cover_area(make_path(FillRule::kEvenOdd, {t, t}), 3, 3).empty());
  EXPECT_EQ(total(path::cover_area(make_path(FillRule::kNonZero, {t, t}), 3, 3)), shoelace(t) / 2);
  EXPECT_TRUE(path::cover_area(make_path(FillRule::kNonZero, {t, reversed(t)}), 3, 3).empty());
}

// One contour down the diagonal and back: w = +1 above it and -1 below, so signed-area
// accumulation cancels to 0 on the diagonal's pixels (a gap); the exact area is 1 there.
// rule: PATH.AREA.EXACT
TEST(PathArea, DoubledBackDiagonalHasNoGap) {
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const path::Path p =
        make_path(rule, {polygon({{0, 0}, {4, 0}, {4, 4}, {0, 0}, {0, 4}, {4, 4}})});
    const auto m = area_map(path::cover_area(p, 4, 4));
    ASSERT_EQ(m.size(), 16u);
    for (const auto& [pixel, a] : m)
      EXPECT_EQ(a, Q(1)) << pixel.second << "," << pixel.first;
  }
}

// Where two edges cross inside a pixel the filled region is still exact: the bow tie's two
// triangles meet at a point in pixel (1, 1).
// rule: PATH.AREA.EXACT
TEST(PathArea, SelfIntersectionInsideAPixel) {
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const path::Path bow = make_path(rule, {polygon({{0, 0}, {3, 3}, {3, 0}, {0, 3}})});
    const auto v = path::cover_area(bow, 3, 3);
    EXPECT_EQ(total(v), Q(9, 2)); // two triangles of area 9/4 each
    const auto m = area_map(v);
    EXPECT_EQ(m.at({1, 1}), Q(1, 2)); // the crossing at (1.5, 1.5): left and right quarters
    EXPECT_EQ(m.at({1, 0}), Q(1));
    EXPECT_EQ(m.at({0, 0}), Q(1, 2));
    EXPECT_FALSE(m.contains({0, 1}));
  }
}

// rule: PATH.AREA.EXACT, PATH.FILL.RULE
TEST(PathArea, StarCentreIsFullUnderNonZeroAndEmptyUnderEvenOdd) {
  const auto star = [](FillRule rule) {
    return make_path(rule, {polygon({{10, 1}, {15.5, 18}, {1, 7.5}, {19, 7.5}, {4.5, 18}})});
  };
  const auto nz = area_map(path::cover_area(star(FillRule::kNonZero), 20, 20));
  const auto eo = area_map(path::cover_area(star(FillRule::kEvenOdd), 20, 20));
  EXPECT_EQ(nz.at({10, 10}), Q(1));
  EXPECT_FALSE(eo.contains({10, 10}));
  // Nonzero = even-odd + the centre pentagon (winding 2).
  Q pentagon = 0;
  for (const auto& [pixel, a] : nz)
    pentagon += a - (eo.contains(pixel) ? eo.at(pixel) : Q(0));
  EXPECT_GT(pentagon, 20);
  EXPECT_LT(pentagon, 40);
}

// rule: PATH.AREA.EXACT
TEST(PathArea, GlyphWithAHoleHasTheRingsArea) {
  const path::Contour outer = polygon({{1, 1}, {9, 1}, {9, 9}, {1, 9}});
  const path::Contour hole = reversed(polygon({{3.5, 3.5}, {6.5, 3.5}, {6.5, 6.5}, {3.5, 6.5}}));
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const auto v = path::cover_area(make_path(rule, {outer, hole}), 10, 10);
    EXPECT_EQ(total(v), Q(64 - 9));
    const auto m = area_map(v);
    EXPECT_EQ(m.at({3, 3}), Q(3, 4));
    EXPECT_EQ(m.at({3, 4}), Q(1, 2));
    EXPECT_FALSE(m.contains({4, 4}));
  }
}

// A path much larger than the target, with vertices at the ends of the coordinate range: only
// the target's pixels are listed, each exactly covered.
// rule: PATH.AREA.EXACT, PATH.BUDGET.LINE
TEST(PathArea, PathsAtTheEdgeOfTheCoordinateRange) {
  const path::Path p = range_triangle(FillRule::kNonZero);
  const auto m = area_map(path::cover_area(p, 8, 8));
  // Below the diagonal y = x: full pixels, half pixels on the diagonal.
  EXPECT_EQ(m.size(), 36u);
  EXPECT_EQ(m.at({0, 0}), Q(1, 2));
  EXPECT_EQ(m.at({7, 0}), Q(1));
  EXPECT_FALSE(m.contains({0, 7}));
}

// rule: PATH.AREA.EXACT, PATH.DEGENERATE
TEST(PathArea, AreasOfSimplePolygonsSumToTheShoelaceArea) {
  const path::Contour polys[] = {
      polygon({{0.5, 0.5}, {7.25, 1}, {6, 6.75}, {3, 4}, {1, 7}}),
      polygon({{3.125, 0.0078125}, {3.1328125, 7.99609375}, {0.00390625, 4}}),
      polygon({{1, 1}, {1, 1}, {5, 1}, {5, 1}, {5, 3}, {1, 3}}), // repeated points
      polygon({{0, 0}, {8, 0}, {8, 8}, {0, 8}}),
  };
  for (const path::Contour& c : polys) {
    const Q expected = (shoelace(c) < 0 ? -shoelace(c) : shoelace(c)) / 2;
    EXPECT_EQ(total(path::cover_area(make_path(FillRule::kNonZero, {c}), 8, 8)), expected);
    EXPECT_EQ(total(path::cover_area(make_path(FillRule::kEvenOdd, {reversed(c)}), 8, 8)),
              expected);
  }
  EXPECT_TRUE(path::cover_area(path::Path{}, 8, 8).empty());
}

// A 256 x 1 px strip whose sides are cut into 131584 segments of one raw unit has the strip's
// exact areas: any number of segments.
// rule: PATH.AREA.EXACT, PATH.DEGENERATE
TEST(PathArea, StripOfMoreThan65536SegmentsHasTheStripsAreas) {
  path::Contour many;
  many.start = pt(1.5, 1);
  for (const auto& [from, to] :
       {std::pair{pt(1.5, 1), pt(257.5, 1)}, std::pair{pt(257.5, 1), pt(257.5, 2)},
        std::pair{pt(257.5, 2), pt(1.5, 2)}, std::pair{pt(1.5, 2), pt(1.5, 1)}}) {
    const std::int32_t n = std::max(std::abs(to.x - from.x), std::abs(to.y - from.y));
    for (std::int32_t k = 1; k <= n; ++k)
      many.segments.push_back(path::Segment{
          path::SegmentKind::kLine,
          {path::Point{from.x + (to.x - from.x) / n * k, from.y + (to.y - from.y) / n * k},
           {},
           {}}});
  }
  ASSERT_GT(many.segments.size(), 65536u);
  const auto v = path::cover_area(make_path(FillRule::kNonZero, {many}), 260, 3);
  EXPECT_EQ(total(v), Q(256));
  const auto m = area_map(v);
  EXPECT_EQ(m.at({1, 1}), Q(1, 2));
  EXPECT_EQ(m.at({1, 2}), Q(1));
  EXPECT_EQ(m.at({1, 257}), Q(1, 2));
  EXPECT_EQ(m.size(), 257u);
}

// Two paths that share a boundary (a square cut along a slanted line into two paths, and a
// third path overlapping nothing): their areas add up to exactly 1 on every pixel they tile,
// and their samples never overlap (PATH.TIE.PARTITION for areas and samples).
// rule: PATH.AREA.EXACT, PATH.TIE.PARTITION
TEST(PathArea, AbuttingPathsTileThePixelsExactly) {
  const path::Path left =
      make_path(FillRule::kNonZero, {polygon({{0, 0}, {2.25, 0}, {3.75, 6}, {0, 6}})});
  const path::Path right =
      make_path(FillRule::kEvenOdd, {polygon({{2.25, 0}, {6, 0}, {6, 6}, {3.75, 6}})});
  const auto a = area_map(path::cover_area(left, 6, 6));
  const auto b = area_map(path::cover_area(right, 6, 6));
  for (std::int32_t y = 0; y < 6; ++y)
    for (std::int32_t x = 0; x < 6; ++x) {
      const Q sum =
          (a.contains({y, x}) ? a.at({y, x}) : Q(0)) + (b.contains({y, x}) ? b.at({y, x}) : Q(0));
      EXPECT_EQ(sum, Q(1)) << x << "," << y;
    }
  const auto sa =
      as_map(path::cover_samples(left, standard_pattern(16), FillConvention::kTopLeft, 6, 6));
  const auto sb =
      as_map(path::cover_samples(right, standard_pattern(16), FillConvention::kTopLeft, 6, 6));
  for (const auto& [pixel, mask] : sa)
    EXPECT_EQ(mask & (sb.contains(pixel) ? sb.at(pixel) : 0u), 0u);
  std::size_t covered = 0;
  for (std::int32_t y = 0; y < 6; ++y)
    for (std::int32_t x = 0; x < 6; ++x)
      covered += static_cast<std::size_t>(std::popcount(
          (sa.contains({y, x}) ? sa.at({y, x}) : 0u) | (sb.contains({y, x}) ? sb.at({y, x}) : 0u)));
  EXPECT_EQ(covered, 36u * 16u);
}

} // namespace
} // namespace rastrules::test
