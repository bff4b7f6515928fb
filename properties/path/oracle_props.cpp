// SPDX-License-Identifier: MIT
// Properties of the exact path oracle on its own (no kernel): its two derivations of the
// winding number agree on lines, a convex polygon's pixel areas sum to its shoelace area, a
// polygon cut along a chord partitions the samples and the areas, areas lie within the 4 x 4
// grid bound of the samples, and curve decisions survive exact subdivision at t = 1/2 and
// degree elevation (both done on coordinates scaled so that they stay integers).
// Implements (properties for): PATH.WINDING, PATH.FILL.RULE, PATH.SAMPLE.TIE, PATH.AREA.EXACT

#include <algorithm>
#include <array>
#include <bit>
#include <climits>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "path_checks.hpp"
#include "path_gen.hpp"
#include "rastrules/oracle/msaa.hpp"
#include "rastrules/oracle/path.hpp"

namespace {

namespace pg = rastrules::path_gen;
namespace pc = rastrules::path_checks;
namespace op = rastrules::oracle::path;
using pg::Raw2;

// rule: PATH.WINDING, PATH.SAMPLE.TIE
RC_GTEST_PROP(PathOracle, LineRuleEqualsExactRootsOnTies, ()) {
  const pg::GPath p = *pg::path(pc::kSide, false);
  pc::show_path(p);
  RC_TAG(pg::name(p.kind));
  const op::Path o = pg::to_oracle(p);
  for (const Raw2& s : pg::tie_points(p)) {
    for (const std::string& fill : pg::conventions()) {
      const std::int64_t a = op::winding(o, s, fill), b = op::winding_by_roots(o, s, fill);
      if (a != b)
        RC_FAIL("(" + std::to_string(s[0]) + ", " + std::to_string(s[1]) + ") " + fill +
                ": line rule " + std::to_string(a) + ", roots " + std::to_string(b));
    }
  }
}

// rule: PATH.AREA.EXACT
RC_GTEST_PROP(PathOracle, ConvexPolygonAreasSumToItsArea, ()) {
  std::vector<Raw2> h;
  while (h.size() < 3)
    h = pg::hull(pg::random_points(pc::kSide, 3, 8));
  pg::GPath p{pg::PathKind::kPolygon, *rc::gen::arbitrary<bool>(), {pg::polygon(h)}};
  // Inside the target of side + 2 px once moved by 1 px: every pixel it reaches is counted.
  p = pg::translated(p, 256, 256);
  pc::show_path(p);
  std::int64_t twice = 0;
  for (std::size_t i = 0; i < h.size(); ++i)
    twice += pg::orient({0, 0}, h[i], h[(i + 1) % h.size()]);
  mpq_class sum = 0;
  for (const auto& [px, a] : pc::oracle_areas(p, pc::kSide + 2))
    sum += a;
  mpq_class expected = mpq_class(twice < 0 ? -twice : twice) / (2 * 65536);
  RC_ASSERT(sum == expected);
}

// rule: PATH.SAMPLE.TIE, PATH.AREA.EXACT
RC_GTEST_PROP(PathOracle, PolygonCutAlongAChordPartitionsSamplesAndAreas, ()) {
  const pc::CutCase c = pc::cut_case(pc::kSide);
  pc::check_cut(
      c, [&](const pg::GPath& p) { return pc::oracle_masks(p, c.pattern, c.fill, pc::kSide); },
      [&](const pg::GPath& p) { return pc::oracle_areas(p, pc::kSide); });
}

// rule: PATH.AREA.EXACT, PATH.SAMPLE.TIE
RC_GTEST_PROP(PathOracle, AreaWithinTheGridBoundOfItsSamples, ()) {
  const pg::GPath p = *pg::path(pc::kSide, false);
  pc::show_path(p);
  RC_TAG(pg::name(p.kind));
  const std::string fill = *rc::gen::elementOf(pg::conventions());
  const std::string problem =
      pc::grid_bound_problem(p, pc::oracle_masks(p, pc::grid4(), fill, pc::kSide),
                             pc::oracle_areas(p, pc::kSide), pc::kSide);
  if (!problem.empty())
    RC_FAIL(problem);
}

// rule: PATH.WINDING, PATH.SAMPLE.TIE
RC_GTEST_PROP(PathOracle, CurveDecisionsSurviveSplittingAtOneHalf, ()) {
  pg::GPath p;
  p.contours.push_back(*pg::curve_contour(pc::kSide));
  p.kind = pg::PathKind::kCurves;
  pc::show_path(p);
  const pg::GPath split = pg::scaled_and_split(p, 8);
  const op::Path a = pg::to_oracle(p), b = pg::to_oracle(split);
  std::vector<Raw2> samples = pg::tie_points(p);
  for (std::int64_t y = 0; y < pc::kSide * 256; y += 128)
    for (std::int64_t x = 0; x < pc::kSide * 256; x += 128)
      samples.push_back({x + 64, y + 64});
  for (const Raw2& s : samples) {
    for (const std::string& fill : pg::conventions()) {
      const std::int64_t wa = op::winding(a, s, fill),
                         wb = op::winding(b, {8 * s[0], 8 * s[1]}, fill);
      if (wa != wb)
        RC_FAIL("(" + std::to_string(s[0]) + ", " + std::to_string(s[1]) + ") " + fill + ": " +
                std::to_string(wa) + " before, " + std::to_string(wb) + " after");
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Curves against an independent reference: away from a curve, a flattening decides exactly.

struct QPoint {
  mpq_class x, y;
};

// The contract's line rule, written again over rationals (the oracle's is in int64).
int rational_line_crossing(const QPoint& a, const QPoint& b, const Raw2& s, int sx, int sy) {
  if (a.y == b.y)
    return 0;
  const mpq_class X(s[0]), Y(s[1]);
  const mpq_class lo = a.y < b.y ? a.y : b.y, hi = a.y < b.y ? b.y : a.y;
  const bool in_y = sy > 0 ? (lo <= Y && Y < hi) : (lo < Y && Y <= hi);
  if (!in_y)
    return 0;
  const mpq_class xc = a.x + (b.x - a.x) * (Y - a.y) / (b.y - a.y);
  const bool right = xc > X || (xc == X && sx < 0);
  return right ? (b.y > a.y ? 1 : -1) : 0;
}

mpq_class orient(const QPoint& a, const QPoint& b, const Raw2& p) {
  return (b.x - a.x) * (mpq_class(p[1]) - a.y) - (b.y - a.y) * (mpq_class(p[0]) - a.x);
}

// Returns whether p lies in the closed convex hull of the control points (some closed
// triangle of three of them contains it; on a degenerate hull's line: counted as inside).
bool in_hull(const std::vector<QPoint>& c, const Raw2& p) {
  for (std::size_t i = 0; i < c.size(); ++i)
    for (std::size_t j = i + 1; j < c.size(); ++j)
      for (std::size_t k = j + 1; k < c.size(); ++k) {
        const int a = sgn(orient(c[i], c[j], p)), b = sgn(orient(c[j], c[k], p)),
                  d = sgn(orient(c[k], c[i], p));
        if ((a >= 0 && b >= 0 && d >= 0) || (a <= 0 && b <= 0 && d <= 0))
          return true;
      }
  return false;
}

// Returns the blossom (polar form) of the Bezier curve with control points c at (u_1, ..., u_n),
// n the degree: the sum over i of c[i] times the sum over the i-element subsets S of
// {1..n} of prod_{j in S} u_j prod_{j not in S} (1 - u_j).
QPoint blossom(const std::vector<QPoint>& c, const std::vector<mpq_class>& u) {
  const std::size_t n = u.size();
  QPoint r{0, 0};
  for (std::uint32_t subset = 0; subset < (1u << n); ++subset) {
    mpq_class weight = 1;
    for (std::size_t j = 0; j < n; ++j)
      weight *= (subset >> j) & 1u ? u[j] : 1 - u[j];
    const QPoint& p = c[static_cast<std::size_t>(std::popcount(subset))];
    r.x += weight * p.x;
    r.y += weight * p.y;
  }
  return r;
}

// Splits the curve into `parts` pieces of equal parameter length, each given by its control
// points: the blossom at (a, ..., a, b, ..., b) for the piece [a, b] (an independent
// derivation; the oracle's bounded areas use de Casteljau).
void subdivide(const std::vector<QPoint>& c, int parts, std::vector<std::vector<QPoint>>& out) {
  const std::size_t n = c.size() - 1;
  for (int k = 0; k < parts; ++k) {
    const mpq_class a = mpq_class(k) / parts, b = mpq_class(k + 1) / parts;
    std::vector<QPoint> piece;
    for (std::size_t i = 0; i <= n; ++i) {
      std::vector<mpq_class> u(n, a);
      std::fill(u.begin() + static_cast<std::ptrdiff_t>(n - i), u.end(), b);
      piece.push_back(blossom(c, u));
    }
    out.push_back(piece);
  }
}

// A curve's winding number at a sample outside the hull of every piece of its subdivision is
// that of the polyline through the pieces' ends (curve and chord stay inside the piece's hull,
// so moving one onto the other never crosses the sample): the oracle's root isolation must
// give exactly the flattening's answer there, under every convention.
// rule: PATH.WINDING, PATH.SAMPLE.TIE, PATH.GEOMETRY
RC_GTEST_PROP(PathOracle, CurveWindingEqualsAFlatteningAwayFromTheCurve, ()) {
  pg::GPath p{pg::PathKind::kCurves, false, {}};
  const int n = *rc::gen::inRange(1, 3);
  for (int i = 0; i < n; ++i)
    p.contours.push_back(*pg::curve_contour(pc::kSide));
  pc::show_path(p);
  std::vector<std::array<QPoint, 2>> chords;      // the flattening
  std::vector<std::vector<QPoint>> hulls;         // where it may differ from the curve
  std::vector<std::array<std::int64_t, 4>> boxes; // integer boxes around the hulls
  for (const pg::GContour& c : p.contours) {
    const std::vector<Raw2> ends = pg::closed_ends(c);
    for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
      std::vector<QPoint> ctrl{{mpq_class(ends[i][0]), mpq_class(ends[i][1])}};
      if (i < c.pieces.size())
        for (const Raw2& r : c.pieces[i].pts)
          ctrl.push_back({mpq_class(r[0]), mpq_class(r[1])});
      else
        ctrl.push_back({mpq_class(ends[i + 1][0]), mpq_class(ends[i + 1][1])});
      std::vector<std::vector<QPoint>> pieces;
      subdivide(ctrl, ctrl.size() > 2 ? 16 : 1, pieces);
      for (const auto& piece : pieces) {
        chords.push_back({piece.front(), piece.back()});
        if (piece.size() > 2) {
          hulls.push_back(piece);
          std::array<std::int64_t, 4> b{INT64_MAX, INT64_MAX, INT64_MIN, INT64_MIN};
          for (const QPoint& q : piece) {
            const mpz_class fx = q.x.get_num() / q.x.get_den(); // truncation: +-1 below
            const mpz_class fy = q.y.get_num() / q.y.get_den();
            b = {std::min(b[0], fx.get_si() - 1), std::min(b[1], fy.get_si() - 1),
                 std::max(b[2], fx.get_si() + 1), std::max(b[3], fy.get_si() + 1)};
          }
          boxes.push_back(b);
        }
      }
    }
  }
  const op::Path o = pg::to_oracle(p);
  const std::string fill = *rc::gen::elementOf(pg::conventions());
  const op::Raw2 d = fill == "top-left"      ? op::Raw2{1, 1}
                     : fill == "top-right"   ? op::Raw2{-1, 1}
                     : fill == "bottom-left" ? op::Raw2{1, -1}
                                             : op::Raw2{-1, -1};
  std::size_t tested = 0, near = 0;
  for (std::int64_t y = -64; y <= pc::kSide * 256 + 64; y += 48) {
    for (std::int64_t x = -64; x <= pc::kSide * 256 + 64; x += 48) {
      const Raw2 s{x, y};
      bool inside = false;
      for (std::size_t h = 0; h < hulls.size() && !inside; ++h) {
        const auto& b = boxes[h];
        inside = x >= b[0] && x <= b[2] && y >= b[1] && y <= b[3] && in_hull(hulls[h], s);
      }
      if (inside) {
        ++near;
        continue;
      }
      std::int64_t expected = 0;
      for (const auto& ch : chords)
        expected +=
            rational_line_crossing(ch[0], ch[1], s, static_cast<int>(d[0]), static_cast<int>(d[1]));
      const std::int64_t got = op::winding(o, s, fill);
      if (got != expected)
        RC_FAIL("(" + std::to_string(x) + ", " + std::to_string(y) + ") raw, " + fill +
                ": oracle " + std::to_string(got) + ", flattening " + std::to_string(expected));
      ++tested;
    }
  }
  RC_CLASSIFY(near > 0, "samples near a curve skipped");
  RC_CLASSIFY(tested < 100, "fewer than 100 samples tested");
}

// The certified curve areas at two depths are intervals that overlap in every pixel (both
// hold the exact area), lie in [0, 1] up to the bound, and the deeper one is narrower; for
// paths of lines the areas are the exact ones with bound 0.
// rule: PATH.AREA.EXACT
RC_GTEST_PROP(PathOracle, CertifiedCurveAreasAreConsistentIntervals, ()) {
  pg::GPath p{pg::PathKind::kCurves, *rc::gen::arbitrary<bool>(), {}};
  const int n = *rc::gen::inRange(1, 3);
  for (int i = 0; i < n; ++i)
    p.contours.push_back(*pg::curve_contour(pc::kSide));
  pc::show_path(p);
  const op::Path o = pg::to_oracle(p);
  std::map<pc::Pixel, std::array<mpq_class, 4>> all; // area, bound at depth 2; at depth 5
  for (const int depth : {2, 5}) {
    const std::size_t at = depth == 2 ? 0 : 2;
    for (const op::PixelAreaBound& a : op::cover_area_bounded(o, pc::kSide, pc::kSide, depth)) {
      all[{a.area.y, a.area.x}][at] = pc::rational(a.area.num, a.area.den);
      all[{a.area.y, a.area.x}][at + 1] = pc::rational(a.bound_num, a.bound_den);
    }
  }
  for (const auto& [px, v] : all) {
    const mpq_class lo = std::max(v[0] - v[1], v[2] - v[3]),
                    hi = std::min(v[0] + v[1], v[2] + v[3]);
    if (lo > hi || lo > 1 || hi < 0)
      RC_FAIL(pc::str(px) + ": depth 2 " + v[0].get_str() + " +- " + v[1].get_str() + ", depth 5 " +
              v[2].get_str() + " +- " + v[3].get_str());
    RC_ASSERT(v[3] <= v[1]);
  }
  if (!pg::has_curves(p)) {
    std::map<pc::Pixel, mpq_class> exact = pc::oracle_areas(p, pc::kSide);
    for (const auto& [px, v] : all)
      RC_ASSERT(v[1] == 0 && v[0] == (exact.count(px) ? exact[px] : mpq_class(0)));
  }
}

// rule: PATH.WINDING, PATH.SAMPLE.TIE
RC_GTEST_PROP(PathOracle, QuadraticEqualsItsDegreeElevatedCubic, ()) {
  const Raw2 p0 = *pg::point(pc::kSide), p1 = *pg::point(pc::kSide), p2 = *pg::point(pc::kSide);
  const auto mul3 = [](Raw2 r) { return Raw2{3 * r[0], 3 * r[1]}; };
  const pg::GPath quad{pg::PathKind::kCurves,
                       false,
                       {pg::GContour{mul3(p0), {pg::GPiece{2, {mul3(p1), mul3(p2)}}}}}};
  // Cubic controls (p0 + 2 p1) / 3 and (2 p1 + p2) / 3, times 3.
  const pg::GPath cubic{pg::PathKind::kCurves,
                        false,
                        {pg::GContour{mul3(p0),
                                      {pg::GPiece{3,
                                                  {{p0[0] + 2 * p1[0], p0[1] + 2 * p1[1]},
                                                   {2 * p1[0] + p2[0], 2 * p1[1] + p2[1]},
                                                   mul3(p2)}}}}}};
  pc::show_path(quad);
  const op::Path a = pg::to_oracle(quad), b = pg::to_oracle(cubic);
  std::vector<Raw2> samples = pg::tie_points(quad);
  for (const Raw2& s : samples) {
    for (const std::string& fill : pg::conventions())
      RC_ASSERT(op::winding(a, s, fill) == op::winding(b, s, fill));
  }
}

} // namespace
