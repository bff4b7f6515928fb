// SPDX-License-Identifier: MIT
// Sample coverage of paths with quadratic and cubic Bézier curves (PATH.CURVE.SAMPLE): curves
// whose points lie on a line cover exactly what the line covers (including control points that
// overshoot, whose crossings fall at irrational parameters exactly on samples), samples
// exactly on a quadratic and on a cubic under every convention, a curve tangent to the
// sample's row, a cubic with a loop and a cubic with a cusp against a fine flattening away
// from the curve, and the row walk against covers_sample.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "path_support.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/path.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

using path::FillRule;
using path::SegmentKind;

// The winding number at (x, y) px of the path with every curve cut into n straight pieces, in
// double, and the distance from (x, y) to that polyline: an independent reference wherever
// the distance is far above the flattening error.
struct Flat {
  double winding = 0;
  double distance = 1e9;
};
Flat flattened(const path::Path& p, double x, double y, int n = 2048) {
  Flat f;
  auto edge = [&](double x0, double y0, double x1, double y1) {
    const double dx = x1 - x0, dy = y1 - y0;
    const double len2 = dx * dx + dy * dy;
    double u = len2 > 0 ? ((x - x0) * dx + (y - y0) * dy) / len2 : 0;
    u = std::clamp(u, 0.0, 1.0);
    f.distance = std::min(f.distance, std::hypot(x0 + u * dx - x, y0 + u * dy - y));
    if ((y0 <= y && y < y1) || (y1 <= y && y < y0)) {
      const double xc = x0 + (y - y0) * dx / dy;
      if (xc > x)
        f.winding += y1 > y0 ? 1 : -1;
    }
  };
  for (const path::Contour& c : p.contours) {
    double cx = c.start.x / 256.0, cy = c.start.y / 256.0;
    for (const path::Segment& s : c.segments) {
      std::array<double, 8> q{cx, cy};
      const int deg =
          s.kind == SegmentKind::kLine ? 1 : (s.kind == SegmentKind::kQuadratic ? 2 : 3);
      for (int k = 0; k < deg; ++k) {
        q[static_cast<std::size_t>(2 * k + 2)] = s.p[static_cast<std::size_t>(k)].x / 256.0;
        q[static_cast<std::size_t>(2 * k + 3)] = s.p[static_cast<std::size_t>(k)].y / 256.0;
      }
      const int pieces = deg == 1 ? 1 : n;
      double px = cx, py = cy;
      for (int i = 1; i <= pieces; ++i) {
        const double t = static_cast<double>(i) / pieces, u = 1 - t;
        double nx = 0, ny = 0;
        if (deg == 1) {
          nx = q[2], ny = q[3];
        } else if (deg == 2) {
          nx = u * u * q[0] + 2 * t * u * q[2] + t * t * q[4];
          ny = u * u * q[1] + 2 * t * u * q[3] + t * t * q[5];
        } else {
          nx = u * u * u * q[0] + 3 * t * u * u * q[2] + 3 * t * t * u * q[4] + t * t * t * q[6];
          ny = u * u * u * q[1] + 3 * t * u * u * q[3] + 3 * t * t * u * q[5] + t * t * t * q[7];
        }
        edge(px, py, nx, ny);
        px = nx, py = ny;
      }
      cx = px, cy = py;
    }
    edge(cx, cy, c.start.x / 256.0, c.start.y / 256.0);
  }
  return f;
}

// Compares the kernel's winding number, and coverage under both fill rules, with the
// flattening at every 1/4 px sample of the box farther than 1/64 px from the curve (the
// flattening is within 10^-5 px of it), under every convention; returns the number of samples
// compared.
int expect_matches_flattening(path::Path p, int w, int h) {
  int compared = 0;
  for (int ys = 0; ys <= 4 * h; ++ys)
    for (int xs = 0; xs <= 4 * w; ++xs) {
      const double x = xs / 4.0, y = ys / 4.0;
      const Flat f = flattened(p, x, y);
      if (f.distance < 1.0 / 64)
        continue;
      ++compared;
      const auto expected = static_cast<std::int64_t>(f.winding);
      for (const FillConvention fc : kAllConventions) {
        const std::int64_t wn = path::winding_number(p, pt(x, y), fc);
        EXPECT_EQ(wn, expected) << "sample (" << x << ", " << y << ")";
        for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd})
          EXPECT_EQ(path::fill_holds(rule, wn), path::fill_holds(rule, expected));
      }
    }
  return compared;
}

// A triangle whose edge (a -> b) is drawn as a line, and as curves whose points all lie on
// that line: controls on the chord at other parameters, and controls that overshoot the ends
// (the curve runs past b and back, or before a and back). Every sample on a 1/8 px grid, the
// ones on the edge included, is covered alike, under every convention and fill rule.
// rule: PATH.CURVE.SAMPLE, PATH.DEGENERATE
TEST(PathCurve, CurvesOnALineCoverWhatTheLineCovers) {
  // a = (0.5, 0.5), b = (4.5, 3.5): the edge runs through (1.5, 1.25), (2.5, 2), ...
  const std::vector<path::Segment> as_curves = {
      quad_to(2.5, 2, 4.5, 3.5),                // the midpoint: linear in t
      quad_to(1.5, 1.25, 4.5, 3.5),             // a quarter: non-uniform speed
      quad_to(8.5, 6.5, 4.5, 3.5),              // overshoots b and comes back
      quad_to(-3.5, -2.5, 4.5, 3.5),            // starts backwards past a
      cubic_to(1.5, 1.25, 3.5, 2.75, 4.5, 3.5), // thirds... of another spacing
      cubic_to(6.5, 5, -1.5, -1, 4.5, 3.5),     // overshoots both ways
      cubic_to(4.5, 3.5, 0.5, 0.5, 4.5, 3.5),   // controls on the ends, swapped
  };
  {
    const FillRule rule = FillRule::kNonZero; // the winding number does not depend on the rule
    const path::Path line{rule,
                          {path::Contour{pt(0.5, 0.5), {line_to(4.5, 3.5), line_to(0.5, 4.5)}}}};
    for (const path::Segment& s : as_curves) {
      const path::Path curve{rule, {path::Contour{pt(0.5, 0.5), {s, line_to(0.5, 4.5)}}}};
      // Every 1/4 px sample of the box, and every 1/8 px point on the edge (ties).
      std::vector<path::Point> samples;
      for (int ys = 0; ys <= 20; ++ys)
        for (int xs = 0; xs <= 20; ++xs)
          samples.push_back(pt(xs / 4.0, ys / 4.0));
      for (int m = -2; m <= 10; ++m)
        samples.push_back(pt(0.5 + 0.5 * m, 0.5 + 0.375 * m));
      for (const FillConvention f : kAllConventions)
        for (const path::Point& p : samples)
          ASSERT_EQ(path::winding_number(curve, p, f), path::winding_number(line, p, f))
              << "sample raw (" << p.x << ", " << p.y << ") convention " << static_cast<int>(f)
              << " segment kind " << static_cast<int>(s.kind);
    }
  }
}

// A quadratic through the pixel centre (3.5, 1.5) at t = 1/2, running down and right there
// with the region on its left: a "right" edge, so only top-right and bottom-right cover it.
// rule: PATH.CURVE.SAMPLE, PATH.SAMPLE.TIE
TEST(PathCurve, SampleExactlyOnAQuadratic) {
  const path::Path p{FillRule::kNonZero,
                     {path::Contour{pt(0.5, 0.5), {quad_to(4.5, 0.5, 4.5, 4.5)}}}};
  const path::Point on = pt(3.5, 1.5);
  EXPECT_FALSE(path::covers_sample(p, on, FillConvention::kTopLeft));
  EXPECT_TRUE(path::covers_sample(p, on, FillConvention::kTopRight));
  EXPECT_FALSE(path::covers_sample(p, on, FillConvention::kBottomLeft));
  EXPECT_TRUE(path::covers_sample(p, on, FillConvention::kBottomRight));
  EXPECT_TRUE(path::covers_sample(p, pt(3.25, 1.5), FillConvention::kTopLeft));
  EXPECT_FALSE(path::covers_sample(p, pt(3.75, 1.5), FillConvention::kTopRight));
  const auto m =
      as_map(path::cover_samples(p, standard_pattern(1), FillConvention::kTopRight, 6, 6));
  EXPECT_TRUE(m.contains({1, 3}));
  EXPECT_FALSE(as_map(path::cover_samples(p, standard_pattern(1), FillConvention::kTopLeft, 6, 6))
                   .contains({1, 3}));
}

// A cubic "D" whose rightmost point (5, 3.5), at t = 1/2, has a vertical tangent going down.
// rule: PATH.CURVE.SAMPLE, PATH.SAMPLE.TIE
TEST(PathCurve, SampleExactlyOnACubic) {
  const path::Path p{FillRule::kEvenOdd,
                     {path::Contour{pt(0.5, 0.5), {cubic_to(6.5, 0.5, 6.5, 6.5, 0.5, 6.5)}}}};
  const path::Point on = pt(5, 3.5);
  EXPECT_FALSE(path::covers_sample(p, on, FillConvention::kTopLeft));
  EXPECT_TRUE(path::covers_sample(p, on, FillConvention::kTopRight));
  EXPECT_FALSE(path::covers_sample(p, on, FillConvention::kBottomLeft));
  EXPECT_TRUE(path::covers_sample(p, on, FillConvention::kBottomRight));
  EXPECT_EQ(path::winding_number(p, pt(4.99609375, 3.5), FillConvention::kTopLeft), 1);
  EXPECT_EQ(path::winding_number(p, pt(5.00390625, 3.5), FillConvention::kTopRight), 0);
  EXPECT_GT(expect_matches_flattening(p, 7, 7), 600);
}

// A bowl whose lowest point (3.5, 2.5) touches the sample's row: the two crossings of the
// displaced row have one x in the limit and cancel, so the tangent point is covered under no
// convention (delta << eps: the sample moves sideways first, below the bowl), while the
// samples just above it are inside.
// rule: PATH.CURVE.SAMPLE, PATH.SAMPLE.TIE
TEST(PathCurve, CurveTangentToTheSampleRow) {
  const path::Path p{FillRule::kNonZero,
                     {path::Contour{pt(1.5, 0.5), {quad_to(3.5, 4.5, 5.5, 0.5)}}}};
  for (const FillConvention f : kAllConventions) {
    EXPECT_EQ(path::winding_number(p, pt(3.5, 2.5), f), 0);
    EXPECT_EQ(path::winding_number(p, pt(3.5, 2.49609375), f), -1); // counter-clockwise on screen
    EXPECT_EQ(path::winding_number(p, pt(3.5, 2.50390625), f), 0);
  }
}

// A cubic whose control polygon crosses itself draws a loop; closed by a line.
// rule: PATH.CURVE.SAMPLE, PATH.FILL.RULE
TEST(PathCurve, CubicWithALoop) {
  const path::Path p{FillRule::kNonZero, {path::Contour{pt(2, 8), {cubic_to(14, 0, 0, 0, 12, 8)}}}};
  EXPECT_GT(expect_matches_flattening(p, 14, 9), 1500);
  // The loop and the body have windings of opposite signs.
  const std::int64_t loop = path::winding_number(p, pt(7, 3), FillConvention::kTopLeft);
  const std::int64_t body = path::winding_number(p, pt(7, 7), FillConvention::kTopLeft);
  EXPECT_EQ(loop * body, -1);
}

// A cubic with a cusp at (5, 7), the deepest point of a V closed along its top: the cusp is a
// touching point of its row (covered under no convention); just above it is inside.
// rule: PATH.CURVE.SAMPLE, PATH.DEGENERATE
TEST(PathCurve, CubicWithACusp) {
  const path::Path p{FillRule::kNonZero, {path::Contour{pt(1, 1), {cubic_to(9, 9, 1, 9, 9, 1)}}}};
  for (const FillConvention f : kAllConventions) {
    EXPECT_FALSE(path::covers_sample(p, pt(5, 7), f));
    EXPECT_TRUE(path::covers_sample(p, pt(5, 6.5), f));
    EXPECT_FALSE(path::covers_sample(p, pt(5, 7.5), f));
  }
  EXPECT_GT(expect_matches_flattening(p, 10, 8), 800);
}

// The row walk equals covers_sample at every sample of several patterns, with curves.
// rule: PATH.COVER.SAMPLE, PATH.CURVE.SAMPLE
TEST(PathCurve, RowWalkEqualsEverySampleWithCurves) {
  const path::Path glyph{
      FillRule::kNonZero,
      {path::Contour{pt(1, 1),
                     {quad_to(4.5, -1, 8, 1), cubic_to(9, 4, 7, 9, 4.5, 8), quad_to(0.5, 8, 1, 1)}},
       path::Contour{pt(3, 3), {quad_to(3, 6, 4.5, 6), quad_to(6, 6, 6, 3), line_to(3, 3)}}}};
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    path::Path p = glyph;
    p.fill_rule = rule;
    for (const std::uint32_t n : {1u, 4u})
      for (const FillConvention f : kAllConventions)
        EXPECT_EQ(as_map(path::cover_samples(p, standard_pattern(n), f, 9, 9)),
                  brute_masks(p, standard_pattern(n), f, 9, 9));
  }
}

} // namespace
} // namespace rastrules::test
