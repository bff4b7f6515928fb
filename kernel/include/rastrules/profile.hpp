// SPDX-License-Identifier: MIT
// Profiles (spec/rules/profile.md): the constexpr profiles d3d11, vulkan and opengl, each one
// Conventions value (rastrules/conventions.hpp), and apply(), which gives a scene a profile's
// conventions.
// Implements: PROFILE.CONVENTIONS, PROFILE.D3D11, PROFILE.VULKAN, PROFILE.OPENGL
#pragma once

#include "rastrules/conventions.hpp"
#include "rastrules/names.hpp"
#include "rastrules/pipeline.hpp"
#include "rastrules/scene.hpp"

namespace rastrules {

enum class ProfileName { kD3D11, kVulkan, kOpenGL };
template <> struct Names<ProfileName> {
  static constexpr NameTable<3, ProfileName> table{{{"d3d11", ProfileName::kD3D11},
                                                    {"vulkan", ProfileName::kVulkan},
                                                    {"opengl", ProfileName::kOpenGL}}};
};

// Returns the conventions of a profile.
// rule: PROFILE.D3D11, PROFILE.VULKAN, PROFILE.OPENGL
[[nodiscard]] constexpr Conventions profile(ProfileName p) {
  Conventions c; // d3d11 (PROFILE.D3D11)
  if (p == ProfileName::kVulkan) {
    c.front_face = FrontFace::kCounterClockwise;
    c.line_mode = LineMode::kVulkanBresenham;
    c.depth = pipe::DepthFormat::kD32F;
  } else if (p == ProfileName::kOpenGL) {
    c.line_mode = LineMode::kVulkanBresenham;
    c.provoking = pipe::Provoking::kLast;
  }
  return c;
}

// Sets the conventions of a scene to c (scene.conventions = c) and makes its sample pattern
// follow c.pattern: the centre pattern of the scene's sample count for kCenter, the standard
// one for kStandard unless the scene's pattern is custom (a custom pattern is left alone, and
// conventions.pattern then stays kCustom).
// rule: PROFILE.CONVENTIONS
void apply(const Conventions& c, Scene& scene);

} // namespace rastrules
