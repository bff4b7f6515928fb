// SPDX-License-Identifier: MIT
// The curve crossings' two exact paths agree (PATH.CURVE.SAMPLE): the integer fast path on
// dyadic parameters (taken when every root is simple and each crossing's x keeps clear of
// integers) and the rational path, on curves with control points on coarse and fine grids
// (tangent rows, roots at the ends, crossings on integer x), for every row through them and
// both row displacements.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "path_detail.hpp"

namespace rastrules::test {
namespace {

using path::detail::Crossing;
using path::detail::Curve;
using path::detail::Tie;

std::vector<std::pair<std::int64_t, int>> sorted(const std::vector<Crossing>& v) {
  std::vector<std::pair<std::int64_t, int>> out;
  for (const Crossing& c : v)
    out.emplace_back(c.threshold, c.dir);
  std::sort(out.begin(), out.end());
  return out;
}

// rule: PATH.CURVE.SAMPLE, PATH.CURVE.FILTER
TEST(PathCurvePaths, FastPathEqualsRationalPath) {
  std::mt19937 rng(20);
  int rows = 0, crossings = 0;
  for (int n = 0; n < 60; ++n) {
    // Coarse grids make ties (rows through control points, integer crossings); the finest
    // grid makes generic curves.
    const int grid = n % 3 == 0 ? 256 : (n % 3 == 1 ? 16 : 1);
    std::uniform_int_distribution<int> coord(0, 8 * 256 / grid);
    Curve c;
    c.degree = n % 2 == 0 ? 2 : 3;
    for (int k = 0; k <= c.degree; ++k)
      c.p[static_cast<std::size_t>(k)] = path::Point{coord(rng) * grid, coord(rng) * grid};
    std::int64_t ymin = c.p[0].y, ymax = c.p[0].y;
    for (int k = 0; k <= c.degree; ++k) {
      ymin = std::min<std::int64_t>(ymin, c.p[static_cast<std::size_t>(k)].y);
      ymax = std::max<std::int64_t>(ymax, c.p[static_cast<std::size_t>(k)].y);
    }
    for (std::int64_t sy = ymin - 1; sy <= ymax + 1;
         sy += std::max<std::int64_t>(1, (ymax - ymin) / 24)) {
      for (const Tie t : {Tie{true, true}, Tie{false, false}}) {
        const auto fast = sorted(path::detail::curve_crossings(c, sy, t));
        const auto exact = sorted(path::detail::curve_crossings_exact(c, sy, t));
        ASSERT_EQ(fast, exact) << "curve " << n << " row " << sy;
        ++rows;
        crossings += static_cast<int>(exact.size());
      }
    }
  }
  EXPECT_GT(rows, 1500);
  EXPECT_GT(crossings, 1000);
}

// A cubic whose y control polygon oscillates (21.7, 3.7, 21.8, -64.8 px): on most rows its
// Bernstein coefficients on [0, 1] change sign three times but the curve crosses once (complex
// roots near [0, 1]), so the root estimates give up. The scan's Descartes count on each of the
// 64 intervals decides those rows in integers; they went to the rational path before, which
// took 42 s under the sanitizers for one fuzz_path input with this curve (over libFuzzer's 10 s
// hang limit in CI).
// rule: PATH.CURVE.SAMPLE
TEST(PathCurvePaths, ScanDecidesRowsWhereDescartesOverCounts) {
  Curve c;
  c.degree = 3;
  c.p = {path::Point{234, 5560}, path::Point{-24691, 950}, path::Point{4416, 5592},
         path::Point{6400, -16586}};
  std::vector<Crossing> integer;
  int rows = 0, compared = 0, one_crossing = 0;
  for (std::int64_t sy = -16586; sy <= 5592; sy += 16) {
    for (const Tie t : {Tie{true, true}, Tie{false, false}}) {
      ASSERT_TRUE(path::detail::curve_crossings_integer(c, sy, t, integer)) << "row " << sy;
      ++rows;
      one_crossing += integer.size() == 1 && sy > 950 && sy < 5560 ? 1 : 0;
      // The rational path on every eighth row (it is the slow one, under the sanitizers).
      if (rows % 8 != 0)
        continue;
      const auto exact = sorted(path::detail::curve_crossings_exact(c, sy, t));
      ASSERT_EQ(sorted(integer), exact) << "row " << sy;
      ASSERT_EQ(sorted(path::detail::curve_crossings(c, sy, t)), exact) << "row " << sy;
      ++compared;
    }
  }
  EXPECT_GT(rows, 2000);
  EXPECT_GT(compared, 300);
  EXPECT_GT(one_crossing, 400); // rows between the polygon's turns
}

// The floating-point filter (PATH.CURVE.FILTER) decides where the double value is clear of its
// error bound and defers at exact zeros and integers: P(t) = 2 t - 1 is -1 at t = 0 (decided)
// and 0 at t = 1/2 (deferred to the integer tests); x(t) = 1 + 2 t is 1.5 at t = 1/4 (floor 1
// on the whole grid interval) and exactly 2 at t = 1/2 (deferred), as is 50 t there.
// rule: PATH.CURVE.FILTER
TEST(PathCurvePaths, FilterDecidesOnlyClearOfItsBound) {
  constexpr std::int64_t kHalf = std::int64_t{1} << 29, kQuarter = std::int64_t{1} << 28;
  EXPECT_EQ(path::detail::curve_filter_sign({-1, 2, 0, 0}, 0), -1);
  EXPECT_EQ(path::detail::curve_filter_sign({-1, 2, 0, 0}, kHalf + 1), 1);
  EXPECT_EQ(path::detail::curve_filter_sign({-1, 2, 0, 0}, kHalf), std::nullopt);
  EXPECT_EQ(path::detail::curve_filter_sign({1, -4, 4, 0}, kHalf), std::nullopt); // (2t - 1)^2
  EXPECT_EQ(path::detail::curve_filter_floor({1, 2, 0, 0}, kQuarter), 1);
  EXPECT_EQ(path::detail::curve_filter_floor({1, 2, 0, 0}, kHalf), std::nullopt);
  EXPECT_EQ(path::detail::curve_filter_floor({0, 50, 0, 0}, kHalf), std::nullopt);
  // Just below an integer: x = 2 - 2^-29 at k = 2^29 - 1, within L 2^-30 = 2^-29 of 2.
  EXPECT_EQ(path::detail::curve_filter_floor({1, 2, 0, 0}, kHalf - 1), std::nullopt);
  EXPECT_EQ(path::detail::curve_filter_floor({1, 2, 0, 0}, kHalf - 4096), 1);
}

} // namespace
} // namespace rastrules::test
