// SPDX-License-Identifier: MIT
// The certified sweep of PATH.AREA.SWEEP on examples: paths it decides whole (glyph-like shapes
// with curves and holes, ties of the rounding beside exact lines, thin bars whose two edges
// share pixels, curved pixels on a rounding boundary decided through the bound), rows it leaves
// to the other methods (a contour drawn twice, two bars the same way round in one pixel, a tiny
// loop) and a path it declines whole (a target too large for its cells). Every alpha of a row it
// decides is compared with the exact methods', and cover_area_alpha's with theirs.
// Tests: PATH.AREA.SWEEP, PATH.AREA.ALPHA

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

struct Swept {
  bool decided = false;           // every row
  std::vector<std::uint8_t> left; // the rows left to the other methods (1)
  std::vector<std::uint8_t> alpha, exact;
};

// The sweep alone, and the exact methods; in the rows the sweep decides they must agree, and
// cover_area_alpha (the sweep first) always agrees with the exact methods.
Swept sweep(const path::Path& p, std::int32_t w, std::int32_t h) {
  Swept s;
  const auto n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  const auto stride = static_cast<std::size_t>(w);
  s.alpha.assign(n, 7);
  s.exact.assign(n, 9);
  pd::cover_alpha_by(p, w, h, pd::AreaMethod::kCells, s.exact, nullptr);
  const bool some = pd::alpha_sweep(pd::boundary_of(p), p.fill_rule, w, h, s.alpha, s.left);
  EXPECT_EQ(s.left.size(), static_cast<std::size_t>(h));
  std::size_t swept = 0;
  for (std::size_t j = 0; j < s.left.size(); ++j) {
    EXPECT_TRUE(some || s.left[j] == 1) << "a declined path leaves every row";
    if (s.left[j] != 0)
      continue;
    ++swept;
    for (std::size_t i = 0; i < stride; ++i)
      EXPECT_EQ(s.alpha[j * stride + i], s.exact[j * stride + i]) << "pixel " << i << ", " << j;
  }
  s.decided = swept == static_cast<std::size_t>(h);
  std::vector<std::uint8_t> pub(n, 5);
  path::cover_area_alpha(p, w, h, pub);
  EXPECT_EQ(pub, s.exact);
  pd::AreaRows rows;
  std::vector<std::uint8_t> by(n, 3);
  pd::cover_alpha_by(p, w, h, pd::AreaMethod::kSweep, by, &rows);
  EXPECT_EQ(by, s.exact);
  EXPECT_EQ(rows.swept, swept);
  return s;
}

// A small curved contour far right of the rest, so that a path of lines is a path with curves.
path::Contour curl(double x) {
  return contour(x, 0.5, {quad_to(x + 1.5, 0.75, x + 1, 2.5), line_to(x, 2.25)});
}

// An 'o': two circles of four cubics, the inner one the other way round (a hole), across
// several pixels: every cell holds one chain, monotone in x or in y.
// rule: PATH.AREA.SWEEP
TEST(PathAreaSweep, AGlyphLikeShapeWithAHoleIsSweptWhole) {
  const auto circle = [](double cx, double cy, double r, bool clockwise) {
    const double k = 0.5546875 * r; // 142 / 256: near 0.5523 r, on the 16.8 grid
    const double s = clockwise ? 1 : -1;
    return contour(cx + r, cy,
                   {cubic_to(cx + r, cy + s * k, cx + k, cy + s * r, cx, cy + s * r),
                    cubic_to(cx - k, cy + s * r, cx - r, cy + s * k, cx - r, cy),
                    cubic_to(cx - r, cy - s * k, cx - k, cy - s * r, cx, cy - s * r),
                    cubic_to(cx + k, cy - s * r, cx + r, cy - s * k, cx + r, cy)});
  };
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const path::Path o = make_path(rule, {circle(5, 5, 4.5, true), circle(5, 5, 2, false)});
    const Swept s = sweep(o, 10, 10);
    EXPECT_TRUE(s.decided);
    EXPECT_EQ(s.alpha[5 * 10 + 5], 0);   // the hole
    EXPECT_EQ(s.alpha[5 * 10 + 1], 255); // the ring
  }
}

// A square on pixel centres beside a curve: its edge pixels are half covered (510 a = 255, a
// tie of the rounding) and every visit of them is exact (lines along the axes), so the sweep
// decides the tie exactly (128).
// rule: PATH.AREA.SWEEP, PATH.AREA.ALPHA
TEST(PathAreaSweep, TiesBesideLinesAlongTheAxesAreDecidedExactly) {
  const path::Path p = make_path(
      FillRule::kNonZero, {polygon({{0.5, 0.5}, {2.5, 0.5}, {2.5, 2.5}, {0.5, 2.5}}), curl(5)});
  const Swept s = sweep(p, 8, 4);
  ASSERT_TRUE(s.decided);
  EXPECT_EQ(s.alpha[0], 64);
  EXPECT_EQ(s.alpha[1], 128);
  EXPECT_EQ(s.alpha[8], 128);
  EXPECT_EQ(s.alpha[9], 255);
}

// A bar a quarter of a pixel thick: its top and bottom edges cross the same pixels, two runs
// apart in y and running opposite ways in x (windings 0, 1, 0): decided. Two bars the same way
// round, one inside the other, within one pixel row (windings 0, 1, 2): that row is left to
// the other methods, which give the answer.
// rule: PATH.AREA.SWEEP
TEST(PathAreaSweep, TwoChainsInAPixelAreDecidedOnlyWhenTheyMeetTwoWindings) {
  const path::Path bar = make_path(
      FillRule::kNonZero, {polygon({{0.5, 1.25}, {3.5, 1.25}, {3.5, 1.5}, {0.5, 1.5}}), curl(5)});
  const Swept one = sweep(bar, 8, 3);
  EXPECT_TRUE(one.decided);
  EXPECT_EQ(one.alpha[8 + 1], 64); // a quarter of the pixel
  const path::Path nested =
      make_path(FillRule::kNonZero,
                {polygon({{0.5, 1.125}, {3.5, 1.125}, {3.5, 1.875}, {0.5, 1.875}}),
                 polygon({{1.25, 1.25}, {2.75, 1.25}, {2.75, 1.5}, {1.25, 1.5}}), curl(5)});
  EXPECT_EQ(sweep(nested, 8, 3).left, (std::vector<std::uint8_t>{0, 1, 0}));
  // A bar standing up: its left and right edges share pixels, apart in x, running opposite
  // ways in y.
  const path::Path stem =
      make_path(FillRule::kNonZero,
                {polygon({{1.25, 0.5}, {1.25, 2.5}, {1.625, 2.5}, {1.625, 0.5}}), curl(5)});
  const Swept up = sweep(stem, 8, 3);
  EXPECT_TRUE(up.decided);
  EXPECT_EQ(up.alpha[8 + 1], 96); // three eighths of the pixel
}

// Three thin bars standing in one pixel column, through the target's rows: six edges apart in x
// whose senses alternate (windings 0, 1, 0, 1, 0, 1, 0): decided. The middle bar the other way
// round (windings 0, 1, 0, -1, 0, 1, 0): three values in a pixel under the nonzero rule's view of
// the sum, every row left.
// rule: PATH.AREA.SWEEP
TEST(PathAreaSweep, SeveralChainsApartMustAlternate) {
  const auto bar = [](double x0, double x1, bool reverse) {
    return reverse ? polygon({{x0, -1}, {x1, -1}, {x1, 4}, {x0, 4}})
                   : polygon({{x0, -1}, {x0, 4}, {x1, 4}, {x1, -1}});
  };
  const path::Path same =
      make_path(FillRule::kNonZero, {bar(1.125, 1.25, false), bar(1.5, 1.625, false),
                                     bar(1.75, 1.875, false), curl(5)});
  const Swept s = sweep(same, 8, 3);
  EXPECT_TRUE(s.decided);
  EXPECT_EQ(s.alpha[8 + 1], 96); // three bars of an eighth
  const path::Path mixed =
      make_path(FillRule::kEvenOdd,
                {bar(1.125, 1.25, false), bar(1.5, 1.625, true), bar(1.75, 1.875, false), curl(5)});
  EXPECT_EQ(sweep(mixed, 8, 3).left, (std::vector<std::uint8_t>{1, 1, 1}));
}

// Two arcs in pixel (1, 1), each a cut from border to border, apart: a bump from one side,
// monotone in one coordinate and turning in the other, and a cut-off corner or a second bump.
// Each has the other on the side of its lower winding (both shapes the same way round), so the
// pixel holds two winding numbers and the sweep decides it; the bump's side holding the other
// arc comes from where the other lies (beside its box, beyond the end on that side). The same
// shapes with one the other way round hold three and leave the row, and so does an arc whose
// joint touches the border.
// rule: PATH.AREA.SWEEP
TEST(PathAreaSweep, ArcsApartWithTheSameChangeOfWindingAreDecided) {
  const auto reversed = [](const path::Contour& c) {
    std::vector<path::Point> v{c.start};
    for (const path::Segment& g : c.segments)
      v.push_back(g.p[0]);
    path::Contour r{v.back(), {}};
    for (std::size_t i = v.size() - 1; i-- > 0;)
      r.segments.push_back(path::Segment{path::SegmentKind::kLine, {v[i], {}, {}}});
    return r;
  };
  const struct {
    const char* what;
    path::Contour a, b;
  } cases[] = {
      // A '<' from the left side (monotone in y), a '^' from the bottom side below it.
      {"bump left, bump below it", polygon({{0.5, 1.1875}, {1.5, 1.3125}, {0.5, 1.4375}}),
       polygon({{1.1875, 2.5}, {1.3125, 1.75}, {1.4375, 2.5}})},
      // The same upside down: a '<' low, a 'v' from the top side above it.
      {"bump left, bump above it", polygon({{0.5, 1.8125}, {1.5, 1.6875}, {0.5, 1.5625}}),
       polygon({{1.1875, 0.5}, {1.3125, 1.25}, {1.4375, 0.5}})},
      // A '^' from the bottom side (monotone in x) with a '<' from the left side beside it.
      {"bump below, bump left of it", polygon({{1.5, 2.5}, {1.6875, 1.3125}, {1.875, 2.5}}),
       polygon({{0.5, 1.5}, {1.3125, 1.5625}, {0.5, 1.6875}})},
      // A 'v' from the top side with a '>' from the right side beside it.
      {"bump above, bump right of it", polygon({{1.5, 0.5}, {1.3125, 1.6875}, {1.125, 0.5}}),
       polygon({{2.5, 1.5}, {1.6875, 1.4375}, {2.5, 1.3125}})},
  };
  // A '>' from the right side whose tip touches the left side (a joint on the border), a '^'
  // below it: the rule asks for joints inside the cell, so the row is left.
  const path::Path touching =
      make_path(FillRule::kNonZero, {polygon({{2.5, 1.25}, {1, 1.5}, {2.5, 1.75}}),
                                     polygon({{1.5, 2.5}, {1.375, 1.875}, {1.25, 2.5}})});
  EXPECT_EQ(sweep(touching, 4, 4).left[1], 1);
  for (const auto& c : cases) {
    SCOPED_TRACE(c.what);
    const Swept same = sweep(make_path(FillRule::kNonZero, {c.a, c.b}), 4, 4);
    EXPECT_EQ(same.left[1], 0);
    const Swept mixed = sweep(make_path(FillRule::kNonZero, {c.a, reversed(c.b)}), 4, 4);
    EXPECT_EQ(mixed.left[1], 1);
  }
}

// A quadratic coming down into pixel (1, 1) and a line leaving its end back up to the right:
// a sharp V (their directions together turn in x and in y). The curve's control points lie on
// one side of the line, so the two meet only at the joint and the pixel is decided. With the
// control point across the line the curve may cross it again inside the pixel (here it does,
// arriving level at the joint: a small loop): the row is left.
// rule: PATH.AREA.SWEEP
TEST(PathAreaSweep, ASharpTurnOfACurveAndALineIsDecidedWhereTheyMeetOnce) {
  const auto v = [](double sx, double cx, double cy) {
    return make_path(
        FillRule::kNonZero,
        {contour(sx, 0.75, {quad_to(cx, cy, 1.25, 1.5), line_to(2.5, 0.875), line_to(2.5, 0.75)})});
  };
  EXPECT_EQ(sweep(v(1.5, 1.5, 1.25), 4, 3).left, (std::vector<std::uint8_t>{0, 0, 0}));
  // Arriving level at the joint, below the line, after crossing it at (1.625, 1.3125) (t = 1/2):
  // a loop of 1/64 px^2.
  EXPECT_EQ(sweep(v(1.75, 1.75, 1.5), 4, 3).left[1], 1);
}

// Rows the sweep leaves: a square drawn twice under even-odd (two runs that meet in every cell of
// its edges: the conflation case, alpha 0 everywhere) leaves its rows, the empty row below
// decided; a cubic with a small loop inside one pixel (extrema too close to tell) leaves the rows
// of its control points and one more each way. A target of more than 2^18 cells is declined
// whole.
// rule: PATH.AREA.SWEEP
TEST(PathAreaSweep, RowsInDoubtGoToTheOtherMethods) {
  const path::Contour sq = polygon({{0.5, 0.5}, {2.5, 0.5}, {2.5, 2.5}, {0.5, 2.5}});
  const Swept twice = sweep(make_path(FillRule::kEvenOdd, {sq, sq, curl(5)}), 8, 4);
  EXPECT_EQ(twice.left, (std::vector<std::uint8_t>{1, 1, 1, 0}));
  EXPECT_EQ(twice.exact[1], 0);
  const path::Path loop =
      make_path(FillRule::kNonZero, {contour(0.25, 1.5,
                                             {cubic_to(2.75, 1.25, 0.25, 1.25, 2.75, 1.5),
                                              line_to(2.75, 2.75), line_to(0.25, 2.75)})});
  EXPECT_EQ(sweep(loop, 4, 4).left, (std::vector<std::uint8_t>{1, 1, 1, 0}));
  std::vector<std::uint8_t> big(std::size_t{600} * 600, 1), left;
  EXPECT_FALSE(pd::alpha_sweep(pd::boundary_of(make_path(FillRule::kNonZero, {curl(5)})),
                               FillRule::kNonZero, 600, 600, big, left));
  EXPECT_EQ(left, std::vector<std::uint8_t>(600, 1));
}

// A quadratic through a grid corner, (1, 1) px at t = 1/2: its crossings of the column line and
// the row line there cannot be told apart, so the cells after it are not known; the sweep leaves
// the rows from there to the curve's end (and one more each way), and decides the rows of the
// lines below it.
// rule: PATH.AREA.SWEEP
TEST(PathAreaSweep, ACurveThroughAGridCornerLeavesItsRows) {
  const path::Path p = make_path(
      FillRule::kNonZero,
      {contour(0.5, 0.25,
               {quad_to(1.125, 0.5, 1.25, 2.75), line_to(1.25, 5.5), line_to(0.5, 5.5)})});
  const Swept s = sweep(p, 3, 7);
  EXPECT_EQ(s.left, (std::vector<std::uint8_t>{1, 1, 1, 1, 0, 0, 0}));
  EXPECT_EQ(s.alpha[4 * 3], 128);    // half of pixel (0, 4)
  EXPECT_EQ(s.alpha[4 * 3 + 1], 64); // a quarter of pixel (1, 4)
}

// Curved pixels whose exact alpha lies on a rounding boundary (510 a = 85, between alphas 42
// and 43; as PathAreaFast.CurvedPixelsOnARoundingBoundaryAreDecidedThroughTheBound): the
// sweep's bound keeps it from rounding them down, so it either leaves the row or gives 43.
// rule: PATH.AREA.SWEEP, PATH.AREA.ALPHA
TEST(PathAreaSweep, CurvedPixelsOnARoundingBoundaryAreDecidedThroughTheBound) {
  int cases = 0, decided = 0;
  for (std::int32_t col = 0; col < 3; ++col)
    for (std::int32_t x0 = 1; x0 < 128; x0 += 7)
      for (std::int32_t x2 = 3; x2 < 128 - x0; x2 += 11) {
        const std::int32_t x1 = 128 - x0 - x2;
        const double l = 256.0 * col, top = 256.0 * col, bottom = top + 256.0;
        const path::Path p = make_path(
            FillRule::kNonZero,
            {contour(0, top / 256,
                     {line_to((l + x0) / 256, top / 256),
                      quad_to((l + x1) / 256, (top + 128) / 256, (l + x2) / 256, bottom / 256),
                      line_to(0, bottom / 256)})});
        const std::int32_t side = col + 2;
        const Swept s = sweep(p, side, side);
        const auto at = static_cast<std::size_t>(col) * static_cast<std::size_t>(side) +
                        static_cast<std::size_t>(col);
        ASSERT_EQ(s.exact[at], 43);
        decided += s.left[static_cast<std::size_t>(col)] == 0 ? 1 : 0;
        ++cases;
      }
  EXPECT_GT(cases, 100);
  RecordProperty("decided", decided);
}

} // namespace
} // namespace rastrules::test
