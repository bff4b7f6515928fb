// SPDX-License-Identifier: MIT
// Aliased lines (D3D diamond exit, Vulkan Bresenham) written a second time, for machines:
// exact, slow, independent. Written from spec/rules/line.md with CGAL's exact kernel over GMP
// rationals (segment against the diamond polygon; the Vulkan epsilon as an exact tiny
// rational); never includes or calls kernel code, and shares none of its types.
// Implements (as oracle): LINE.MAJOR.AXIS, LINE.D3D.TEST_AREA, LINE.D3D.EXIT,
//   LINE.VK.TEST_AREA, LINE.VK.EXIT, LINE.ZERO_LENGTH, LINE.TARGET.CLIP

#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace rastrules::oracle {

// A position in raw 16.8 units (1/256 px), y down.
using LineRaw = std::array<std::int64_t, 2>;

// Returns whether the aliased line from a to b (raw, snapped) covers pixel (px, py) under mode
// "d3d" or "vulkan-bresenham" (spelled as spec/scene.md's line_mode spells them).
bool aliased_line_covers(const LineRaw& a, const LineRaw& b, const std::string& mode,
                         std::int64_t px, std::int64_t py);

// Returns every pixel of the target [0, w) x [0, h) the line covers, row by row (y, then x),
// found by testing every pixel of the segment's bounding box grown by 2 px, clipped to the
// target.
std::vector<std::array<std::int32_t, 2>> aliased_line_pixels(const LineRaw& a, const LineRaw& b,
                                                             const std::string& mode,
                                                             std::int32_t w, std::int32_t h);

} // namespace rastrules::oracle
