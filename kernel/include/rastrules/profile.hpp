// SPDX-License-Identifier: MIT
// Profiles (spec/rules/profile.md): every convention a rasterizer must choose, as one value,
// and the constexpr profiles d3d11, vulkan and opengl. Not fields, because they are not
// choices here: the subpixel precision is the fixed 16.8 of SNAP.VERTEX.FORMAT (kSubpixelBits,
// the precision every proof is written for) with round-half-to-even snapping, and window
// coordinates are y-down with pixel centres at +0.5 (COORD.PIXEL.*).
// Implements: PROFILE.CONVENTIONS, PROFILE.D3D11, PROFILE.VULKAN, PROFILE.OPENGL
#pragma once

#include "rastrules/fixed.hpp"
#include "rastrules/line.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/names.hpp"
#include "rastrules/pipeline.hpp"
#include "rastrules/scene.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules {

// rule: PROFILE.CONVENTIONS
struct Conventions {
  FillConvention fill = FillConvention::kTopLeft; // TRI.FILL.CONVENTION
  FrontFace front_face = FrontFace::kClockwise;   // TRI.CULL.MODE
  LineMode line_mode = LineMode::kD3DDiamond;     // SCENE.LINE_MODE
  PatternKind pattern = PatternKind::kStandard;   // MSAA.PATTERN.STANDARD
  CentroidRule centroid = CentroidRule::kD3D11;   // MSAA.CENTROID.*
  bool multisample_enable = false; // MSAA.LINE.MODE: D3D's MultisampleEnable, D3D11's default
  pipe::Provoking provoking = pipe::Provoking::kFirst;           // PIPE.INTERP.FLAT
  pipe::DepthFormat depth = pipe::DepthFormat::kD24;             // PIPE.DEPTH.FORMAT
  static constexpr int kSubpixelBits = rastrules::kSubpixelBits; // fixed: SNAP.VERTEX.FORMAT
  friend constexpr bool operator==(const Conventions&, const Conventions&) = default;
};

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

// Sets the conventions on a scene: raster state, line mode, centroid rule, the sample pattern's
// kind (a standard pattern or the centre pattern of the scene's sample count; a custom pattern
// is left alone when the profile says standard), the provoking vertex and, when the scene has a
// depth state, the depth format.
// rule: PROFILE.CONVENTIONS
void apply(const Conventions& c, Scene& scene);

// Returns the conventions a scene follows (depth d24 for a scene without a depth state).
[[nodiscard]] Conventions conventions_of(const Scene& scene);

} // namespace rastrules
