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
TEST(Profile, ApplyGivesTheSceneTheProfile) {
  for (const auto& [word, name] : Names<ProfileName>::table) {
    Scene s;
    apply(profile(name), s);
    EXPECT_EQ(s.conventions, profile(name)) << word;
    EXPECT_FALSE(has_pipeline_state(s)) << word; // a convention asks for no stage
  }
  // The sample pattern's kind follows the profile, keeping the sample count.
  Scene s;
  set_sample_pattern(s, standard_pattern(4));
  Conventions c;
  c.pattern = PatternKind::kCenter;
  apply(c, s);
  EXPECT_EQ(s.msaa.pattern.kind, PatternKind::kCenter);
  EXPECT_EQ(s.msaa.count(), 4u);
  EXPECT_EQ(s.conventions.pattern, PatternKind::kCenter);
  // A custom pattern is left alone, and the conventions say so.
  set_sample_pattern(s, custom_pattern({{1, 2}, {-3, 4}}));
  apply(profile(ProfileName::kVulkan), s);
  EXPECT_EQ(s.msaa.pattern.kind, PatternKind::kCustom);
  EXPECT_EQ(s.conventions.pattern, PatternKind::kCustom);
  EXPECT_EQ(s.conventions.front_face, FrontFace::kCounterClockwise);
}

// rule: PROFILE.CONVENTIONS
TEST(Profile, APatternOfAnotherKindThanTheConventionsNameIsRejected) {
  Scene s;
  s.width = s.height = 4;
  s.msaa.pattern = center_pattern(4); // conventions.pattern still says "standard"
  const auto r = prepare(s);
  ASSERT_TRUE(std::holds_alternative<SceneError>(r));
  EXPECT_EQ(std::get<SceneError>(r).what(),
            "sample_pattern: is a \"center\" pattern but conventions.pattern is \"standard\"");
  set_sample_pattern(s, center_pattern(4));
  EXPECT_TRUE(std::holds_alternative<PreparedScene>(prepare(s)));
}

// The pipeline reads the provoking vertex and the depth format from the one Conventions value.
// rule: PROFILE.CONVENTIONS, PIPE.INTERP.FLAT, PIPE.DEPTH.FORMAT
TEST(Profile, ThePipelineReadsItsConventionsFromTheScene) {
  Scene s;
  s.width = s.height = 4;
  s.attributes = {pipe::AttributeDecl{"k", pipe::Interpolation::kFlat, pipe::Location::kCenter}};
  s.depth = pipe::DepthState{};
  s.depth->func = pipe::CompareFunc::kAlways;
  Primitive t = make_triangle({FloatPoint{0, 0}, FloatPoint{4, 0}, FloatPoint{0, 4}});
  t.z = {0.25f, 0.25f, 0.25f};
  t.attr = {{1.0f}, {2.0f}, {3.0f}};
  s.primitives.push_back(t);
  const auto first = [](const Scene& scene) {
    auto r = pipe::run_pipeline(scene);
    EXPECT_TRUE(std::holds_alternative<pipe::PipeResult>(r));
    return std::get<pipe::PipeResult>(std::move(r)).data.at(0);
  };
  const pipe::FragmentData d3d11 = first(s);
  EXPECT_EQ(d3d11.attr.at(0), 1.0f);
  EXPECT_EQ(d3d11.depth.at(0).unorm, 4194304u);  // d24: 0.25 * (2^24 - 1), rounded
  s.conventions = profile(ProfileName::kOpenGL); // provoking vertex last
  EXPECT_EQ(first(s).attr.at(0), 3.0f);
  s.conventions = profile(ProfileName::kVulkan); // d32f: 0.25 is stored as the float
  EXPECT_EQ(first(s).depth.at(0).f, 0.25f);
}

// rule: PROFILE.D3D11, PROFILE.VULKAN, TRI.CULL.MODE
TEST(Profile, TheFrontFaceDecidesWhatBackFaceCullingRemoves) {
  Scene s;
  s.width = s.height = 4;
  s.cull = CullMode::kBack;
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
