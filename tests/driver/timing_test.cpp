// SPDX-License-Identifier: MIT
// Examples for BENCH.LAVAPIPE: lavapipe's coverage-only timing counts, with its occlusion query,
// exactly the samples the reference covers on scenes without ties (no pixel centre on an
// edge, so every correct rasterizer agrees), honours the repeats, and answers "not available"
// with a reason for scenes it does not time (lines, points, multisampling, bad input). The
// tests that need lavapipe skip only when no CPU Vulkan device exists.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "rastrules/driver/driver.hpp"
#include "rastrules/driver/timing.hpp"
#include "rastrules/scene.hpp"

namespace rastrules::driver {
namespace {

// Whether lavapipe can be opened at all (the adapter's own check), else the reason.
std::string lavapipe_missing() {
  std::string error;
  const std::unique_ptr<Driver> d = open_driver("lavapipe", &error);
  return d ? std::string() : (error.empty() ? std::string("lavapipe not built") : error);
}

#define RASTRULES_NEED_LAVAPIPE()                                                                  \
  if (const std::string missing = lavapipe_missing(); !missing.empty())                            \
  GTEST_SKIP() << "no CPU Vulkan device: " << missing

// Twice the edge function of (a, b) at p, all in 1/256 px (exact in 64 bits here).
std::int64_t edge(const std::array<std::int64_t, 2>& a, const std::array<std::int64_t, 2>& b,
                  const std::array<std::int64_t, 2>& p) {
  return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
}

// `n` random triangles of several sizes in a w x h target, vertices on the 1/256 grid (exact
// in float32, so snapping changes nothing), none degenerate, and none with a pixel centre on
// one of its edges (checked exactly over the bounding box), some partly outside the target.
Scene tie_free_scene(int w, int h, int n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  Scene s;
  s.width = w;
  s.height = h;
  while (static_cast<int>(s.primitives.size()) < n) {
    const std::int64_t size = std::array<std::int64_t, 3>{3, 12, 40}[rng() % 3] * 256;
    std::uniform_int_distribution<std::int64_t> cx(-4 * 256, std::int64_t{w + 4} * 256);
    std::uniform_int_distribution<std::int64_t> cy(-4 * 256, std::int64_t{h + 4} * 256);
    std::uniform_int_distribution<std::int64_t> d(-size, size);
    const std::int64_t ox = cx(rng), oy = cy(rng);
    std::array<std::array<std::int64_t, 2>, 3> v{};
    for (auto& p : v)
      p = {ox + d(rng), oy + d(rng)};
    if (edge(v[0], v[1], v[2]) == 0)
      continue;
    bool tie = false;
    std::int64_t x0 = std::min({v[0][0], v[1][0], v[2][0]}) / 256 - 1;
    std::int64_t x1 = std::max({v[0][0], v[1][0], v[2][0]}) / 256 + 1;
    std::int64_t y0 = std::min({v[0][1], v[1][1], v[2][1]}) / 256 - 1;
    std::int64_t y1 = std::max({v[0][1], v[1][1], v[2][1]}) / 256 + 1;
    for (std::int64_t y = y0; y <= y1 && !tie; ++y) {
      for (std::int64_t x = x0; x <= x1 && !tie; ++x) {
        const std::array<std::int64_t, 2> c{x * 256 + 128, y * 256 + 128};
        tie = edge(v[0], v[1], c) == 0 || edge(v[1], v[2], c) == 0 || edge(v[2], v[0], c) == 0;
      }
    }
    if (tie)
      continue;
    std::array<FloatPoint, 3> f{};
    for (std::size_t i = 0; i < 3; ++i) {
      f[i] = {static_cast<float>(v[i][0]) / 256.0F, static_cast<float>(v[i][1]) / 256.0F};
    }
    s.primitives.push_back(make_triangle(f));
  }
  return s;
}

// The reference's covered samples: one per fragment (single sample, overlaps counted twice).
std::uint64_t reference_count(const Scene& s) {
  const auto r = render(s);
  if (const auto* e = std::get_if<SceneError>(&r)) {
    ADD_FAILURE() << e->what();
    return 0;
  }
  return std::get<std::vector<Fragment>>(r).size();
}

// rule: BENCH.LAVAPIPE
TEST(LavapipeTiming, OcclusionCountEqualsTheReferenceOnTieFreeScenes) {
  RASTRULES_NEED_LAVAPIPE();
  for (const std::uint32_t seed : {1U, 2U, 3U}) {
    Scene s = tie_free_scene(96, 80, 300, seed);
    for (const CullMode cull : {CullMode::kNone, CullMode::kBack, CullMode::kFront}) {
      s.cull = cull;
      const std::uint64_t want = reference_count(s);
      ASSERT_GT(want, 1000U);
      const CoverageTiming t = time_lavapipe_coverage(s, 3);
      ASSERT_TRUE(t.available) << t.why_not;
      EXPECT_TRUE(t.why_not.empty());
      EXPECT_EQ(t.samples_passed, want) << "seed " << seed << ", cull " << to_string(cull);
      EXPECT_EQ(t.repeats, 3);
      EXPECT_GT(t.seconds_min, 0.0);
      EXPECT_LE(t.seconds_min, t.seconds_median);
      EXPECT_NE(t.device.find("llvmpipe"), std::string::npos) << t.device;
      EXPECT_FALSE(t.includes.empty());
      EXPECT_EQ(t.includes.find('\n'), std::string::npos) << t.includes;
    }
  }
}

// rule: BENCH.LAVAPIPE
TEST(LavapipeTiming, ALargeTargetKeepsPositionsExact) {
  RASTRULES_NEED_LAVAPIPE();
  // A large target (K = 2048) with small triangles: the viewport scale keeps them exact.
  const Scene s = tie_free_scene(1500, 40, 200, 7);
  const CoverageTiming t = time_lavapipe_coverage(s, 1);
  ASSERT_TRUE(t.available) << t.why_not;
  EXPECT_EQ(t.samples_passed, reference_count(s));
}

// rule: BENCH.LAVAPIPE
TEST(LavapipeTiming, RepeatsAreHonoured) {
  RASTRULES_NEED_LAVAPIPE();
  const Scene s = tie_free_scene(32, 32, 20, 4);
  for (const int repeats : {1, 2, 7}) {
    const CoverageTiming t = time_lavapipe_coverage(s, repeats);
    ASSERT_TRUE(t.available) << t.why_not;
    EXPECT_EQ(t.repeats, repeats);
    EXPECT_LE(t.seconds_min, t.seconds_median);
    if (repeats == 1) {
      EXPECT_EQ(t.seconds_min, t.seconds_median);
    }
  }
  // An empty scene draws nothing and counts nothing.
  Scene empty;
  empty.width = 8;
  empty.height = 8;
  const CoverageTiming t = time_lavapipe_coverage(empty, 2);
  ASSERT_TRUE(t.available) << t.why_not;
  EXPECT_EQ(t.samples_passed, 0U);
}

// rule: BENCH.LAVAPIPE
TEST(LavapipeTiming, ScenesItDoesNotTimeAreNotAvailableWithAReason) {
  // Checked before lavapipe is opened: these hold with or without it.
  auto expect_refused = [](const Scene& s, int repeats, const std::string& why) {
    const CoverageTiming t = time_lavapipe_coverage(s, repeats);
    EXPECT_FALSE(t.available);
    EXPECT_NE(t.why_not.find(why), std::string::npos)
        << "expected \"" << why << "\" in: " << t.why_not;
    EXPECT_EQ(t.samples_passed, 0U);
  };
  Scene lines = tie_free_scene(16, 16, 3, 5);
  Primitive line;
  line.type = PrimitiveType::kLine;
  line.v = {{1.5F, 1.25F}, {12.0F, 9.0F}};
  lines.primitives.push_back(line);
  expect_refused(lines, 3, "primitives[3] is a line");
  Scene points = tie_free_scene(16, 16, 1, 5);
  Primitive point;
  point.type = PrimitiveType::kPoint;
  point.v = {{3.0F, 3.0F}};
  points.primitives.insert(points.primitives.begin(), point);
  expect_refused(points, 3, "primitives[0] is a point");
  Scene msaa = tie_free_scene(16, 16, 3, 6);
  set_sample_pattern(msaa, standard_pattern(4));
  expect_refused(msaa, 3, "single-sample only");
  Scene fill = tie_free_scene(16, 16, 3, 6);
  fill.conventions.fill = FillConvention::kBottomRight;
  expect_refused(fill, 3, "fill convention bottom-right");
  Scene nan = tie_free_scene(16, 16, 3, 6);
  nan.primitives[1].v[2][1] = std::numeric_limits<float>::quiet_NaN();
  expect_refused(nan, 3, "invalid scene: primitives[1].v[2][1]: is NaN");
  expect_refused(tie_free_scene(16, 16, 3, 6), 0, "repeats must be at least 1");
}

} // namespace
} // namespace rastrules::driver
