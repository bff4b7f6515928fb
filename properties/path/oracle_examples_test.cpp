// SPDX-License-Identifier: MIT
// Examples of the exact path oracle (rastrules/oracle/path.hpp), each value computed by hand:
// areas of a unit square, half-pixel triangles and nested squares, a pentagram's centre under
// both fill rules, the conflation case (a contour drawn twice: area 0 under evenodd), the
// doubled-back diagonal, and samples on edges and corners under each fill convention.
// Implements (examples for): PATH.WINDING, PATH.FILL.RULE, PATH.SAMPLE.TIE, PATH.AREA.EXACT

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "rastrules/oracle/msaa.hpp"
#include "rastrules/oracle/path.hpp"

namespace {

namespace op = rastrules::oracle::path;
using op::Raw2;

constexpr std::int64_t kPx = 256; // raw units per pixel

const std::vector<std::string>& conventions() {
  static const std::vector<std::string> k = {"top-left", "top-right", "bottom-left",
                                             "bottom-right"};
  return k;
}

// A contour of lines through the given points (raw), closed implicitly.
op::Contour polygon(const std::vector<Raw2>& pts) {
  op::Contour c{pts.front(), {}};
  for (std::size_t i = 1; i < pts.size(); ++i)
    c.pieces.push_back(op::Piece{op::PieceKind::kLine, {pts[i]}});
  return c;
}

op::Path path_of(std::vector<op::Contour> contours, const std::string& rule = "nonzero") {
  return op::Path{rule, std::move(contours)};
}

// Returns "num/den" of pixel (x, y), "0" when the oracle lists no area there.
std::string area_at(const std::vector<op::PixelArea>& areas, std::int32_t x, std::int32_t y) {
  for (const op::PixelArea& a : areas) {
    if (a.x == x && a.y == y)
      return a.num + "/" + a.den;
  }
  return "0";
}

Raw2 centre(std::int64_t x, std::int64_t y) {
  return {kPx * x + kPx / 2, kPx * y + kPx / 2};
}

// rule: PATH.AREA.EXACT, PATH.WINDING
TEST(PathOracle, UnitSquareHasAreaOneAndWindingPlusOneClockwise) {
  // (1,1) -> (2,1) -> (2,2) -> (1,2): right, then down: clockwise on screen, w = +1 inside.
  const op::Path p = path_of({polygon({{256, 256}, {512, 256}, {512, 512}, {256, 512}})});
  const auto areas = op::cover_area(p, 4, 4);
  ASSERT_EQ(areas.size(), 1u);
  EXPECT_EQ(area_at(areas, 1, 1), "1/1");
  EXPECT_EQ(op::winding(p, centre(1, 1), "top-left"), 1);
  const op::Path ccw = path_of({polygon({{256, 256}, {256, 512}, {512, 512}, {512, 256}})});
  EXPECT_EQ(op::winding(ccw, centre(1, 1), "top-left"), -1);
  EXPECT_EQ(area_at(op::cover_area(ccw, 4, 4), 1, 1), "1/1");
}

// rule: PATH.AREA.EXACT
TEST(PathOracle, HalfPixelTriangleAndATriangleOverFourPixels) {
  const op::Path half = path_of({polygon({{0, 0}, {256, 0}, {0, 256}})});
  const auto a = op::cover_area(half, 2, 2);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(area_at(a, 0, 0), "1/2");
  // x + y < 2 px: pixel (0,0) whole, (1,0) and (0,1) half, (1,1) only touched at a corner.
  const op::Path big = path_of({polygon({{0, 0}, {512, 0}, {0, 512}})});
  const auto b = op::cover_area(big, 3, 3);
  EXPECT_EQ(b.size(), 3u);
  EXPECT_EQ(area_at(b, 0, 0), "1/1");
  EXPECT_EQ(area_at(b, 1, 0), "1/2");
  EXPECT_EQ(area_at(b, 0, 1), "1/2");
  EXPECT_EQ(area_at(b, 1, 1), "0");
  // A thin triangle: (0,0) (1,0) (0, 1/256) px has area 1/512.
  const op::Path thin = path_of({polygon({{0, 0}, {256, 0}, {0, 1}})});
  EXPECT_EQ(area_at(op::cover_area(thin, 1, 1), 0, 0), "1/512");
}

// rule: PATH.FILL.RULE, PATH.WINDING
TEST(PathOracle, PentagramCentreUnderBothRules) {
  // Tips on a circle of radius 6 px around (8, 8) px, rounded to 1/256 px, joined 0-2-4-1-3.
  const std::vector<Raw2> tips = {
      {2048, 512}, {3509, 1573}, {2951, 3291}, {1145, 3291}, {587, 1573}};
  const std::vector<Raw2> star = {tips[0], tips[2], tips[4], tips[1], tips[3]};
  for (const char* rule : {"nonzero", "evenodd"}) {
    const op::Path p = path_of({polygon(star)}, rule);
    const bool nonzero = std::string(rule) == "nonzero";
    for (const std::string& fill : conventions()) {
      // The centre pentagon: |w| = 2; inside the top tip, below (8, 2) px: |w| = 1.
      EXPECT_EQ(std::abs(op::winding(p, centre(7, 7), fill)), 2);
      EXPECT_EQ(std::abs(op::winding(p, centre(7, 4), fill)), 1);
      EXPECT_EQ(op::winding(p, centre(0, 0), fill), 0);
      EXPECT_EQ(op::covers(p, centre(7, 7), fill), nonzero) << rule;
      EXPECT_TRUE(op::covers(p, centre(7, 4), fill));
    }
    // Pixel (7, 7) lies inside the centre pentagon (inner radius about 2.3 px): area 1 under
    // nonzero, 0 under evenodd.
    EXPECT_EQ(area_at(op::cover_area(p, 16, 16), 7, 7), nonzero ? "1/1" : "0") << rule;
  }
}

// rule: PATH.FILL.RULE, PATH.AREA.EXACT
TEST(PathOracle, ConflationAContourDrawnTwiceIsEmptyUnderEvenOdd) {
  // The case accumulation rasterizers get wrong (0.48 instead of 0): the same contour twice.
  const op::Contour tri = polygon({{30, 20}, {230, 60}, {90, 240}});
  const op::Path evenodd = path_of({tri, tri}, "evenodd");
  EXPECT_TRUE(op::cover_area(evenodd, 2, 2).empty());
  EXPECT_TRUE(
      op::cover_samples(evenodd, rastrules::oracle::msaa::standard_pattern(16), "top-left", 2, 2)
          .empty());
  const op::Path nonzero = path_of({tri, tri}, "nonzero");
  // Twice the area of (30,20) (230,60) (90,240) raw: |200*220 - 40*60| = 41600 raw^2.
  EXPECT_EQ(area_at(op::cover_area(nonzero, 2, 2), 0, 0), "325/1024"); // 20800 / 65536
  EXPECT_EQ(op::winding(nonzero, centre(0, 0), "top-left"), 2);
}

// rule: PATH.WINDING, PATH.AREA.EXACT
TEST(PathOracle, DoubledBackDiagonalAndOppositeContoursCoverNothing) {
  const op::Path diagonal = path_of({polygon({{0, 0}, {512, 512}})});
  EXPECT_TRUE(op::cover_area(diagonal, 3, 3).empty());
  for (const std::string& fill : conventions())
    EXPECT_TRUE(op::cover_samples(diagonal, {{0, 0}}, fill, 3, 3).empty()) << fill;
  const op::Contour cw = polygon({{0, 0}, {512, 0}, {512, 512}, {0, 512}});
  const op::Contour ccw = polygon({{0, 0}, {0, 512}, {512, 512}, {512, 0}});
  EXPECT_TRUE(op::cover_area(path_of({cw, ccw}), 3, 3).empty());
}

// rule: PATH.WINDING, PATH.FILL.RULE, PATH.AREA.EXACT
TEST(PathOracle, NestedSquaresAHoleOrADoubleWinding) {
  const op::Contour outer = polygon({{0, 0}, {768, 0}, {768, 768}, {0, 768}});
  const op::Contour inner_cw = polygon({{256, 256}, {512, 256}, {512, 512}, {256, 512}});
  const op::Contour inner_ccw = polygon({{256, 256}, {256, 512}, {512, 512}, {512, 256}});
  // Opposite orientation: a hole under both rules.
  for (const char* rule : {"nonzero", "evenodd"}) {
    const auto a = op::cover_area(path_of({outer, inner_ccw}, rule), 3, 3);
    EXPECT_EQ(a.size(), 8u) << rule;
    EXPECT_EQ(area_at(a, 1, 1), "0") << rule;
  }
  // Same orientation: w = 2 in the middle, filled under nonzero only.
  EXPECT_EQ(area_at(op::cover_area(path_of({outer, inner_cw}, "nonzero"), 3, 3), 1, 1), "1/1");
  EXPECT_EQ(area_at(op::cover_area(path_of({outer, inner_cw}, "evenodd"), 3, 3), 1, 1), "0");
  EXPECT_EQ(op::winding(path_of({outer, inner_cw}), centre(1, 1), "top-left"), 2);
}

// rule: PATH.SAMPLE.TIE
TEST(PathOracle, SquareCornersOnSamplesBelongToOneConventionEach) {
  // The square from the centre of pixel (0,0) to the centre of pixel (1,1): each corner is a
  // sample; s' = s + (sx e, sy e^2) enters the square only at the corner (sx, sy) points into.
  const std::vector<Raw2> corners = {{128, 128}, {384, 128}, {384, 384}, {128, 384}};
  const std::vector<std::vector<Raw2>> orders = {corners,
                                                 {corners[0], corners[3], corners[2], corners[1]}};
  for (const auto& order : orders) {
    const op::Path p = path_of({polygon(order)});
    EXPECT_TRUE(op::covers(p, {128, 128}, "top-left"));
    EXPECT_FALSE(op::covers(p, {128, 128}, "top-right"));
    EXPECT_FALSE(op::covers(p, {128, 128}, "bottom-left"));
    EXPECT_FALSE(op::covers(p, {128, 128}, "bottom-right"));
    EXPECT_TRUE(op::covers(p, {384, 128}, "top-right"));
    EXPECT_FALSE(op::covers(p, {384, 128}, "top-left"));
    EXPECT_TRUE(op::covers(p, {128, 384}, "bottom-left"));
    EXPECT_FALSE(op::covers(p, {128, 384}, "bottom-right"));
    EXPECT_TRUE(op::covers(p, {384, 384}, "bottom-right"));
    EXPECT_FALSE(op::covers(p, {384, 384}, "top-left"));
    // Edge midpoints: the top edge belongs to top-*, the left edge to *-left.
    EXPECT_TRUE(op::covers(p, {256, 128}, "top-left"));
    EXPECT_TRUE(op::covers(p, {256, 128}, "top-right"));
    EXPECT_FALSE(op::covers(p, {256, 128}, "bottom-left"));
    EXPECT_TRUE(op::covers(p, {128, 256}, "bottom-left"));
    EXPECT_FALSE(op::covers(p, {128, 256}, "bottom-right"));
    EXPECT_TRUE(op::covers(p, {384, 256}, "top-right"));
    EXPECT_FALSE(op::covers(p, {384, 256}, "top-left"));
  }
}

// rule: PATH.SAMPLE.TIE
TEST(PathOracle, DiagonalEdgeThroughACentreByConvention) {
  // The hypotenuse x + y = 1 px of (0,0) (1,0) (0,1) passes through the centre of pixel (0,0);
  // the interior is towards -x and -y: s' enters it iff sx + sy e moves x + y down, i.e.
  // sx = -1 (top-right and bottom-right).
  const op::Path p = path_of({polygon({{0, 0}, {256, 0}, {0, 256}})});
  EXPECT_FALSE(op::covers(p, centre(0, 0), "top-left"));
  EXPECT_TRUE(op::covers(p, centre(0, 0), "top-right"));
  EXPECT_FALSE(op::covers(p, centre(0, 0), "bottom-left"));
  EXPECT_TRUE(op::covers(p, centre(0, 0), "bottom-right"));
}

// rule: PATH.WINDING, PATH.SAMPLE.TIE
TEST(PathOracle, CurvesDecidedByExactRoots) {
  // M (0,0) Q (6,1.5) (0,3) px, closed by the line back: x(t) = 12 t (1 - t) px, y(t) = 3t px,
  // going down on the right: w = +1 inside. Rightmost point (3, 1.5) px, a vertical tangent:
  // a sample there is covered only when s' moves left (sx = -1). The same shape as a cubic
  // (degree elevation: controls (4, 1) and (4, 2) px) decides the same.
  const op::Contour quad{{0, 0}, {op::Piece{op::PieceKind::kQuadratic, {{1536, 384}, {0, 768}}}}};
  const op::Contour cubic{{0, 0},
                          {op::Piece{op::PieceKind::kCubic, {{1024, 256}, {1024, 512}, {0, 768}}}}};
  for (const op::Contour& c : {quad, cubic}) {
    const op::Path p = path_of({c});
    EXPECT_EQ(op::winding(p, {700, 384}, "top-left"), 1);
    EXPECT_EQ(op::winding(p, {700, 384}, "bottom-right"), 1);
    EXPECT_FALSE(op::covers(p, {768, 384}, "top-left"));
    EXPECT_TRUE(op::covers(p, {768, 384}, "top-right"));
    EXPECT_FALSE(op::covers(p, {768, 384}, "bottom-left"));
    EXPECT_TRUE(op::covers(p, {768, 384}, "bottom-right"));
    EXPECT_FALSE(op::covers(p, {769, 384}, "top-right"));
    EXPECT_TRUE(op::covers(p, {767, 384}, "top-left"));
    // The start (0, 0): the region there is the wedge between the closing line (straight
    // down) and the curve's tangent (4, 1), which no s' = (+-e, +-e^2) enters.
    for (const std::string& fill : conventions())
      EXPECT_FALSE(op::covers(p, {0, 0}, fill)) << fill;
    EXPECT_TRUE(op::covers(p, {1, 1}, "top-left"));
  }
}

// rule: PATH.AREA.EXACT
TEST(PathOracle, CurveAreaWithinItsCertifiedBound) {
  // The region between x = 0 and x(t) = 12 t (1 - t) px, y(t) = 3t px: area = integral of x dy
  // = 36 * 1/6 = 6 px^2 over all pixels, the quadratic and its degree-elevated cubic alike.
  const op::Contour quad{{0, 0}, {op::Piece{op::PieceKind::kQuadratic, {{1536, 384}, {0, 768}}}}};
  const op::Contour cubic{{0, 0},
                          {op::Piece{op::PieceKind::kCubic, {{1024, 256}, {1024, 512}, {0, 768}}}}};
  for (const op::Contour& c : {quad, cubic}) {
    double last_bound = 1e9;
    for (int depth : {2, 5, 8}) {
      double sum = 0, bound = 0;
      for (const op::PixelAreaBound& a : op::cover_area_bounded(path_of({c}), 4, 4, depth)) {
        sum += a.area.approx;
        bound += a.bound_approx;
        EXPECT_GE(a.area.approx, 0.0);
        EXPECT_LE(a.area.approx, 1.0);
      }
      EXPECT_LE(std::abs(sum - 6.0), bound + 1e-12) << depth;
      EXPECT_LT(bound, last_bound / 64) << depth; // about 8x per level, 512x per 3 levels
      last_bound = bound;
    }
    EXPECT_LT(last_bound, 1.0 / 1024);
  }
  // Lines: the exact areas, bound 0.
  const auto lines =
      op::cover_area_bounded(path_of({polygon({{0, 0}, {512, 0}, {0, 512}})}), 3, 3, 4);
  ASSERT_EQ(lines.size(), 3u);
  for (const op::PixelAreaBound& a : lines)
    EXPECT_EQ(a.bound_num, "0");
}

// rule: PATH.SAMPLE.TIE
TEST(PathOracle, HorizontalTangentAtASampleIsNotCovered) {
  // M (-0.5,-0.5) Q (0.5,1.5) (1.5,-0.5) px: y = 0.5 - (x - 0.5)^2 px below the chord, tip at
  // the centre of pixel (0,0) with a horizontal tangent. Under bottom-* the contract's literal
  // s' = s + (sx e, -e^2) lies ON this parabola; the oracle reads the displacement as y moved
  // infinitely less than x (see path.cpp): the tip is not covered under any convention, as
  // splitting into y-monotone pieces with the line rule gives.
  op::Contour cup{{-128, -128}, {op::Piece{op::PieceKind::kQuadratic, {{128, 384}, {384, -128}}}}};
  const op::Path p = path_of({cup});
  for (const std::string& fill : conventions())
    EXPECT_FALSE(op::covers(p, centre(0, 0), fill)) << fill;
  EXPECT_TRUE(op::covers(p, {128, 120}, "top-left"));
}

// rule: PATH.WINDING, PATH.SAMPLE.TIE
TEST(PathOracle, LinesByRootsAgreeWithTheLineRule) {
  const op::Path p = path_of({polygon({{0, 0}, {512, 256}, {256, 512}, {256, 128}, {0, 384}})});
  for (const std::string& fill : conventions()) {
    for (std::int64_t y = -8; y <= 520; y += 8) {
      for (std::int64_t x = -8; x <= 520; x += 8)
        ASSERT_EQ(op::winding(p, {x, y}, fill), op::winding_by_roots(p, {x, y}, fill))
            << fill << " (" << x << ", " << y << ")";
    }
  }
}

} // namespace
