// SPDX-License-Identifier: MIT
// Examples for 2x2 quads: even alignment, lane order, helper lanes (per primitive, per line
// strip segment, per sample index, inside the target only) and fine versus coarse
// derivatives of centroid evaluation points.

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

#include "msaa_support.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::test {
namespace {

Primitive tri(FloatPoint a, FloatPoint b, FloatPoint c) {
  return prim_px(PrimitiveType::kTriangle, {a, b, c});
}

Fragment helper_at(std::uint32_t prim, std::int32_t x, std::int32_t y) {
  Fragment f{prim, x, y, 0u};
  f.helper = true;
  return f;
}

// rule: MSAA.QUAD.ALIGN, MSAA.QUAD.LANE
TEST(QuadLane, ZOrderInEvenAlignedQuads) {
  EXPECT_EQ(quad_lane(0, 0), 0u);
  EXPECT_EQ(quad_lane(1, 0), 1u);
  EXPECT_EQ(quad_lane(0, 1), 2u);
  EXPECT_EQ(quad_lane(1, 1), 3u);
  EXPECT_EQ(quad_lane(7, 4), 1u);
  EXPECT_EQ(quad_lane(6, 9), 2u);
}

// rule: MSAA.QUAD.HELPER, MSAA.QUAD.ALIGN
TEST(QuadHelper, ASmallTriangleRunsItsWholeQuad) {
  // Covers only the centre of pixel (1, 1): its quad is the even-aligned one at (0, 0).
  MultisampleState ms;
  ms.quads = true;
  const auto f =
      frags_of(msaa_scene(4, 4, ms, {tri({1.25f, 1.25f}, {1.875f, 1.25f}, {1.25f, 1.875f})}));
  const std::vector<Fragment> want = {helper_at(0, 0, 0), helper_at(0, 1, 0), helper_at(0, 0, 1),
                                      Fragment{0, 1, 1, 1u}};
  EXPECT_EQ(f, want);
  // Without quads: just the covered pixel.
  EXPECT_EQ(frags_of(msaa_scene(4, 4, MultisampleState{},
                                {tri({1.25f, 1.25f}, {1.875f, 1.25f}, {1.25f, 1.875f})})),
            (std::vector<Fragment>{Fragment{0, 1, 1, 1u}}));
}

// rule: MSAA.QUAD.HELPER
TEST(QuadHelper, HelpersOutsideTheTargetAreNotListed) {
  MultisampleState ms;
  ms.derivatives = DerivativeMode::kFine; // implies quads
  const auto f =
      frags_of(msaa_scene(3, 3, ms, {tri({2.25f, 2.25f}, {2.875f, 2.25f}, {2.25f, 2.875f})}));
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].x, 2);
  EXPECT_EQ(f[0].y, 2);
  EXPECT_FALSE(f[0].helper);
  // Its neighbours outside the target still take part in the derivatives (pixel centres).
  EXPECT_EQ(f[0].derivatives, (EvalDerivatives{16, 0, 0, 16}));
}

// rule: MSAA.QUAD.HELPER
TEST(QuadHelper, PerSampleIndexUnderSampleShading) {
  // Covers only sample 0 (1.375, 1.125) of pixel (1, 1) under 4x.
  MultisampleState ms = with_pattern(standard_pattern(4));
  ms.shading = ShadingRate::kSample;
  ms.quads = true;
  const auto f =
      frags_of(msaa_scene(4, 4, ms, {tri({1.3125f, 1.0625f}, {1.5f, 1.0625f}, {1.3125f, 1.25f})}));
  ASSERT_EQ(f.size(), 4u);
  const std::array<std::array<std::int32_t, 2>, 4> xy = {{{0, 0}, {1, 0}, {0, 1}, {1, 1}}};
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(f[i].x, xy[i][0]);
    EXPECT_EQ(f[i].y, xy[i][1]);
    EXPECT_EQ(f[i].sample, 0u);
    EXPECT_EQ(f[i].helper, i != 3);
    EXPECT_EQ(f[i].mask, i == 3 ? 1u : 0u);
  }
}

// rule: MSAA.QUAD.HELPER
TEST(QuadHelper, PerLineStripSegment) {
  // D3D aliased strip (0.5, 0.5) -> (2.5, 0.5) -> (2.5, 2.5): segment 0 draws (0, 0), (1, 0);
  // segment 1 draws (2, 0), (2, 1). Each segment's quads are its own.
  MultisampleState ms;
  ms.quads = true;
  const auto f = frags_of(msaa_scene(
      4, 4, ms, {prim_px(PrimitiveType::kLineStrip, {{0.5f, 0.5f}, {2.5f, 0.5f}, {2.5f, 2.5f}})}));
  struct Row {
    std::int32_t x, y;
    std::uint32_t seg;
    bool helper;
  };
  const std::vector<Row> want = {{0, 0, 0, false}, {1, 0, 0, false}, {2, 0, 1, false},
                                 {3, 0, 1, true},  {0, 1, 0, true},  {1, 1, 0, true},
                                 {2, 1, 1, false}, {3, 1, 1, true}};
  ASSERT_EQ(f.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(f[i].x, want[i].x) << i;
    EXPECT_EQ(f[i].y, want[i].y) << i;
    EXPECT_EQ(f[i].seg, want[i].seg) << i;
    EXPECT_EQ(f[i].helper, want[i].helper) << i;
  }
}

// The 4x scene of the derivative examples: hypotenuse x + y = 3. Pixel (1, 1) covers samples
// 0 and 2 (centroid: sample 0, (-2, -6)); (2, 0) and (0, 2) likewise; (0, 0), (1, 0), (0, 1)
// are fully covered (centroid: the centre).
Scene derivative_scene(DerivativeMode d) {
  MultisampleState ms = with_pattern(standard_pattern(4));
  ms.has_centroid = true;
  ms.derivatives = d;
  return msaa_scene(4, 4, ms, {tri({0, 0}, {3, 0}, {0, 3})});
}

const Fragment* find(const std::vector<Fragment>& f, std::int32_t x, std::int32_t y) {
  for (const Fragment& fr : f) {
    if (fr.x == x && fr.y == y)
      return &fr;
  }
  return nullptr;
}

// rule: MSAA.DERIV.FINE
TEST(Derivatives, FineFollowsEachLanesRowAndColumnOfCentroids) {
  const auto f = frags_of(derivative_scene(DerivativeMode::kFine));
  // Evaluation points in 1/16 px: P0 (8, 8), P1 (24, 8), P2 (8, 24), P3 (24-2, 24-6) = (22, 18).
  EXPECT_EQ(find(f, 0, 0)->derivatives, (EvalDerivatives{16, 0, 0, 16}));
  EXPECT_EQ(find(f, 1, 0)->derivatives, (EvalDerivatives{16, 0, -2, 10}));
  EXPECT_EQ(find(f, 0, 1)->derivatives, (EvalDerivatives{14, -6, 0, 16}));
  EXPECT_EQ(find(f, 1, 1)->derivatives, (EvalDerivatives{14, -6, -2, 10}));
  // Quad (2, 0): P0 = centroid of (2, 0) = (40-2, 8-6) = (38, 2); the helpers (3, 0), (2, 1),
  // (3, 1) have nothing covered and a full mask: their centres (56, 8), (40, 24), (56, 24).
  ASSERT_TRUE(find(f, 3, 0)->helper);
  EXPECT_EQ(find(f, 3, 0)->centroid, (Centroid{{0, 0}, CentroidBranch::kNoneCoveredCenter}));
  EXPECT_EQ(find(f, 2, 0)->derivatives, (EvalDerivatives{18, 6, 2, 22}));
  EXPECT_EQ(find(f, 3, 0)->derivatives, (EvalDerivatives{18, 6, 0, 16}));
  EXPECT_EQ(find(f, 2, 1)->derivatives, (EvalDerivatives{16, 0, 2, 22}));
  EXPECT_EQ(find(f, 3, 1)->derivatives, (EvalDerivatives{16, 0, 0, 16}));
}

// rule: MSAA.DERIV.COARSE
TEST(Derivatives, CoarseGivesEveryLaneLane0sPair) {
  const auto f = frags_of(derivative_scene(DerivativeMode::kCoarse));
  for (const auto& [x, y] :
       std::vector<std::array<std::int32_t, 2>>{{0, 0}, {1, 0}, {0, 1}, {1, 1}}) {
    EXPECT_EQ(find(f, x, y)->derivatives, (EvalDerivatives{16, 0, 0, 16})) << x << "," << y;
  }
  for (const auto& [x, y] :
       std::vector<std::array<std::int32_t, 2>>{{2, 0}, {3, 0}, {2, 1}, {3, 1}}) {
    EXPECT_EQ(find(f, x, y)->derivatives, (EvalDerivatives{18, 6, 2, 22})) << x << "," << y;
  }
}

// rule: MSAA.QUAD.HELPER, MSAA.CENTROID.D3D11
TEST(QuadHelper, AHelpersCentroidIsTheFirstSampleOfAPartialMask) {
  Scene s = derivative_scene(DerivativeMode::kNone);
  s.msaa.quads = true;
  s.msaa.sample_mask = 0b0110;
  const auto f = frags_of(s);
  const Fragment* h = find(f, 3, 0); // (2, 0) covers 0 and 2; after the mask only 2
  ASSERT_NE(h, nullptr);
  EXPECT_TRUE(h->helper);
  EXPECT_EQ(h->mask, 0u);
  EXPECT_EQ(h->centroid, (Centroid{{6, -2}, CentroidBranch::kNoneCoveredMaskSample}));
  EXPECT_EQ(find(f, 2, 0)->centroid, (Centroid{{-6, 2}, CentroidBranch::kFirstCovered}));
}

// rule: MSAA.DERIV.FINE, MSAA.DERIV.COARSE
TEST(Derivatives, SampleShadingDerivativesAreOnePixel) {
  Scene s = derivative_scene(DerivativeMode::kFine);
  s.msaa.shading = ShadingRate::kSample;
  for (const Fragment& f : frags_of(s)) {
    EXPECT_EQ(f.derivatives, (EvalDerivatives{16, 0, 0, 16}));
    EXPECT_TRUE(f.sample.has_value());
  }
  // The templates on plain values.
  const std::array<int, 4> p = {1, 4, 10, 20};
  EXPECT_EQ(fine_derivatives(p, 0), (Derivatives<int>{3, 9}));
  EXPECT_EQ(fine_derivatives(p, 3), (Derivatives<int>{10, 16}));
  EXPECT_EQ(coarse_derivatives(p), (Derivatives<int>{3, 9}));
}

} // namespace
} // namespace rastrules::test
