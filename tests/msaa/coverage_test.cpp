// SPDX-License-Identifier: MIT
// Examples for per-sample coverage in scenes: triangles, points and lines under 4x, the
// sample mask, pixel- and sample-frequency shading, and the one-sample-at-the-centre case.

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <tuple>
#include <vector>

#include "msaa_support.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/raster/walk_msaa.hpp"
#include "rastrules/scene.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

// Standard 4x sample positions within a pixel, from its top-left corner:
// 0 (0.375, 0.125), 1 (0.875, 0.375), 2 (0.125, 0.625), 3 (0.625, 0.875).
MultisampleState four() {
  return with_pattern(standard_pattern(4));
}

Primitive tri(FloatPoint a, FloatPoint b, FloatPoint c) {
  return prim_px(PrimitiveType::kTriangle, {a, b, c});
}

// Each fragment as (primitive, x, y, strip segment, mask); with `mask`, that mask in place of
// its own.
using FragmentKey = std::tuple<std::uint32_t, std::int32_t, std::int32_t,
                               std::optional<std::uint32_t>, std::uint32_t>;
std::vector<FragmentKey> keys_of(const std::vector<Fragment>& fragments,
                                 std::optional<std::uint32_t> mask = std::nullopt) {
  std::vector<FragmentKey> out;
  for (const Fragment& f : fragments)
    out.emplace_back(f.prim, f.x, f.y, f.seg, mask.value_or(f.mask));
  return out;
}

// rule: MSAA.COVER.SAMPLE
TEST(CoverSample, TriangleCoversSamplesUnderTheTopLeftRule) {
  // Hypotenuse x + y = 3 through pixels (1, 1) and (2, 0).
  const auto f = frags_of(msaa_scene(4, 4, four(), {tri({0, 0}, {3, 0}, {0, 3})}));
  const MaskMap want = {{{0, 0}, 0xF}, {{1, 0}, 0xF},    {{2, 0}, 0b0101},
                        {{0, 1}, 0xF}, {{1, 1}, 0b0101}, {{0, 2}, 0b0101}};
  EXPECT_EQ(masks_of(f), want);
  // Sample 2 of pixel (1, 1), (1.125, 1.625), exactly on a horizontal edge: covered when it is
  // a top edge (inclusive), not when it is a bottom edge.
  const TriangleSetup top = triangle_px({0, 1.625}, {3, 1.625}, {0, 3});    // top edge y = 1.625
  const TriangleSetup bottom = triangle_px({0, 0}, {3, 1.625}, {0, 1.625}); // bottom edge
  EXPECT_EQ(sample_coverage(top, 1, 1, standard_pattern(4)) & 0b0100u, 0b0100u);
  EXPECT_EQ(sample_coverage(bottom, 1, 1, standard_pattern(4)) & 0b0100u, 0u);
}

// rule: MSAA.COVER.SAMPLE
TEST(CoverSample, PixelsWhoseCentresLieOutsideTheBoundingBoxCanBeCovered) {
  // A thin triangle in x in [2.0, 2.25]: no pixel centre in its box, but samples at x 2.125
  // (index 2) of pixel column 2.
  const auto f = frags_of(msaa_scene(4, 4, four(), {tri({2, 0}, {2.25f, 0}, {2, 4})}));
  for (const Fragment& fr : f) {
    EXPECT_EQ(fr.x, 2);
    EXPECT_EQ(fr.mask & 0b1011u, 0u); // only sample 2 (x offset -6/16) is that far left
  }
  EXPECT_FALSE(f.empty());
  // Same at the top-left edge of the target: sample (-8, -8) of pixel (0, 0) is (0, 0).
  // The triangle x, y >= 0, x + y <= 1/8 px holds sample 15 (-7, -8) = (1/16, 0) on its top
  // edge, and no other sample of the 16x pattern.
  const auto g = frags_of(msaa_scene(2, 2, with_pattern(standard_pattern(16)),
                                     {tri({0, 0}, {0.125f, 0}, {0, 0.125f})}));
  ASSERT_EQ(g.size(), 1u);
  EXPECT_EQ(g[0].mask, 1u << 15);
}

// rule: MSAA.COVER.SAMPLE
TEST(CoverSample, TraversalBoundsReachThePatternsExtremes) {
  // The widened bounds include every pixel with a sample in the box, and no more.
  const TriangleSetup t = triangle_px({10, 10}, {10.5, 10}, {10, 10.5});
  const raster::PixelRect r4 = raster::sample_pixel_bounds(t, standard_pattern(4), 64, 64);
  EXPECT_EQ(r4.x0, 10);
  EXPECT_EQ(r4.x1, 10);
  const raster::PixelRect rc = raster::sample_pixel_bounds(t, custom_pattern({{-8, -8}}), 64, 64);
  EXPECT_EQ(rc.x0, 10); // sample at the pixel's corner: pixel 10's corner (10, 10) is in the box
  EXPECT_EQ(rc.x1, 10);
  const TriangleSetup u = triangle_px({9.5, 9.5}, {10, 9.5}, {9.5, 10});
  const raster::PixelRect ru = raster::sample_pixel_bounds(u, custom_pattern({{-8, -8}}), 64, 64);
  EXPECT_EQ(ru.x0, 10); // corner (10, 10) only; pixel 9's corner (9, 9) lies left of the box
  EXPECT_EQ(ru.x1, 10);
  EXPECT_EQ(ru.y0, 10);
}

// rule: MSAA.COVER.SAMPLE
TEST(CoverSample, TraversalEqualsTheDirectTestAtEverySample) {
  // Pseudo-random triangles on a 6 x 5 target, partly outside it, with every fill convention
  // and pattern kind: the incremental per-sample walk yields exactly the pixels with a
  // non-zero sample_coverage() (covers() at each sample), with that mask.
  std::uint64_t state = 99;
  auto next = [&](std::int32_t n) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<std::int32_t>((state >> 33) % static_cast<std::uint64_t>(n));
  };
  const std::vector<SamplePattern> patterns = {
      standard_pattern(2), standard_pattern(4), standard_pattern(8), standard_pattern(16),
      custom_pattern({{-8, -8}, {7, 7}, {-8, 7}, {7, -8}, {0, 0}})};
  for (int i = 0; i < 400; ++i) {
    RasterState st;
    st.fill = static_cast<FillConvention>(i % 4);
    const auto coord = [&] { return (next(8 * 16) - 16) / 16.0; }; // [-1, 7) on the 1/16 grid
    const TriangleSetup t =
        triangle_px({coord(), coord()}, {coord(), coord()}, {coord(), coord()}, st);
    const SamplePattern& pat = patterns[static_cast<std::size_t>(i) % patterns.size()];
    MaskMap walked, direct;
    raster::walk_triangle_samples(
        t, pat, 6, 5, [&](std::int32_t x, std::int32_t y, std::uint32_t m) {
          EXPECT_TRUE(walked.emplace(std::make_pair(x, y), m).second) << "pixel emitted twice";
        });
    for (std::int32_t y = 0; y < 5; ++y) {
      for (std::int32_t x = 0; x < 6; ++x) {
        if (const std::uint32_t m = sample_coverage(t, x, y, pat); m != 0)
          direct[{x, y}] = m;
      }
    }
    EXPECT_EQ(walked, direct) << "triangle " << i;
  }
}

// rule: MSAA.COVER.SAMPLE
TEST(CoverSample, OneSampleAtTheCentreIsTheSingleSampleResult) {
  const std::vector<Primitive> prims = {
      tri({0.3f, 0.2f}, {7.7f, 1.1f}, {2.2f, 6.9f}), tri({1, 1}, {5, 1}, {1, 5}),
      prim_px(PrimitiveType::kPoint, {{3.5f, 3.5f}}),
      prim_px(PrimitiveType::kLine, {{0.5f, 0.5f}, {7.25f, 5.75f}})};
  const auto single = frags_of(msaa_scene(8, 8, MultisampleState{}, prims));
  ASSERT_FALSE(single.empty());
  // Through the multisampled path: a one-sample custom pattern at (0, 0) under sample shading.
  MultisampleState ms = with_pattern(custom_pattern({{0, 0}}));
  ms.shading = ShadingRate::kSample;
  const auto multi = frags_of(msaa_scene(8, 8, ms, prims));
  EXPECT_EQ(keys_of(multi), keys_of(single, 1u));
  for (const Fragment& f : multi)
    EXPECT_EQ(f.sample, 0u);
  // A centre pattern of 8 covers all 8 samples exactly where the single sample is covered.
  const auto centre =
      frags_of(msaa_scene(8, 8, with_pattern(center_pattern(8)), {prims[0], prims[1], prims[2]}));
  std::vector<Fragment> want;
  for (const Fragment& f : single) {
    if (f.prim < 3)
      want.push_back(Fragment{f.prim, f.x, f.y, 0xFFu});
  }
  EXPECT_EQ(centre, want);
}

// rule: MSAA.MASK.AND
TEST(MaskAnd, TheSampleMaskRemovesSamplesAndEmptyPixels) {
  MultisampleState ms = four();
  ms.sample_mask = 0b1010;
  const auto f = frags_of(msaa_scene(4, 4, ms, {tri({0, 0}, {3, 0}, {0, 3})}));
  // Pixels (2, 0), (1, 1), (0, 2) had only samples 0 and 2: no fragment at all.
  const MaskMap want = {{{0, 0}, 0b1010}, {{1, 0}, 0b1010}, {{0, 1}, 0b1010}};
  EXPECT_EQ(masks_of(f), want);
  // Mask 0: nothing.
  ms.sample_mask = 0;
  EXPECT_TRUE(frags_of(msaa_scene(4, 4, ms, {tri({0, 0}, {3, 0}, {0, 3})})).empty());
  // The default 0xFFFFFFFF is all samples.
  EXPECT_EQ(four().effective_mask(), 0xFu);
}

// rule: MSAA.POINT.PER_SAMPLE
TEST(PointPerSample, APointOnAPixelCornerSplitsItsSamplesOverFourPixels) {
  // Square [0.5, 1.5]^2. Single-sample: only pixel (0, 0), whose centre is the square's
  // top-left corner. Under 4x each of the four pixels gets one sample.
  const Primitive pt = prim_px(PrimitiveType::kPoint, {{1, 1}});
  EXPECT_EQ(masks_of(frags_of(msaa_scene(4, 4, MultisampleState{}, {pt}))), (MaskMap{{{0, 0}, 1}}));
  EXPECT_EQ(masks_of(frags_of(msaa_scene(4, 4, four(), {pt}))),
            (MaskMap{{{0, 0}, 0b1000}, {{1, 0}, 0b0100}, {{0, 1}, 0b0010}, {{1, 1}, 0b0001}}));
  // Centred on a pixel centre: all four samples of that pixel.
  EXPECT_EQ(masks_of(frags_of(
                msaa_scene(4, 4, four(), {prim_px(PrimitiveType::kPoint, {{1.5f, 1.5f}})}))),
            (MaskMap{{{1, 1}, 0xF}}));
}

// The 4x masks of the 1.4 px wide horizontal line from (0.5, 2.5) to (3.5, 2.5): y in
// [2.5 - 179/256, 2.5 + 179/256], x in [0.5, 3.5) (LINE.QUAD.SHAPE), worked out by hand.
const MaskMap kWideLine4x = {{{0, 1}, 0b1000}, {{1, 1}, 0b1000}, {{2, 1}, 0b1000}, {{0, 2}, 0b1010},
                             {{1, 2}, 0xF},    {{2, 2}, 0xF},    {{3, 2}, 0b0101}, {{1, 3}, 0b0001},
                             {{2, 3}, 0b0001}, {{3, 3}, 0b0001}};

// rule: MSAA.LINE.MODE
TEST(LineMode, D3DLinesWithMultisampleEnableBecomeQuadrilateralLinesPerSample) {
  const Primitive line = prim_px(PrimitiveType::kLine, {{0.5f, 2.5f}, {3.5f, 2.5f}});
  Scene s = msaa_scene(5, 5, four(), {line});
  s.conventions.line_mode = LineMode::kD3DDiamond;
  s.conventions.multisample_enable = true;
  EXPECT_EQ(masks_of(frags_of(s)), kWideLine4x);
  // Antialiased: the same, with no coverage value.
  Primitive aa = line;
  aa.aa = true;
  s.primitives = {aa};
  const auto f = frags_of(s);
  EXPECT_EQ(masks_of(f), kWideLine4x);
  for (const Fragment& fr : f)
    EXPECT_FALSE(fr.coverage_q16.has_value());
  // quad-wide is the same rectangle, whatever MultisampleEnable says.
  s.primitives = {line};
  s.conventions.line_mode = LineMode::kQuadWide;
  EXPECT_EQ(masks_of(frags_of(s)), kWideLine4x);
  s.conventions.multisample_enable = false;
  EXPECT_EQ(masks_of(frags_of(s)), kWideLine4x);
  // With one sample nothing changes: the D3D aliased line stays aliased.
  Scene one = msaa_scene(5, 5, MultisampleState{}, {line});
  EXPECT_EQ(masks_of(frags_of(one)), (MaskMap{{{0, 2}, 1}, {{1, 2}, 1}, {{2, 2}, 1}}));
}

// Issue 15 part 1b, found 2026-11-25: D3D11's rasterizer state has MultisampleEnable false by
// default, and then "all of the MSAA samples in the pixel are hit" by an aliased line (D3D11.3
// 15.14.1); rastrules drew the 1.4 px quadrilateral instead (row 0 mask 8, (0, 1) = 10,
// (4, 1) = 5, row 2 mask 1). The default is now the diamond-exit line in every sample.
// rule: MSAA.LINE.MODE, LINE.D3D.EXIT
TEST(LineMode, D3DLinesWithoutMultisampleEnableHitEverySampleOfTheirPixels) {
  const Primitive line = prim_px(PrimitiveType::kLine, {{0.5f, 1.5f}, {4.5f, 1.5f}});
  Scene s = msaa_scene(8, 4, four(), {line});
  s.conventions.line_mode = LineMode::kD3DDiamond;
  ASSERT_FALSE(s.conventions.multisample_enable); // the default, D3D11's
  EXPECT_EQ(masks_of(frags_of(s)),
            (MaskMap{{{0, 1}, 0xF}, {{1, 1}, 0xF}, {{2, 1}, 0xF}, {{3, 1}, 0xF}}));
  // The same pixels as with one sample, each with the masked pattern.
  Scene one = msaa_scene(8, 4, MultisampleState{}, {line});
  s.msaa.sample_mask = 0b0101;
  EXPECT_EQ(keys_of(frags_of(s)), keys_of(frags_of(one), 0b0101u));
  // With MultisampleEnable: the quadrilateral the issue saw.
  s.msaa.sample_mask = 0xFFFFFFFFu;
  s.conventions.multisample_enable = true;
  EXPECT_EQ(masks_of(frags_of(s)), (MaskMap{{{0, 0}, 8},
                                            {{1, 0}, 8},
                                            {{2, 0}, 8},
                                            {{3, 0}, 8},
                                            {{0, 1}, 10},
                                            {{1, 1}, 0xF},
                                            {{2, 1}, 0xF},
                                            {{3, 1}, 0xF},
                                            {{4, 1}, 5},
                                            {{1, 2}, 1},
                                            {{2, 2}, 1},
                                            {{3, 2}, 1},
                                            {{4, 2}, 1}}));
}

// Without MultisampleEnable an antialiased d3d line keeps the single-sample line's pixels and
// coverage, each pixel with every sample (D3D11.3 15.14.1: alpha-AA lines hit every sample).
// rule: MSAA.LINE.MODE, LINE.AA.FRAGMENT
TEST(LineMode, AntialiasedD3DLinesWithoutMultisampleEnableKeepTheirCoverage) {
  Primitive line = prim_px(PrimitiveType::kLine, {{0.5f, 1.3f}, {4.5f, 2.1f}});
  line.aa = true;
  const auto single = frags_of(msaa_scene(8, 4, MultisampleState{}, {line}));
  Scene s = msaa_scene(8, 4, four(), {line});
  const auto multi = frags_of(s);
  ASSERT_EQ(multi.size(), single.size());
  for (std::size_t i = 0; i < multi.size(); ++i) {
    EXPECT_EQ(std::tie(multi[i].x, multi[i].y), std::tie(single[i].x, single[i].y));
    EXPECT_EQ(multi[i].mask, 0xFu);
    EXPECT_EQ(multi[i].coverage_q16, single[i].coverage_q16);
  }
}

// rule: MSAA.LINE.MODE
TEST(LineMode, BresenhamPixelsGetTheWholeMaskedPattern) {
  const Primitive strip =
      prim_px(PrimitiveType::kLineStrip, {{0.5f, 0.5f}, {4.5f, 2.5f}, {1.5f, 4.5f}});
  Scene one = msaa_scene(6, 6, MultisampleState{}, {strip});
  one.conventions.line_mode = LineMode::kVulkanBresenham;
  const auto single = frags_of(one);
  Scene s = one;
  s.msaa = four();
  s.msaa.sample_mask = 0b0110;
  const auto multi = frags_of(s);
  EXPECT_EQ(keys_of(multi), keys_of(single, 0b0110u));
}

// rule: MSAA.SHADING.PIXEL
TEST(ShadingPixel, OneFragmentPerCoveredPixelWithItsMask) {
  const auto f = frags_of(msaa_scene(4, 4, four(), {tri({0, 0}, {3, 0}, {0, 3})}));
  ASSERT_EQ(f.size(), 6u);
  for (const Fragment& fr : f) {
    EXPECT_FALSE(fr.sample.has_value());
    EXPECT_FALSE(fr.helper);
    EXPECT_FALSE(fr.centroid.has_value()); // not asked for
    EXPECT_FALSE(fr.derivatives.has_value());
  }
}

// rule: MSAA.SHADING.SAMPLE
TEST(ShadingSample, OneFragmentPerCoveredSampleInTheMask) {
  MultisampleState ms = four();
  ms.shading = ShadingRate::kSample;
  ms.sample_mask = 0b0111;
  const auto f = frags_of(msaa_scene(4, 4, ms, {tri({0, 0}, {3, 0}, {0, 3})}));
  // (0,0), (1,0), (0,1): samples 0, 1, 2; (2,0), (1,1), (0,2): samples 0, 2. In (y, x, sample).
  std::vector<std::array<std::uint32_t, 3>> got;
  for (const Fragment& fr : f) {
    ASSERT_TRUE(fr.sample.has_value());
    EXPECT_EQ(fr.mask, 1u << *fr.sample);
    got.push_back({static_cast<std::uint32_t>(fr.y), static_cast<std::uint32_t>(fr.x), *fr.sample});
  }
  const std::vector<std::array<std::uint32_t, 3>> want = {
      {0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 1, 0}, {0, 1, 1}, {0, 1, 2}, {0, 2, 0}, {0, 2, 2},
      {1, 0, 0}, {1, 0, 1}, {1, 0, 2}, {1, 1, 0}, {1, 1, 2}, {2, 0, 0}, {2, 0, 2}};
  EXPECT_EQ(got, want);
}

} // namespace
} // namespace rastrules::test
