// SPDX-License-Identifier: MIT
// Profiles (spec/rules/profile.md): each profile's conventions as the spec lists them, applied
// to and read back from scenes, and what they change in coverage.

#include <gtest/gtest.h>

#include <variant>
#include <vector>

#include "rastrules/profile.hpp"

namespace rastrules {
namespace {

// rule: PROFILE.CONVENTIONS, PROFILE.D3D11, PROFILE.VULKAN, PROFILE.OPENGL
TEST(Profile, EachProfileHasTheConventionsTheSpecLists) {
  const Conventions d3d11 = profile(ProfileName::kD3D11);
  EXPECT_EQ(d3d11, Conventions{}); // the kernel's defaults are D3D11's
  EXPECT_EQ(d3d11.front_face, FrontFace::kClockwise);
  EXPECT_EQ(d3d11.line_mode, LineMode::kD3DDiamond);
  EXPECT_EQ(d3d11.depth, pipe::DepthFormat::kD24);
  const Conventions vulkan = profile(ProfileName::kVulkan);
  EXPECT_EQ(vulkan.fill, FillConvention::kTopLeft);
  EXPECT_EQ(vulkan.front_face, FrontFace::kCounterClockwise);
  EXPECT_EQ(vulkan.line_mode, LineMode::kVulkanBresenham);
  EXPECT_EQ(vulkan.provoking, pipe::Provoking::kFirst);
  EXPECT_EQ(vulkan.depth, pipe::DepthFormat::kD32F);
  const Conventions opengl = profile(ProfileName::kOpenGL);
  EXPECT_EQ(opengl.front_face, FrontFace::kClockwise); // GL_CCW in a y-up window
  EXPECT_EQ(opengl.line_mode, LineMode::kVulkanBresenham);
  EXPECT_EQ(opengl.provoking, pipe::Provoking::kLast);
  EXPECT_EQ(Conventions::kSubpixelBits, 8);
  EXPECT_EQ(from_name<ProfileName>("opengl"), ProfileName::kOpenGL);
  EXPECT_EQ(name_of(ProfileName::kVulkan), "vulkan");
}

// rule: PROFILE.CONVENTIONS
TEST(Profile, ApplyThenReadGivesTheProfileBack) {
  for (const auto& [word, name] : Names<ProfileName>::table) {
    Scene s;
    apply(profile(name), s);
    Conventions want = profile(name);
    want.depth = pipe::DepthFormat::kD24; // a scene without a depth state has no depth format
    EXPECT_EQ(conventions_of(s), want) << word;
    EXPECT_FALSE(has_pipeline_state(s)) << word; // a convention asks for no stage
    rastrules::Scene ps;
    ps.depth = pipe::DepthState{};
    apply(profile(name), ps);
    EXPECT_EQ(conventions_of(ps), profile(name)) << word;
  }
  // The sample pattern's kind follows the profile, keeping the sample count.
  Scene s;
  s.msaa.pattern = standard_pattern(4);
  Conventions c;
  c.pattern = PatternKind::kCenter;
  apply(c, s);
  EXPECT_EQ(s.msaa.pattern.kind, PatternKind::kCenter);
  EXPECT_EQ(s.msaa.count(), 4u);
}

// rule: PROFILE.D3D11, PROFILE.VULKAN, TRI.CULL.MODE
TEST(Profile, TheFrontFaceDecidesWhatBackFaceCullingRemoves) {
  Scene s;
  s.width = s.height = 4;
  s.state.cull = CullMode::kBack;
  // Clockwise on screen (y down): front under d3d11, back under vulkan.
  s.primitives.push_back(make_triangle({FloatPoint{0, 0}, FloatPoint{4, 0}, FloatPoint{0, 4}}));
  const auto count = [&](ProfileName p) {
    Scene t = s;
    apply(profile(p), t);
    const auto r = render(t);
    return std::get<std::vector<Fragment>>(r).size();
  };
  EXPECT_GT(count(ProfileName::kD3D11), 0u);
  EXPECT_EQ(count(ProfileName::kVulkan), 0u);
  EXPECT_EQ(count(ProfileName::kOpenGL), count(ProfileName::kD3D11));
}

} // namespace
} // namespace rastrules
