// SPDX-License-Identifier: MIT
// Examples for the 2D library adapters (DRIVER.PATH.*): what each library reports for paths
// whose coverage is known without a rasterizer (pixel-aligned squares, a half pixel), and the
// scenes each refuses.

#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "rastrules/driver/driver.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::driver {
namespace {

FloatContour polygon(const std::vector<FloatPoint>& pts) {
  FloatContour c;
  c.start = pts.front();
  for (std::size_t i = 1; i < pts.size(); ++i) {
    FloatPathSegment s;
    s.p[0] = pts[i];
    c.segments.push_back(s);
  }
  return c;
}

Scene path_scene(std::vector<FloatContour> contours, path::Coverage coverage,
                 path::FillRule rule = path::FillRule::kNonZero, std::int32_t side = 8) {
  Scene s;
  s.width = s.height = side;
  FloatPath p;
  p.fill_rule = rule;
  p.coverage = coverage;
  p.contours = std::move(contours);
  s.primitives.push_back(make_path(std::move(p)));
  return s;
}

std::unique_ptr<Driver> open(const std::string& name) {
  std::string error;
  auto d = open_driver(name, &error);
  EXPECT_NE(d, nullptr) << error;
  return d;
}

std::vector<Fragment> draw_ok(Driver& d, const Scene& s) {
  EXPECT_EQ(d.unsupported(s), "");
  DrawResult r = d.draw(s);
  if (const auto* e = std::get_if<DriverError>(&r)) {
    ADD_FAILURE() << e->message;
    return {};
  }
  return std::get<std::vector<Fragment>>(r);
}

const std::vector<FloatPoint> kSquare = {{2, 1}, {5, 1}, {5, 4}, {2, 4}};

// rule: DRIVER.PATH.LIBRARY, DRIVER.PATH.FREETYPE
TEST(PathLibraryFreeType, APixelAlignedSquareCoversItsPixelsAliasedAndAtFullAlpha) {
  auto d = open("freetype");
  ASSERT_NE(d, nullptr);
  EXPECT_TRUE(d->info().paths.samples && d->info().paths.area);
  EXPECT_EQ(d->info().paths.grid, "26.6");
  for (const auto coverage : {path::Coverage::kSamples, path::Coverage::kArea}) {
    const auto frags = draw_ok(*d, path_scene({polygon(kSquare)}, coverage));
    ASSERT_EQ(frags.size(), 9u) << to_string(coverage);
    for (const Fragment& f : frags) {
      EXPECT_GE(f.x, 2);
      EXPECT_LE(f.x, 4);
      EXPECT_GE(f.y, 1);
      EXPECT_LE(f.y, 3);
      EXPECT_EQ(f.mask, 1u);
      if (coverage == path::Coverage::kArea)
        EXPECT_EQ(f.area.text(), "1");
      else
        EXPECT_FALSE(f.area);
    }
  }
}

// rule: DRIVER.PATH.FREETYPE
TEST(PathLibraryFreeType, AHalfPixelTriangleGetsHalfAlphaAndEvenOddEmptiesATwiceDrawnSquare) {
  auto d = open("freetype");
  ASSERT_NE(d, nullptr);
  const auto half =
      draw_ok(*d, path_scene({polygon({{1, 1}, {2, 1}, {2, 2}})}, path::Coverage::kArea));
  ASSERT_EQ(half.size(), 1u);
  EXPECT_EQ(half[0].x, 1);
  EXPECT_EQ(half[0].y, 1);
  // 1/2 px^2 as 8-bit alpha: FreeType stores 127 or 128.
  EXPECT_GE(half[0].area.alpha(), 127);
  EXPECT_LE(half[0].area.alpha(), 128);
  const auto twice = draw_ok(*d, path_scene({polygon(kSquare), polygon(kSquare)},
                                            path::Coverage::kArea, path::FillRule::kEvenOdd));
  EXPECT_TRUE(twice.empty());
  const auto nonzero =
      draw_ok(*d, path_scene({polygon(kSquare), polygon(kSquare)}, path::Coverage::kArea));
  EXPECT_EQ(nonzero.size(), 9u);
}

// rule: DRIVER.PATH.LIBRARY
TEST(PathLibraryFreeType, RefusesTrianglesMultisamplingAndPointsOffItsGrid) {
  auto d = open("freetype");
  ASSERT_NE(d, nullptr);
  Scene tri;
  tri.width = tri.height = 4;
  tri.primitives.push_back(make_triangle({FloatPoint{0, 0}, FloatPoint{4, 0}, FloatPoint{0, 4}}));
  EXPECT_EQ(d->unsupported(tri), "primitives[0]: freetype draws paths only");
  Scene msaa = path_scene({polygon(kSquare)}, path::Coverage::kSamples);
  set_sample_pattern(msaa, standard_pattern(4));
  EXPECT_EQ(d->unsupported(msaa), "freetype draws one sample at the pixel centre");
  // 1/256 px is not on 26.6 (1/64 px).
  const Scene fine =
      path_scene({polygon({{1, 1}, {2.00390625f, 1}, {2, 2}})}, path::Coverage::kSamples);
  EXPECT_EQ(d->unsupported(fine),
            "primitives[0]: control point (513, 256) raw is not on freetype's 26.6 grid");
  EXPECT_EQ(d->info().triangles, false);
}

// Opens a driver; when this build knows no such driver, returns nullptr with *missing set to
// the error, and the test skips: the cairo and AGG adapters (DRIVER.PATH.CAIRO,
// DRIVER.PATH.AGG) are built only when their library is found. Any other failure to open is a
// failure.
std::unique_ptr<Driver> open_built(const std::string& name, std::string* missing) {
  std::string error;
  auto d = open_driver(name, &error);
  if (d == nullptr && error.starts_with("unknown driver")) {
    *missing = error;
  } else {
    EXPECT_NE(d, nullptr) << error;
  }
  return d;
}

// A contour from start along one curve: a quadratic (ctrl: its control point and end) or a
// cubic (ctrl: its two control points and end).
FloatContour curve_contour(FloatPoint start, const std::vector<FloatPoint>& ctrl) {
  FloatContour c;
  c.start = start;
  FloatPathSegment s;
  s.kind = ctrl.size() == 2 ? path::SegmentKind::kQuadratic : path::SegmentKind::kCubic;
  for (std::size_t i = 0; i < ctrl.size(); ++i)
    s.p[i] = ctrl[i];
  c.segments.push_back(s);
  return c;
}

// The fragment at (x, y), or nullptr.
const Fragment* fragment_at(const std::vector<Fragment>& frags, std::int32_t x, std::int32_t y) {
  for (const Fragment& f : frags)
    if (f.x == x && f.y == y)
      return &f;
  return nullptr;
}

// What every library must draw alike: the pixel-aligned square is its 9 pixels, aliased and
// at alpha 255; drawn twice, even-odd empties it and nonzero keeps it.
void expect_square_fills(Driver& d) {
  EXPECT_TRUE(d.info().paths.samples && d.info().paths.area);
  EXPECT_TRUE(d.info().paths.nonzero && d.info().paths.evenodd);
  EXPECT_TRUE(d.info().paths.quadratics && d.info().paths.cubics);
  EXPECT_EQ(d.info().paths.grid, "24.8");
  EXPECT_EQ(d.info().paths.grid_raw, 1);
  for (const auto coverage : {path::Coverage::kSamples, path::Coverage::kArea}) {
    const auto frags = draw_ok(d, path_scene({polygon(kSquare)}, coverage));
    ASSERT_EQ(frags.size(), 9u) << to_string(coverage);
    for (const Fragment& f : frags) {
      EXPECT_TRUE(f.x >= 2 && f.x <= 4 && f.y >= 1 && f.y <= 3) << f.x << ", " << f.y;
      EXPECT_EQ(f.mask, 1u);
      if (coverage == path::Coverage::kArea)
        EXPECT_EQ(f.area.text(), "1");
      else
        EXPECT_FALSE(f.area);
    }
    const auto twice = draw_ok(
        d, path_scene({polygon(kSquare), polygon(kSquare)}, coverage, path::FillRule::kEvenOdd));
    EXPECT_TRUE(twice.empty()) << to_string(coverage);
    const auto nonzero = draw_ok(d, path_scene({polygon(kSquare), polygon(kSquare)}, coverage));
    EXPECT_EQ(nonzero.size(), 9u) << to_string(coverage);
  }
}

// The region under the parabola from (1, 1) through the control (7, 1) to (7, 7), closed along
// the bottom and the left side, as a quadratic and as the same curve in cubic form (controls
// (5, 1) and (7, 3)). Pixel (5, 4) (centre (5.5, 4.5); the curve passes (5.5, 2.5)) is inside
// the curve but outside the chord from (1, 1) to (7, 7): a library that drew the chord would
// miss it. Pixel (6, 1) (centre (6.5, 1.5); the curve passes (6.5, 4.03)) is outside.
const FloatPoint kCurveStart{1, 1};
const std::vector<FloatPoint> kQuadratic = {{7, 1}, {7, 7}};
const std::vector<FloatPoint> kCubic = {{5, 1}, {7, 3}, {7, 7}};

std::vector<Fragment> draw_curve(Driver& d, const std::vector<FloatPoint>& ctrl,
                                 path::Coverage coverage) {
  FloatContour c = curve_contour(kCurveStart, ctrl);
  FloatPathSegment back;
  back.p[0] = {1, 7};
  c.segments.push_back(back);
  return draw_ok(d, path_scene({c}, coverage));
}

void expect_curves_drawn(Driver& d) {
  for (const auto& ctrl : {kQuadratic, kCubic})
    for (const auto coverage : {path::Coverage::kSamples, path::Coverage::kArea}) {
      const auto frags = draw_curve(d, ctrl, coverage);
      const std::string what =
          (ctrl.size() == 2 ? "quadratic, " : "cubic, ") + std::string(to_string(coverage));
      const Fragment* in = fragment_at(frags, 5, 4);
      ASSERT_NE(in, nullptr) << what;
      if (coverage == path::Coverage::kArea) {
        EXPECT_EQ(in->area.text(), "1") << what;
      }
      EXPECT_EQ(fragment_at(frags, 6, 1), nullptr) << what;
    }
}

// A pixel half covered, cut along its diagonal (exactly 1/2 px^2).
const std::vector<FloatPoint> kHalfPixel = {{1, 1}, {2, 1}, {2, 2}};

// rule: DRIVER.PATH.LIBRARY, DRIVER.PATH.CAIRO
TEST(PathLibraryCairo, APixelAlignedSquareCoversItsPixelsAndEvenOddEmptiesItDrawnTwice) {
  std::string missing;
  auto d = open_built("cairo", &missing);
  if (!missing.empty())
    GTEST_SKIP() << missing;
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->info().name, "cairo");
  EXPECT_EQ(d->info().max_target_side, 32767);
  expect_square_fills(*d);
}

// The alpha of the one pixel a half-pixel triangle covers, drawn antialiased.
std::uint8_t half_pixel_alpha(Driver& d, const std::vector<FloatPoint>& triangle) {
  const auto frags = draw_ok(d, path_scene({polygon(triangle)}, path::Coverage::kArea));
  if (frags.size() != 1 || frags[0].x != 1 || frags[0].y != 1) {
    ADD_FAILURE() << frags.size() << " fragments, not pixel (1, 1) alone";
    return 0;
  }
  return frags[0].area.alpha();
}

// The half pixel's mirror image across its diagonal: the same 1/2 px^2 on the other side.
const std::vector<FloatPoint> kHalfPixelMirrored = {{1, 1}, {2, 2}, {1, 2}};

// rule: DRIVER.PATH.CAIRO
TEST(PathLibraryCairo, AHalfPixelTriangleGets128Or136ByHowCairoTakesItsRow) {
  std::string missing;
  auto d = open_built("cairo", &missing);
  if (!missing.empty())
    GTEST_SKIP() << missing;
  ASSERT_NE(d, nullptr);
  // cairo's documentation promises no value. Its scan converter (cairo 1.16, every mode but
  // NONE and FAST) computes a pixel row analytically unless an edge starts, ends or passes
  // another within the row; then it takes 15 sub-rows, each edge's x at the sub-row's centre
  // (exact spans in 1/256 px). Here the edges meet at (2, 2), the row's end, which its test
  // for a crossing counts, so the row is sub-sampled: exactly 1/2, stored as 128.
  EXPECT_EQ(half_pixel_alpha(*d, kHalfPixel), 128);
  // The mirror image's edges meet at the row's start, which the test does not count, so the
  // row is analytic, and there each edge's x is taken half a sub-row (1/30 px) below the row's
  // top and bottom: the diagonal is counted 1/30 px to the right, the area as 1/2 + 1/30,
  // stored as 136.
  EXPECT_EQ(half_pixel_alpha(*d, kHalfPixelMirrored), 136);
}

// rule: DRIVER.PATH.CAIRO
TEST(PathLibraryCairo, AliasedRowsAreSampledJustAboveThePixelCentres) {
  std::string missing;
  auto d = open_built("cairo", &missing);
  if (!missing.empty())
    GTEST_SKIP() << missing;
  ASSERT_NE(d, nullptr);
  // CAIRO_ANTIALIAS_NONE (the mono scan converter) takes each edge's x at y + 127/256, not at
  // the centre's y + 128/256, and sets pixels whose centre is at or right of the left edge
  // and left of the right one. A right edge through the centre, (2, 1) to (1, 2), is 1/256 px
  // right of it there: the pixel is set. Its mirror's right edge, (1, 1) to (2, 2), is 1/256
  // px left of it: the pixel is not.
  const auto down_left =
      draw_ok(*d, path_scene({polygon({{1, 1}, {2, 1}, {1, 2}})}, path::Coverage::kSamples));
  ASSERT_EQ(down_left.size(), 1u);
  EXPECT_EQ(down_left[0].x, 1);
  EXPECT_EQ(down_left[0].y, 1);
  EXPECT_TRUE(
      draw_ok(*d, path_scene({polygon(kHalfPixelMirrored)}, path::Coverage::kSamples)).empty());
}

// rule: DRIVER.PATH.CAIRO
TEST(PathLibraryCairo, DrawsQuadraticsAsTheirCubicAndCubics) {
  std::string missing;
  auto d = open_built("cairo", &missing);
  if (!missing.empty())
    GTEST_SKIP() << missing;
  ASSERT_NE(d, nullptr);
  expect_curves_drawn(*d);
  // The quadratic's cubic form has control points on the 1/256 px grid here ((1 + 2 * 7) / 3
  // = 5, (2 * 1 + 7) / 3 = 3), so cairo is given the same cubic both ways and draws the same
  // pixels.
  for (const auto coverage : {path::Coverage::kSamples, path::Coverage::kArea}) {
    const auto quad = draw_curve(*d, kQuadratic, coverage);
    const auto cubic = draw_curve(*d, kCubic, coverage);
    ASSERT_EQ(quad.size(), cubic.size()) << to_string(coverage);
    for (std::size_t i = 0; i < quad.size(); ++i) {
      EXPECT_EQ(quad[i].x, cubic[i].x);
      EXPECT_EQ(quad[i].y, cubic[i].y);
      EXPECT_EQ(quad[i].area.text(), cubic[i].area.text());
    }
  }
}

// rule: DRIVER.PATH.CAIRO
TEST(PathLibraryCairo, TakesAnAntialiasModeAndRefusesAnUnknownOne) {
  std::string missing;
  auto d = open_built("cairo:best", &missing);
  if (!missing.empty())
    GTEST_SKIP() << missing;
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->info().name, "cairo:best");
  EXPECT_NE(d->info().paths.antialiased_method.find("CAIRO_ANTIALIAS_BEST"), std::string::npos)
      << d->info().paths.antialiased_method;
  expect_square_fills(*d);
  // In cairo 1.16 BEST, GOOD and DEFAULT are one scan converter (above): the same alphas.
  EXPECT_EQ(half_pixel_alpha(*d, kHalfPixel), 128);
  EXPECT_EQ(half_pixel_alpha(*d, kHalfPixelMirrored), 136);
  for (const char* mode : {"cairo:default", "cairo:good"}) {
    auto other = open_built(mode, &missing);
    ASSERT_NE(other, nullptr) << mode;
    EXPECT_EQ(half_pixel_alpha(*other, kHalfPixel), 128) << mode;
  }
  // FAST is another: 4 x 4 samples at (i + 1/2) / 4, alpha 16 per sample. The diagonal's four
  // samples count for the triangle right of it: 10 samples (160), 6 for its mirror (96).
  auto fast = open_built("cairo:fast", &missing);
  ASSERT_NE(fast, nullptr);
  EXPECT_EQ(fast->info().name, "cairo:fast");
  EXPECT_EQ(half_pixel_alpha(*fast, kHalfPixel), 160);
  EXPECT_EQ(half_pixel_alpha(*fast, kHalfPixelMirrored), 96);
  std::string error;
  EXPECT_EQ(open_driver("cairo:nonsense", &error), nullptr);
  EXPECT_EQ(error, "unknown cairo antialias mode 'nonsense' (known: default, best, good, fast)");
}

// rule: DRIVER.PATH.LIBRARY, DRIVER.PATH.AGG
TEST(PathLibraryAgg, APixelAlignedSquareCoversItsPixelsAndEvenOddEmptiesItDrawnTwice) {
  std::string missing;
  auto d = open_built("agg", &missing);
  if (!missing.empty())
    GTEST_SKIP() << missing;
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->info().name, "agg");
  expect_square_fills(*d);
}

// rule: DRIVER.PATH.AGG
TEST(PathLibraryAgg, AHalfPixelTriangleGetsCover128AndIsDrawnAliased) {
  std::string missing;
  auto d = open_built("agg", &missing);
  if (!missing.empty())
    GTEST_SKIP() << missing;
  ASSERT_NE(d, nullptr);
  // AGG's cover is the pixel's area in 1/256 of a pixel (its doubled 24.8 area shifted right
  // by 9), not in 1/255: half a pixel is 128, stored as such with a linear gamma.
  EXPECT_EQ(half_pixel_alpha(*d, kHalfPixel), 128);
  // The threshold gamma (0.5) keeps covers from 128 up: the half pixel is drawn aliased.
  const auto aliased = draw_ok(*d, path_scene({polygon(kHalfPixel)}, path::Coverage::kSamples));
  ASSERT_EQ(aliased.size(), 1u);
  EXPECT_EQ(aliased[0].x, 1);
  EXPECT_EQ(aliased[0].y, 1);
}

// rule: DRIVER.PATH.AGG
TEST(PathLibraryAgg, AliasedPixelsAreThoseAtLeastHalfCovered) {
  std::string missing;
  auto d = open_built("agg", &missing);
  if (!missing.empty())
    GTEST_SKIP() << missing;
  ASSERT_NE(d, nullptr);
  // A 2 x 2 px square half a pixel off the grid: its centre pixel is covered whole, its edge
  // pixels half (cover 128) and its corner pixels a quarter (64). AGG's aliased mode keeps
  // covers from 128 up: a plus sign, where sampling the pixel centres would give 2 x 2 pixels.
  const auto plus =
      draw_ok(*d, path_scene({polygon({{1.5f, 1.5f}, {3.5f, 1.5f}, {3.5f, 3.5f}, {1.5f, 3.5f}})},
                             path::Coverage::kSamples));
  ASSERT_EQ(plus.size(), 5u);
  for (const auto& [x, y] : {std::pair{2, 1}, {1, 2}, {2, 2}, {3, 2}, {2, 3}})
    EXPECT_NE(fragment_at(plus, x, y), nullptr) << x << ", " << y;
  // Both halves of a pixel cut along its diagonal are at least half: each sets the pixel.
  EXPECT_EQ(half_pixel_alpha(*d, kHalfPixelMirrored), 128);
  EXPECT_EQ(draw_ok(*d, path_scene({polygon(kHalfPixelMirrored)}, path::Coverage::kSamples)).size(),
            1u);
}

// rule: DRIVER.PATH.AGG
TEST(PathLibraryAgg, DrawsQuadraticsAndCubics) {
  std::string missing;
  auto d = open_built("agg", &missing);
  if (!missing.empty())
    GTEST_SKIP() << missing;
  ASSERT_NE(d, nullptr);
  expect_curves_drawn(*d);
}

// The findings of spec/findings.md (FINDING.PATH2D.*), as each library draws them: a change
// of a library that changes them fails here and the findings are revisited.
struct FindingAlphas {
  const char* driver;
  int twice_evenodd;  // pixel (0, 0) of a half pixel drawn twice, even-odd (exact 0)
  int diagonal;       // pixel (0, 0) of two opposite triangles on a diagonal, nonzero (exact 255)
  int quadratic;      // pixel (0, 0) between a quadratic and its chord (exact 85)
  bool dropout;       // pixel (0, 1) of a zero-area contour, aliased (exact: not covered)
  bool twice_aliased; // pixel (0, 0) of a rectangle drawn twice, even-odd, aliased (exact: not)
};

int alpha_at(Driver& d, const Scene& s, std::int32_t x, std::int32_t y) {
  const auto frags = draw_ok(d, s);
  const Fragment* f = fragment_at(frags, x, y);
  return f == nullptr ? 0 : f->area.alpha();
}

// rule: DRIVER.PATH.FREETYPE, DRIVER.PATH.CAIRO, DRIVER.PATH.AGG
TEST(PathLibraryFindings, ConflationFlatteningDropoutAndEvenOddAsSpecFindingsRecordThem) {
  const std::vector<FloatPoint> half = {{0.5f, 0}, {1, 0}, {1, 1}, {0.5f, 1}};
  const Scene twice = path_scene({polygon(half), polygon(half)}, path::Coverage::kArea,
                                 path::FillRule::kEvenOdd, 2);
  const Scene diagonal =
      path_scene({polygon({{0, 0}, {2, 2}, {0, 2}}), polygon({{0, 0}, {2, 2}, {2, 0}})},
                 path::Coverage::kArea, path::FillRule::kNonZero, 2);
  const Scene quadratic = path_scene({curve_contour({1, 1}, {{0, 1}, {0, 0}})},
                                     path::Coverage::kArea, path::FillRule::kNonZero, 2);
  const Scene line = path_scene({polygon({{0.5f, 3}, {1.5f, 0}})}, path::Coverage::kSamples,
                                path::FillRule::kNonZero, 4);
  const std::vector<FloatPoint> bar = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  const Scene twice_aliased = path_scene({polygon(bar), polygon(bar)}, path::Coverage::kSamples,
                                         path::FillRule::kEvenOdd, 2);
  for (const FindingAlphas& f : {FindingAlphas{"freetype", 255, 0, 64, true, true},
                                 FindingAlphas{"cairo", 0, 255, 80, false, false},
                                 FindingAlphas{"agg", 255, 0, 72, false, false}}) {
    std::string missing;
    auto d = open_built(f.driver, &missing);
    if (d == nullptr)
      continue;
    SCOPED_TRACE(f.driver);
    EXPECT_EQ(alpha_at(*d, twice, 0, 0), f.twice_evenodd);
    EXPECT_EQ(alpha_at(*d, diagonal, 0, 0), f.diagonal);
    EXPECT_EQ(alpha_at(*d, diagonal, 1, 1), f.diagonal);
    EXPECT_EQ(alpha_at(*d, quadratic, 0, 0), f.quadratic);
    EXPECT_EQ(fragment_at(draw_ok(*d, line), 0, 1) != nullptr, f.dropout);
    EXPECT_EQ(fragment_at(draw_ok(*d, twice_aliased), 0, 0) != nullptr, f.twice_aliased);
  }
}

} // namespace
} // namespace rastrules::driver
