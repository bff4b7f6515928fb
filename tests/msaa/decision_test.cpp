// SPDX-License-Identifier: MIT
// Multisampling decision records (rastrules/decision.hpp) against the kernel's rasterization:
// per pixel and segment, the record's fragment mask, centroid and helper lanes equal the
// fragments rasterize_primitive emits, and the per-sample triangle records explain the
// coverage mask, under standard, centre and custom patterns, sample masks, both centroid
// rules, pixel and sample shading and quads; for triangles, points, quadrilateral lines
// (D3D lines on a multisampled target) and Bresenham lines (every sample of a produced pixel).

#include <gtest/gtest.h>

#include "rastrules/decision.hpp"
#include "rastrules/rules.hpp"
#include "support.hpp"

namespace rastrules {
namespace {

// rule: MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.CENTROID.D3D11, MSAA.QUAD.HELPER
TEST(MsaaDecision, AHalfCoveredPixelsRecordHasTheMaskCentroidAndHelpersOfItsFragments) {
  // The triangle (1, 1) -> (2, 1) -> (1, 2) covers the standard 4x samples 0 (-2, -6)/16 and
  // 2 (-6, 2)/16 of pixel (1, 1), left of the diagonal x + y = 3, and no other sample.
  Scene scene = test::scene_px(4, 4, RasterState{}, {{{{1, 1}, {2, 1}, {1, 2}}}});
  set_sample_pattern(scene, standard_pattern(4));
  scene.msaa.has_centroid = true;
  scene.msaa.quads = true;
  const PreparedScene s = test::prepared(scene);
  const PixelDecision d = decide_pixel(s, 0, 1, 1);
  ASSERT_TRUE(d.msaa.has_value());
  EXPECT_EQ(d.msaa->pattern_rule, rules::kMsaaPatternStandard);
  ASSERT_EQ(d.msaa->samples.size(), 4u);
  EXPECT_TRUE(d.msaa->samples[0].triangles[0].covered);
  EXPECT_FALSE(d.msaa->samples[1].triangles[0].covered);
  ASSERT_EQ(d.msaa->segments.size(), 1u);
  const SegmentMaskDecision& g = d.msaa->segments[0];
  EXPECT_EQ(g.coverage, 0b0101u);
  EXPECT_EQ(g.mask, 0b0101u);
  ASSERT_TRUE(g.centroid.has_value());
  EXPECT_EQ(g.centroid->branch, CentroidBranch::kFirstCovered);
  EXPECT_EQ(g.centroid->offset, (SampleOffset{-2, -6}));
  EXPECT_FALSE(g.helper);
  // The other three pixels of the quad run as helper lanes.
  const PixelDecision h = decide_pixel(s, 0, 0, 0);
  EXPECT_FALSE(h.covered);
  EXPECT_TRUE(h.msaa->segments[0].helper);
  EXPECT_FALSE(decide_pixel(s, 0, 2, 2).msaa->segments[0].helper); // another quad
  EXPECT_EQ(test::decision_disagreement(s), "");
}

// A multisample state and the centroid rule (a convention) it is checked with.
struct MsaaState {
  MultisampleState ms;
  CentroidRule centroid = CentroidRule::kD3D11;
};

// A scene of every primitive kind (antialiased lines only in the D3D line mode; no Bresenham
// lines under sample shading, which the scene format rejects) under ms.
Scene msaa_scene(const MsaaState& st, LineMode mode, std::uint32_t seed) {
  const MultisampleState& ms = st.ms;
  const bool lines = mode != LineMode::kVulkanBresenham || ms.shading != ShadingRate::kSample;
  Scene scene;
  scene.width = 9;
  scene.height = 8;
  scene.conventions.line_mode = mode;
  scene.msaa = ms;
  scene.conventions.pattern = ms.pattern.kind;
  scene.conventions.centroid = st.centroid;
  scene.cull = CullMode::kBack;
  for (const auto& [type, n] : {std::pair{PrimitiveType::kTriangle, std::size_t{6}},
                                {PrimitiveType::kPoint, std::size_t{4}},
                                {PrimitiveType::kLine, std::size_t{3}},
                                {PrimitiveType::kLineStrip, std::size_t{2}}}) {
    const bool line = type == PrimitiveType::kLine || type == PrimitiveType::kLineStrip;
    for (Primitive& p : test::tie_heavy_primitives(type, n, seed++, scene.width, scene.height)) {
      if (lines || !line)
        scene.primitives.push_back(p);
    }
  }
  if (mode == LineMode::kD3DDiamond) {
    for (Primitive& p : test::tie_heavy_primitives(PrimitiveType::kLineStrip, 2, seed, scene.width,
                                                   scene.height)) {
      p.aa = true;
      scene.primitives.push_back(p);
    }
  }
  return scene;
}

// The multisample states the agreement is checked under.
std::vector<MsaaState> states() {
  std::vector<MsaaState> out;
  MultisampleState a; // 4x, partial mask, D3D11 centroid, pixel shading, quads
  a.pattern = standard_pattern(4);
  a.sample_mask = 0b1011u;
  a.has_centroid = true;
  a.quads = true;
  out.push_back({a});
  MultisampleState b = a; // D3D10 centroid, full mask, sample shading
  b.sample_mask = 0xFFFFFFFFu;
  b.shading = ShadingRate::kSample;
  out.push_back({b, CentroidRule::kD3D10});
  MultisampleState c; // 8x, fine derivatives (quads), D3D10 centroid under a partial mask
  c.pattern = standard_pattern(8);
  c.derivatives = DerivativeMode::kFine;
  c.has_centroid = true;
  c.sample_mask = 0b01100110u;
  out.push_back({c, CentroidRule::kD3D10});
  MultisampleState d; // 2x, one sample masked away, no centroid
  d.pattern = standard_pattern(2);
  d.sample_mask = 0b10u;
  out.push_back({d});
  MultisampleState e; // a custom pattern of 3 samples, sample shading, quads
  e.pattern = custom_pattern({SampleOffset{0, 0}, SampleOffset{-8, -8}, SampleOffset{7, 3}});
  e.shading = ShadingRate::kSample;
  e.quads = true;
  out.push_back({e});
  MultisampleState f; // one sample at the centre, with a centroid: the multisampled path
  f.has_centroid = true;
  out.push_back({f});
  MultisampleState g; // 16x, every sample
  g.pattern = standard_pattern(16);
  out.push_back({g});
  return out;
}

// rule: MSAA.COVER.SAMPLE, MSAA.MASK.AND, MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
// rule: MSAA.QUAD.HELPER, MSAA.SHADING.PIXEL, MSAA.SHADING.SAMPLE, MSAA.LINE.MODE
// rule: MSAA.POINT.PER_SAMPLE
TEST(MsaaDecision, EveryPixelsRecordAgreesWithTheRasterizedFragments) {
  std::uint32_t seed = 41;
  const std::vector<MsaaState> all = states();
  for (std::size_t i = 0; i < all.size(); ++i) {
    for (const LineMode mode :
         {LineMode::kD3DDiamond, LineMode::kVulkanBresenham, LineMode::kQuadNarrow}) {
      const Scene scene = msaa_scene(all[i], mode, seed);
      seed += 8;
      EXPECT_EQ(test::decision_disagreement(test::prepared(scene)), "")
          << "state " << i << ", line_mode " << to_string(mode);
    }
  }
}

} // namespace
} // namespace rastrules
