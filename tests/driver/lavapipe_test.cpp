// SPDX-License-Identifier: MIT
// Examples for DRIVER.LAVAPIPE.*: the adapter draws small scenes with lavapipe (Mesa's Vulkan
// CPU driver) and compares them with the reference driver. Where lavapipe really differs from
// the kernel, the test asserts lavapipe's documented behaviour (spec/findings.md, FINDING.*).
// The tests skip only when no CPU Vulkan device exists (scripts/deps installs one).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "gpu_test_support.hpp"
#include "rastrules/driver/driver.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::driver {
namespace {

using gpu_test::describe;
using gpu_test::draw_ok;
using gpu_test::expect_draws;
using gpu_test::frags;
using gpu_test::line;
using gpu_test::line_scene;
using gpu_test::prim;
using gpu_test::reference;
using gpu_test::scene;

// One lavapipe driver for the whole program (gpu_test::shared_driver).
#define RASTRULES_LAVAPIPE_OR_SKIP(var)                                                            \
  RASTRULES_DRIVER_OR_SKIP(var, "lavapipe", "no CPU Vulkan device")

// Draws s with lavapipe and the reference, expects the same non-empty fragments.
void expect_same_as_reference(const Scene& s) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  expect_draws(*d, s, reference(s));
}

// rule: DRIVER.LAVAPIPE.DEVICE
TEST(Lavapipe, ReportsTheCpuDeviceAndItsConventions) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  const DriverInfo& i = d->info();
  EXPECT_EQ(i.name, "lavapipe");
  EXPECT_NE(i.description.find("llvmpipe"), std::string::npos) << i.description;
  EXPECT_EQ(i.subpixel_bits, 8);
  const auto has = [&](std::uint32_t n) {
    return std::find(i.sample_counts.begin(), i.sample_counts.end(), n) != i.sample_counts.end();
  };
  EXPECT_TRUE(has(1));
  EXPECT_TRUE(has(4));
  EXPECT_TRUE(i.points);
  EXPECT_TRUE(i.lines_bresenham);
  EXPECT_TRUE(i.lines_rectangular);
  EXPECT_FALSE(i.lines_d3d);
  EXPECT_GE(i.max_target_side, 4096);
}

// rule: DRIVER.LAVAPIPE.SUPPORT
TEST(Lavapipe, NamesWhatItCannotDraw) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  Scene s = scene(8, 8);
  s.primitives.push_back(line({0.5F, 0.5F}, {5.5F, 2.5F}));
  EXPECT_NE(d->unsupported(s).find("d3d"), std::string::npos); // default line mode
  s.conventions.line_mode = LineMode::kQuadWide;
  EXPECT_NE(d->unsupported(s).find("quad-wide"), std::string::npos);
  s.conventions.line_mode = LineMode::kVulkanBresenham;
  EXPECT_EQ(d->unsupported(s), "");
  // Triangles and points do not depend on the line mode.
  Scene t = scene(8, 8);
  t.primitives.push_back(prim(PrimitiveType::kPoint, {{2.0F, 2.0F}}));
  EXPECT_EQ(d->unsupported(t), "");
  set_sample_pattern(t, center_pattern(4));
  EXPECT_NE(d->unsupported(t).find("center"), std::string::npos);
  set_sample_pattern(t, standard_pattern(16));
  EXPECT_NE(d->unsupported(t).find("16 samples"), std::string::npos);
  set_sample_pattern(t, standard_pattern(4));
  t.msaa.shading = ShadingRate::kSample;
  EXPECT_NE(d->unsupported(t).find("sample-frequency"), std::string::npos);
  t.msaa.shading = ShadingRate::kPixel;
  t.primitives[0].v[0] = {30000.0F, 2.0F}; // needs a viewport wider than the device's
  EXPECT_NE(d->unsupported(t).find("viewport"), std::string::npos);
  const DrawResult r = d->draw(t);
  ASSERT_TRUE(std::holds_alternative<DriverError>(r));
  EXPECT_NE(std::get<DriverError>(r).message.find("unsupported"), std::string::npos);
}

// rule: DRIVER.LAVAPIPE.COVERAGE, DRIVER.LAVAPIPE.POSITION
TEST(Lavapipe, TriangleMatchesTheReference) {
  Scene s = scene(8, 8);
  s.primitives.push_back(make_triangle({{{0.5F, 0.5F}, {7.0F, 1.5F}, {2.0F, 7.25F}}}));
  expect_same_as_reference(s);
}

// Edges through pixel centres: the top-left rule decides every centre on the shared edge.
// rule: DRIVER.LAVAPIPE.COVERAGE
TEST(Lavapipe, SharedEdgePairMatchesTheReference) {
  Scene s = scene(8, 8);
  s.primitives.push_back(make_triangle({{{0.5F, 0.5F}, {6.5F, 0.5F}, {0.5F, 6.5F}}}));
  s.primitives.push_back(make_triangle({{{6.5F, 0.5F}, {6.5F, 6.5F}, {0.5F, 6.5F}}}));
  s.primitives.push_back(make_triangle({{{7.5F, 7.5F}, {7.5F, 1.5F}, {3.5F, 7.5F}}}));
  expect_same_as_reference(s);
}

// Vertices at half a subpixel (ties of SNAP.VERTEX.ROUND) and between: the exact position
// transfer and lavapipe's round-half-to-even snapping of triangle vertices, 1x and 4x.
// rule: DRIVER.LAVAPIPE.POSITION
TEST(Lavapipe, TriangleSnappingTiesMatchTheReference) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  std::mt19937 rng(20260611);
  const auto coord = [&] {
    const auto v = static_cast<float>(rng() % 4096U);
    return (rng() % 2U == 0U) ? v / 512.0F : v / 1024.0F; // ties at odd multiples of 1/512
  };
  for (std::uint32_t samples : {1U, 4U}) {
    for (int c = 0; c < 60; ++c) {
      Scene s = scene(8, 8, samples);
      s.primitives.push_back(
          make_triangle({{{coord(), coord()}, {coord(), coord()}, {coord(), coord()}}}));
      const auto got = draw_ok(*d, s);
      const auto want = reference(s);
      ASSERT_EQ(got, want) << "case " << c << " samples " << samples
                           << "\nlavapipe:" << describe(got) << "\nreference:" << describe(want);
    }
  }
}

// Back-face culling with each front face: Vulkan's framebuffer is y-down like the kernel's,
// so on-screen winding maps directly.
// rule: DRIVER.LAVAPIPE.SUPPORT
TEST(Lavapipe, CullingMapsWindingDirectly) {
  for (FrontFace front : {FrontFace::kClockwise, FrontFace::kCounterClockwise}) {
    for (CullMode cull : {CullMode::kBack, CullMode::kFront}) {
      Scene s = scene(8, 8);
      s.cull = cull;
      s.conventions.front_face = front;
      // Clockwise on screen (y down), then counter-clockwise.
      s.primitives.push_back(make_triangle({{{0.5F, 0.5F}, {6.5F, 0.5F}, {0.5F, 6.5F}}}));
      s.primitives.push_back(make_triangle({{{7.5F, 1.5F}, {7.5F, 7.5F}, {1.5F, 7.5F}}}));
      s.primitives.push_back(make_triangle({{{1.0F, 1.0F}, {1.0F, 7.0F}, {7.0F, 7.0F}}}));
      expect_same_as_reference(s);
    }
  }
}

// rule: DRIVER.LAVAPIPE.COVERAGE
TEST(Lavapipe, PointsMatchTheReference) {
  Scene s = scene(8, 6);
  s.primitives.push_back(prim(PrimitiveType::kPoint, {{2.5F, 2.5F}}));
  s.primitives.push_back(prim(PrimitiveType::kPoint, {{4.0F, 4.0F}})); // edges through centres
  s.primitives.push_back(prim(PrimitiveType::kPoint, {{7.75F, 0.25F}}));
  expect_same_as_reference(s);
  Scene m = s;
  set_sample_pattern(m, standard_pattern(4));
  m.primitives.push_back(prim(PrimitiveType::kPoint, {{6.125F, 1.5F}})); // samples on the edges
  expect_same_as_reference(m);
}

// FINDING.LAVAPIPE.POINT_SNAP: lavapipe rounds a point position that lies exactly half a
// subpixel between two 16.8 values upward, where SNAP.VERTEX.ROUND rounds to even (lavapipe
// rounds triangle vertices to even, TriangleSnappingTiesMatchTheReference).
// rule: DRIVER.LAVAPIPE.COVERAGE, SNAP.VERTEX.ROUND
TEST(Lavapipe, PointPositionTiesRoundUp) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  Scene s = scene(8, 4);
  s.primitives.push_back(prim(PrimitiveType::kPoint, {{6.001953125F, 1.5F}})); // 1536.5 raw
  EXPECT_EQ(describe(reference(s)),
            describe(frags(0, {{5, 1, 1}}))); // 1536 raw: square [5.5, 6.5), centre 5.5
  EXPECT_EQ(describe(draw_ok(*d, s)), describe(frags(0, {{6, 1, 1}}))); // as if 1537 raw
  // Just below the tie both agree.
  s.primitives[0].v[0] = {5.998046875F, 1.5F}; // 1535.5 raw: even and up are both 1536
  EXPECT_EQ(describe(draw_ok(*d, s)), describe(reference(s)));
  // The same tie in y, and on a 4x target.
  Scene t = scene(8, 4);
  t.primitives.push_back(prim(PrimitiveType::kPoint, {{6.5F, 2.001953125F}}));
  EXPECT_EQ(describe(reference(t)), describe(frags(0, {{6, 1, 1}})));
  EXPECT_EQ(describe(draw_ok(*d, t)), describe(frags(0, {{6, 2, 1}})));
  Scene m = scene(8, 4, 4);
  m.primitives.push_back(prim(PrimitiveType::kPoint, {{6.126953125F, 1.5F}})); // 1568.5 raw
  EXPECT_EQ(describe(reference(m)), describe(frags(0, {{5, 1, 10}, {6, 1, 5}})));
  EXPECT_EQ(describe(draw_ok(*d, m)),
            describe(frags(0, {{5, 1, 2}, {6, 1, 13}}))); // as if 1569 raw
}

// Bresenham lines whose end points are on pixel centres or away from every diamond: exactly
// the reference (LINE.VK.EXIT).
// rule: DRIVER.LAVAPIPE.COVERAGE
TEST(Lavapipe, BresenhamLinesMatchTheReferenceAwayFromTies) {
  Scene s = scene(12, 12);
  s.conventions.line_mode = LineMode::kVulkanBresenham;
  s.primitives.push_back(line({0.5F, 1.5F}, {10.5F, 5.5F}));
  s.primitives.push_back(line({5.5F, 2.5F}, {3.5F, 10.5F}));
  s.primitives.push_back(line({10.25F, 10.125F}, {1.375F, 7.0625F}));
  expect_same_as_reference(s);
}

// The deviations Vulkan allows from the exact diamond-exit rule (spec-anchors section 4):
// every fragment within one unit of a diamond-exit fragment, the count within one, no two
// fragments in one column of an x-major line (row of a y-major line).
// When the exact rule produces nothing, the one fragment allowed must be within one unit of
// the pixel holding the start point.
bool within_vulkan_allowance(const std::vector<Fragment>& got, const std::vector<Fragment>& exact,
                             bool x_major, FloatPoint start) {
  if (got.size() + 1 < exact.size() || exact.size() + 1 < got.size())
    return false;
  for (const Fragment& g : got) {
    const bool near = exact.empty()
                          ? std::abs(static_cast<float>(g.x) - std::floor(start[0])) <= 1.0F &&
                                std::abs(static_cast<float>(g.y) - std::floor(start[1])) <= 1.0F
                          : std::any_of(exact.begin(), exact.end(), [&](const Fragment& e) {
                              return std::abs(e.x - g.x) <= 1 && std::abs(e.y - g.y) <= 1;
                            });
    if (!near)
      return false;
  }
  std::set<std::int32_t> majors;
  for (const Fragment& g : got) {
    if (!majors.insert(x_major ? g.x : g.y).second)
      return false;
  }
  return true;
}

// FINDING.LAVAPIPE.BRESENHAM: lavapipe's Bresenham lines differ from LINE.VK.EXIT when an end
// point lies inside or on a diamond, within the deviations Vulkan allows.
// rule: DRIVER.LAVAPIPE.COVERAGE, LINE.VK.EXIT
TEST(Lavapipe, BresenhamEndsDeviateWithinVulkanAllowance) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  // The minimal scenes of the finding.
  const Scene a = line_scene(8, 8, 1, LineMode::kVulkanBresenham,
                             {line({1.25F, 1.5F}, {6.75F, 3.25F})}); // b on the diamond of (6, 3)
  EXPECT_EQ(describe(reference(a)),
            describe(frags(0, {{1, 1, 1}, {2, 1, 1}, {3, 2, 1}, {4, 2, 1}, {5, 2, 1}})));
  EXPECT_EQ(describe(draw_ok(*d, a)),
            describe(frags(0, {{1, 1, 1}, {2, 1, 1}, {3, 2, 1}, {4, 2, 1}, {5, 2, 1}, {6, 3, 1}})));
  const Scene b =
      line_scene(8, 8, 1, LineMode::kVulkanBresenham,
                 {line({7.75F, 6.5F}, {7.75F, 4.5F})}); // a inside the diamond of (7, 6)
  EXPECT_EQ(describe(reference(b)), describe(frags(0, {{7, 5, 1}, {7, 6, 1}})));
  EXPECT_EQ(describe(draw_ok(*d, b)), describe(frags(0, {{7, 5, 1}})));
  const Scene c =
      line_scene(8, 8, 1, LineMode::kVulkanBresenham,
                 {line({3.5F, 6.5F}, {3.5F, 2.5F})}); // y-major, upwards, centre to centre
  EXPECT_EQ(describe(reference(c)),
            describe(frags(0, {{3, 3, 1}, {3, 4, 1}, {3, 5, 1}, {3, 6, 1}})));
  EXPECT_EQ(describe(draw_ok(*d, c)), describe(frags(0, {{3, 3, 1}, {3, 4, 1}, {3, 5, 1}})));
  // Seeded lines with tie-heavy end points: every difference is an allowed one, and there
  // are differences (the finding still holds).
  std::mt19937 rng(1984);
  const auto coord = [&] {
    const auto v = static_cast<float>(rng() % 64U);
    return (rng() % 2U == 0U) ? v / 8.0F : v / 4.0F + 0.25F;
  };
  int differ = 0;
  for (int n = 0; n < 150; ++n) {
    Scene s = scene(16, 16);
    s.conventions.line_mode = LineMode::kVulkanBresenham;
    const FloatPoint p{coord(), coord()};
    const FloatPoint q{coord(), coord()};
    s.primitives.push_back(line(p, q));
    const auto got = draw_ok(*d, s);
    const auto want = reference(s);
    if (got != want)
      ++differ;
    const bool x_major = std::abs(q[0] - p[0]) >= std::abs(q[1] - p[1]);
    EXPECT_TRUE(within_vulkan_allowance(got, want, x_major, p))
        << "(" << p[0] << "," << p[1] << ")-(" << q[0] << "," << q[1]
        << ")\nlavapipe:" << describe(got) << "\nreference:" << describe(want);
  }
  EXPECT_GT(differ, 0);
}

// A line strip is the sequence of its segments as independent lines (LINE.STRIP.SEQUENCE),
// and gl_PrimitiveID gives each fragment its segment.
// rule: DRIVER.LAVAPIPE.COVERAGE
TEST(Lavapipe, LineStripIsItsSegmentsWithTheirIndex) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  for (LineMode mode : {LineMode::kVulkanBresenham, LineMode::kQuadNarrow}) {
    Scene s = scene(12, 12);
    s.conventions.line_mode = mode;
    // Segments: x-major to the right, y-major downwards, x-major to the left, all from and to
    // pixel centres (lavapipe drops the first pixel of a y-major segment going up from a
    // centre, FINDING.LAVAPIPE.BRESENHAM).
    const std::vector<FloatPoint> v = {{1.5F, 1.5F}, {9.5F, 3.5F}, {4.5F, 10.5F}, {0.5F, 8.5F}};
    s.primitives.push_back(make_triangle({{{0.0F, 0.0F}, {1.0F, 0.0F}, {0.0F, 1.0F}}}));
    s.primitives.push_back(prim(PrimitiveType::kLineStrip, v));
    const auto strip = draw_ok(*d, s);
    Scene t = scene(12, 12);
    t.conventions.line_mode = mode;
    for (std::size_t k = 0; k + 1 < v.size(); ++k)
      t.primitives.push_back(line(v[k], v[k + 1]));
    std::vector<Fragment> lines;
    for (Fragment f : draw_ok(*d, t)) {
      f.seg = f.prim;
      f.prim = 1;
      lines.push_back(f);
    }
    std::sort(lines.begin(), lines.end(), fragment_before);
    std::vector<Fragment> strip_only;
    std::copy_if(strip.begin(), strip.end(), std::back_inserter(strip_only),
                 [](const Fragment& f) { return f.prim == 1; });
    EXPECT_EQ(strip_only, lines);
    EXPECT_TRUE(std::any_of(strip_only.begin(), strip_only.end(),
                            [](const Fragment& f) { return f.seg == 2U; }));
    // End points on pixel centres: no tie, the reference agrees too.
    EXPECT_EQ(strip, reference(s))
        << "lavapipe:" << describe(strip) << "\nreference:" << describe(reference(s));
  }
}

// rule: DRIVER.LAVAPIPE.COVERAGE
TEST(Lavapipe, RectangularLinesMatchTheReference) {
  Scene s = scene(12, 12);
  s.conventions.line_mode = LineMode::kQuadNarrow;
  s.primitives.push_back(line({0.5F, 1.25F}, {10.5F, 5.25F}));
  s.primitives.push_back(line({3.0F, 10.0F}, {5.0F, 2.0F}));
  s.primitives.push_back(line({0.5F, 3.0F}, {4.5F, 3.0F})); // edges through centres
  expect_same_as_reference(s);
  Scene m = s;
  set_sample_pattern(m, standard_pattern(4));
  expect_same_as_reference(m);
}

// rule: DRIVER.LAVAPIPE.COVERAGE
TEST(Lavapipe, Msaa4TieHeavyTriangleMatchesTheReference) {
  Scene s = scene(8, 8, 4);
  // Vertices on the 1/8 px grid: edges pass through many of the 1/16-grid sample positions.
  s.primitives.push_back(make_triangle({{{0.125F, 0.375F}, {6.875F, 1.625F}, {2.375F, 7.125F}}}));
  s.primitives.push_back(make_triangle({{{6.875F, 1.625F}, {7.625F, 7.375F}, {2.375F, 7.125F}}}));
  expect_same_as_reference(s);
}

// rule: DRIVER.LAVAPIPE.COVERAGE
TEST(Lavapipe, Msaa4SampleMaskMatchesTheReference) {
  for (std::uint32_t mask : {0x5U, 0x2U, 0xEU}) {
    Scene s = scene(8, 8, 4);
    s.msaa.sample_mask = mask;
    s.primitives.push_back(make_triangle({{{0.125F, 0.375F}, {6.875F, 1.625F}, {2.375F, 7.125F}}}));
    s.primitives.push_back(prim(PrimitiveType::kPoint, {{6.125F, 6.5F}}));
    expect_same_as_reference(s);
  }
}

// FINDING.LAVAPIPE.MSAA_BRESENHAM: on a 4x target lavapipe's Bresenham lines produce the
// single-sample pixels with only sample 0 in gl_SampleMaskIn, where MSAA.LINE.MODE (and
// Vulkan) cover every sample of a produced pixel.
// rule: DRIVER.LAVAPIPE.COVERAGE, MSAA.LINE.MODE
TEST(Lavapipe, Msaa4BresenhamCoversOnlySampleZero) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  const Scene s =
      line_scene(8, 4, 4, LineMode::kVulkanBresenham, {line({0.5F, 1.5F}, {4.5F, 1.5F})});
  EXPECT_EQ(describe(reference(s)),
            describe(frags(0, {{0, 1, 15}, {1, 1, 15}, {2, 1, 15}, {3, 1, 15}})));
  EXPECT_EQ(describe(draw_ok(*d, s)),
            describe(frags(0, {{0, 1, 1}, {1, 1, 1}, {2, 1, 1}, {3, 1, 1}})));
}

// FINDING.LAVAPIPE.MSAA_RECT_EDGE: on a 4x target lavapipe draws nothing for a rectangular
// line whose rectangle crosses the right or bottom edge of the target; one pixel wider, it
// draws exactly the reference's fragments.
// rule: DRIVER.LAVAPIPE.COVERAGE, RASTER.TARGET.CLIP
TEST(Lavapipe, Msaa4RectangularLineCrossingTheRightOrBottomEdgeIsDropped) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  const Primitive right = line({7.75F, 6.5F}, {7.75F, 4.5F}); // rectangle x in [7.25, 8.25]
  const Primitive low = line({1.5F, 7.75F}, {5.5F, 7.75F});   // y in [7.25, 8.25]
  const Scene s = line_scene(8, 8, 4, LineMode::kQuadNarrow, {right});
  EXPECT_FALSE(reference(s).empty());
  EXPECT_TRUE(draw_ok(*d, s).empty());
  const Scene bottom = line_scene(8, 8, 4, LineMode::kQuadNarrow, {low});
  EXPECT_FALSE(reference(bottom).empty());
  EXPECT_TRUE(draw_ok(*d, bottom).empty());
  // The same lines crossing the left and top edges are drawn like the reference.
  expect_same_as_reference(
      line_scene(8, 8, 4, LineMode::kQuadNarrow,
                 {line({0.25F, 6.5F}, {0.25F, 4.5F}), line({1.5F, 0.25F}, {5.5F, 0.25F})}));
  // One pixel wider and taller, nothing crosses the edge: the reference's fragments (the
  // extra column and row are outside the smaller target).
  expect_same_as_reference(line_scene(9, 9, 4, LineMode::kQuadNarrow, {right, low}));
  // Single-sample rectangular lines crossing the edge are drawn.
  expect_same_as_reference(line_scene(8, 8, 1, LineMode::kQuadNarrow, {right, low}));
}

// FINDING.LAVAPIPE.MSAA_RECT_SHORT: on a 4x target lavapipe draws nothing for this 0.5 px
// rectangular line; at one sample it agrees with the reference.
// rule: DRIVER.LAVAPIPE.COVERAGE, LINE.QUAD.SHAPE
TEST(Lavapipe, Msaa4ShortRectangularLineIsDropped) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  const Primitive short_line = line({5.625F, 1.625F}, {5.625F, 1.125F});
  const Scene s = line_scene(8, 8, 4, LineMode::kQuadNarrow, {short_line});
  EXPECT_EQ(describe(reference(s)), describe(frags(0, {{5, 1, 3}})));
  EXPECT_TRUE(draw_ok(*d, s).empty());
  expect_same_as_reference(
      line_scene(8, 8, 1, LineMode::kQuadNarrow,
                 {short_line, line({2.5F, 2.0F}, {2.5F, 2.75F})})); // covers the centre (2.5, 2.5)
}

// Draw state is reused: different target sizes, sample counts and line modes in sequence
// give the same answers as fresh draws.
// rule: DRIVER.LAVAPIPE.COVERAGE
TEST(Lavapipe, ReusedStateGivesTheSameAnswers) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  Scene big = scene(40, 24, 4);
  big.primitives.push_back(make_triangle({{{0.5F, 0.5F}, {39.5F, 3.0F}, {10.0F, 23.5F}}}));
  Scene small = scene(8, 8);
  small.primitives.push_back(make_triangle({{{0.5F, 0.5F}, {7.0F, 1.5F}, {2.0F, 7.25F}}}));
  const auto big1 = draw_ok(*d, big);
  const auto small1 = draw_ok(*d, small);
  EXPECT_EQ(draw_ok(*d, big), big1);
  EXPECT_EQ(draw_ok(*d, small), small1);
  EXPECT_EQ(big1, reference(big));
  Scene empty = scene(8, 8);
  EXPECT_TRUE(draw_ok(*d, empty).empty());
}

// The coverage buffer grows with the target and the primitive count; draws after each growth
// still match the reference. (A regression test: the adapter once rebound its descriptor set
// only when the new buffer's handle differed from the old one; lavapipe reused the handle
// value, the set kept pointing at freed memory, and draws crashed or came back empty.)
// rule: DRIVER.LAVAPIPE.COVERAGE
TEST(Lavapipe, GrowingBuffersKeepWorking) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  std::mt19937 rng(77);
  for (int round = 0; round < 4; ++round) {
    for (std::int32_t side = 4; side <= 40; side += 6) {
      Scene s = scene(side, side, round % 2 == 0 ? 1U : 4U);
      const auto coord = [&] {
        return static_cast<float>(rng() % static_cast<unsigned>(side * 8)) / 8.0F;
      };
      const int count = 1 + side / 2 + round * 4;
      for (int i = 0; i < count; ++i) {
        s.primitives.push_back(
            make_triangle({{{coord(), coord()}, {coord(), coord()}, {coord(), coord()}}}));
      }
      ASSERT_EQ(describe(draw_ok(*d, s)), describe(reference(s)))
          << "round " << round << " side " << side;
    }
  }
}

// rule: DRIVER.LAVAPIPE.DEVICE
TEST(Lavapipe, OpensAndClosesASecondDriver) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  Scene s = scene(8, 8, 4);
  s.primitives.push_back(make_triangle({{{0.5F, 0.5F}, {7.0F, 1.5F}, {2.0F, 7.25F}}}));
  std::string error;
  auto second = open_driver("lavapipe", &error);
  ASSERT_NE(second, nullptr) << error;
  EXPECT_EQ(draw_ok(*second, s), draw_ok(*d, s));
  second.reset();
  EXPECT_EQ(draw_ok(*d, s), reference(s));
}

// --- Values of pipeline scenes (DRIVER.LAVAPIPE.VALUES): gpu_test_support.hpp ----------------

// rule: DRIVER.LAVAPIPE.VALUES, DRIVER.VALUES
TEST(LavapipeValues, ReportsValuesAndNamesWhatItCannotDraw) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  gpu_test::expect_values_support(*d);
}

// rule: DRIVER.LAVAPIPE.VALUES, PIPE.INTERP.LINEAR, PIPE.INTERP.FLAT, PIPE.DEPTH.FORMAT
TEST(LavapipeValues, ExactValuesMatchTheReference) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  gpu_test::expect_exact_values(*d);
}

// rule: DRIVER.LAVAPIPE.VALUES, MSAA.SHADING.SAMPLE, PIPE.INTERP.LOCATION
TEST(LavapipeValues, SampleRateShadingGivesEachSampleItsExactValues) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  gpu_test::expect_exact_sample_values(*d, /*centre_at_sample=*/false);
}

// rule: DRIVER.LAVAPIPE.VALUES, PIPE.DEPTH.FORMAT, MSAA.PATTERN.STANDARD
TEST(LavapipeValues, MultisampledDepthIsReadPerSampleInD16AndD32F) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  gpu_test::expect_multisampled_depth(*d);
}

// rule: DRIVER.LAVAPIPE.VALUES, PIPE.DEPTH.BIAS
TEST(LavapipeValues, DepthBiasMovesTrianglesByOneToTwoStepsPerUnit) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  gpu_test::expect_biased_depth(*d);
}

// rule: DRIVER.LAVAPIPE.VALUES, LINE.STRIP.SEQUENCE, PIPE.INTERP.FLAT, PIPE.CLIP.LINE
TEST(LavapipeValues, StripSegmentsKeepTheirKeysAndProvokingVertices) {
  RASTRULES_LAVAPIPE_OR_SKIP(d);
  gpu_test::expect_strip_values(*d);
}

} // namespace
} // namespace rastrules::driver
