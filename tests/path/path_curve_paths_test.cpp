// SPDX-License-Identifier: MIT
// The curve crossings' two exact paths agree (PATH.CURVE.SAMPLE): the integer fast path on
// dyadic parameters (taken when every root is simple and each crossing's x keeps clear of
// integers) and the rational path, on curves with control points on coarse and fine grids
// (tangent rows, roots at the ends, crossings on integer x), for every row through them and
// both row displacements.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <random>
#include <span>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

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

// The crossings as the samples at raw x = o mod 256 see them (PATH.CURVE.COARSE): each
// threshold's class floor((T - o) / 256) with its direction, sorted.
std::vector<std::pair<std::int64_t, int>> classes(const std::vector<Crossing>& v, std::int64_t o) {
  std::vector<std::pair<std::int64_t, int>> out;
  for (const Crossing& c : v)
    out.emplace_back(floor_div(c.threshold - o, 256), c.dir);
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

using Q = boost::multiprecision::cpp_rational;

// The number of simple roots (where the sign changes) of d0 + d1 t + d2 t^2 (d2 != 0) in the
// open interval (l, r), exactly: with t = l + (r - l) s, the roots of e0 + e1 s + e2 s^2 in
// (0, 1), from its values at 0 and 1, its discriminant and its vertex. Written here, apart from
// the kernel's reasoning, to check the pieces it proves.
int simple_roots_between(const std::array<Q, 3>& d, const Q& l, const Q& r) {
  const Q w = r - l;
  const Q e0 = d[0] + d[1] * l + d[2] * l * l, e1 = (d[1] + 2 * d[2] * l) * w, e2 = d[2] * w * w;
  const Q q0 = e0, q1 = e0 + e1 + e2, disc = e1 * e1 - 4 * e0 * e2;
  const auto inside = [](const Q& v) { return v > 0 && v < 1; };
  if (disc <= 0)
    return 0; // no real root, or a double one (no sign change)
  if (q0 == 0)
    return inside(-e1 / e2) ? 1 : 0; // roots 0 and -e1 / e2
  if (q1 == 0)
    return inside(e0 / e2) ? 1 : 0; // roots 1 and e0 / e2 (their product is e0 / e2)
  if ((q0 < 0) != (q1 < 0))
    return 1;
  return inside(-e1 / (2 * e2)) && ((q0 > 0) == (e2 > 0)) ? 2 : 0;
}

// The curves of the monotone pieces' tests: random ones on coarse and fine grids (end tangents,
// an extremum at t = 1/2), and named ones: y' with two simple roots 2^-25 apart at t = 1/2 at the
// edge of the coordinate range (D = 9, the smallest for a curve: c1 and c2 are multiples of 3),
// two roots 2^-21 apart near t = 1/2048, a double root of y' at t = 1/2 (a flat inflection, D = 0;
// the row through it meets a triple root), y' = 0 at t = 0 twice over (y = 2048 t^3), and y'
// positive on [0, 1] with its vertex at t = 1/2 and both roots outside (one piece).
std::vector<Curve> monotone_test_curves() {
  std::vector<Curve> curves;
  std::mt19937 rng(27);
  for (int n = 0; n < 80; ++n) {
    const int grid = n % 4 == 0 ? 256 : (n % 4 == 1 ? 16 : 1);
    std::uniform_int_distribution<int> coord(-4 * 256 / grid, 8 * 256 / grid);
    Curve c;
    c.degree = 3;
    for (int k = 0; k <= 3; ++k)
      c.p[static_cast<std::size_t>(k)] = path::Point{coord(rng) * grid, coord(rng) * grid};
    switch (n % 5) {
    case 0: // horizontal tangents at both ends: y' = 0 at t = 0 and 1
      c.p[1].y = c.p[0].y;
      c.p[2].y = c.p[3].y;
      break;
    case 1: // y'(1/2) = 0 (y1 - y0 = (y2 - y0) + (y3 - y0)): an extremum at t = 1/2, whose
            // y = (y0 + 3 y1 + 3 y2 + y3) / 8 is a raw row on the coarse grid (a tangent row)
      c.p[1].y = c.p[2].y + c.p[3].y - c.p[0].y;
      break;
    case 2: // one horizontal tangent
      c.p[1].y = c.p[0].y;
      break;
    default:
      break;
    }
    curves.push_back(c);
  }
  constexpr std::int32_t kM = 1 << 23;
  const auto named = [&](std::array<std::int32_t, 4> ys) {
    Curve c;
    c.degree = 3;
    for (std::size_t k = 0; k < 4; ++k)
      c.p[k] = path::Point{static_cast<std::int32_t>(k) * 300 - 200, ys[k]};
    curves.push_back(c);
  };
  named({-kM, kM - 1, -kM + 1, kM - 2});            // roots of y' at 1/2 - 2^-25 and 1/2
  named({0, 1, -2047, 2049 * 2049 - 3 * 2049 + 2}); // roots 1/2050 and 1/2048
  named({-1024, 1024, -1024, 1024});                // y' = 6144 (2 t - 1)^2
  named({0, 0, 0, 2048});                           // y = 2048 t^3
  named({0, 256, 1536, 1792}); // y' = 768 + 6144 t - 6144 t^2: its vertex inside, roots outside
  return curves;
}

// The monotone pieces of cubics (PATH.CURVE.SAMPLE): on curves whose y starts or ends at an
// extremum (a horizontal tangent, as glyph cubics mostly do), with an extremum at t = 1/2 whose
// row is a raw row (a tangent row), and generic ones (inflections, both roots of y' inside) on
// coarse and fine grids, every row walked in order through one prepared curve
// gives the rational path's crossings, whichever path decides it; the pieces decide most rows,
// and leave the rows near a y-extremum inside (0, 1) and through a piece's end to the
// estimates.
// rule: PATH.CURVE.SAMPLE, PATH.CURVE.FILTER
TEST(PathCurvePaths, MonotonePiecesGiveTheRationalPathsCrossings) {
  int rows = 0, decided = 0, crossings = 0, with_pieces = 0, left_near_extremum = 0, n = -1;
  std::vector<Crossing> out, scratch, mono;
  for (const Curve& c : monotone_test_curves()) {
    ++n;
    path::detail::PreparedCurve p;
    path::detail::prepare_curve(c, p);
    with_pieces += p.mono.n > 0 ? 1 : 0;
    // Rows across the curve, and for an extremum at t = 1/2 on a raw row, that row (tangent:
    // inside a bracket) and the raw rows next to it, in order.
    const std::int64_t step = std::max<std::int64_t>(1, (p.ymax - p.ymin) / 24);
    std::vector<std::int64_t> sys;
    for (std::int64_t sy = p.ymin - 1; sy <= p.ymax + 1; sy += step)
      sys.push_back(sy);
    const std::int64_t y8 = c.p[0].y + 3 * c.p[1].y + 3 * c.p[2].y + c.p[3].y;
    const bool tangent_row = n < 80 && n % 5 == 1 && y8 % 8 == 0;
    if (tangent_row)
      sys.insert(sys.end(), {y8 / 8 - 1, y8 / 8, y8 / 8 + 1});
    std::sort(sys.begin(), sys.end());
    for (const Tie t : {Tie{true, true}, Tie{false, false}}) {
      path::detail::prepare_curve(c, p); // a fresh walk: the starts of the rows before reset
      for (const std::int64_t sy : sys) {
        out.clear();
        path::detail::curve_crossings_prepared(p, sy, t, out, scratch);
        const auto exact = sorted(path::detail::curve_crossings_exact(c, sy, t));
        ASSERT_EQ(sorted(out), exact) << "curve " << n << " row " << sy;
        mono.clear();
        const bool by_pieces = path::detail::curve_crossings_monotone(p, sy, t, mono);
        if (by_pieces) {
          ASSERT_EQ(sorted(mono), exact) << "curve " << n << " row " << sy;
          ++decided;
        }
        if (tangent_row && sy == y8 / 8 && p.mono.n > 0) {
          EXPECT_FALSE(by_pieces) << "curve " << n << ": the tangent row " << sy;
          ++left_near_extremum;
        }
        ++rows;
        crossings += static_cast<int>(exact.size());
      }
    }
  }
  EXPECT_GT(with_pieces, 50);
  EXPECT_GT(rows, 4000);
  EXPECT_GT(crossings, 3500);
  EXPECT_GT(decided, rows * 3 / 4);
  EXPECT_GT(left_near_extremum, 0);
}

// The row walk asks a curve for a band of rows at once (curve_crossings_band, appending to
// room the walk reserved): the same crossings, row by row, as one row at a time, for bands that
// start and end above, across and below the curve's y-range, with exact thresholds and with
// the samples' class.
// rule: PATH.CURVE.SAMPLE, PATH.CURVE.COARSE
TEST(PathCurvePaths, ABandOfRowsGivesEachRowsCrossings) {
  std::vector<Crossing> one, scratch, left;
  std::vector<Crossing> room;
  std::vector<path::detail::RowCrossings> band_out;
  int rows = 0, crossings = 0, n = -1;
  for (const Curve& c : monotone_test_curves()) {
    ++n;
    path::detail::PreparedCurve single, banded;
    path::detail::prepare_curve(c, single);
    const std::int64_t step = std::max<std::int64_t>(1, (single.ymax - single.ymin) / 20);
    std::vector<path::detail::BandRow> all;
    for (std::int64_t sy = single.ymin - 3 * step; sy <= single.ymax + 3 * step; sy += step)
      all.push_back(path::detail::BandRow{sy, n % 2 == 0 ? path::detail::kExactThresholds : 128});
    for (const Tie t : {Tie{true, true}, Tie{false, true}}) {
      path::detail::prepare_curve(c, single);
      path::detail::prepare_curve(c, banded);
      for (std::size_t first = 0; first < all.size(); first += 5) {
        const std::span<const path::detail::BandRow> band =
            std::span{all}.subspan(first, std::min<std::size_t>(5, all.size() - first));
        // Room for three crossings a row, after one already there (the band appends).
        room.assign(4 * band.size(), Crossing{-7, 1});
        band_out.clear();
        for (std::size_t i = 0; i < band.size(); ++i)
          band_out.push_back(path::detail::RowCrossings{room.data() + 4 * i, 1, 4});
        path::detail::curve_crossings_band(banded, band, t, band_out, scratch, left);
        for (std::size_t i = 0; i < band.size(); ++i) {
          one.assign(1, Crossing{-7, 1});
          path::detail::curve_crossings_prepared(single, band[i].sy, t, one, scratch,
                                                 band[i].sample_x);
          const std::vector<Crossing> got(band_out[i].begin(), band_out[i].end());
          ASSERT_EQ(sorted(got), sorted(one)) << "curve " << n << " row " << band[i].sy;
          ++rows;
          crossings += static_cast<int>(one.size()) - 1;
        }
      }
    }
  }
  EXPECT_GT(rows, 4000);
  EXPECT_GT(crossings, 3000);
}

// A band row's room is a bound, not a hope: an S-shaped cubic crossing one row three times,
// given room for two, throws logic_error and leaves the memory past its room alone (the walk
// reserves three a curve, so this names a broken bound rather than writing past it).
// rule: PATH.CURVE.SAMPLE
TEST(PathCurvePaths, ABandRowPastItsRoomIsALogicErrorNotAWrite) {
  Curve c;
  c.degree = 3;
  c.p = {path::Point{0, -10}, path::Point{1000, 2000}, path::Point{2000, -2000},
         path::Point{3000, 10}};
  path::detail::PreparedCurve p;
  path::detail::prepare_curve(c, p);
  const std::vector<path::detail::BandRow> band{path::detail::BandRow{0}};
  std::vector<Crossing> scratch, left;
  for (const std::size_t cap : {std::size_t{3}, std::size_t{2}}) {
    std::vector<Crossing> room(4, Crossing{-7, 1});
    std::vector<path::detail::RowCrossings> out{path::detail::RowCrossings{room.data(), 0, cap}};
    if (cap == 3) {
      path::detail::curve_crossings_band(p, band, Tie{}, out, scratch, left);
      EXPECT_EQ(out[0].size(), 3u);
    } else {
      EXPECT_THROW(path::detail::curve_crossings_band(p, band, Tie{}, out, scratch, left),
                   std::logic_error);
      EXPECT_EQ(out[0].size(), 2u);
    }
    EXPECT_EQ(room[3].threshold, -7) << "cap " << cap;
    if (cap == 2) {
      EXPECT_EQ(room[2].threshold, -7);
    }
  }
}

// PATH.CURVE.COARSE: rows of the monotone test curves walked in order with the samples'
// offset o (that of the aliased sample, 128, and another of the 16-sample grid) give, class
// by class, the rational path's crossings; the coarse thresholds (256 q + o, not floor(x_c))
// decide most crossings the pieces decide, and a walk asking exact thresholds gets exact ones.
// rule: PATH.CURVE.COARSE, PATH.CURVE.SAMPLE
TEST(PathCurvePaths, MonotonePiecesDecideTheSamplesClassOfEachCrossing) {
  int rows = 0, coarse = 0, crossings = 0;
  std::vector<Crossing> out, scratch;
  for (const Curve& c : monotone_test_curves()) {
    path::detail::PreparedCurve p;
    path::detail::prepare_curve(c, p);
    const std::int64_t rows_step = std::max<std::int64_t>(1, (p.ymax - p.ymin) / 12);
    for (const std::int64_t o : {std::int64_t{128}, std::int64_t{200}}) {
      for (const Tie t : {Tie{true, true}, Tie{false, true}}) {
        path::detail::prepare_curve(c, p); // a fresh walk
        for (std::int64_t sy = p.ymin - 1; sy <= p.ymax + 1; sy += rows_step) {
          out.clear();
          path::detail::curve_crossings_prepared(p, sy, t, out, scratch, o);
          const std::vector<Crossing> exact = path::detail::curve_crossings_exact(c, sy, t);
          ASSERT_EQ(classes(out, o), classes(exact, o)) << "row " << sy << ", offset " << o;
          const auto s = sorted(out), e = sorted(exact);
          for (std::size_t k = 0; k < s.size(); ++k)
            coarse += s[k] != e[k] && (s[k].first - o) % 256 == 0 ? 1 : 0;
          crossings += static_cast<int>(exact.size());
          ++rows;
        }
      }
    }
  }
  EXPECT_GT(rows, 4000);
  EXPECT_GT(coarse, crossings / 2) << "of " << crossings << " crossings";
}

// PATH.CURVE.COARSE leaves a sample on the curve to the tie: x = 1152 t and a monotone y with
// y(1/2) an integer row, so that the row crosses at t = 1/2 exactly on the sample x = 576
// (offset 64 = 576 mod 256). Whichever side of 576 the double estimate lands, a class taken
// without the margin would be the tie's for one of the two directions only; the walks give
// the rational path's classes under both.
// rule: PATH.CURVE.COARSE, PATH.SAMPLE.TIE
TEST(PathCurvePaths, CoarseThresholdsLeaveSamplesOnTheCurveToTheTie) {
  std::vector<Crossing> out, scratch;
  int on_sample = 0;
  for (std::int32_t i = 0; i < 10; ++i)
    for (std::int32_t j = 0; j < 10; ++j) {
      Curve c;
      c.degree = 3;
      const std::array<std::int32_t, 4> ys{0, 40 + 8 * i, 320 + 8 * j, 1000};
      for (std::size_t k = 0; k < 4; ++k)
        c.p[k] = path::Point{384 * static_cast<std::int32_t>(k), ys[k]};
      const std::int64_t mid = (3 * ys[1] + 3 * ys[2] + ys[3]) / 8; // y(1/2), exact
      std::vector<std::int64_t> sys{mid};
      for (std::int64_t sy = 1; sy < 1000; sy += 37)
        sys.push_back(sy);
      std::sort(sys.begin(), sys.end());
      sys.erase(std::unique(sys.begin(), sys.end()), sys.end());
      for (const Tie t : {Tie{true, true}, Tie{false, true}}) {
        path::detail::PreparedCurve p;
        path::detail::prepare_curve(c, p);
        for (const std::int64_t sy : sys) {
          out.clear();
          path::detail::curve_crossings_prepared(p, sy, t, out, scratch, 64);
          const std::vector<Crossing> exact = path::detail::curve_crossings_exact(c, sy, t);
          ASSERT_EQ(classes(out, 64), classes(exact, 64))
              << "y controls " << ys[1] << ", " << ys[2] << ", row " << sy;
          if (sy == mid)
            on_sample +=
                exact.size() == 1 && (exact[0].threshold == 576 || exact[0].threshold == 575) ? 1
                                                                                              : 0;
        }
      }
    }
  EXPECT_EQ(on_sample, 200); // every curve's middle row crosses on the sample
}

// The pieces prepare_curve proves are what PATH.CURVE.SAMPLE says: on each, y' changes sign
// nowhere inside (simple_roots_between, exact), its ends are grid points in order, their values
// are y(k / 2^30) 2^90 exactly, and each bracket between two pieces is 3 cells wide; and a cubic
// whose y' changes sign nowhere in (0, 1) always gets its one piece (a sign taken the wrong way
// at an end where y' = 0, or the vertex test read the wrong way, refuses some).
// rule: PATH.CURVE.SAMPLE
TEST(PathCurvePaths, MonotonePiecesAreMonotone) {
  int proved = 0, pieces = 0, brackets = 0, monotone = 0;
  const Q grid = Q(1) / Q(boost::multiprecision::cpp_int(1) << 30);
  for (const Curve& c : monotone_test_curves()) {
    path::detail::PreparedCurve p;
    path::detail::prepare_curve(c, p);
    const std::array<Q, 4> y{c.p[0].y, c.p[1].y, c.p[2].y, c.p[3].y};
    const std::array<Q, 4> pc{y[0], 3 * (y[1] - y[0]), 3 * (y[0] - 2 * y[1] + y[2]),
                              y[3] - 3 * y[2] + 3 * y[1] - y[0]};
    const std::array<Q, 3> dy{pc[1], 2 * pc[2], 3 * pc[3]};
    // y' without a sign change in (0, 1) (ends where y' = 0 included): one piece, always.
    if (pc[3] != 0 && simple_roots_between(dy, Q(0), Q(1)) == 0) {
      EXPECT_EQ(p.mono.n, 1) << "the curve from y " << c.p[0].y << " is monotone";
      ++monotone;
    }
    if (p.mono.n == 0)
      continue;
    ++proved;
    for (int j = 0; j < p.mono.n; ++j) {
      const auto i = static_cast<std::size_t>(j);
      ASSERT_LT(p.mono.lo[i], p.mono.hi[i]);
      EXPECT_EQ(simple_roots_between(dy, Q(p.mono.lo[i]) * grid, Q(p.mono.hi[i]) * grid), 0)
          << "piece " << j << " of the curve from y " << c.p[0].y;
      for (const auto& [k, value] :
           {std::pair{p.mono.lo[i], p.mono.ylo[i]}, std::pair{p.mono.hi[i], p.mono.yhi[i]}}) {
        const Q t = Q(k) * grid;
        const Q exact = ((pc[3] * t + pc[2]) * t + pc[1]) * t + pc[0];
        // The end's key: 2 floor(y), plus 1 where y is not an integer.
        const boost::multiprecision::cpp_int num = numerator(exact), den = denominator(exact);
        boost::multiprecision::cpp_int fl = num / den;
        if (fl * den > num)
          --fl; // toward minus infinity
        const boost::multiprecision::cpp_int key = 2 * fl + (fl * den == num ? 0 : 1);
        EXPECT_EQ(boost::multiprecision::cpp_int(value), key)
            << "piece " << j << " end at k " << k << " of the curve from y " << c.p[0].y;
      }
      if (j + 1 < p.mono.n) {
        EXPECT_EQ(p.mono.lo[i + 1] - p.mono.hi[i], 3);
      }
      ++pieces;
    }
    brackets += p.mono.brackets;
  }
  EXPECT_GT(proved, 50);
  EXPECT_GT(monotone, 20);
  EXPECT_GT(pieces, proved);
  EXPECT_GT(brackets, 10);
}

// Named rows of the monotone pieces: the cubic (0, 0), (256, 768), (768, 256), (1024, 512) has
// y = 2304 t - 3840 t^2 + 2048 t^3, a maximum 448 at t = 1/2 and a minimum 432 at t = 3/4 (two
// brackets, three pieces). The rows y = 448 and 432 touch the curve (two crossings that cancel)
// inside a bracket, and rows 0 and 512 pass through its ends: the pieces leave them to the
// estimates. Row 440 crosses all three pieces, 447 and 433 next to the extrema too, 300 and
// 480 one piece each: the pieces decide those.
// rule: PATH.CURVE.SAMPLE
TEST(PathCurvePaths, MonotonePiecesLeaveExtremaAndEndsToTheEstimates) {
  Curve c;
  c.degree = 3;
  c.p = {path::Point{0, 0}, path::Point{256, 768}, path::Point{768, 256}, path::Point{1024, 512}};
  path::detail::PreparedCurve p;
  path::detail::prepare_curve(c, p);
  ASSERT_EQ(p.mono.n, 3);
  ASSERT_EQ(p.mono.brackets, 2);
  std::vector<Crossing> mono, out, scratch;
  for (const Tie t : {Tie{true, true}, Tie{false, false}}) {
    path::detail::prepare_curve(c, p);
    for (const std::int64_t sy : {0, 300, 432, 433, 440, 447, 448, 480, 512}) {
      mono.clear();
      const bool decided = path::detail::curve_crossings_monotone(p, sy, t, mono);
      EXPECT_EQ(decided, sy != 0 && sy != 432 && sy != 448 && sy != 512) << "row " << sy;
      out.clear();
      path::detail::curve_crossings_prepared(p, sy, t, out, scratch);
      const auto exact = sorted(path::detail::curve_crossings_exact(c, sy, t));
      EXPECT_EQ(sorted(out), exact) << "row " << sy;
      if (decided) {
        EXPECT_EQ(sorted(mono), exact) << "row " << sy;
        EXPECT_EQ(exact.size(), sy > 432 && sy < 448 ? 3u : 1u) << "row " << sy;
      }
    }
  }
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
