// SPDX-License-Identifier: MIT
// Examples for DRIVER.OPENGL.*: the adapter draws small scenes with Mesa's llvmpipe through
// EGL (OpenGL 4.5 core, origin upper-left) and compares them with the reference driver. Where
// llvmpipe's OpenGL really differs from the kernel, the test asserts the documented behaviour
// (spec/findings.md, FINDING.OPENGL.*). The tests skip only when no llvmpipe EGL device exists.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "gpu_test_support.hpp"
#include "rastrules/driver/driver.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::driver {
namespace {

using gpu_test::describe;
using gpu_test::draw_ok;
using gpu_test::expect_draws;
using gpu_test::line;
using gpu_test::line_scene;
using gpu_test::prim;
using gpu_test::reference;
using gpu_test::scene;

// One OpenGL driver for the whole program (gpu_test::shared_driver): the context, program and
// buffers are reused.
#define RASTRULES_OPENGL_OR_SKIP(var)                                                              \
  RASTRULES_DRIVER_OR_SKIP(var, "opengl", "no llvmpipe EGL device")

// The reference under llvmpipe's tie rule (FINDING.OPENGL.FILL_BOTTOM_LEFT).
std::vector<Fragment> reference_bottom_left(Scene s) {
  s.conventions.fill = FillConvention::kBottomLeft;
  return reference(s);
}

// Draws s with OpenGL and expects want, which must not be empty.
void expect_same_as(const Scene& s, const std::vector<Fragment>& want) {
  RASTRULES_OPENGL_OR_SKIP(d);
  expect_draws(*d, s, want);
}

// rule: DRIVER.OPENGL.DEVICE
TEST(OpenGL, ReportsLlvmpipeAndItsConventions) {
  RASTRULES_OPENGL_OR_SKIP(d);
  const DriverInfo& i = d->info();
  EXPECT_EQ(i.name, "opengl");
  EXPECT_NE(i.description.find("llvmpipe"), std::string::npos) << i.description;
  EXPECT_NE(i.description.find("upper-left"), std::string::npos) << i.description;
  EXPECT_EQ(i.subpixel_bits, 8);
  EXPECT_EQ(i.sample_counts, (std::vector<std::uint32_t>{1, 4}));
  EXPECT_TRUE(i.points);
  EXPECT_TRUE(i.lines_bresenham);
  EXPECT_FALSE(i.lines_d3d);
  EXPECT_TRUE(i.sample_mask);
  EXPECT_GE(i.max_target_side, 4096);
}

// rule: DRIVER.OPENGL.SUPPORT
TEST(OpenGL, NamesWhatItCannotDraw) {
  RASTRULES_OPENGL_OR_SKIP(d);
  Scene s = scene(8, 8);
  s.primitives.push_back(line({0.5F, 0.5F}, {5.5F, 2.5F}));
  EXPECT_NE(d->unsupported(s).find("d3d"), std::string::npos); // default line mode
  s.conventions.line_mode = LineMode::kVulkanBresenham;
  EXPECT_EQ(d->unsupported(s), "");
  set_sample_pattern(s, standard_pattern(4));
  EXPECT_NE(d->unsupported(s).find("rectangles"), std::string::npos);
  s.conventions.line_mode = LineMode::kQuadNarrow;
  EXPECT_EQ(d->unsupported(s), "");
  Scene t = scene(8, 8);
  t.primitives.push_back(prim(PrimitiveType::kPoint, {{2.0F, 2.0F}}));
  t.msaa.sample_mask = 0x2U;
  EXPECT_NE(d->unsupported(t).find("sample mask"), std::string::npos);
  t.msaa.sample_mask = 0xFFFFFFFFU;
  EXPECT_EQ(d->unsupported(t), "");
  set_sample_pattern(t, center_pattern(4));
  EXPECT_NE(d->unsupported(t).find("center"), std::string::npos);
  set_sample_pattern(t, standard_pattern(8));
  EXPECT_NE(d->unsupported(t).find("8 samples"), std::string::npos);
  set_sample_pattern(t, standard_pattern(4));
  t.msaa.shading = ShadingRate::kSample;
  EXPECT_NE(d->unsupported(t).find("sample-frequency"), std::string::npos);
  t.msaa.shading = ShadingRate::kPixel;
  t.primitives[0].v[0] = {30000.0F, 2.0F};
  EXPECT_NE(d->unsupported(t).find("viewport"), std::string::npos);
  const DrawResult r = d->draw(t);
  ASSERT_TRUE(std::holds_alternative<DriverError>(r));
  EXPECT_NE(std::get<DriverError>(r).message.find("unsupported"), std::string::npos);
}

// rule: DRIVER.OPENGL.COVERAGE, DRIVER.OPENGL.POSITION, DRIVER.OPENGL.ORIGIN
TEST(OpenGL, TriangleMatchesTheReference) {
  Scene s = scene(8, 6); // not square: a y flip would show
  s.primitives.push_back(make_triangle({{{0.3F, 0.7F}, {7.0F, 1.2F}, {2.1F, 5.75F}}}));
  expect_same_as(s, reference(s));
}

// FINDING.OPENGL.FILL_BOTTOM_LEFT: edges through pixel centres keep their samples on the
// bottom and left edges (y down), not on the top and left ones.
// rule: DRIVER.OPENGL.ORIGIN, TRI.FILL.CONVENTION
TEST(OpenGL, SharedEdgePairFollowsTheBottomLeftRule) {
  RASTRULES_OPENGL_OR_SKIP(d);
  Scene s = scene(8, 8);
  s.primitives.push_back(make_triangle({{{0.5F, 0.5F}, {6.5F, 0.5F}, {0.5F, 6.5F}}}));
  s.primitives.push_back(make_triangle({{{6.5F, 0.5F}, {6.5F, 6.5F}, {0.5F, 6.5F}}}));
  const auto got = draw_ok(*d, s);
  EXPECT_EQ(got, reference_bottom_left(s)) << describe(got);
  EXPECT_NE(got, reference(s));
  // The minimal scene of the finding: the bottom edge y = 0.5 through the centre of (0, 0).
  Scene m = scene(1, 1);
  m.primitives.push_back(make_triangle({{{0.0F, 0.0F}, {0.0F, 0.5F}, {1.0F, 0.5F}}}));
  EXPECT_TRUE(reference(m).empty());
  EXPECT_EQ(describe(draw_ok(*d, m)), " {0 0,0 m1}");
}

// A fan around a pixel centre, with edges through other centres: every centre is covered
// exactly once, by the triangle the bottom-left rule names.
// rule: DRIVER.OPENGL.COVERAGE
TEST(OpenGL, FanWithTiesAtPixelCentres) {
  Scene s = scene(8, 8);
  const FloatPoint c{3.5F, 3.5F};
  const std::array<FloatPoint, 6> ring{
      {{0.5F, 0.5F}, {6.5F, 0.5F}, {7.5F, 3.5F}, {6.5F, 7.5F}, {0.5F, 7.5F}, {0.5F, 3.5F}}};
  for (std::size_t i = 0; i < ring.size(); ++i) {
    s.primitives.push_back(make_triangle({{c, ring[i], ring[(i + 1) % ring.size()]}}));
  }
  expect_same_as(s, reference_bottom_left(s));
}

// Culling with each front face: under GL_UPPER_LEFT the signed area is taken in the y-down
// window, so on-screen clockwise is GL_CW.
// rule: DRIVER.OPENGL.ORIGIN, DRIVER.OPENGL.SUPPORT
TEST(OpenGL, CullingWithBothFrontFaces) {
  for (FrontFace front : {FrontFace::kClockwise, FrontFace::kCounterClockwise}) {
    for (CullMode cull : {CullMode::kBack, CullMode::kFront}) {
      Scene s = scene(8, 8);
      s.cull = cull;
      s.conventions.front_face = front;
      s.primitives.push_back(
          make_triangle({{{0.3F, 0.2F}, {6.7F, 0.4F}, {0.2F, 6.6F}}})); // clockwise
      s.primitives.push_back(
          make_triangle({{{1.2F, 1.1F}, {1.3F, 7.1F}, {7.2F, 7.3F}}})); // counter-clockwise
      const auto want = reference(s);
      ASSERT_FALSE(want.empty());
      EXPECT_TRUE(std::all_of(want.begin(), want.end(), [&](const Fragment& f) {
        return f.prim == ((cull == CullMode::kBack) == (front == FrontFace::kClockwise) ? 0U : 1U);
      }));
      expect_same_as(s, want);
    }
  }
}

// Points: away from ties like the reference; with square edges through pixel centres under the
// bottom-left rule (FINDING.OPENGL.FILL_BOTTOM_LEFT).
// rule: DRIVER.OPENGL.COVERAGE
TEST(OpenGL, PointsFollowTheBottomLeftRule) {
  RASTRULES_OPENGL_OR_SKIP(d);
  Scene s = scene(8, 6);
  s.primitives.push_back(prim(PrimitiveType::kPoint, {{2.5F, 2.5F}}));
  s.primitives.push_back(prim(PrimitiveType::kPoint, {{7.75F, 0.25F}}));
  EXPECT_EQ(draw_ok(*d, s), reference(s));
  s.primitives.push_back(prim(PrimitiveType::kPoint, {{4.0F, 4.0F}})); // edges through centres
  EXPECT_EQ(describe(draw_ok(*d, s)), describe(reference_bottom_left(s)));
  Scene m = s;
  set_sample_pattern(m, standard_pattern(4));
  m.primitives.push_back(prim(PrimitiveType::kPoint, {{6.125F, 1.5F}})); // samples on the edges
  EXPECT_EQ(describe(draw_ok(*d, m)), describe(reference_bottom_left(m)));
}

// FINDING.OPENGL.POINT_SNAP: like lavapipe (FINDING.LAVAPIPE.POINT_SNAP), a point x exactly
// half a subpixel between two 16.8 values is rounded up, where SNAP.VERTEX.ROUND rounds to even.
// rule: DRIVER.OPENGL.COVERAGE, SNAP.VERTEX.ROUND
TEST(OpenGL, PointPositionTiesRoundUp) {
  RASTRULES_OPENGL_OR_SKIP(d);
  Scene s = scene(8, 4);
  s.primitives.push_back(prim(PrimitiveType::kPoint, {{6.001953125F, 1.5F}})); // 1536.5 raw
  // 1536 raw: square [5.5, 6.5), its left edge through the centre of (5, 1), which both the
  // top-left and the bottom-left rule keep.
  EXPECT_EQ(describe(reference_bottom_left(s)), " {0 5,1 m1}");
  EXPECT_EQ(describe(draw_ok(*d, s)), " {0 6,1 m1}"); // as if 1537 raw
  s.primitives[0].v[0] = {5.998046875F, 1.5F};        // 1535.5 raw: even and up are both 1536
  EXPECT_EQ(describe(draw_ok(*d, s)), describe(reference_bottom_left(s)));
}

// Lines away from diamond ties (aliased, width 1, one sample) match "vulkan-bresenham".
// rule: DRIVER.OPENGL.COVERAGE, DRIVER.OPENGL.SUPPORT
TEST(OpenGL, LinesAwayFromTiesMatchTheReference) {
  Scene s = scene(8, 8);
  s.conventions.line_mode = LineMode::kVulkanBresenham;
  s.primitives.push_back(line({0.5F, 1.5F}, {6.5F, 1.5F}));
  s.primitives.push_back(line({1.5F, 0.5F}, {1.5F, 6.5F}));
  s.primitives.push_back(line({0.5F, 0.5F}, {6.5F, 3.5F}));
  s.primitives.push_back(line({7.3F, 0.2F}, {2.1F, 6.7F}));
  expect_same_as(s, reference(s));
}

// FINDING.OPENGL.LINES: the minimal scenes where llvmpipe's aliased lines differ from
// LINE.VK.EXIT (1x1 target); the expected values are the documented ones.
// rule: DRIVER.OPENGL.SUPPORT, LINE.VK.EXIT
TEST(OpenGL, LineEndsDifferFromTheDiamondExitRule) {
  RASTRULES_OPENGL_OR_SKIP(d);
  const auto one = [](FloatPoint a, FloatPoint b) {
    return line_scene(1, 1, 1, LineMode::kVulkanBresenham, {line(a, b)});
  };
  for (const Scene& s : {one({0.0F, 0.0F}, {1.0F, 0.0F}), one({1.0F, 0.0F}, {0.0F, 0.0F}),
                         one({0.5F, 0.0F}, {-1.0F, 1.0F})}) {
    EXPECT_EQ(describe(reference(s)), "");
    EXPECT_EQ(describe(draw_ok(*d, s)), " {0 0,0 m1}");
  }
  const Scene missing = one({1.0F, 0.5F}, {0.0F, 2.0F});
  EXPECT_EQ(describe(reference(missing)), " {0 0,0 m1}");
  EXPECT_EQ(describe(draw_ok(*d, missing)), "");
}

// A strip is its segments drawn as independent lines (LINE.STRIP.SEQUENCE), each segment's
// fragments tagged with its seg (gl_PrimitiveID within the draw).
// rule: DRIVER.OPENGL.COVERAGE, LINE.STRIP.SEQUENCE
TEST(OpenGL, LineStripIsItsSegments) {
  RASTRULES_OPENGL_OR_SKIP(d);
  std::mt19937 rng(20261122);
  const auto coord = [&] { return static_cast<float>(rng() % 33U) / 4.0F; };
  for (int c = 0; c < 40; ++c) {
    Scene strip = scene(8, 8);
    strip.conventions.line_mode = LineMode::kVulkanBresenham;
    std::vector<FloatPoint> v;
    for (int i = 0; i < 4; ++i)
      v.push_back({coord(), coord()});
    strip.primitives.push_back(prim(PrimitiveType::kLineStrip, v));
    Scene lines = strip;
    lines.primitives.clear();
    for (std::size_t i = 0; i + 1 < v.size(); ++i)
      lines.primitives.push_back(line(v[i], v[i + 1]));
    std::vector<Fragment> want;
    for (Fragment f : draw_ok(*d, lines)) {
      f.seg = f.prim;
      f.prim = 0;
      want.push_back(f);
    }
    std::sort(want.begin(), want.end(), fragment_before);
    const auto got = draw_ok(*d, strip);
    ASSERT_EQ(got, want) << "case " << c << "\nstrip:" << describe(got)
                         << "\nlines:" << describe(want);
  }
}

// On a 4x target OpenGL lines are rectangles 1 px wide: "quad-narrow" (MSAA.LINE.MODE), for
// lines at least 1 px long and inside the target (FINDING.OPENGL.MSAA_RECT for the others).
// rule: DRIVER.OPENGL.SUPPORT, MSAA.LINE.MODE
TEST(OpenGL, Msaa4LinesAreRectangles) {
  RASTRULES_OPENGL_OR_SKIP(d);
  std::mt19937 rng(20261123);
  const auto coord = [&] { return static_cast<float>(rng() % 49U) / 8.0F + 1.0F; }; // [1, 7]
  const auto point = [&](FloatPoint from) {
    for (;;) {
      const FloatPoint p{coord(), coord()};
      if (std::hypot(p[0] - from[0], p[1] - from[1]) >= 1.0F)
        return p;
    }
  };
  for (int c = 0; c < 100; ++c) {
    Scene s = scene(8, 8, 4);
    s.conventions.line_mode = LineMode::kQuadNarrow;
    const FloatPoint a{coord(), coord()};
    s.primitives.push_back(line(a, point(a)));
    const FloatPoint b{coord(), coord()};
    const FloatPoint b1 = point(b);
    s.primitives.push_back(prim(PrimitiveType::kLineStrip, {b, b1, point(b1)}));
    const auto got = draw_ok(*d, s);
    const auto want = reference_bottom_left(s);
    EXPECT_EQ(got, want) << "case " << c << "\nopengl:" << describe(got)
                         << "\nexpected:" << describe(want);
  }
}

// FINDING.OPENGL.MSAA_RECT: on a 4x target llvmpipe draws nothing for a rectangular line that
// crosses the right or bottom edge of the target or, for some, is shorter than 1 px (the same
// rasterizer as FINDING.LAVAPIPE.MSAA_RECT_EDGE and FINDING.LAVAPIPE.MSAA_RECT_SHORT).
// rule: DRIVER.OPENGL.SUPPORT, RASTER.TARGET.CLIP, LINE.QUAD.SHAPE
TEST(OpenGL, Msaa4RectangularLinesAtTheEdgeOrShortAreDropped) {
  RASTRULES_OPENGL_OR_SKIP(d);
  for (const auto& [a, b] :
       {std::pair<FloatPoint, FloatPoint>{{7.75F, 6.5F}, {7.75F, 4.5F}},
        std::pair<FloatPoint, FloatPoint>{{1.5F, 7.75F}, {5.5F, 7.75F}},
        std::pair<FloatPoint, FloatPoint>{{5.625F, 1.625F}, {5.625F, 1.125F}}}) {
    const Scene s = line_scene(8, 8, 4, LineMode::kQuadNarrow, {line(a, b)});
    EXPECT_FALSE(reference(s).empty());
    EXPECT_EQ(describe(draw_ok(*d, s)), "");
  }
  // The shrunk scene of the short case: a horizontal half-pixel line on the top edge.
  const Scene m = line_scene(1, 1, 4, LineMode::kQuadNarrow, {line({1.0F, 0.0F}, {0.5F, 0.0F})});
  EXPECT_EQ(describe(reference_bottom_left(m)), " {0 0,0 m2}");
  EXPECT_EQ(describe(draw_ok(*d, m)), "");
}

// rule: DRIVER.OPENGL.COVERAGE
TEST(OpenGL, Msaa4TieHeavyTriangleAndSampleMask) {
  for (std::uint32_t mask : {0xFU, 0x5U, 0x2U, 0xEU}) {
    Scene s = scene(8, 8, 4);
    s.msaa.sample_mask = mask;
    s.primitives.push_back(make_triangle({{{0.125F, 0.375F}, {6.875F, 1.625F}, {2.375F, 7.125F}}}));
    s.primitives.push_back(make_triangle({{{6.875F, 1.625F}, {7.625F, 7.375F}, {2.375F, 7.125F}}}));
    s.primitives.push_back(prim(PrimitiveType::kPoint, {{6.125F, 6.5F}}));
    expect_same_as(s, reference_bottom_left(s));
  }
}

// --- Values of pipeline scenes (DRIVER.OPENGL.VALUES): gpu_test_support.hpp ------------------

// rule: DRIVER.OPENGL.VALUES, DRIVER.VALUES
TEST(OpenGLValues, ReportsValuesAndNamesWhatItCannotDraw) {
  RASTRULES_OPENGL_OR_SKIP(d);
  gpu_test::expect_values_support(*d);
}

// rule: DRIVER.OPENGL.VALUES, PIPE.INTERP.LINEAR, PIPE.INTERP.FLAT, PIPE.DEPTH.FORMAT
TEST(OpenGLValues, ExactValuesMatchTheReference) {
  RASTRULES_OPENGL_OR_SKIP(d);
  gpu_test::expect_exact_values(*d);
}

// rule: DRIVER.OPENGL.VALUES, MSAA.SHADING.SAMPLE, PIPE.INTERP.LOCATION
TEST(OpenGLValues, SampleRateShadingGivesEachSampleItsExactValues) {
  RASTRULES_OPENGL_OR_SKIP(d);
  gpu_test::expect_exact_sample_values(*d, /*centre_at_sample=*/true);
}

// rule: DRIVER.OPENGL.VALUES, PIPE.DEPTH.FORMAT, MSAA.PATTERN.STANDARD
TEST(OpenGLValues, MultisampledDepthIsReadPerSampleInD16AndD32F) {
  RASTRULES_OPENGL_OR_SKIP(d);
  gpu_test::expect_multisampled_depth(*d);
}

// rule: DRIVER.OPENGL.VALUES, PIPE.DEPTH.BIAS
TEST(OpenGLValues, DepthBiasMovesTrianglesByOneToTwoStepsPerUnit) {
  RASTRULES_OPENGL_OR_SKIP(d);
  gpu_test::expect_biased_depth(*d);
}

// rule: DRIVER.OPENGL.VALUES, LINE.STRIP.SEQUENCE, PIPE.INTERP.FLAT, PIPE.CLIP.LINE
TEST(OpenGLValues, StripSegmentsKeepTheirKeysAndProvokingVertices) {
  RASTRULES_OPENGL_OR_SKIP(d);
  gpu_test::expect_strip_values(*d);
}

} // namespace
} // namespace rastrules::driver
