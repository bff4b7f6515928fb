// SPDX-License-Identifier: MIT
// The cell method of exact area coverage (PATH.AREA.CELLS) on examples: which rows it decides
// and which it leaves to the slab method, and that both give the same exact areas — vertices
// and edges on grid lines and grid corners (decided by cells), a contour inside one pixel,
// edges crossing in a pixel and an edge doubling back (left to the slabs), and the shrunk
// counterexamples of the properties.

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "path_detail.hpp"
#include "path_support.hpp"
#include "rastrules/path.hpp"

namespace rastrules::test {
namespace {

using path::FillRule;
using Q = boost::multiprecision::cpp_rational;
namespace pd = path::detail;

struct ByMethod {
  std::vector<path::AreaCoverage> cells, slabs;
  pd::AreaRows cell_rows, slab_rows;
};

ByMethod both(const path::Path& p, std::int32_t w, std::int32_t h) {
  ByMethod r;
  pd::cover_area_by(
      p, w, h, pd::AreaMethod::kCells, [&](const path::AreaCoverage& a) { r.cells.push_back(a); },
      &r.cell_rows);
  pd::cover_area_by(
      p, w, h, pd::AreaMethod::kSlabs, [&](const path::AreaCoverage& a) { r.slabs.push_back(a); },
      &r.slab_rows);
  EXPECT_EQ(r.cells, r.slabs);
  EXPECT_EQ(r.cell_rows.cells + r.cell_rows.slabs, r.slab_rows.slabs);
  EXPECT_EQ(r.cells, path::cover_area(p, w, h));
  return r;
}

// rule: PATH.AREA.CELLS
TEST(PathAreaCells, VerticesAndEdgesOnGridLinesAreDecidedByCells) {
  // A square with vertices on grid lines (not corners), a diamond through pixel midpoints of
  // the grid lines, and a horizontal edge along a row's border.
  const path::Contour square = polygon({{0.5, 1}, {3, 0.5}, {3.5, 3}, {1, 3.5}});
  const path::Contour diamond = polygon({{2, 4.5}, {3.5, 6}, {2, 7.5}, {0.5, 6}});
  const path::Contour bar = polygon({{4.25, 1}, {6.75, 1}, {6.75, 2.5}, {4.25, 2.5}});
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const ByMethod r = both(make_path(rule, {square, diamond, reversed(bar)}), 8, 8);
    EXPECT_EQ(r.cell_rows.slabs, 0u);
    EXPECT_EQ(r.cell_rows.cells, 8u);
    const auto m = area_map(r.cells); // by (y, x)
    EXPECT_EQ(m.at({1, 4}), Q(3, 4)); // the bar: x in [4.25, 6.75], y in [1, 2.5]
    EXPECT_EQ(m.at({2, 5}), Q(1, 2));
    EXPECT_EQ(m.at({1, 5}), Q(1));
    EXPECT_EQ(m.at({5, 1}), Q(7, 8)); // the diamond: x + y >= 6.5 in x in [1, 2], y in [5, 6]
  }
}

// A vertex on a grid corner and an edge through one: the moved border meets them on a side.
// rule: PATH.AREA.CELLS
TEST(PathAreaCells, VerticesAndEdgesThroughGridCornersAreDecidedByCells) {
  const ByMethod corner = both(
      make_path(FillRule::kNonZero, {polygon({{1, 1}, {3.3125, 1.375}, {2.1875, 3.625}})}), 4, 4);
  EXPECT_EQ(corner.cell_rows.slabs, 0u);
  const ByMethod through =
      both(make_path(FillRule::kEvenOdd, {polygon({{0.5, 0.5}, {3.5, 3.5}, {3.5, 0.25}}),
                                          polygon({{3.75, 0.5}, {0.75, 3.5}, {0.25, 3.75}})}),
           4, 4);
  EXPECT_GT(through.cell_rows.cells, 0u);
}

// rule: PATH.AREA.CELLS
TEST(PathAreaCells, RowsWhereACellMayHoldThreeWindingsGoToSlabs) {
  // A contour inside one pixel (its winding is seen by no side of the pixel).
  const ByMethod inside = both(
      make_path(FillRule::kNonZero, {polygon({{0.5, 0.5}, {3.5, 0.5}, {3.5, 3.5}, {0.5, 3.5}}),
                                     polygon({{2.1875, 2.1875}, {2.8125, 2.3125}, {2.5, 2.6875}})}),
      4, 4);
  EXPECT_EQ(inside.cell_rows.slabs, 1u);
  EXPECT_EQ(area_map(inside.cells).at({2, 2}), Q(1));
  // Two edges crossing inside a pixel (a bow tie), an edge doubling back.
  const ByMethod crossing = both(
      make_path(FillRule::kEvenOdd,
                {polygon({{0.3125, 0.3125}, {3.6875, 3.625}, {3.6875, 0.3125}, {0.3125, 3.625}})}),
      4, 4);
  EXPECT_GT(crossing.cell_rows.slabs, 0u);
  const ByMethod back = both(
      make_path(FillRule::kNonZero,
                {polygon({{0.3125, 0.3125}, {3.6875, 3.625}, {0.3125, 0.3125}, {0.5, 3.125}})}),
      4, 4);
  EXPECT_GT(back.cell_rows.slabs, 0u);
}

// rule: PATH.AREA.ALPHA
TEST(PathAreaCells, AlphaIsTheExactAreaRoundedHalfUpOnce) {
  // Quarters, halves and whole pixels; a sliver of 1/1024 px^2 (alpha 0, still listed by
  // cover_area); a triangle whose areas are not dyadic-friendly (its edges' heights are 3 px).
  const path::Path square =
      make_path(FillRule::kNonZero, {polygon({{0.5, 0.5}, {2.5, 0.5}, {2.5, 2.5}, {0.5, 2.5}})});
  std::vector<std::uint8_t> a(16, 99);
  path::cover_area_alpha(square, 4, 4, a);
  EXPECT_EQ(
      a, (std::vector<std::uint8_t>{64, 128, 64, 0, 128, 255, 128, 0, 64, 128, 64, 0, 0, 0, 0, 0}));
  const path::Path sliver = make_path(
      FillRule::kNonZero, {polygon({{1, 1}, {1.0625, 1}, {1.0625, 1.015625}, {1, 1.015625}})});
  std::vector<std::uint8_t> b(4, 99);
  path::cover_area_alpha(sliver, 2, 2, b);
  EXPECT_EQ(b, (std::vector<std::uint8_t>{0, 0, 0, 0}));
  EXPECT_EQ(path::cover_area(sliver, 2, 2).size(), 1u);
  const path::Path tri = make_path(FillRule::kEvenOdd, {polygon({{0.25, 0}, {3, 3}, {0, 3}})});
  std::vector<std::uint8_t> c(9, 99);
  path::cover_area_alpha(tri, 3, 3, c);
  for (const path::AreaCoverage& p : path::cover_area(tri, 3, 3)) {
    const Q v = p.area * 255 + Q(1, 2);
    const auto want = static_cast<int>(boost::multiprecision::numerator(v) /
                                       boost::multiprecision::denominator(v));
    EXPECT_EQ(c[static_cast<std::size_t>(p.y * 3 + p.x)], want) << p.x << ", " << p.y;
  }
  std::vector<std::uint8_t> wrong(8);
  EXPECT_THROW(path::cover_area_alpha(tri, 3, 3, wrong), std::invalid_argument);
}

// A vertical edge along a column line through a row's top: it counts for the columns before it
// (PathAreaCells.EqualSlabsOnTheGeneratorsPaths, seed 7400622224423696521: the cells listed
// nothing in row 0).
// rule: PATH.AREA.CELLS
TEST(PathAreaCells, RegressionVerticalEdgeOnAColumnLineCountsForTheColumnsBeforeIt) {
  const path::Path p = make_path(
      FillRule::kNonZero,
      {raw_polygon(
          {{-8388608, -8388608}, {-192, -192}, {-192, 512}, {128, 512}, {512, 528}, {512, -192}})});
  const ByMethod r = both(p, 4, 4);
  EXPECT_EQ(r.cell_rows.slabs, 0u);
  const auto m = area_map(r.cells);
  EXPECT_EQ(m.at({0, 0}), Q(1));
  EXPECT_EQ(m.at({0, 1}), Q(1));
}

// Edges across the whole coordinate range and ending at its right end, in the widest target
// (the bounds proofs/path/area_budget.cpp proves assume at most kMaxTargetSide px a side): both
// methods agree, every row by cells; a larger target is refused.
// rule: PATH.AREA.CELLS
TEST(PathAreaCells, EdgesAtTheEndsOfTheRangeInTheWidestTarget) {
  constexpr std::int64_t kMax = std::int64_t{1} << 23;
  const path::Path p =
      make_path(FillRule::kNonZero,
                {raw_polygon({{-kMax, -kMax}, {kMax, kMax}, {kMax, -kMax}}),
                 raw_polygon({{kMaxTargetSide * 256 - 64, 600}, {kMax, 700}, {1024, 740}})});
  const ByMethod r = both(p, kMaxTargetSide, 3);
  EXPECT_EQ(r.cell_rows.slabs, 0u);
  const auto m = area_map(r.cells);
  EXPECT_EQ(m.at({0, 0}), Q(1, 2)); // where y < x: half of pixel (0, 0)
  EXPECT_EQ(m.at({0, 5}), Q(1));
  EXPECT_EQ(m.at({1, 16383}), Q(1));
  std::vector<std::uint8_t> alpha(static_cast<std::size_t>(kMaxTargetSide) * 3);
  path::cover_area_alpha(p, kMaxTargetSide, 3, alpha);
  EXPECT_EQ(alpha[0], 128);
  try {
    (void)path::cover_area(p, kMaxTargetSide + 1, 3);
    ADD_FAILURE() << "a target above kMaxTargetSide was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "path: area coverage of a target wider or taller than 16384 px (PATH.AREA.CELLS)");
  }
  std::vector<std::uint8_t> tall(4 * (static_cast<std::size_t>(kMaxTargetSide) + 1));
  EXPECT_THROW(path::cover_area_alpha(p, 4, kMaxTargetSide + 1, tall), std::invalid_argument);
}

} // namespace
} // namespace rastrules::test
