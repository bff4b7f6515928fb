// SPDX-License-Identifier: MIT
// Examples that reach the branches of the multisampled kernel paths the other examples and the
// properties leave unrun (kernel/COVERAGE.md): an antialiased line on the per-sample path with
// one sample, for_each_fragment() off the single-sample triangle path, resolve() given a
// hand-built prepared scene or fragments outside it, the widest full mask, and the
// member-by-member equality of the multisampling output types.

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <variant>
#include <vector>

#include "msaa_support.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::test {
namespace {

Primitive aa_line(FloatPoint a, FloatPoint b) {
  Primitive p = prim_px(PrimitiveType::kLine, {a, b});
  p.aa = true;
  return p;
}

// rule: MSAA.LINE.MODE, MSAA.QUAD.HELPER
TEST(MsaaCoverageGaps, AntialiasedLineWithOneSampleKeepsItsCoverageOnThePerSamplePath) {
  // One sample at the centre, but quads asked for: the scene leaves the single-sample path,
  // and a "d3d" line with one sample is still the antialiased line (MSAA.LINE.MODE: "with one
  // sample nothing changes"): same pixels, same coverage, mask 1; helper lanes added.
  const Primitive line = aa_line({0.5f, 1.25f}, {6.5f, 3.75f});
  const std::vector<Fragment> plain = frags_of(msaa_scene(8, 6, MultisampleState{}, {line}));
  ASSERT_FALSE(plain.empty());
  MultisampleState ms;
  ms.quads = true;
  const std::vector<Fragment> quads = frags_of(msaa_scene(8, 6, ms, {line}));
  std::vector<Fragment> lit;
  std::size_t helpers = 0;
  for (const Fragment& f : quads) {
    if (f.helper) {
      ++helpers;
      EXPECT_EQ(f.mask, 0u);
      EXPECT_FALSE(f.coverage_q16.has_value());
    } else {
      lit.push_back(f);
    }
  }
  EXPECT_EQ(lit, plain);
  for (const Fragment& f : lit) {
    ASSERT_TRUE(f.coverage_q16.has_value());
    EXPECT_GE(*f.coverage_q16, 1u);
    EXPECT_LE(*f.coverage_q16, 65536u);
  }
  // A line one pixel wide never fills every quad it touches.
  EXPECT_GT(helpers, 0u);
}

// rule: MSAA.LIMITS, MSAA.RESOLVE.AVERAGE
TEST(MsaaCoverageGaps, ResolveRejectsAHandBuiltSceneWithNoSampleOrNoPixel) {
  // resolve() takes any PreparedScene; prepare() never makes these, a caller can.
  PreparedScene s;
  s.width = 2;
  s.height = 2;
  auto expect_target_error = [](const PreparedScene& scene) {
    const auto r = resolve(scene, {});
    ASSERT_TRUE(std::holds_alternative<SceneError>(r));
    EXPECT_EQ(std::get<SceneError>(r).field, "target");
  };
  PreparedScene no_width = s;
  no_width.width = 0;
  expect_target_error(no_width);
  PreparedScene no_height = s;
  no_height.height = 0;
  expect_target_error(no_height);
  PreparedScene no_sample = s;
  no_sample.msaa.pattern.positions.clear();
  expect_target_error(no_sample);
  // The same scene with its sample resolves to the clear colour.
  const auto ok = resolve(s, {});
  ASSERT_TRUE(std::holds_alternative<ResolvedImage>(ok));
  EXPECT_EQ(std::get<ResolvedImage>(ok).pixels, std::vector<Rgba8>(4, s.clear_color));
}

// rule: SCENE.OUTPUT.MSAA, MSAA.COVER.SAMPLE
TEST(MsaaCoverageGaps, ForEachFragmentStreamsWhatRasterizeListsOnEveryPath) {
  // The streaming entry point: single-sample triangles take the walk directly; multisampled
  // primitives and single-sample non-triangles replay rasterize_primitive().
  const Primitive tri = prim_px(PrimitiveType::kTriangle, {{0.25f, 0.5f}, {5.5f, 1}, {1, 4.75f}});
  const Primitive point = prim_px(PrimitiveType::kPoint, {{3, 3}});
  const Primitive line = prim_px(PrimitiveType::kLine, {{0.5f, 4.5f}, {5.5f, 0.5f}});
  for (const MultisampleState& ms : {MultisampleState{}, with_pattern(standard_pattern(4))}) {
    const auto prepared = prepare(msaa_scene(6, 5, ms, {tri, point, line}));
    ASSERT_TRUE(std::holds_alternative<PreparedScene>(prepared));
    const PreparedScene& s = std::get<PreparedScene>(prepared);
    for (std::size_t p = 0; p < s.primitives.size(); ++p) {
      std::vector<Fragment> streamed;
      for_each_fragment(s, p, [&](const Fragment& f) { streamed.push_back(f); });
      EXPECT_FALSE(streamed.empty()) << "primitive " << p << ", " << ms.count() << " samples";
      EXPECT_EQ(streamed, rasterize_primitive(s, p))
          << "primitive " << p << ", " << ms.count() << " samples";
    }
  }
}

// rule: MSAA.RESOLVE.AVERAGE
TEST(MsaaCoverageGaps, ResolveNamesEachFragmentOutsideTheScene) {
  const Scene scene = msaa_scene(3, 2, with_pattern(standard_pattern(4)),
                                 {prim_px(PrimitiveType::kTriangle, {{0, 0}, {3, 0}, {0, 2}})});
  const auto prepared = prepare(scene);
  ASSERT_TRUE(std::holds_alternative<PreparedScene>(prepared));
  const PreparedScene& s = std::get<PreparedScene>(prepared);
  const Fragment inside{0, 1, 1, 0xFu};
  const std::vector<Fragment> outside = {
      Fragment{1, 0, 0, 0xFu},  // no primitive 1
      Fragment{0, -1, 0, 0xFu}, // left of the target
      Fragment{0, 3, 0, 0xFu},  // right of it
      Fragment{0, 0, -1, 0xFu}, // above it
      Fragment{0, 0, 2, 0xFu},  // below it
  };
  for (const Fragment& bad : outside) {
    const auto r = resolve(s, {inside, bad});
    ASSERT_TRUE(std::holds_alternative<SceneError>(r)) << bad.prim << " " << bad.x << " " << bad.y;
    EXPECT_EQ(std::get<SceneError>(r).field, "fragments[1]");
  }
  // The inside fragment alone writes its primitive's colour to all four samples.
  const auto ok = resolve(s, {inside});
  ASSERT_TRUE(std::holds_alternative<ResolvedImage>(ok));
  EXPECT_EQ(std::get<ResolvedImage>(ok).pixels[1 * 3 + 1], s.primitives[0].color);
  EXPECT_EQ(std::get<ResolvedImage>(ok).pixels[0], s.clear_color);
}

// rule: MSAA.MASK.AND
TEST(MsaaCoverageGaps, FullMaskReachesAllThirtyTwoBits) {
  EXPECT_EQ(full_mask(0), 0u);
  EXPECT_EQ(full_mask(1), 1u);
  EXPECT_EQ(full_mask(16), 0xFFFFu);
  EXPECT_EQ(full_mask(31), 0x7FFFFFFFu);
  EXPECT_EQ(full_mask(32), 0xFFFFFFFFu);
  // The default sample mask keeps exactly the pattern's samples.
  MultisampleState ms;
  ms.pattern = standard_pattern(16);
  EXPECT_EQ(ms.effective_mask(), 0xFFFFu);
}

// rule: SCENE.OUTPUT.MSAA
TEST(MsaaCoverageGaps, FragmentsDifferInAnyMultisamplingField) {
  Fragment a{0, 1, 2, 0x3u, std::uint32_t{1}, std::nullopt};
  a.sample = 1;
  a.centroid = Centroid{SampleOffset{2, -6}, CentroidBranch::kFirstCovered};
  a.derivatives = EvalDerivatives{16, 0, 0, 16};
  EXPECT_EQ(a, a);
  auto differs = [&](auto change) {
    Fragment b = a;
    change(b);
    return !(a == b);
  };
  EXPECT_TRUE(differs([](Fragment& f) { f.prim = 1; }));
  EXPECT_TRUE(differs([](Fragment& f) { f.x = 0; }));
  EXPECT_TRUE(differs([](Fragment& f) { f.y = 0; }));
  EXPECT_TRUE(differs([](Fragment& f) { f.mask = 0x1u; }));
  EXPECT_TRUE(differs([](Fragment& f) { f.seg = 0u; }));
  EXPECT_TRUE(differs([](Fragment& f) { f.coverage_q16 = 65536u; }));
  EXPECT_TRUE(differs([](Fragment& f) { f.helper = true; }));
  EXPECT_TRUE(differs([](Fragment& f) { f.sample = 2u; }));
  EXPECT_TRUE(differs([](Fragment& f) { f.centroid->branch = CentroidBranch::kNearestCovered; }));
  EXPECT_TRUE(differs([](Fragment& f) { f.centroid->offset.y = -5; }));
  EXPECT_TRUE(differs([](Fragment& f) { f.derivatives->ddx_x = 8; }));
  EXPECT_TRUE(differs([](Fragment& f) { f.derivatives->ddx_y = 1; }));
  EXPECT_TRUE(differs([](Fragment& f) { f.derivatives->ddy_x = 1; }));
  EXPECT_TRUE(differs([](Fragment& f) { f.derivatives->ddy_y = 8; }));
  EXPECT_TRUE(differs([](Fragment& f) { f.derivatives.reset(); }));
}

// rule: MSAA.DERIV.FINE, MSAA.DERIV.COARSE
TEST(MsaaCoverageGaps, DerivativesOfAQuadDifferPerLaneOnlyWhenFine) {
  // Values 0, 3, 10, 20 in lane order: fine rows 3 and 10, columns 10 and 17; coarse lane 0's.
  const std::array<std::int32_t, 4> p = {0, 3, 10, 20};
  EXPECT_EQ(fine_derivatives(p, 0), (Derivatives<std::int32_t>{3, 10}));
  EXPECT_EQ(fine_derivatives(p, 3), (Derivatives<std::int32_t>{10, 17}));
  EXPECT_FALSE(fine_derivatives(p, 1) == fine_derivatives(p, 2)); // ddx 3 vs 10, ddy 17 vs 10
  EXPECT_FALSE(fine_derivatives(p, 0) == fine_derivatives(p, 1)); // same ddx, ddy 10 vs 17
  EXPECT_EQ(coarse_derivatives(p), fine_derivatives(p, 0));
  EXPECT_FALSE(coarse_derivatives(p) == fine_derivatives(p, 3));
}

} // namespace
} // namespace rastrules::test
