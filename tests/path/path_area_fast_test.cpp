// SPDX-License-Identifier: MIT
// The certified floating-point cells of PATH.AREA.FAST on examples: where they decide a row
// (ties such as a half-covered pixel exactly, beside curves too; a curve and a line that meet at
// a sharp corner), where they leave it to the exact methods (several windings in a pixel), and
// the shrunk counterexample of the properties. Every alpha is compared with the exact methods'.
// Tests: PATH.AREA.FAST, PATH.AREA.ALPHA

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "path_detail.hpp"
#include "path_support.hpp"
#include "rastrules/path.hpp"

namespace rastrules::test {
namespace {

using path::FillRule;
namespace pd = path::detail;

struct Alphas {
  std::vector<std::uint8_t> fast, exact;
  pd::AreaRows rows;
};

// The alpha by the fast cells (with the exact methods behind them) and by the exact methods
// alone; they must agree.
Alphas alphas(const path::Path& p, std::int32_t w, std::int32_t h) {
  Alphas a;
  const auto n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  a.fast.assign(n, 7);
  a.exact.assign(n, 9);
  pd::cover_alpha_by(p, w, h, pd::AreaMethod::kFast, a.fast, &a.rows);
  pd::cover_alpha_by(p, w, h, pd::AreaMethod::kCells, a.exact, nullptr);
  EXPECT_EQ(a.fast, a.exact);
  std::vector<std::uint8_t> pub(n, 5);
  path::cover_area_alpha(p, w, h, pub);
  EXPECT_EQ(pub, a.fast);
  return a;
}

// A square on pixel centres: its edge pixels are half covered (alpha 128: 255 / 2 + 1/2 is
// exactly 128, a tie of the rounding), decided exactly since every number of it is exact.
// rule: PATH.AREA.FAST, PATH.AREA.ALPHA
TEST(PathAreaFast, HalfCoveredPixelsAreDecidedExactly) {
  const path::Path square =
      make_path(FillRule::kNonZero, {polygon({{0.5, 0.5}, {2.5, 0.5}, {2.5, 2.5}, {0.5, 2.5}})});
  const Alphas a = alphas(square, 4, 4);
  EXPECT_EQ(a.rows.fast, 4u);
  EXPECT_EQ(a.fast, (std::vector<std::uint8_t>{64, 128, 64, 0, 128, 255, 128, 0, 64, 128, 64, 0, 0,
                                               0, 0, 0}));
}

// A half-covered pixel left of a curve: the cover right of it is summed by end points, so the
// curve's inexact crossings of the column lines cancel and the tie is decided exactly (before,
// such rows went to the exact methods: Nimbus Sans 'R' at 24 px).
// rule: PATH.AREA.FAST
TEST(PathAreaFast, AHalfCoveredPixelLeftOfACurveIsDecided) {
  const path::Path p =
      make_path(FillRule::kNonZero,
                {contour(0.5, 0, {line_to(3, 0), quad_to(5.25, 1.125, 3, 3), line_to(0.5, 3)})});
  const Alphas a = alphas(p, 6, 3);
  EXPECT_EQ(a.rows.fast, 3u);
  EXPECT_EQ(a.fast[0], 128);
  EXPECT_EQ(a.fast[6], 128);
}

// A curve and a line meeting at a sharp corner inside a pixel, both going off into the same
// quadrant: exact integer tests prove that the curve keeps to one side of the line, so the pixel
// holds two winding numbers; likewise two curves meeting at such a corner (a line through the
// corner between them).
// rule: PATH.AREA.FAST
TEST(PathAreaFast, SharpCornersOfCurvesAreDecided) {
  // The line runs down-right into J = (3.5, 2.5); the curve leaves J up-left, above the line.
  const path::Path line_curve = make_path(
      FillRule::kNonZero, {contour(0.5, 0.5, {line_to(3.5, 2.5), quad_to(2, 1, 0.25, 0.25)})});
  EXPECT_EQ(alphas(line_curve, 4, 4).rows.fast, 4u);
  const path::Path two_curves =
      make_path(FillRule::kNonZero,
                {contour(0.5, 0.5, {quad_to(3, 1, 3.5, 2.5), quad_to(3.375, 1, 3, 0.25)})});
  EXPECT_EQ(alphas(two_curves, 4, 4).rows.fast, 4u);
  // The same line with a curve that leaves J up-left below it and crosses it: in doubt.
  const path::Path crossing = make_path(
      FillRule::kNonZero, {contour(0.5, 0.5, {line_to(3.5, 2.5), quad_to(2, 1.25, 0.5, 1.5)})});
  EXPECT_LT(alphas(crossing, 4, 4).rows.fast, 4u);
  const path::Path cubic =
      make_path(FillRule::kEvenOdd,
                {contour(0.5, 3.5, {cubic_to(0.5, 0.5, 3.5, 0.5, 3.5, 3.5), line_to(2, 1.75)})});
  EXPECT_EQ(alphas(cubic, 4, 4).rows.fast, 4u);
}

// A square drawn twice under even-odd (the conflation case): in its edge pixels the two
// contours' sub-arcs meet (the same points), so the fast cells leave those rows to the exact
// methods, which give 0.
// rule: PATH.AREA.FAST
TEST(PathAreaFast, RowsWhereContoursMeetGoToTheExactMethods) {
  const path::Contour sq = polygon({{0.5, 0.5}, {2.5, 0.5}, {2.5, 2.5}, {0.5, 2.5}});
  const path::Path twice = make_path(FillRule::kEvenOdd, {sq, sq});
  const Alphas a = alphas(twice, 3, 3);
  EXPECT_LT(a.rows.fast, 3u);
  EXPECT_EQ(a.fast, std::vector<std::uint8_t>(9, 0));
  // Two triangles crossing inside pixels: those rows are the exact methods' too.
  const path::Path star =
      make_path(FillRule::kNonZero, {polygon({{0.25, 0.375}, {3.75, 0.625}, {1.125, 3.75}}),
                                     polygon({{3.625, 3.125}, {0.375, 2.875}, {2.25, 0.125}})});
  EXPECT_LT(alphas(star, 4, 4).rows.fast, 4u);
}

// A vertex right of the target on a column line there: right of the target only the line
// x = w counts as a side, every other end is shared by the sub-arc beside it
// (PathAreaCells.EqualSlabsOnTheGeneratorsPaths, seed 13680150306108285340: pixel (3, 0) got
// 13 for 3).
// rule: PATH.AREA.FAST
TEST(PathAreaFast, RegressionAVertexRightOfTheTargetOnAColumnLine) {
  const path::Path p =
      make_path(FillRule::kNonZero, {raw_polygon({{1280, 16}, {1360, 544}, {864, 352}})});
  const Alphas a = alphas(p, 4, 4);
  EXPECT_EQ(a.fast[3], 3);
  EXPECT_EQ(a.rows.fast, 4u);
}

// A vertical edge along a column line right of the target, from a vertex that another edge
// ends at: right of the target only the line x = w counts, so the edge's ends are shared like
// any other (PathAreaCells.EqualSlabsOnTheGeneratorsPaths, seed 11: row 0 got 255 for 0).
// rule: PATH.AREA.FAST
TEST(PathAreaFast, RegressionAnEdgeAlongAColumnLineRightOfTheTarget) {
  const path::Path p = make_path(
      FillRule::kNonZero,
      {raw_polygon(
          {{1280, 128}, {1280, 1024}, {512, 640}, {1280, 128}, {1280, 1024}, {512, 640}})});
  const Alphas a = alphas(p, 4, 4);
  EXPECT_EQ(a.fast[0], 0);
  EXPECT_EQ(a.fast[7], 128);
}

// A cubic whose control points all lie on the target's right side x = w, running up and down
// along it, closed by lines into the target: the fast cells gave pixel (3, 0) alpha 26 for the
// exact 114 (PathCurveArea.FastCellsGiveTheAlphaOfTheArea, seed 4470124809348599784, shrunk).
// Curves along a grid line now go to the exact methods.
// rule: PATH.AREA.FAST
TEST(PathAreaFast, RegressionACurveAlongTheTargetsRightSide) {
  path::Contour c;
  c.start = path::Point{-192, 0};
  c.segments = {
      path::Segment{path::SegmentKind::kLine, {path::Point{1024, -192}, {}, {}}},
      path::Segment{path::SegmentKind::kCubic,
                    {path::Point{1024, 288}, path::Point{1024, -32}, path::Point{1024, 128}}}};
  const Alphas a = alphas(make_path(FillRule::kNonZero, {c}), 4, 4);
  EXPECT_EQ(a.fast[3], 114);
  EXPECT_EQ(a.rows.fast, 0u);
}

// Curved pixels whose exact alpha is a tie of the rounding: a quadratic with y linear in t
// (its control point halfway up) across one pixel row covers (x0 + x1 + x2) / 3 - left of the
// pixel, here 128 / 3 raw over 256, an area of exactly 1/6: 510 a = 85, the boundary between
// alphas 42 and 43 (floor(255 / 6 + 1/2) = 43). Q's coefficient M_3 / 3 is inexact, so the
// fast cells carry a bound and must leave the pixel to the exact methods or decide it through
// the bound; a bound left out (PATH.AREA.FAST's plain-double alpha taken without its pad)
// rounds some of these to 42.
// rule: PATH.AREA.FAST, PATH.AREA.ALPHA
TEST(PathAreaFast, CurvedPixelsOnARoundingBoundaryAreDecidedThroughTheBound) {
  int cases = 0;
  for (std::int32_t col = 0; col < 3; ++col)
    for (std::int32_t x0 = 1; x0 < 128; x0 += 7)
      for (std::int32_t x2 = 3; x2 < 128 - x0; x2 += 11) {
        const std::int32_t x1 = 128 - x0 - x2; // x0 + x1 + x2 = 128 (raw, from the column's left)
        const double l = 256.0 * col, top = 256.0 * col, bottom = top + 256.0;
        path::Path p = make_path(
            FillRule::kNonZero,
            {contour(0, top / 256,
                     {line_to((l + x0) / 256, top / 256),
                      quad_to((l + x1) / 256, (top + 128) / 256, (l + x2) / 256, bottom / 256),
                      line_to(0, bottom / 256)})});
        const std::int32_t w = col + 2, h = col + 2;
        const Alphas a = alphas(p, w, h);
        const auto at = static_cast<std::size_t>(col) * static_cast<std::size_t>(w) +
                        static_cast<std::size_t>(col);
        ASSERT_EQ(a.fast[at], 43) << "col " << col << " x0 " << x0 << " x2 " << x2;
        ++cases;
      }
  EXPECT_GT(cases, 100);
}

} // namespace
} // namespace rastrules::test
