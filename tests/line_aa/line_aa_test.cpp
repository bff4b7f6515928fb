// SPDX-License-Identifier: MIT
// Antialiased lines (D3D reference algorithm): the AA-line diagram of D3D11.3, coverage values
// computed by hand for horizontal, vertical and 45-degree lines, the fragment rule at its
// edge, zero-length lines and the 8-bit blend.

#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "rastrules/fixed.hpp"
#include "rastrules/line.hpp"
#include "rastrules/line_aa.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

using Coverage = std::map<Pixel, std::uint32_t>;

Coverage aa_px(Px a, Px b, std::int32_t w, std::int32_t h) {
  Coverage out;
  std::vector<Pixel> order;
  rasterize_aa_line(sample_px(a.x, a.y), sample_px(b.x, b.y), w, h,
                    [&](std::int32_t x, std::int32_t y, std::uint32_t c) {
                      EXPECT_TRUE(out.emplace(Pixel{x, y}, c).second) << "pixel emitted twice";
                      order.push_back(Pixel{x, y});
                    });
  for (std::size_t i = 1; i < order.size(); ++i)
    EXPECT_LT(order[i - 1], order[i]) << "not row order";
  return out;
}

std::vector<Pixel> keys(const Coverage& c) {
  std::vector<Pixel> v;
  for (const auto& [p, q] : c)
    v.push_back(p);
  return v;
}

// Exact value v (a fraction of 1) in units of 1/65536.
double q16(double v) {
  return v * 65536.0;
}

// A horizontal or vertical line through pixel centres (the values are computed in
// LineAACoverage.HorizontalLineThroughPixelCentres): 29/50 at `mid`, away from the ends;
// 21/100 one pixel `across` the line on either side; no fragment two pixels across; 29/100 at
// `end`, the pixel centred on an endpoint.
void expect_line_through_centres(const Coverage& c, Pixel mid, Pixel across, Pixel end) {
  const auto off = [&](std::int32_t k) {
    return Pixel{mid.x + k * across.x, mid.y + k * across.y};
  };
  EXPECT_NEAR(c.at(mid), q16(29.0 / 50.0), 1.0);
  EXPECT_NEAR(c.at(off(-1)), q16(21.0 / 100.0), 1.0);
  EXPECT_NEAR(c.at(off(1)), q16(21.0 / 100.0), 1.0);
  EXPECT_NEAR(c.at(end), q16(29.0 / 100.0), 1.0);
  EXPECT_EQ(c.count(off(-2)), 0u);
  EXPECT_EQ(c.count(off(2)), 0u);
}

// rule: LINE.AA.FRAGMENT, LINE.AA.COVERAGE, LINE.AA.RECT
TEST(LineAADiagram, ReproducesTheD3DAALineDiagram) {
  // D3D11.3 AA-line diagram: endpoints at about (2.2, 2.9) and (4.75, 2.23) in the drawn
  // 8 x 6 grid (measured on the picture; snapped here to (2.25, 2.875) and (4.75, 2.25)).
  // The circled pixels (coverage > 0) are the 5 x 5 block of columns 1..5, rows 0..4 less the
  // two corners the tilted rectangle misses: (1, 0) and (5, 4).
  const Coverage c = aa_px({2.25, 2.875}, {4.75, 2.25}, 8, 6);
  const std::vector<Pixel> expected = pixels_in_picture({
      "..####..",
      ".#####..",
      ".#####..",
      ".#####..",
      ".####...",
      "........",
  });
  EXPECT_EQ(keys(c), expected) << picture(keys(c), 8, 6);
  // The pixels the rectangle crosses carry the most coverage; every value is in (0, 1].
  for (const auto& [p, q] : c) {
    EXPECT_GT(q, 0u);
    EXPECT_LE(q, 65536u);
  }
  EXPECT_GT(c.at({3, 2}), c.at({3, 0}));
  EXPECT_GT(c.at({3, 2}), c.at({1, 4}));
}

// rule: LINE.AA.COVERAGE, LINE.AA.PRECISION
TEST(LineAACoverage, HorizontalLineThroughPixelCentres) {
  // a = (0.5, 2.5), b = (10.5, 2.5): the rectangle is [0.5, 10.5] x [2, 3].
  // Pixel (5, 2), centre (5.5, 2.5): every square R_i (width w) lies inside the rectangle in x
  // and meets it in the full height 1, so area_i = w and
  //   coverage = (1/5) (1/1 + 1/1.5 + 1/2 + 1/2.5 + 1/3) = (1/5)(87/30) = 29/50 = 0.58.
  // Pixel (5, 1), centre y = 1.5: R_i (half-width h) meets y in [2, min(3, 1.5 + h)], heights
  // 0, 1/4, 1/2, 3/4, 1; area_i = 2h * height, so coverage = (1/5) sum height / (2h)
  //   = (1/5)(0 + 1/6 + 1/4 + 3/10 + 1/3) = (1/5)(63/60) = 21/100 = 0.21. Row 3 mirrors row 1.
  // Pixel (0, 2) is centred on the endpoint a: each square holds half of what (5, 2) holds,
  //   coverage = 29/100.
  // Rows 0 and 4 touch the rectangle only along a line: no fragment.
  const Coverage c = aa_px({0.5, 2.5}, {10.5, 2.5}, 12, 5);
  expect_line_through_centres(c, {5, 2}, {0, 1}, {0, 2});
  EXPECT_EQ(c.at({5, 1}), c.at({5, 3}));
  // Columns 0..11 all have fragments (R4 of column 11 reaches back to x = 10).
  EXPECT_EQ(c.count({11, 2}), 1u);
  // Away from the ends a column sums to 29/50 + 2 * 21/100 = 1: the line's area per column.
  EXPECT_NEAR(c.at({5, 1}) + c.at({5, 2}) + c.at({5, 3}), 65536.0, 3.0);
}

// rule: LINE.AA.COVERAGE, LINE.AA.PRECISION
TEST(LineAACoverage, VerticalLineThroughPixelCentres) {
  // The horizontal case turned by 90 degrees: the same values by the same computation.
  const Coverage c = aa_px({3.5, 1.5}, {3.5, 9.5}, 7, 12);
  expect_line_through_centres(c, {3, 5}, {1, 0}, {3, 1});
}

// rule: LINE.AA.COVERAGE, LINE.AA.PRECISION
TEST(LineAACoverage, FortyFiveDegreeLineThroughPixelCentres) {
  // a = (0.5, 0.5), b = (8.5, 8.5). Pixel (4, 4) lies on the line far from both ends. Around
  // its centre the rectangle is the band |u - v| <= s, s = sqrt(2)/2 (half-width 1/2 measured
  // across the diagonal). A square of width w loses two corner triangles with legs w - s:
  //   area = w^2 - (w - s)^2 = 2 w s - s^2 = sqrt(2) w - 1/2.
  //   coverage = (1/5) sum (sqrt(2)/w - 1/(2 w^2))
  //            = (1/5)(sqrt(2) * 87/30 - (1/2)(1769/900)) = 0.6236882...
  const double s2 = std::sqrt(2.0);
  const double expected = (s2 * 87.0 / 30.0 - 1769.0 / 1800.0) / 5.0;
  const Coverage c = aa_px({0.5, 0.5}, {8.5, 8.5}, 10, 10);
  EXPECT_NEAR(c.at({4, 4}), q16(expected), 1.0);
  // The 45-degree rectangle is symmetric about the diagonal: (5, 4) and (4, 5) agree.
  EXPECT_NEAR(c.at({5, 4}), c.at({4, 5}), 1.0);
  EXPECT_EQ(c.at({5, 4}), c.at({4, 5}));
}

// rule: LINE.AA.COVERAGE, LINE.AA.PRECISION, LINE.AA.TRAVERSAL
TEST(LineAACoverage, LineAcrossTheWholeVertexRangeKeepsItsPrecision) {
  // From (-32768, -32768) to (32767.99609375, 32767.99609375): exactly 45 degrees through the
  // centres (i + 1/2, i + 1/2), 2^24 - 1 raw units each way, the largest D the kernel accepts.
  // Pixel (4, 4) of a 16 x 16 target has the 45-degree value of the test above.
  const Vec2 a{Subpixel::from_raw(kMinVertexRaw), Subpixel::from_raw(kMinVertexRaw)};
  const Vec2 b{Subpixel::from_raw(kMaxVertexRaw), Subpixel::from_raw(kMaxVertexRaw)};
  Coverage c;
  rasterize_aa_line(a, b, 16, 16, [&](std::int32_t x, std::int32_t y, std::uint32_t q) {
    c.emplace(Pixel{x, y}, q);
  });
  const double expected = (std::sqrt(2.0) * 87.0 / 30.0 - 1769.0 / 1800.0) / 5.0;
  EXPECT_NEAR(c.at({4, 4}), q16(expected), 1.0);
  EXPECT_NEAR(c.at({15, 15}), q16(expected), 1.0);
  // A diagonal band. On R4 of pixel (i, j), x - y ranges over the open interval
  // (i - j - 3, i - j + 3); the rectangle is the band |x - y| <= sqrt(2)/2 (away from the far
  // ends). They overlap in positive area iff |i - j| <= 3.
  for (const auto& [p, q] : c)
    EXPECT_LE(std::abs(p.x - p.y), 3) << p;
  EXPECT_EQ(c.size(), 16u + 2u * (15u + 14u + 13u));
  EXPECT_EQ(c.count({0, 3}), 1u);
  EXPECT_EQ(c.count({0, 4}), 0u);
}

// rule: LINE.AA.FRAGMENT
TEST(LineAAFragment, TinyPositiveCoverageStillProducesAFragment) {
  // A horizontal line with rectangle [-5, -1 + 1/256] x [-2 + 1/256, -1 + 1/256] overlaps
  // R4 = (-1, 2)^2 of pixel (0, 0) in a 1/256 x 1/256 corner: exact coverage
  // 2^-16 / (5 * 9) = 1/45 of a unit of 1/65536, which rounds to 0; the fragment exists and
  // carries the smallest positive coverage, 1.
  const Coverage c = aa_px({-5, -1.5 + 1.0 / 256}, {-1 + 1.0 / 256, -1.5 + 1.0 / 256}, 2, 2);
  EXPECT_EQ(keys(c), (std::vector<Pixel>{{0, 0}}));
  EXPECT_EQ(c.at({0, 0}), 1u);
  // One subpixel shorter, the rectangle only touches R4 along its boundary: no fragment.
  EXPECT_TRUE(aa_px({-5, -1.5 + 1.0 / 256}, {-1, -1.5 + 1.0 / 256}, 2, 2).empty());
  // One subpixel higher, likewise.
  EXPECT_TRUE(aa_px({-5, -1.5}, {-1 + 1.0 / 256, -1.5}, 2, 2).empty());
}

// rule: LINE.AA.ZERO_LENGTH
TEST(LineAAZeroLength, AZeroLengthLineProducesNoFragments) {
  EXPECT_TRUE(aa_px({2.5, 2.5}, {2.5, 2.5}, 5, 5).empty());
  EXPECT_TRUE(aa_px({2.25, 1.0}, {2.25, 1.0}, 5, 5).empty());
  const AACoverage c = aa_line_coverage(sample_px(2.5, 2.5), sample_px(2.5, 2.5), 2, 2);
  EXPECT_FALSE(c.positive);
  EXPECT_EQ(c.q16, 0u);
  // One subpixel of length is a rectangle of area 1/256: fragments again.
  EXPECT_FALSE(aa_px({2.5, 2.5}, {2.5 + 1.0 / 256, 2.5}, 5, 5).empty());
}

// rule: LINE.AA.TRAVERSAL, RASTER.TARGET.CLIP
TEST(LineAATraversal, OnlyTargetPixelsInRowOrder) {
  // A long line mostly outside the target: fragments only inside [0, 4) x [0, 3).
  const Coverage c = aa_px({-100.25, 1.5}, {200.5, 1.75}, 4, 3);
  EXPECT_EQ(keys(c), pixels_in_picture({"####", "####", "####"}));
  // The same pixels, same values, as the per-pixel coverage function.
  for (const auto& [p, q] : c) {
    EXPECT_EQ(aa_line_coverage(sample_px(-100.25, 1.5), sample_px(200.5, 1.75), p.x, p.y).q16, q);
  }
}

// rule: LINE.AA.COVERAGE, LINE.AA.PRECISION
TEST(LineAACoverage, AnyPixelPositionIsAccepted) {
  // Pixels far outside the vertex range are answered (coverage 0) without leaving the budget.
  const Vec2 a{Subpixel::from_raw(kMinVertexRaw), Subpixel::from_raw(kMinVertexRaw)};
  const Vec2 b{Subpixel::from_raw(kMaxVertexRaw), Subpixel::from_raw(kMaxVertexRaw)};
  for (const std::int32_t p : {INT32_MIN, -40000, 40000, INT32_MAX}) {
    EXPECT_FALSE(aa_line_coverage(a, b, p, p).positive);
    EXPECT_EQ(aa_line_coverage(a, b, p, 0).q16, 0u);
  }
  // The last pixel the long diagonal reaches in each direction.
  EXPECT_TRUE(aa_line_coverage(a, b, -32768, -32768).positive);
  EXPECT_TRUE(aa_line_coverage(a, b, 32767, 32767).positive);
}

// rule: LINE.AA.BLEND
TEST(LineAABlend, EightBitBlendRoundsToNearestHalvesUp) {
  // Full coverage, opaque source: the source.
  EXPECT_EQ(aa_blend_unorm8(255, 255, 0, 65536), 255);
  EXPECT_EQ(aa_blend_unorm8(17, 255, 200, 65536), 17);
  // Zero coverage or zero alpha: the destination.
  EXPECT_EQ(aa_blend_unorm8(255, 255, 40, 0), 40);
  EXPECT_EQ(aa_blend_unorm8(255, 0, 40, 65536), 40);
  // Half coverage: 255 * 1/2 = 127.5, a half, rounds up to 128.
  EXPECT_EQ(aa_blend_unorm8(255, 255, 0, 32768), 128);
  // Downwards too: 0 over 255 at half coverage = 127.5 -> 128.
  EXPECT_EQ(aa_blend_unorm8(0, 255, 255, 32768), 128);
  // 100 + (200 - 100) * (128/255) = 150.196... -> 150.
  EXPECT_EQ(aa_blend_unorm8(200, 128, 100, 65536), 150);
  // The centre pixel of the horizontal line (coverage 38011 ~ 0.58): 255 * 38011/65536 =
  // 147.90... -> 148 over black.
  EXPECT_EQ(aa_blend_unorm8(255, 255, 0, 38011), 148);
  // Alpha and coverage multiply: 255 * (51/255) * (1/2) = 25.5 -> 26.
  EXPECT_EQ(aa_blend_unorm8(255, 51, 0, 32768), 26);
}

} // namespace
} // namespace rastrules::test
