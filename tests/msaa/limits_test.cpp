// SPDX-License-Identifier: MIT
// Examples for MSAA.LIMITS and SCENE.MSAA: every multisample value prepare() rejects, with the
// field it names, and the values at the edges it accepts.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "msaa_support.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::test {
namespace {

Scene with(MultisampleState ms, std::vector<Primitive> prims = {}) {
  return msaa_scene(4, 4, std::move(ms), std::move(prims));
}

Primitive line() {
  return prim_px(PrimitiveType::kLine, {{0.5f, 0.5f}, {3.5f, 1.5f}});
}

// rule: MSAA.LIMITS
TEST(Limits, StandardAndCentreCountsArePowersOfTwoUpTo16) {
  MultisampleState ms;
  ms.pattern = SamplePattern{PatternKind::kStandard, std::vector<SampleOffset>(3)};
  EXPECT_EQ(error_of(with(ms)).field, "samples");
  ms.pattern = SamplePattern{PatternKind::kCenter, std::vector<SampleOffset>(5)};
  EXPECT_EQ(error_of(with(ms)).field, "samples");
  ms.pattern = SamplePattern{PatternKind::kCenter, std::vector<SampleOffset>(32)};
  EXPECT_EQ(error_of(with(ms)).field, "samples");
  // A "standard" pattern must hold the standard positions.
  ms.pattern = standard_pattern(4);
  ms.pattern.positions[2] = SampleOffset{0, 0};
  EXPECT_EQ(error_of(with(ms)).field, "sample_pattern");
  ms.pattern = center_pattern(2);
  ms.pattern.positions[1] = SampleOffset{1, 0};
  EXPECT_EQ(error_of(with(ms)).field, "sample_pattern");
  for (const std::uint32_t n : {1u, 2u, 4u, 8u, 16u}) {
    EXPECT_TRUE(
        std::holds_alternative<PreparedScene>(prepare(with(with_pattern(standard_pattern(n))))));
    EXPECT_TRUE(
        std::holds_alternative<PreparedScene>(prepare(with(with_pattern(center_pattern(n))))));
  }
}

// rule: MSAA.LIMITS, MSAA.PATTERN.CUSTOM
TEST(Limits, CustomPatternsHold1To16PositionsOnTheGrid) {
  EXPECT_EQ(error_of(with(with_pattern(custom_pattern({})))).field, "sample_pattern");
  EXPECT_EQ(error_of(with(with_pattern(custom_pattern(std::vector<SampleOffset>(17))))).field,
            "sample_pattern");
  EXPECT_TRUE(std::holds_alternative<PreparedScene>(
      prepare(with(with_pattern(custom_pattern(std::vector<SampleOffset>(16)))))));
  const SceneError e =
      error_of(with(with_pattern(custom_pattern({{0, 0}, {1, 1}, {2, 2}, {8, 0}}))));
  EXPECT_EQ(e.field, "sample_pattern[3][0]");
  EXPECT_NE(e.message.find("[-8, 7]"), std::string::npos);
  EXPECT_EQ(error_of(with(with_pattern(custom_pattern({{0, -9}})))).field, "sample_pattern[0][1]");
  EXPECT_TRUE(std::holds_alternative<PreparedScene>(
      prepare(with(with_pattern(custom_pattern({{-8, -8}, {7, 7}, {3, 3}}))))));
}

// rule: MSAA.LIMITS, MSAA.MASK.AND
TEST(Limits, SampleMaskHasNoBitsBeyondThePattern) {
  MultisampleState ms = with_pattern(standard_pattern(4));
  ms.sample_mask = 0x10;
  const SceneError e = error_of(with(ms));
  EXPECT_EQ(e.field, "sample_mask");
  EXPECT_NE(e.message.find("[0, 15]"), std::string::npos);
  ms.sample_mask = 0xFFFFFFFEu; // not the "all samples" default
  EXPECT_EQ(error_of(with(ms)).field, "sample_mask");
  for (const std::uint32_t m : {0u, 0xFu, 0x5u, 0xFFFFFFFFu}) {
    ms.sample_mask = m;
    EXPECT_TRUE(std::holds_alternative<PreparedScene>(prepare(with(ms)))) << m;
  }
  MultisampleState sixteen = with_pattern(standard_pattern(16));
  sixteen.sample_mask = 0x1FFFF;
  EXPECT_EQ(error_of(with(sixteen)).field, "sample_mask");
}

// rule: MSAA.LIMITS
TEST(Limits, EnumerationsOutsideTheirValues) {
  MultisampleState ms;
  ms.has_centroid = true;
  Scene bad_rule = with(ms);
  bad_rule.conventions.centroid = static_cast<CentroidRule>(7);
  EXPECT_EQ(error_of(bad_rule).field, "centroid");
  ms = MultisampleState{};
  ms.shading = static_cast<ShadingRate>(7);
  EXPECT_EQ(error_of(with(ms)).field, "shading");
  ms = MultisampleState{};
  ms.derivatives = static_cast<DerivativeMode>(7);
  EXPECT_EQ(error_of(with(ms)).field, "derivatives");
  ms = MultisampleState{};
  ms.pattern.kind = static_cast<PatternKind>(7);
  EXPECT_EQ(error_of(with(ms)).field, "sample_pattern");
  EXPECT_EQ(to_string(static_cast<ShadingRate>(7)), "unknown");
  EXPECT_EQ(to_string(static_cast<DerivativeMode>(7)), "unknown");
}

// rule: MSAA.LINE.MODE, MSAA.LIMITS
TEST(Limits, QuadrilateralLinesOnACentrePatternOfSeveralSamples) {
  Scene s = with(with_pattern(center_pattern(4)), {line()});
  s.conventions.line_mode = LineMode::kQuadWide;
  const SceneError e = error_of(s);
  EXPECT_EQ(e.field, "sample_pattern");
  EXPECT_NE(e.message.find("primitives[0]"), std::string::npos);
  // D3D lines become quadrilateral lines with more than one sample and MultisampleEnable: also
  // rejected; without it they keep their own rasterizer and are accepted.
  s.conventions.line_mode = LineMode::kD3DDiamond;
  s.conventions.multisample_enable = true;
  EXPECT_EQ(error_of(s).field, "sample_pattern");
  s.conventions.multisample_enable = false;
  EXPECT_TRUE(std::holds_alternative<PreparedScene>(prepare(s)));
  // One sample, Bresenham lines, or no line: accepted.
  s.msaa = with_pattern(center_pattern(1));
  EXPECT_TRUE(std::holds_alternative<PreparedScene>(prepare(s)));
  s.msaa = with_pattern(center_pattern(4));
  s.conventions.line_mode = LineMode::kVulkanBresenham;
  EXPECT_TRUE(std::holds_alternative<PreparedScene>(prepare(s)));
  s.conventions.line_mode = LineMode::kQuadNarrow;
  s.primitives = {prim_px(PrimitiveType::kPoint, {{1, 1}})};
  EXPECT_TRUE(std::holds_alternative<PreparedScene>(prepare(s)));
}

// rule: MSAA.SHADING.SAMPLE, MSAA.LIMITS
TEST(Limits, SampleShadingOfBresenhamLinesWithSeveralSamples) {
  MultisampleState ms = with_pattern(standard_pattern(4));
  ms.shading = ShadingRate::kSample;
  Scene s = with(ms, {line()});
  s.conventions.line_mode = LineMode::kVulkanBresenham;
  EXPECT_EQ(error_of(s).field, "shading");
  // Quadrilateral lines are tested per sample: accepted; so is one sample.
  s.conventions.line_mode = LineMode::kQuadNarrow;
  EXPECT_TRUE(std::holds_alternative<PreparedScene>(prepare(s)));
  s.conventions.line_mode = LineMode::kVulkanBresenham;
  s.msaa = with_pattern(standard_pattern(1));
  s.msaa.shading = ShadingRate::kSample;
  EXPECT_TRUE(std::holds_alternative<PreparedScene>(prepare(s)));
}

// rule: SCENE.MSAA
TEST(SceneMsaa, PrepareCopiesTheStateAndColours) {
  MultisampleState ms = with_pattern(standard_pattern(8));
  ms.sample_mask = 0x3C;
  ms.has_centroid = true;
  Primitive p = prim_px(PrimitiveType::kTriangle, {{0, 0}, {2, 0}, {0, 2}});
  p.color = {1, 2, 3, 4};
  Scene s = with(ms, {p});
  s.conventions.centroid = CentroidRule::kD3D10;
  s.clear_color = {9, 8, 7, 6};
  const PreparedScene ps = std::get<PreparedScene>(prepare(s));
  EXPECT_EQ(ps.msaa.pattern, ms.pattern);
  EXPECT_EQ(ps.msaa.effective_mask(), 0x3Cu);
  EXPECT_EQ(ps.conventions.centroid, CentroidRule::kD3D10);
  EXPECT_EQ(ps.clear_color, (Rgba8{9, 8, 7, 6}));
  EXPECT_EQ(ps.primitives[0].color, (Rgba8{1, 2, 3, 4}));
  // Field order: the target is checked before the multisample state.
  Scene bad = s;
  bad.width = 0;
  bad.msaa.sample_mask = 0x100;
  EXPECT_EQ(error_of(bad).field, "target.width");
}

} // namespace
} // namespace rastrules::test

namespace rastrules::test {
namespace {

// rule: SCENE.OUTPUT.MSAA
TEST(SceneOutputMsaa, OrderIsPrimYXSegSampleMissingFirst) {
  Fragment a{0, 1, 1, 1u};
  Fragment b = a;
  b.sample = 0;
  Fragment c = a;
  c.sample = 2;
  Fragment d{0, 1, 1, 1u, 0u}; // seg 0, no sample
  Fragment e = d;
  e.sample = 1;
  Fragment f{0, 2, 1, 1u}; // next x
  Fragment g{0, 0, 2, 1u}; // next row
  Fragment h{1, 0, 0, 1u}; // next primitive
  const std::vector<Fragment> ordered = {a, b, c, d, e, f, g, h};
  for (std::size_t i = 0; i < ordered.size(); ++i) {
    for (std::size_t j = 0; j < ordered.size(); ++j) {
      EXPECT_EQ(fragment_before(ordered[i], ordered[j]), i < j) << i << " " << j;
    }
  }
  // Helpers sit in place among covered fragments of the same primitive.
  MultisampleState ms = with_pattern(standard_pattern(4));
  ms.quads = true;
  ms.shading = ShadingRate::kSample;
  const auto frags =
      frags_of(msaa_scene(4, 4, ms,
                          {prim_px(PrimitiveType::kTriangle, {{0, 0}, {3, 0}, {0, 3}}),
                           prim_px(PrimitiveType::kPoint, {{1, 1}})}));
  ASSERT_FALSE(frags.empty());
  EXPECT_TRUE(std::is_sorted(frags.begin(), frags.end(), fragment_before));
  bool any_helper = false;
  for (const Fragment& fr : frags)
    any_helper = any_helper || fr.helper;
  EXPECT_TRUE(any_helper);
}

} // namespace
} // namespace rastrules::test
