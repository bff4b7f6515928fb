// SPDX-License-Identifier: MIT
// The conventions a rasterizer must choose, as one value (spec/rules/profile.md). A Scene holds
// one (Scene::conventions); rastrules/profile.hpp gives the constexpr profiles d3d11, vulkan
// and opengl. Not fields, because they are not choices here: the subpixel precision is the
// fixed 16.8 of SNAP.VERTEX.FORMAT (kSubpixelBits, the precision every proof is written for)
// with round-half-to-even snapping, and window coordinates are y-down with pixel centres at
// +0.5 (COORD.PIXEL.*).
// Implements: PROFILE.CONVENTIONS
#pragma once

#include "rastrules/fixed.hpp"
#include "rastrules/line.hpp"
#include "rastrules/msaa.hpp"
#include "rastrules/pipe_state.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules {

// Each field cites the rule it chooses for. In a scene, `pattern` is the kind of
// msaa.pattern (standard, center or custom: validate() and prepare() reject a scene where they
// differ), `centroid` applies when the scene asks for centroids, and `depth` when it has a
// depth state.
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

} // namespace rastrules
