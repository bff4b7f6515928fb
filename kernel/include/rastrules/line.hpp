// SPDX-License-Identifier: MIT
// Lines: aliased (D3D diamond exit, Vulkan Bresenham), quadrilateral, antialiased.
// Implements: LINE.* (spec/rules/line.md)
// The three kinds live in line_aliased.hpp, line_quad.hpp and line_aa.hpp.

#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/name_table.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules {

// How a line primitive is rasterized (the profile's line mode).
enum class LineMode {
  kD3DDiamond,      // D3D aliased: diamond exit, half-open diamond per x-/y-major
  kVulkanBresenham, // Vulkan BRESENHAM: open diamond, endpoints shifted by (-e, -e^2)
  kQuadWide,        // D3D quadrilateral line (multisampling): rectangle 1.4 px wide
  kQuadNarrow,      // Vulkan strict / D3D12 QUADRILATERAL_NARROW: rectangle 1.0 px wide
};
template <> struct Names<LineMode> {
  static constexpr auto table =
      in_enum_order<LineMode>({"d3d", "vulkan-bresenham", "quad-wide", "quad-narrow"});
};

// A covered pixel of an aliased or quadrilateral line.
using PixelEmit = std::function<void(std::int32_t x, std::int32_t y)>;

// Calls emit for every pixel of the target [0,w)x[0,h) covered by the aliased line from a to b
// (snapped), in the order the line travels from a to b. Modes kD3DDiamond and
// kVulkanBresenham only. No floating point.
void rasterize_aliased_line(Vec2 a, Vec2 b, LineMode mode, std::int32_t width, std::int32_t height,
                            const PixelEmit& emit);

// Returns the two triangles of the quadrilateral line from a to b (snapped) of width 1.4 px
// (kQuadWide) or 1.0 px (kQuadNarrow), corners rounded to 16.8 as LINE.QUAD.CORNERS says.
// Empty when a == b (a zero-length quadrilateral line covers nothing).
[[nodiscard]] std::vector<std::array<Vec2, 3>> quad_line_triangles(Vec2 a, Vec2 b, LineMode mode);

// Antialiased line coverage in fixed point: coverage_q16 / 65536 in [0, 1].
inline constexpr int kAACoverageBits = 16;
using AAEmit = std::function<void(std::int32_t x, std::int32_t y, std::uint32_t coverage_q16)>;

// Calls emit, row by row (y, then x), for every pixel of the target with coverage > 0 under the
// D3D reference algorithm (LINE.AA.COVERAGE): the width-1 rectangle from a to b against the five
// squares R0..R4 centred on the pixel centre. Coverage is within the bound stated in
// LINE.AA.PRECISION of the exact value.
void rasterize_aa_line(Vec2 a, Vec2 b, std::int32_t width, std::int32_t height, const AAEmit& emit);

} // namespace rastrules
