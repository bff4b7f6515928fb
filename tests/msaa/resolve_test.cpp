// SPDX-License-Identifier: MIT
// Examples for resolve: exact averages rounded half to even, primitives written in fragment
// order over the clear colour, helpers writing nothing, and the size limit.

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "msaa_support.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::test {
namespace {

Rgba8 grey(std::uint8_t v) {
  return Rgba8{v, v, v, v};
}

// rule: MSAA.RESOLVE.AVERAGE
TEST(ResolveAverage, RoundsHalfToEven) {
  EXPECT_EQ(resolve_pixel({grey(1), grey(2)}), grey(2));                   // 1.5 -> 2
  EXPECT_EQ(resolve_pixel({grey(2), grey(3)}), grey(2));                   // 2.5 -> 2
  EXPECT_EQ(resolve_pixel({grey(0), grey(0), grey(0), grey(1)}), grey(0)); // 0.25
  EXPECT_EQ(resolve_pixel({grey(0), grey(0), grey(1), grey(1)}), grey(0)); // 0.5 -> 0
  EXPECT_EQ(resolve_pixel({grey(0), grey(1), grey(1), grey(1)}), grey(1)); // 0.75
  EXPECT_EQ(resolve_pixel({grey(1), grey(1), grey(2), grey(2)}), grey(2)); // 1.5 -> 2
  EXPECT_EQ(resolve_pixel({grey(255), grey(0)}), grey(128));               // 127.5 -> 128
  EXPECT_EQ(resolve_pixel({grey(254), grey(255)}), grey(254));             // 254.5 -> 254
  // Channels are independent; a non-power-of-two count (custom pattern of 3): 1/3, 2/3.
  EXPECT_EQ(resolve_pixel({Rgba8{0, 255, 1, 9}, Rgba8{0, 0, 0, 9}, Rgba8{1, 0, 1, 9}}),
            (Rgba8{0, 85, 1, 9}));
  EXPECT_EQ(resolve_pixel({Rgba8{1, 2, 0, 0}, Rgba8{1, 2, 0, 0}, Rgba8{0, 0, 0, 0}}),
            (Rgba8{1, 1, 0, 0}));
  EXPECT_EQ(resolve_pixel({grey(77)}), grey(77));
}

// rule: MSAA.RESOLVE.AVERAGE
TEST(ResolveAverage, WritesColoursInFragmentOrderOverTheClearColour) {
  MultisampleState ms = with_pattern(standard_pattern(4));
  ms.quads = true; // helpers must not write
  Primitive a = prim_px(PrimitiveType::kTriangle, {{0, 0}, {3, 0}, {0, 3}});
  a.color = {255, 0, 0, 255};
  Primitive b = prim_px(PrimitiveType::kPoint, {{1, 1}}); // one sample of each of 4 pixels
  b.color = {0, 0, 255, 255};
  Scene s = msaa_scene(4, 4, ms, {a, b});
  s.clear_color = {0, 0, 0, 0};
  auto prepared = prepare(s);
  const PreparedScene& ps = std::get<PreparedScene>(prepared);
  const auto frags = rasterize(ps);
  auto r = resolve(ps, frags);
  ASSERT_TRUE(std::holds_alternative<ResolvedImage>(r));
  const ResolvedImage& img = std::get<ResolvedImage>(r);
  ASSERT_EQ(img.pixels.size(), 16u);
  auto at = [&](int x, int y) { return img.pixels[static_cast<std::size_t>(y * 4 + x)]; };
  // (0, 0): red on all 4, then blue on sample 3: (191.25, 0, 63.75, 255).
  EXPECT_EQ(at(0, 0), (Rgba8{191, 0, 64, 255}));
  // (1, 1): red on samples 0, 2, then blue on sample 0; samples 1, 3 clear:
  // red 63.75, blue 63.75, alpha 127.5 -> 128 (half to even).
  EXPECT_EQ(at(1, 1), (Rgba8{64, 0, 64, 128}));
  // (2, 0): red on samples 0 and 2: 127.5 -> 128.
  EXPECT_EQ(at(2, 0), (Rgba8{128, 0, 0, 128}));
  // Helper lanes of the red triangle, e.g. (3, 0), write nothing: the clear colour.
  EXPECT_EQ(at(3, 0), (Rgba8{0, 0, 0, 0}));
  EXPECT_EQ(at(3, 3), (Rgba8{0, 0, 0, 0}));
}

// rule: MSAA.RESOLVE.AVERAGE, MSAA.LIMITS
TEST(ResolveAverage, RejectsTargetsBeyondTheSampleBudget) {
  Scene s = msaa_scene(8192, 8192, with_pattern(standard_pattern(2)), {});
  auto prepared = prepare(s);
  ASSERT_TRUE(std::holds_alternative<PreparedScene>(prepared));
  auto r = resolve(std::get<PreparedScene>(prepared), {});
  ASSERT_TRUE(std::holds_alternative<SceneError>(r));
  EXPECT_EQ(std::get<SceneError>(r).field, "target");
  // The one wording of the limit, the command line's too (after "--resolve: ").
  EXPECT_EQ(std::get<SceneError>(r).message,
            "the 8192x8192 target with 2 samples has 134217728 samples, more than 67108864 "
            "(limit MSAA.LIMITS)");
  EXPECT_EQ(resolve_size_problem(4096, 4096, 4), std::nullopt);
  EXPECT_EQ(resolve_size_problem(0, 4, 1),
            "the 0x4 target with 1 samples has 0 samples, none to resolve (limit MSAA.LIMITS)");
  // Just above the budget: 4097 x 4096 x 4 = 2^26 + 2^14.
  auto pt = prepare(msaa_scene(4097, 4096, with_pattern(standard_pattern(4)), {}));
  EXPECT_TRUE(std::holds_alternative<SceneError>(resolve(std::get<PreparedScene>(pt), {})));
  // A fragment naming a pixel outside the scene is an error, not a crash.
  auto small = prepare(msaa_scene(2, 2, MultisampleState{}, {}));
  auto bad = resolve(std::get<PreparedScene>(small), {Fragment{0, 5, 0, 1u}});
  ASSERT_TRUE(std::holds_alternative<SceneError>(bad));
  EXPECT_EQ(std::get<SceneError>(bad).field, "fragments[0]");
}

} // namespace
} // namespace rastrules::test
