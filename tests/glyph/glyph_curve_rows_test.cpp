// SPDX-License-Identifier: MIT
// Examples: on the curves of real glyphs, the kernel's integer paths of curve crossings (the
// exact rational-root path of quadratics, the estimated and scanned fast paths) give exactly the
// crossings of the rational path, on every sample row of every curve, for both vertical tie
// signs and both horizontal ones. Glyph outlines meet sample rows at dyadic roots (t = 1/2,
// 1/4), at rational roots whose x is an integer (t = 1/3 with x = 1204) and at curve ends, which
// the fast path once left to the rational path (100 to 180 us a row).
// Tests: PATH.CURVE.SAMPLE, PATH.CURVE.FILTER

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "glyph_support.hpp"
#include "path_detail.hpp"
#include "rastrules/io/glyph.hpp"

namespace {

namespace kp = rastrules::path;
namespace kd = rastrules::path::detail;

bool same(const std::vector<kd::Crossing>& a, const std::vector<kd::Crossing>& b) {
  if (a.size() != b.size())
    return false;
  std::vector<std::pair<std::int64_t, int>> x, y;
  for (const auto& c : a)
    x.emplace_back(c.threshold, c.dir);
  for (const auto& c : b)
    y.emplace_back(c.threshold, c.dir);
  std::sort(x.begin(), x.end());
  std::sort(y.begin(), y.end());
  return x == y;
}

// The rows named in the comment: quadratics of DejaVu Sans glyphs at 24 px, and a cubic.
// rule: PATH.CURVE.SAMPLE, PATH.CURVE.FILTER
TEST(GlyphCurveRows, RationalRootsAndIntegerCrossingsMatchTheRationalPath) {
  const std::vector<std::pair<kd::Curve, std::int64_t>> rows = {
      {kd::Curve{2, {{{824, 596}, {688, 632}, {564, 700}, {564, 700}}}}, 640},          // t = 1/2
      {kd::Curve{2, {{{820, 2008}, {820, 2212}, {876, 2272}, {876, 2272}}}}, 2176},     // t = 1/2
      {kd::Curve{2, {{{748, 2008}, {1128, 1720}, {1880, 1720}, {1880, 1720}}}}, 1920},  // x = 885
      {kd::Curve{2, {{{2052, 3460}, {2292, 3460}, {2528, 3396}, {2528, 3396}}}}, 3456}, // t = 1/4
      {kd::Curve{2, {{{1400, 6112}, {1156, 6400}, {612, 6400}, {612, 6400}}}}, 6272},   // x = 1204
      {kd::Curve{2, {{{1400, 6112}, {1156, 6400}, {612, 6400}, {612, 6400}}}}, 6112},   // an end
      {kd::Curve{2, {{{1400, 6112}, {1156, 6400}, {612, 6400}, {612, 6400}}}}, 6400}, // tangent end
      // A cubic of Nimbus Sans' S at 12 px: a dyadic root (t = 1/2, x = 1742.5), which the
      // estimates confine around the grid point; once 300 us on the rational path.
      {kd::Curve{3, {{{2028, 676}, {1904, 420}, {1644, 284}, {1268, 284}}}}, 384},
  };
  for (const auto& [curve, sy] : rows)
    for (const bool x_right : {true, false})
      for (const bool y_down : {true, false}) {
        const kd::Tie t{x_right, y_down};
        EXPECT_TRUE(
            same(kd::curve_crossings(curve, sy, t), kd::curve_crossings_exact(curve, sy, t)))
            << "row " << sy << " from (" << curve.p[0].x << ", " << curve.p[0].y << ")";
      }
}

// Every fourth sample row of every curve of three glyphs (quadratics and cubics), and every row
// through a curve's first or last point (an end row).
// rule: PATH.CURVE.SAMPLE, PATH.CURVE.FILTER
TEST(GlyphCurveRows, FastCrossingsEqualRationalOnGlyphRows) {
  int rows = 0, end_rows = 0, cubic_end_rows = 0;
  for (const auto& [font, size] : {std::pair{std::string(RASTRULES_FONT_DEJAVU), 24},
                                   std::pair{std::string(RASTRULES_FONT_CUBIC), 17},
                                   std::pair{std::string(RASTRULES_FONT_CUBIC), 24}})
    for (const char32_t c : {U'g', U'S', U'@'}) {
      const rastrules::io::Glyph g = rastrules::glyph_support::load_or_fail(font, c, size);
      const kd::Boundary b = kd::boundary_of(g.path);
      for (const kd::Curve& curve : b.curves)
        for (std::int32_t j = 0; j < g.height; ++j) {
          const std::int64_t sy = 256 * std::int64_t{j} + 128;
          const bool end =
              sy == curve.p[0].y || sy == curve.p[static_cast<std::size_t>(curve.degree)].y;
          if (!end && j % 4 != 0)
            continue; // every curve end on a row, and every fourth row (CI time under sanitizers)
          end_rows += end ? 1 : 0;
          cubic_end_rows += end && curve.degree == 3 ? 1 : 0;
          for (const bool y_down : {true, false}) {
            const kd::Tie t{true, y_down};
            const auto fast = kd::curve_crossings(curve, sy, t);
            ASSERT_TRUE(same(fast, kd::curve_crossings_exact(curve, sy, t)))
                << "row " << sy << " of U+" << static_cast<unsigned>(c) << " at " << size;
            rows += fast.empty() ? 0 : 1;
          }
        }
    }
  EXPECT_GT(rows, 50);
  EXPECT_GT(cubic_end_rows, 0);
  EXPECT_GT(end_rows, cubic_end_rows);
}

// The monotone pieces (PATH.CURVE.SAMPLE) on the cubics of Nimbus Sans (the path ladder's
// glyphs, at 24 px): every row of every cubic, walked in order through one prepared curve as
// the row walk does, gives the rational path's crossings; and the pieces are proved for the
// cubics and decide their rows (the counts are printed); the aliased walk's crossings are
// those of the rational path class by class, most with a class threshold.
// rule: PATH.CURVE.SAMPLE, PATH.CURVE.FILTER, PATH.CURVE.COARSE
TEST(GlyphCurveRows, MonotonePiecesDecideNimbusCubicRows) {
  int cubics = 0, with_pieces = 0, rows = 0, decided = 0, coarse = 0, crossings = 0;
  std::vector<kd::Crossing> out, scratch, mono;
  for (const char32_t c : std::u32string(U"ag&@8eS%")) {
    const rastrules::io::Glyph g =
        rastrules::glyph_support::load_or_fail(RASTRULES_FONT_CUBIC, c, 24);
    const kd::Boundary b = kd::boundary_of(g.path);
    for (const kd::Curve& curve : b.curves) {
      if (curve.degree != 3)
        continue;
      kd::PreparedCurve p;
      kd::prepare_curve(curve, p);
      if (p.y[3] == 0)
        continue; // a quadratic in the power basis: the quadratic rows
      ++cubics;
      with_pieces += p.mono.n > 0 ? 1 : 0;
      const kd::Tie t{true, true};
      for (std::int32_t j = 0; j < g.height; ++j) {
        const std::int64_t sy = 256 * std::int64_t{j} + 128;
        if (sy < p.ymin || sy > p.ymax)
          continue;
        ++rows;
        mono.clear();
        decided += kd::curve_crossings_monotone(p, sy, t, mono) ? 1 : 0;
        out.clear();
        kd::curve_crossings_prepared(p, sy, t, out, scratch);
        const auto exact = kd::curve_crossings_exact(curve, sy, t);
        ASSERT_TRUE(same(out, exact)) << "row " << sy << " of U+" << static_cast<unsigned>(c);
        ASSERT_TRUE(mono.empty() || same(mono, exact)) << "row " << sy;
      }
      // The aliased walk's crossings (PATH.CURVE.COARSE: the sample at raw x = 128 mod 256)
      // on a fresh walk of the same curve: each in the class of the exact one.
      kd::prepare_curve(curve, p);
      for (std::int32_t j = 0; j < g.height; ++j) {
        const std::int64_t sy = 256 * std::int64_t{j} + 128;
        if (sy < p.ymin || sy > p.ymax)
          continue;
        out.clear();
        kd::curve_crossings_prepared(p, sy, t, out, scratch, 128);
        const auto exact = kd::curve_crossings_exact(curve, sy, t);
        const auto classes = [](const std::vector<kd::Crossing>& v) {
          std::vector<std::pair<std::int64_t, int>> r;
          for (const kd::Crossing& x : v)
            r.emplace_back(rastrules::floor_div(x.threshold - 128, 256), x.dir);
          std::sort(r.begin(), r.end());
          return r;
        };
        ASSERT_EQ(classes(out), classes(exact))
            << "row " << sy << " of U+" << static_cast<unsigned>(c);
        for (const kd::Crossing& x : out) {
          const bool is_exact = std::any_of(exact.begin(), exact.end(), [&](const kd::Crossing& e) {
            return e.threshold == x.threshold;
          });
          coarse += is_exact ? 0 : 1;
          ++crossings;
        }
      }
    }
  }
  std::printf("aliased walk: %d of %d crossings carry a class threshold (PATH.CURVE.COARSE)\n",
              coarse, crossings);
  EXPECT_GE(coarse * 100, crossings * 80);
  std::printf("Nimbus Sans cubics at 24 px: %d, with pieces %d; rows %d, decided by them %d\n",
              cubics, with_pieces, rows, decided);
  EXPECT_GT(cubics, 100);
  EXPECT_GE(with_pieces * 100, cubics * 95);
  EXPECT_GE(decided * 100, rows * 95);
}

} // namespace
