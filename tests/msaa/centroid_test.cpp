// SPDX-License-Identifier: MIT
// Examples for the centroid rules: every branch of the D3D11 rule and of the D3D10 reference
// rule (with full and partial sample masks), the outward order, Vulkan's "inside the primitive
// and the pixel" requirement on standard patterns, and a custom pattern whose convex hull
// misses the centre, where D3D11's branch 1 picks a point outside the primitive.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "msaa_support.hpp"
#include "rastrules/msaa.hpp"
#include "support.hpp"

namespace rastrules::test {
namespace {

const SampleOffset kCentre{0, 0};

// Standard 4x: 0 (-2,-6), 1 (6,-2), 2 (-6,2), 3 (2,6); all at the same distance from the
// centre, so the D3D10 outward order is the index order.
const SamplePattern k4 = standard_pattern(4);
// A custom pattern where index order and distance order differ: squared distances 98, 1, 20, 1.
const SamplePattern kSkew = custom_pattern({{7, 7}, {1, 0}, {-4, 2}, {0, -1}});

Centroid d3d11(std::uint32_t c, std::uint32_t m, const SamplePattern& p = k4) {
  return centroid(CentroidRule::kD3D11, c, m, p);
}
Centroid d3d10(std::uint32_t c, std::uint32_t m, const SamplePattern& p = kSkew) {
  return centroid(CentroidRule::kD3D10, c, m, p);
}

// rule: MSAA.CENTROID.D3D11
TEST(CentroidD3D11, Branch1AllSamplesCoveredIsThePixelCentre) {
  EXPECT_EQ(d3d11(0xF, 0xF), (Centroid{kCentre, CentroidBranch::kFullCoverageCenter}));
  // The default mask 0xFFFFFFFF is the full mask.
  EXPECT_EQ(d3d11(0xF, 0xFFFFFFFFu), (Centroid{kCentre, CentroidBranch::kFullCoverageCenter}));
}

// rule: MSAA.CENTROID.D3D11
// The sample mask applies before the centroid: a fully covered pixel under a partial mask is
// not "all samples covered" (branch 1) but takes the first unmasked sample (branch 2). The
// reported case: 4 samples, mask 2: sample 1, at (0.875, 0.375) in the pixel, not the centre
// (earlier the mask was read after branch 1). Multipass supersampling by cycling single-bit
// masks needs exactly this.
TEST(CentroidD3D11, AFullyCoveredPixelUnderAPartialMaskTakesTheFirstUnmaskedSample) {
  EXPECT_EQ(d3d11(0xF, 0b0010), (Centroid{{6, -2}, CentroidBranch::kFirstCovered}));
  for (std::uint32_t k = 0; k < 4; ++k)
    EXPECT_EQ(d3d11(0xF, 1u << k), (Centroid{k4.positions[k], CentroidBranch::kFirstCovered}));
  EXPECT_EQ(d3d11(0xF, 0b0100), (Centroid{{-6, 2}, CentroidBranch::kFirstCovered}));
}

// rule: MSAA.CENTROID.D3D11
TEST(CentroidD3D11, Branch2FirstCoveredSampleInIndexOrderAfterTheMask) {
  EXPECT_EQ(d3d11(0b1010, 0xF), (Centroid{{6, -2}, CentroidBranch::kFirstCovered}));
  // A partial mask removes sample 1: the first covered sample in the mask is 3.
  EXPECT_EQ(d3d11(0b1010, 0b1000), (Centroid{{2, 6}, CentroidBranch::kFirstCovered}));
  // Index order, not distance: in kSkew sample 0 is the farthest.
  EXPECT_EQ(d3d11(0b1001, 0xF, kSkew), (Centroid{{7, 7}, CentroidBranch::kFirstCovered}));
}

// rule: MSAA.CENTROID.D3D11
TEST(CentroidD3D11, Branch3aNothingCoveredPartialMaskIsTheMasksFirstSample) {
  // Covered samples all outside the mask (c & m == 0).
  EXPECT_EQ(d3d11(0b0011, 0b1100), (Centroid{{-6, 2}, CentroidBranch::kNoneCoveredMaskSample}));
  // A helper lane (nothing covered).
  EXPECT_EQ(d3d11(0, 0b0110), (Centroid{{6, -2}, CentroidBranch::kNoneCoveredMaskSample}));
}

// rule: MSAA.CENTROID.D3D11
TEST(CentroidD3D11, Branch3bNothingCoveredFullMaskIsThePixelCentre) {
  EXPECT_EQ(d3d11(0, 0xF), (Centroid{kCentre, CentroidBranch::kNoneCoveredCenter}));
  // m == 0: no sample of the mask to pick, the pixel centre.
  EXPECT_EQ(d3d11(0b0101, 0), (Centroid{kCentre, CentroidBranch::kNoneCoveredCenter}));
}

// rule: MSAA.CENTROID.D3D10
TEST(CentroidD3D10, Branch1FullCoverageAndFullMaskIsThePixelCentre) {
  EXPECT_EQ(d3d10(0xF, 0xF), (Centroid{kCentre, CentroidBranch::kFullCoverageCenter}));
}

// rule: MSAA.CENTROID.D3D10
TEST(CentroidD3D10, FullCoveragePartialMaskIsTheNearestSampleInTheMask) {
  // The mask is applied first: c' = {0, 2}; the nearer is 2 (distance^2 20 < 98). D3D11 takes
  // the first of c' in index order, 0.
  EXPECT_EQ(d3d10(0xF, 0b0101), (Centroid{{-4, 2}, CentroidBranch::kNearestCovered}));
  EXPECT_EQ(d3d11(0xF, 0b0101, kSkew), (Centroid{{7, 7}, CentroidBranch::kFirstCovered}));
}

// rule: MSAA.CENTROID.D3D10
TEST(CentroidD3D10, Branch2aNothingCoveredFullMaskIsThePixelCentre) {
  EXPECT_EQ(d3d10(0, 0xF), (Centroid{kCentre, CentroidBranch::kNoneCoveredCenter}));
  EXPECT_EQ(d3d10(0b0110, 0), (Centroid{kCentre, CentroidBranch::kNoneCoveredCenter}));
}

// rule: MSAA.CENTROID.D3D10
TEST(CentroidD3D10, Branch2bNothingCoveredPartialMaskIsTheMasksNearestSample) {
  // m = {0, 3}: 3 is nearer (1 < 98). D3D11 takes the first in index order, 0.
  EXPECT_EQ(d3d10(0b0110, 0b1001), (Centroid{{0, -1}, CentroidBranch::kNoneCoveredMaskSample}));
  EXPECT_EQ(d3d11(0b0110, 0b1001, kSkew),
            (Centroid{{7, 7}, CentroidBranch::kNoneCoveredMaskSample}));
}

// rule: MSAA.CENTROID.D3D10
TEST(CentroidD3D10, Branch3NearestCoveredSampleMovingOutward) {
  EXPECT_EQ(d3d10(0b1001, 0xF), (Centroid{{0, -1}, CentroidBranch::kNearestCovered}));
  // Equal distances (samples 1 and 3, both 1): the lower index.
  EXPECT_EQ(d3d10(0b1010, 0xF), (Centroid{{1, 0}, CentroidBranch::kNearestCovered}));
  // On a standard pattern where all distances tie, index order.
  EXPECT_EQ(d3d10(0b1100, 0xF, k4), (Centroid{{-6, 2}, CentroidBranch::kNearestCovered}));
}

// rule: MSAA.CENTROID.D3D10
TEST(CentroidD3D10, OutwardOrder) {
  EXPECT_EQ(outward_order(kSkew), (std::vector<std::uint32_t>{1, 3, 2, 0}));
  EXPECT_EQ(outward_order(k4), (std::vector<std::uint32_t>{0, 1, 2, 3}));
  // 16x: squared distances 2, 10, 13, 17, 29, 29, 34, 34, 40, 49, 52, 52, 64, 65, 85, 113.
  std::vector<std::uint32_t> id(16);
  for (std::uint32_t k = 0; k < 16; ++k)
    id[k] = k;
  EXPECT_EQ(outward_order(standard_pattern(16)), id);
}

// rule: MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
TEST(CentroidNames, EveryBranchHasAName) {
  for (const CentroidBranch b :
       {CentroidBranch::kFullCoverageCenter, CentroidBranch::kFirstCovered,
        CentroidBranch::kNearestCovered, CentroidBranch::kNoneCoveredMaskSample,
        CentroidBranch::kNoneCoveredCenter}) {
    EXPECT_NE(to_string(b), "unknown");
  }
  EXPECT_EQ(to_string(static_cast<CentroidBranch>(42)), "unknown");
  EXPECT_EQ(to_string(static_cast<CentroidRule>(42)), "unknown");
}

// rule: MSAA.CENTROID.WITHIN
TEST(CentroidWithin, CustomPatternWhoseHullMissesTheCentre) {
  // All four samples in the pixel's lower-right quarter: (0.75..0.875, 0.75..0.875) in pixel 0.
  const SamplePattern p = custom_pattern({{4, 4}, {6, 4}, {4, 6}, {6, 6}});
  const TriangleSetup t = triangle_px({0.6875, 0.6875}, {3, 0.6875}, {0.6875, 3});
  ASSERT_EQ(sample_coverage(t, 0, 0, p), 0xFu);
  for (const CentroidRule rule : {CentroidRule::kD3D11, CentroidRule::kD3D10}) {
    const Centroid c = centroid(rule, 0xF, 0xF, p);
    EXPECT_EQ(c, (Centroid{kCentre, CentroidBranch::kFullCoverageCenter}));
    // The pixel centre (0.5, 0.5) is outside the triangle: Vulkan's requirement fails here.
    EXPECT_FALSE(covers(t, sample_position(0, 0, c.offset)));
  }
  // The scene reports exactly that point.
  MultisampleState ms = with_pattern(p);
  ms.has_centroid = true;
  const auto f = frags_of(msaa_scene(
      2, 2, ms,
      {prim_px(PrimitiveType::kTriangle, {{0.6875f, 0.6875f}, {3, 0.6875f}, {0.6875f, 3}})}));
  ASSERT_FALSE(f.empty());
  EXPECT_EQ(f[0].x, 0);
  EXPECT_EQ(f[0].y, 0);
  ASSERT_TRUE(f[0].centroid.has_value());
  EXPECT_EQ(f[0].centroid->offset, kCentre);
}

// rule: MSAA.CENTROID.WITHIN
TEST(CentroidWithin, StandardPatternsKeepTheCentroidInsideThePrimitive) {
  // Deterministic pseudo-random triangles on the 1/16 grid around pixel (1, 1): whenever a
  // sample is covered, both rules pick a point the triangle covers (in the pixel by the grid).
  std::uint64_t state = 12345;
  auto next = [&](std::int32_t n) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<std::int32_t>((state >> 33) % static_cast<std::uint64_t>(n));
  };
  int checked = 0;
  for (int i = 0; i < 3000; ++i) {
    std::array<Px, 3> v{};
    for (Px& p : v)
      p = Px{next(64) / 16.0, next(64) / 16.0};
    const TriangleSetup t = triangle_px(v[0], v[1], v[2]);
    for (const std::uint32_t n : {2u, 4u, 8u, 16u}) {
      const SamplePattern pat = i % 2 == 0 ? standard_pattern(n) : center_pattern(n);
      const std::uint32_t c = sample_coverage(t, 1, 1, pat);
      if (c == 0)
        continue;
      for (const std::uint32_t m : {full_mask(n), 0b0101u & full_mask(n)}) {
        if ((c & m) == 0)
          continue;
        for (const CentroidRule rule : {CentroidRule::kD3D11, CentroidRule::kD3D10}) {
          const Centroid ce = centroid(rule, c, m, pat);
          EXPECT_TRUE(covers(t, sample_position(1, 1, ce.offset)))
              << "triangle " << i << " n " << n << " rule " << to_string(rule);
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 1000);
}

} // namespace
} // namespace rastrules::test
