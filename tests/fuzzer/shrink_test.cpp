// SPDX-License-Identifier: MIT
// Shrinking and generation are deterministic; shrinking keeps the mismatch and removes what
// does not matter.

#include <gtest/gtest.h>

#include <set>

#include "rastrules/driver/driver.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"
#include "rastrules/io/scene_json.hpp"

namespace rastrules::fuzzer {
namespace {

// rule: FUZZ.GENERATE, FUZZ.PROFILE
TEST(Generate, SameSeedAndIndexGiveTheSameSceneWhateverElseWasDrawn) {
  std::string err;
  auto d = driver::open_driver("reference", &err);
  ASSERT_NE(d, nullptr) << err;
  auto a = generate_case(42, 17, Profile::kVulkan, *d);
  (void)generate_case(42, 3, Profile::kVulkan, *d);
  auto b = generate_case(42, 17, Profile::kVulkan, *d);
  auto c = generate_case(43, 17, Profile::kVulkan, *d);
  ASSERT_TRUE(a && b && c);
  EXPECT_EQ(io::write_scene(a->scene), io::write_scene(b->scene));
  EXPECT_NE(io::write_scene(a->scene), io::write_scene(c->scene));
  EXPECT_EQ(a->scene.conventions.line_mode, LineMode::kVulkanBresenham);
  EXPECT_EQ(a->scene.conventions.fill, FillConvention::kTopLeft);
}

// rule: FUZZ.GENERATE
TEST(Generate, FamiliesTheDriverCannotDrawAreNotGenerated) {
  std::string err;
  auto d = driver::open_driver("imprecise", &err);
  ASSERT_NE(d, nullptr) << err;
  std::set<std::string> families;
  for (std::uint64_t i = 0; i < 200; ++i) {
    auto c = generate_case(5, i, Profile::kD3D11, *d);
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(d->unsupported(c->scene), "");
    families.insert(c->family);
  }
  EXPECT_EQ(families.count("points"), 0u);
  EXPECT_EQ(families.count("lines"), 0u);
  EXPECT_EQ(families, (std::set<std::string>{"random", "shared-edge", "fan", "grid", "sliver"}));
}

// rule: FUZZ.SHRINK
TEST(Shrink, KeepsTheMismatchDropsUnrelatedPrimitivesAndIsDeterministic) {
  // A predicate standing for a driver bug: "some triangle has a vertex at x >= 5".
  const auto differs = [](const Scene& s) {
    for (const Primitive& p : s.primitives) {
      for (const FloatPoint& v : p.v) {
        if (v[0] >= 5.0f)
          return true;
      }
    }
    return false;
  };
  Scene s;
  s.width = 12;
  s.height = 9;
  s.primitives.push_back(
      make_triangle({FloatPoint{1.5f, 2.25f}, FloatPoint{3.0f, 7.125f}, FloatPoint{2.0f, 1.0f}}));
  s.primitives.push_back(make_triangle(
      {FloatPoint{7.3359375f, 3.5f}, FloatPoint{9.0f, 8.75f}, FloatPoint{6.5f, 4.0f}}));
  s.primitives.push_back(
      make_triangle({FloatPoint{0.5f, 0.5f}, FloatPoint{1.0f, 3.0f}, FloatPoint{2.0f, 2.0f}}));
  const Scene a = shrink(s, differs);
  const Scene b = shrink(s, differs);
  EXPECT_EQ(io::write_scene(a), io::write_scene(b));
  ASSERT_EQ(a.primitives.size(), 1u);
  EXPECT_TRUE(differs(a));
  // The one coordinate that matters went to the simplest value keeping x >= 5: 5 itself; all
  // the others to 0; the target to 1x1.
  int fives = 0;
  for (const FloatPoint& v : a.primitives[0].v) {
    for (const float c : v) {
      EXPECT_TRUE(c == 0.0f || c == 5.0f) << io::write_scene(a);
      fives += c == 5.0f ? 1 : 0;
    }
  }
  EXPECT_EQ(fives, 1);
  EXPECT_EQ(a.width, 1);
  EXPECT_EQ(a.height, 1);
}

} // namespace
} // namespace rastrules::fuzzer
