// SPDX-License-Identifier: MIT
// Sample coverage of paths of lines (PATH.*): winding numbers and their sign, the fill rules,
// the tie rule against the triangle rule at tie points, every fill convention on an edge and
// on a vertex, the star, a contour drawn twice, a glyph-like shape with a hole, the doubled-back
// diagonal, paths at the edge of the coordinate range, and the row walk of cover_samples
// against covers_sample at every sample of every pattern.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "fill_convention_cases.hpp"
#include "path_support.hpp"
#include "rastrules/fixed.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/path.hpp"
#include "rastrules/triangle.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

using path::FillRule;

const SamplePattern kCentre = standard_pattern(1);

path::Path square(FillRule rule) {
  return make_path(rule, {polygon({{1, 1}, {5, 1}, {5, 5}, {1, 5}})});
}

// A path's parts and their names: contours of segments, the fill rule spelled as scenes do.
// rule: PATH.GEOMETRY
TEST(PathGeometry, ContoursOfSegmentsAndTheFillRuleNames) {
  EXPECT_EQ(to_string(FillRule::kNonZero), "nonzero");
  EXPECT_EQ(to_string(FillRule::kEvenOdd), "evenodd");
  EXPECT_EQ(from_name<FillRule>("evenodd"), FillRule::kEvenOdd);
  EXPECT_EQ(to_string(path::SegmentKind::kCubic), "cubic");
  // Two contours: each segment starts where the previous one ended.
  const path::Path p = make_path(FillRule::kNonZero, {polygon({{1, 1}, {3, 1}, {3, 3}, {1, 3}}),
                                                      polygon({{5, 1}, {7, 1}, {7, 3}, {5, 3}})});
  EXPECT_EQ(path::cover_samples(p, kCentre, FillConvention::kTopLeft, 8, 4).size(), 8u);
  EXPECT_EQ(path::winding_number(p, pt(6, 2), FillConvention::kTopLeft), 1);
  EXPECT_EQ(path::winding_number(p, pt(4, 2), FillConvention::kTopLeft), 0);
}

// rule: PATH.WINDING
TEST(PathWinding, ClockwiseOnScreenIsPlusOneAndItsReverseMinusOne) {
  const path::Path cw = square(FillRule::kNonZero);
  const path::Path ccw = make_path(FillRule::kNonZero, {reversed(cw.contours[0])});
  EXPECT_EQ(path::winding_number(cw, pt(3, 3), FillConvention::kTopLeft), 1);
  EXPECT_EQ(path::winding_number(ccw, pt(3, 3), FillConvention::kTopLeft), -1);
  EXPECT_EQ(path::winding_number(cw, pt(7, 3), FillConvention::kTopLeft), 0);
  EXPECT_EQ(path::winding_number(cw, pt(3, 7), FillConvention::kTopLeft), 0);
}

// rule: PATH.FILL.RULE, PATH.WINDING
TEST(PathFillRule, NegativeOddWindingIsInsideUnderEvenOdd) {
  const path::Path ccw =
      make_path(FillRule::kEvenOdd, {reversed(square(FillRule::kEvenOdd).contours[0])});
  EXPECT_TRUE(path::covers_sample(ccw, pt(3, 3), FillConvention::kTopLeft));
  EXPECT_TRUE(path::fill_holds(FillRule::kEvenOdd, -1));
  EXPECT_TRUE(path::fill_holds(FillRule::kEvenOdd, -3));
  EXPECT_FALSE(path::fill_holds(FillRule::kEvenOdd, -2));
  EXPECT_FALSE(path::fill_holds(FillRule::kEvenOdd, 0));
  EXPECT_TRUE(path::fill_holds(FillRule::kNonZero, -2));
  EXPECT_FALSE(path::fill_holds(FillRule::kNonZero, 0));
}

// rule: PATH.CONTOUR.CLOSE
TEST(PathClose, AnOpenContourFillsAsItsClosedForm) {
  path::Path open = make_path(FillRule::kNonZero, {polygon({{1, 1}, {5, 1}, {5, 5}, {1, 5}})});
  path::Path closed = open;
  closed.contours[0].segments.push_back(
      path::Segment{path::SegmentKind::kLine, {pt(1, 1), {}, {}}});
  for (const FillConvention f : kAllConventions)
    EXPECT_EQ(path::cover_samples(open, kCentre, f, 8, 8),
              path::cover_samples(closed, kCentre, f, 8, 8));
  EXPECT_EQ(path::cover_samples(open, kCentre, FillConvention::kTopLeft, 8, 8).size(), 16u);
}

// The triangles of the fill-convention examples (tests/tri/fill_convention_test.cpp) and a few
// slanted ones, in pixels.
const std::array<std::array<Px, 3>, 11> kTriangles = {{
    {{{0, 0}, {4, 0}, {0, 4}}},
    {{{0, 4}, {4, 0}, {4, 4}}},
    {{{4, 0}, {4, 4}, {0, 2}}},
    {{{0, 0}, {4, 2}, {0, 4}}},
    {{{2, 0}, {4, 4}, {0, 4}}},
    {{{0, 0}, {4, 0}, {2, 4}}},
    {{{0, 0}, {4, 4}, {0, 4}}},
    {{{4, 0}, {4, 4}, {0, 4}}},
    {{{0.5, 0.25}, {3.75, 1.5}, {1.25, 3.5}}},
    {{{1, 0.5}, {3, 0.5}, {3, 3.5}}},
    {{{0.5, 0.5}, {3.5, 2}, {2, 2}}},
}};

path::Path triangle_path(const std::array<Px, 3>& t, FillRule rule) {
  return make_path(rule, {polygon({{t[0].x, t[0].y}, {t[1].x, t[1].y}, {t[2].x, t[2].y}})});
}

// Every sample on a 1/4 px grid over the triangle's box (vertices, edges and their crossings
// with the grid are tie points), both windings, both fill rules, every convention: the path
// covers a sample iff TRI.COVER.SAMPLE does.
// rule: PATH.TIE.TRIANGLE, PATH.SAMPLE.TIE
TEST(PathTieRule, OneTrianglePathCoversWhatTheTriangleRuleCovers) {
  for (const auto& tri : kTriangles) {
    for (const bool reverse : {false, true}) {
      const std::array<Px, 3> v = reverse ? std::array<Px, 3>{tri[0], tri[2], tri[1]} : tri;
      for (const FillConvention f : kAllConventions) {
        RasterState state;
        state.fill = f;
        const TriangleSetup setup = triangle_px(v[0], v[1], v[2], state);
        for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
          const path::Path p = triangle_path(v, rule);
          for (int ys = -1; ys <= 17; ++ys)
            for (int xs = -1; xs <= 17; ++xs) {
              const Vec2 s = sample_px(xs / 4.0, ys / 4.0);
              EXPECT_EQ(path::covers_sample(p, pt(xs / 4.0, ys / 4.0), f), covers(setup, s))
                  << "triangle (" << v[0].x << "," << v[0].y << ") (" << v[1].x << "," << v[1].y
                  << ") (" << v[2].x << "," << v[2].y << ") sample (" << xs / 4.0 << "," << ys / 4.0
                  << ") convention " << static_cast<int>(f);
            }
        }
      }
    }
  }
}

// rule: PATH.TIE.TRIANGLE, PATH.DEGENERATE
TEST(PathTieRule, DegenerateTriangleCoversNothing) {
  const path::Path p = make_path(FillRule::kNonZero, {polygon({{0, 0}, {2, 2}, {4, 4}})});
  for (const FillConvention f : kAllConventions)
    EXPECT_TRUE(path::cover_samples(p, standard_pattern(16), f, 6, 6).empty());
}

// rule: PATH.SAMPLE.TIE
// The table of tests/tri/fill_convention_test.cpp (samples on edges and vertices under each
// convention), drawn as one-triangle paths.
TEST(PathTieRule, EveryConventionOnAnEdgeAndOnAVertex) {
  for (const ConventionCase& c : kConventionCases) {
    for (const bool reverse : {false, true}) {
      const std::array<Px, 3> v = reverse ? std::array<Px, 3>{c.tri[0], c.tri[2], c.tri[1]} : c.tri;
      for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
        const path::Path p = triangle_path(v, rule);
        const path::Point s = pt(c.sample.x, c.sample.y);
        EXPECT_EQ(path::covers_sample(p, s, FillConvention::kTopLeft), c.top_left) << c.name;
        EXPECT_EQ(path::covers_sample(p, s, FillConvention::kTopRight), c.top_right) << c.name;
        EXPECT_EQ(path::covers_sample(p, s, FillConvention::kBottomLeft), c.bottom_left) << c.name;
        EXPECT_EQ(path::covers_sample(p, s, FillConvention::kBottomRight), c.bottom_right)
            << c.name;
      }
    }
  }
}

// A sample on a horizontal edge between two squares stacked in one path, and on the vertex
// where four squares of one path meet: the half-open rule gives each sample to exactly one
// square, and inside the union the sample is covered under every convention.
// rule: PATH.SAMPLE.TIE, PATH.TIE.PARTITION
TEST(PathTieRule, SharedEdgesAndVerticesInsideOnePathAreCovered) {
  const path::Path four = make_path(
      FillRule::kEvenOdd,
      {polygon({{0, 0}, {2, 0}, {2, 2}, {0, 2}}), polygon({{2, 0}, {4, 0}, {4, 2}, {2, 2}}),
       polygon({{0, 2}, {2, 2}, {2, 4}, {0, 4}}), polygon({{2, 2}, {4, 2}, {4, 4}, {2, 4}})});
  for (const FillConvention f : kAllConventions) {
    EXPECT_EQ(path::winding_number(four, pt(2, 2), f), 1);
    EXPECT_EQ(path::winding_number(four, pt(1, 2), f), 1);
    EXPECT_EQ(path::winding_number(four, pt(2, 1), f), 1);
    EXPECT_TRUE(path::covers_sample(four, pt(2, 2), f));
  }
}

// Two paths that share an edge (a square cut along its diagonal into two paths): every sample
// of the square, the diagonal's included, is covered by exactly one of them.
// rule: PATH.TIE.PARTITION
TEST(PathTieRule, PathsSharingAnEdgePartitionTheSamples) {
  const path::Path upper = make_path(FillRule::kNonZero, {polygon({{0, 0}, {4, 0}, {4, 4}})});
  const path::Path lower = make_path(FillRule::kNonZero, {polygon({{0, 0}, {4, 4}, {0, 4}})});
  const path::Path whole =
      make_path(FillRule::kNonZero, {polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}})});
  for (const FillConvention f : kAllConventions)
    for (int ys = -2; ys <= 18; ++ys)
      for (int xs = -2; xs <= 18; ++xs) {
        const path::Point s = pt(xs / 4.0, ys / 4.0);
        const int n = int{path::covers_sample(upper, s, f)} + int{path::covers_sample(lower, s, f)};
        EXPECT_EQ(n, int{path::covers_sample(whole, s, f)}) << xs / 4.0 << "," << ys / 4.0;
      }
}

// The pentagram: winding 2 in the centre pentagon, 1 in the points.
// rule: PATH.FILL.RULE, PATH.WINDING
TEST(PathFillRule, StarIsFullUnderNonZeroAndHollowUnderEvenOdd) {
  // Points of a star on a 20 px target, drawn as one self-intersecting contour.
  const auto star = [](FillRule rule) {
    return make_path(rule, {polygon({{10, 1}, {15.5, 18}, {1, 7.5}, {19, 7.5}, {4.5, 18}})});
  };
  const path::Point centre = pt(10.5, 10.5);
  const path::Point tip = pt(10.5, 4.5);
  EXPECT_EQ(path::winding_number(star(FillRule::kNonZero), centre, FillConvention::kTopLeft), 2);
  EXPECT_EQ(path::winding_number(star(FillRule::kNonZero), tip, FillConvention::kTopLeft), 1);
  EXPECT_TRUE(path::covers_sample(star(FillRule::kNonZero), centre, FillConvention::kTopLeft));
  EXPECT_FALSE(path::covers_sample(star(FillRule::kEvenOdd), centre, FillConvention::kTopLeft));
  EXPECT_TRUE(path::covers_sample(star(FillRule::kEvenOdd), tip, FillConvention::kTopLeft));
  const auto nz = as_map(
      path::cover_samples(star(FillRule::kNonZero), kCentre, FillConvention::kTopLeft, 20, 20));
  const auto eo = as_map(
      path::cover_samples(star(FillRule::kEvenOdd), kCentre, FillConvention::kTopLeft, 20, 20));
  EXPECT_TRUE(nz.contains({10, 10}));
  EXPECT_FALSE(eo.contains({10, 10}));
  EXPECT_GT(nz.size(), eo.size());
  for (const auto& [pixel, mask] : eo)
    EXPECT_TRUE(nz.contains(pixel)) << "even-odd covers a pixel nonzero does not";
}

// rule: PATH.FILL.RULE, PATH.DEGENERATE
TEST(PathFillRule, ContourDrawnTwiceIsEmptyUnderEvenOddAndFullUnderNonZero) {
  const path::Contour c = polygon({{1, 1}, {5, 2}, {4, 6}, {1, 5}});
  const path::Path eo = make_path(FillRule::kEvenOdd, {c, c});
  const path::Path nz = make_path(FillRule::kNonZero, {c, c});
  const path::Path once = make_path(FillRule::kNonZero, {c});
  for (const FillConvention f : kAllConventions) {
    EXPECT_TRUE(path::cover_samples(eo, standard_pattern(16), f, 8, 8).empty());
    EXPECT_EQ(path::cover_samples(nz, standard_pattern(16), f, 8, 8),
              path::cover_samples(once, standard_pattern(16), f, 8, 8));
  }
  EXPECT_EQ(path::winding_number(nz, pt(3, 3), FillConvention::kTopLeft), 2);
  // The same contour once in each direction cancels under both rules.
  const path::Path both = make_path(FillRule::kNonZero, {c, reversed(c)});
  EXPECT_TRUE(
      path::cover_samples(both, standard_pattern(16), FillConvention::kTopLeft, 8, 8).empty());
}

// rule: PATH.FILL.RULE, PATH.COVER.SAMPLE
TEST(PathFillRule, GlyphWithAHole) {
  const path::Contour outer = polygon({{1, 1}, {9, 1}, {9, 9}, {1, 9}});
  const path::Contour hole_ccw = reversed(polygon({{3, 3}, {7, 3}, {7, 7}, {3, 7}}));
  const path::Contour hole_cw = polygon({{3, 3}, {7, 3}, {7, 7}, {3, 7}});
  const std::vector<Pixel> ring = pixels_in_picture({
      "..........",
      ".########.",
      ".########.",
      ".##....##.",
      ".##....##.",
      ".##....##.",
      ".##....##.",
      ".########.",
      ".########.",
      "..........",
  });
  const auto pixels = [](const std::vector<path::SampleCoverage>& v) {
    std::vector<Pixel> p;
    for (const path::SampleCoverage& c : v)
      p.push_back(Pixel{c.x, c.y});
    return p;
  };
  const FillConvention f = FillConvention::kTopLeft;
  // Opposite orientations: a hole under both rules.
  EXPECT_EQ(pixels(path::cover_samples(make_path(FillRule::kNonZero, {outer, hole_ccw}), kCentre, f,
                                       10, 10)),
            ring);
  EXPECT_EQ(pixels(path::cover_samples(make_path(FillRule::kEvenOdd, {outer, hole_ccw}), kCentre, f,
                                       10, 10)),
            ring);
  // Same orientation: a hole under even-odd only.
  EXPECT_EQ(pixels(path::cover_samples(make_path(FillRule::kEvenOdd, {outer, hole_cw}), kCentre, f,
                                       10, 10)),
            ring);
  EXPECT_EQ(path::cover_samples(make_path(FillRule::kNonZero, {outer, hole_cw}), kCentre, f, 10, 10)
                .size(),
            64u);
}

// One contour runs down the diagonal of a square and back up it: w = +1 on one side, -1 on
// the other, and every sample of the square, the diagonal's included, is covered.
// rule: PATH.SAMPLE.TIE, PATH.FILL.RULE
TEST(PathTieRule, DoubledBackDiagonalLeavesNoGap) {
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const path::Path p =
        make_path(rule, {polygon({{0, 0}, {4, 0}, {4, 4}, {0, 0}, {0, 4}, {4, 4}})});
    const path::Path plain = make_path(rule, {polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}})});
    for (const FillConvention f : kAllConventions) {
      // Exactly the samples of the plain square (whose own edges follow the convention).
      EXPECT_EQ(path::cover_samples(p, standard_pattern(16), f, 5, 5),
                path::cover_samples(plain, standard_pattern(16), f, 5, 5));
      for (int k = 0; k < 16; ++k) // samples on the diagonal, inside the square
        EXPECT_TRUE(path::covers_sample(p, pt(k / 4.0 + 0.125, k / 4.0 + 0.125), f));
    }
  }
}

// Vertices at the ends of the range [-2^23, 2^23]: the crossing test stays exact
// (PATH.BUDGET.LINE) and agrees with the triangle rule.
// rule: PATH.BUDGET.LINE, PATH.TIE.TRIANGLE
TEST(PathBudget, PathsAtTheEdgeOfTheCoordinateRange) {
  constexpr std::int32_t kLo = kRangeLo;
  constexpr std::int32_t kHi = kRangeHi;
  // A huge thin triangle whose long edge passes exactly through pixel centres of the target.
  const path::Path p = range_triangle(FillRule::kNonZero);
  for (const FillConvention f : kAllConventions) {
    const auto got = as_map(path::cover_samples(p, kCentre, f, 16, 16));
    RasterState state;
    state.fill = f;
    const std::array<Vec2, 3> v{Vec2{Subpixel::from_raw(kLo), Subpixel::from_raw(kLo)},
                                Vec2{Subpixel::from_raw(kHi), Subpixel::from_raw(kHi)},
                                Vec2{Subpixel::from_raw(kLo), Subpixel::from_raw(kHi)}};
    // The triangle rule's own arithmetic is proved for [-2^23, 2^23 - 1]; this triangle's
    // edge values stay below 2^50 and are exact in int64_t as well.
    const TriangleSetup t = setup_triangle(v, state);
    for (std::int32_t y = 0; y < 16; ++y)
      for (std::int32_t x = 0; x < 16; ++x)
        EXPECT_EQ(got.contains({y, x}), covers(t, pixel_center(x, y))) << x << "," << y;
    // The diagonal x = y through the centres: below it (y > x) covered; on it by the rule.
    EXPECT_TRUE(got.contains({5, 4}));
    EXPECT_FALSE(got.contains({4, 5}));
  }
  // A contour with its corners at all four extremes covers the whole target, once.
  const path::Path all = make_path(FillRule::kEvenOdd,
                                   {raw_polygon({{kLo, kLo}, {kHi, kLo}, {kHi, kHi}, {kLo, kHi}})});
  EXPECT_EQ(path::cover_samples(all, standard_pattern(4), FillConvention::kTopLeft, 16, 16).size(),
            256u);
  EXPECT_EQ(path::winding_number(all, path::Point{kLo, kLo}, FillConvention::kTopLeft), 1);
  EXPECT_EQ(path::winding_number(all, path::Point{kHi, kHi}, FillConvention::kTopLeft), 0);
}

// The row walk of cover_samples equals covers_sample at every sample of every pattern and
// convention, on self-intersecting paths with several contours and tie-heavy vertices, in its
// list form and its callback form alike.
// rule: PATH.COVER.SAMPLE, MSAA.SAMPLE.POSITION
TEST(PathCoverSamples, RowWalkEqualsEverySampleOfEveryPattern) {
  std::vector<path::Path> paths;
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    paths.push_back(
        make_path(rule, {polygon({{0.5, 0.5}, {7.5, 3.5}, {0.5, 7.5}, {7.5, 0.5}, {3.5, 7.5}})}));
    paths.push_back(make_path(
        rule, {polygon({{1, 1}, {6, 1}, {6, 6}, {1, 6}}), polygon({{2.5, 2.5}, {9, 4}, {4, 9}}),
               reversed(polygon({{3, 0.5}, {5.0625, 0.5}, {5.0625, 7.25}}))}));
    paths.push_back(
        make_path(rule, {polygon({{-3, -2}, {12, 3.5}, {2.5, 12}, {2.5, 1}, {6.25, 6.75}})}));
  }
  std::vector<SamplePattern> patterns;
  for (const std::uint32_t n : {1u, 2u, 4u, 8u, 16u})
    patterns.push_back(standard_pattern(n));
  patterns.push_back(center_pattern(4));
  patterns.push_back(custom_pattern({{-8, -8}, {7, 7}, {0, -8}, {-8, 0}, {0, 0}, {7, -8}}));
  for (const path::Path& p : paths)
    for (const SamplePattern& pattern : patterns)
      for (const FillConvention f : kAllConventions) {
        const std::vector<path::SampleCoverage> list = path::cover_samples(p, pattern, f, 9, 9);
        EXPECT_EQ(as_map(list), brute_masks(p, pattern, f, 9, 9))
            << "pattern of " << pattern.count() << " convention " << static_cast<int>(f);
        // The callback form emits the same pixels in the same order (the list form appends a
        // row's run of one-sample pixels at once).
        std::vector<path::SampleCoverage> called;
        path::cover_samples(p, pattern, f, 9, 9,
                            [&](const path::SampleCoverage& c) { called.push_back(c); });
        EXPECT_EQ(called, list) << "pattern of " << pattern.count();
      }
}

// mono_bit reads FreeType mono's layout: most significant bit first, rows pitch bytes apart.
// rule: PATH.COVER.MONO
TEST(PathCoverSamples, MonoBitReadsTheMostSignificantBitFirst) {
  const std::vector<std::uint8_t> bits{0x80, 0x01, 0x00, 0x00, 0x40, 0x00};
  std::vector<std::pair<std::int32_t, std::int32_t>> set;
  for (std::int32_t y = 0; y < 2; ++y)
    for (std::int32_t x = 0; x < 24; ++x)
      if (path::mono_bit(bits, 3, x, y))
        set.emplace_back(x, y);
  EXPECT_EQ(set, (std::vector<std::pair<std::int32_t, std::int32_t>>{{0, 0}, {15, 0}, {9, 1}}));
}

// The mono bitmap holds exactly the pixels of the one-sample list, bit by bit, with runs that
// start and end inside a byte, on byte boundaries and across several bytes, with rows padded
// (pitch above (w + 7) / 8): padding bits and bytes stay 0 even in a buffer written over.
// rule: PATH.COVER.MONO, PATH.COVER.SAMPLE
TEST(PathCoverSamples, MonoBitmapHoldsTheOneSampleListsPixels) {
  std::vector<path::Path> paths;
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    paths.push_back(make_path(
        rule, {polygon({{0.5, 0.5}, {37.5, 3.5}, {0.5, 9.5}, {30.5, 0.5}, {13.5, 11.5}})}));
    paths.push_back(
        make_path(rule, {polygon({{-3, -2}, {40, 3.5}, {2.5, 12}, {2.5, 1}, {26.25, 6.75}}),
                         reversed(polygon({{7, 1}, {16, 1}, {16, 8}, {7, 8}})),
                         polygon({{8, 2}, {24, 2}, {24, 9}, {8, 9}})}));
  }
  for (const path::Path& p : paths)
    for (const FillConvention f : kAllConventions)
      for (const std::int32_t w : {1, 7, 8, 9, 16, 17, 33}) {
        constexpr std::int32_t h = 12;
        std::vector<std::vector<bool>> listed(h, std::vector<bool>(static_cast<std::size_t>(w)));
        for (const path::SampleCoverage& c : path::cover_samples(p, kCentre, f, w, h))
          listed[static_cast<std::size_t>(c.y)][static_cast<std::size_t>(c.x)] = true;
        for (const std::size_t pitch :
             {(static_cast<std::size_t>(w) + 7) / 8, (static_cast<std::size_t>(w) + 7) / 8 + 3}) {
          std::vector<std::uint8_t> bits(pitch * h, 0xA5);
          path::cover_samples_mono(p, f, w, h, bits, pitch);
          for (std::int32_t y = 0; y < h; ++y) {
            for (std::int32_t x = 0; x < w; ++x)
              EXPECT_EQ(path::mono_bit(bits, pitch, x, y),
                        listed[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)])
                  << "pixel (" << x << ", " << y << "), w " << w << ", pitch " << pitch;
            for (std::size_t x = static_cast<std::size_t>(w); x < pitch * 8; ++x)
              EXPECT_EQ(path::mono_bit(bits, pitch, static_cast<std::int32_t>(x), y), false)
                  << "padding bit " << x << " of row " << y << ", w " << w;
          }
        }
      }
}

// A buffer that does not fit the target is refused, naming the rule; an empty target writes
// every byte it is given (none, or rows of padding).
// rule: PATH.COVER.MONO
TEST(PathCoverSamples, MonoBitmapRefusesABufferThatDoesNotFit) {
  const path::Path p = square(FillRule::kNonZero);
  std::vector<std::uint8_t> bits(8, 0xFF);
  const auto refused = [&](std::int32_t w, std::int32_t h, std::size_t size, std::size_t pitch) {
    std::vector<std::uint8_t> b(size, 0);
    try {
      path::cover_samples_mono(p, FillConvention::kTopLeft, w, h, b, pitch);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what()).find("PATH.COVER.MONO") != std::string::npos;
    }
    return false;
  };
  EXPECT_TRUE(refused(9, 4, 4, 1));         // pitch below (9 + 7) / 8
  EXPECT_TRUE(refused(8, 4, 5, 1));         // 5 bytes for 4 rows of 1
  EXPECT_TRUE(refused(8, 4, 3, 1));         // 3 bytes for 4 rows of 1
  EXPECT_TRUE(refused(-1, 4, 0, 0));        // a negative width
  EXPECT_TRUE(refused(8, 16385, 16385, 1)); // taller than kMaxTargetSide
  // A pitch whose product with h wraps around std::size_t.
  EXPECT_TRUE(refused(8, 4, 0, (std::numeric_limits<std::size_t>::max() / 4) + 1));
  path::cover_samples_mono(p, FillConvention::kTopLeft, 0, 4, bits, 2);
  EXPECT_EQ(bits, std::vector<std::uint8_t>(8, 0));
  std::vector<std::uint8_t> none;
  path::cover_samples_mono(p, FillConvention::kTopLeft, 8, 0, none, 1);
  // The square [1, 5]^2 covers the centres of pixels 1..4 of rows 1..4.
  std::vector<std::uint8_t> four(6, 0xFF);
  path::cover_samples_mono(p, FillConvention::kTopLeft, 6, 6, four, 1);
  EXPECT_EQ(four, (std::vector<std::uint8_t>{0x00, 0x78, 0x78, 0x78, 0x78, 0x00}));
}

// rule: PATH.COVER.SAMPLE, PATH.DEGENERATE
TEST(PathCoverSamples, EmptyPathsAndPointContoursCoverNothing) {
  path::Path empty;
  EXPECT_TRUE(path::cover_samples(empty, kCentre, FillConvention::kTopLeft, 4, 4).empty());
  path::Path point;
  point.contours.push_back(path::Contour{pt(2, 2), {}});
  point.contours.push_back(path::Contour{
      pt(1.5, 1.5), {path::Segment{path::SegmentKind::kLine, {pt(1.5, 1.5), {}, {}}}}});
  EXPECT_TRUE(
      path::cover_samples(point, standard_pattern(16), FillConvention::kTopLeft, 4, 4).empty());
  EXPECT_EQ(path::winding_number(point, pt(2, 2), FillConvention::kTopRight), 0);
  EXPECT_TRUE(
      path::cover_samples(square(FillRule::kNonZero), kCentre, FillConvention::kTopLeft, 0, 4)
          .empty());
}

// A square whose sides are cut into 65540 segments of one raw unit or less covers exactly what
// the square covers: any number of segments, no limit and no overflow.
// rule: PATH.DEGENERATE, PATH.WINDING.BOUND
TEST(PathDegenerate, SquareOfMoreThan65536SegmentsCoversWhatTheSquareCovers) {
  path::Contour many;
  many.start = pt(0.5, 0.5);
  const auto side = [&](path::Point from, path::Point to) {
    const std::int32_t n = std::max(std::abs(to.x - from.x), std::abs(to.y - from.y));
    for (std::int32_t k = 1; k <= n; ++k)
      many.segments.push_back(path::Segment{
          path::SegmentKind::kLine,
          {path::Point{from.x + (to.x - from.x) / n * k, from.y + (to.y - from.y) / n * k},
           {},
           {}}});
  };
  side(pt(0.5, 0.5), pt(64.5, 0.5));
  side(pt(64.5, 0.5), pt(64.5, 64.5));
  side(pt(64.5, 64.5), pt(0.5, 64.5));
  side(pt(0.5, 64.5), pt(0.5, 0.5));
  for (int k = 0; k < 4; ++k) // and four zero-length segments at the end
    many.segments.push_back(path::Segment{path::SegmentKind::kLine, {pt(0.5, 0.5), {}, {}}});
  ASSERT_GT(many.segments.size(), 65536u);
  const path::Path p = make_path(FillRule::kEvenOdd, {many});
  const path::Path square = make_path(
      FillRule::kEvenOdd, {polygon({{0.5, 0.5}, {64.5, 0.5}, {64.5, 64.5}, {0.5, 64.5}})});
  for (const FillConvention f : kAllConventions)
    EXPECT_EQ(path::cover_samples(p, standard_pattern(4), f, 66, 66),
              path::cover_samples(square, standard_pattern(4), f, 66, 66));
  EXPECT_EQ(path::winding_number(p, pt(32, 32), FillConvention::kTopLeft), 1);
}

} // namespace
} // namespace rastrules::test
