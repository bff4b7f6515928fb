// SPDX-License-Identifier: MIT
// Points: a one-pixel square centred on the snapped position, rasterized as two triangles in
// a Z pattern under the triangle rules, never culled.
// Implements: POINT.* (spec/rules/point.md)

#pragma once

#include <array>
#include <cstdint>

#include "rastrules/fixed.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules {

// Snapped point centres must leave room for the half-pixel square inside SNAP.VERTEX.RANGE:
// raw values in [kMinPointRaw, kMaxPointRaw].
inline constexpr std::int32_t kMinPointRaw = kMinVertexRaw + kSubpixelHalf;
inline constexpr std::int32_t kMaxPointRaw = kMaxVertexRaw - kSubpixelHalf;

// Returns the two triangles of the point square with snapped centre c (Z pattern, diagonal from
// the lower-left to the upper-right corner, as D3D11.3's point diagram draws it).
// Preconditions: c.x, c.y in [kMinPointRaw, kMaxPointRaw].
[[nodiscard]] std::array<std::array<Vec2, 3>, 2> point_triangles(Vec2 c);

// Returns the set-up triangles of the point (culling off, the state's fill convention).
[[nodiscard]] std::array<TriangleSetup, 2> setup_point(Vec2 c, const RasterState& state);

} // namespace rastrules
