// SPDX-License-Identifier: MIT
// The D3D11.3 multisample rasterization diagram (shared/reference/img/MSAARast.png,
// "Rasterization Examples with > 1 Sample Per Pixel"), reproduced for the primitives whose
// geometry the picture fixes exactly.
//
// Reading the picture: the grid is 8 x 4 pixels, one pixel is 80 picture pixels, the grid's
// top-left corner at picture (3.75, 460). The picture uses "a hypothetical example grid" of
// four samples, the same in every pixel: decoding the dots of pixel (0, 0) gives offsets
// (-3,-5), (5,-3), (-5,3), (3,5) in 1/16 px (a rotated grid, not the standard 4x pattern; the
// picture does not number them, so the index order below is ours). Circles mark covered
// samples, diamonds pixel-frequency shader invocations (our fragments), crosses pixels with
// no invocation.
//
// Top-left triangle: vertices (0.1875, 0.6875), (2.4375, 0.6875), (0.1875, 1.6875) px, all on
// the 1/16 grid. Its top edge runs through sample (-5,3) of pixels (0..2, 0) (circled: top
// edges are inclusive); its first vertex is that sample of pixel (0, 0) (circled); its third
// vertex is sample (-5,3) of pixel (0, 1), not circled (it lies on the excluded long edge);
// sample (-3,-5) of pixel (1, 1) lies exactly on the long edge and is not circled.
//
// The point: centre (4.3125, 0.8125) px, square [3.8125, 4.8125] x [0.3125, 1.3125]. Its
// top-left corner is sample (5,-3) of pixel (3, 0) (circled), its top-right corner sample
// (5,-3) of pixel (4, 0) (not circled), its bottom-left corner sample (5,-3) of pixel (3, 1)
// (not circled). The picture draws a diamond at pixel (3, 1) although no sample of that pixel
// is circled; under the top-left rule the bottom-left corner is on two excluded edges, so the
// kernel (and the picture's own circles) give pixel (3, 1) no coverage and no fragment.
//
// The second point: its square is exactly pixel (2, 2) (centre (2.5, 2.5)): all four samples
// circled, one diamond.
//
// The triangle of pixels (0..1, 2): vertices read as (0.1875, 2.375), (1.6875, 2.375),
// (0.25, 3.0) px (to +-0.01 px). It holds no sample (no circle, no diamond), although it holds
// the centre (cross) of pixel (0, 2): sample (-5,3) of
// pixel (0, 2) is left of its steep left edge, and sample (3,5) of pixel (0, 2),
// (0.6875, 2.8125), lies just below its long edge (by 0.0027 px at this reading). It shows that
// a primitive can cross pixels without covering any of their samples.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "msaa_support.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::test {
namespace {

// Sample indices in our order of the picture's pattern.
constexpr std::uint32_t kA = 1u << 0; // (-3,-5)
constexpr std::uint32_t kB = 1u << 1; // (5,-3)
constexpr std::uint32_t kC = 1u << 2; // (-5,3)
constexpr std::uint32_t kD = 1u << 3; // (3,5)

SamplePattern picture_pattern() {
  return custom_pattern({{-3, -5}, {5, -3}, {-5, 3}, {3, 5}});
}

// rule: MSAA.COVER.SAMPLE, MSAA.SHADING.PIXEL
TEST(MSAARastDiagram, TopLeftTriangle) {
  const Scene s =
      msaa_scene(8, 4, with_pattern(picture_pattern()),
                 {prim_px(PrimitiveType::kTriangle,
                          {{0.1875f, 0.6875f}, {2.4375f, 0.6875f}, {0.1875f, 1.6875f}})});
  // Circles per pixel; diamonds at exactly these four pixels; crosses at (1, 1) and (2, 1).
  const MaskMap want = {{{0, 0}, kC | kD}, {{1, 0}, kC | kD}, {{2, 0}, kC}, {{0, 1}, kA | kB}};
  EXPECT_EQ(masks_of(frags_of(s)), want);
}

// rule: MSAA.POINT.PER_SAMPLE, MSAA.SHADING.PIXEL
TEST(MSAARastDiagram, Point) {
  const Scene s = msaa_scene(8, 4, with_pattern(picture_pattern()),
                             {prim_px(PrimitiveType::kPoint, {{4.3125f, 0.8125f}})});
  const MaskMap want = {{{3, 0}, kB}, {{4, 0}, kC | kD}, {{4, 1}, kA}};
  EXPECT_EQ(masks_of(frags_of(s)), want);
}

// rule: MSAA.POINT.PER_SAMPLE
TEST(MSAARastDiagram, PointFillingAPixel) {
  const Scene s = msaa_scene(8, 4, with_pattern(picture_pattern()),
                             {prim_px(PrimitiveType::kPoint, {{2.5f, 2.5f}})});
  EXPECT_EQ(masks_of(frags_of(s)), (MaskMap{{{2, 2}, kA | kB | kC | kD}}));
}

// rule: MSAA.COVER.SAMPLE
TEST(MSAARastDiagram, TriangleBetweenTheSamples) {
  const Scene s = msaa_scene(
      8, 4, with_pattern(picture_pattern()),
      {prim_px(PrimitiveType::kTriangle, {{0.1875f, 2.375f}, {1.6875f, 2.375f}, {0.25f, 3.0f}})});
  EXPECT_TRUE(frags_of(s).empty());
  // Its interior does hold the centre of pixel (0, 2) (the picture's cross lies inside it):
  // with the centre pattern that pixel would be fully covered. The sample pattern decides.
  EXPECT_EQ(masks_of(frags_of(msaa_scene(8, 4, with_pattern(center_pattern(4)), s.primitives))),
            (MaskMap{{{0, 2}, 0xF}}));
}

// rule: MSAA.SHADING.SAMPLE
TEST(MSAARastDiagram, SampleFrequencyRunsOncePerCircle) {
  // "When Sample-Frequency PS execution has been requested, a Pixel Shader invocation occurs
  // here" (at each circle): 7 circles for the triangle.
  MultisampleState ms = with_pattern(picture_pattern());
  ms.shading = ShadingRate::kSample;
  const Scene s =
      msaa_scene(8, 4, ms,
                 {prim_px(PrimitiveType::kTriangle,
                          {{0.1875f, 0.6875f}, {2.4375f, 0.6875f}, {0.1875f, 1.6875f}})});
  const std::vector<Fragment> f = frags_of(s);
  ASSERT_EQ(f.size(), 7u);
  for (const Fragment& fr : f) {
    ASSERT_TRUE(fr.sample.has_value());
    EXPECT_EQ(fr.mask, 1u << *fr.sample);
  }
}

} // namespace
} // namespace rastrules::test
