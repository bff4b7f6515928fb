// SPDX-License-Identifier: MIT
// Aliased lines: the per-pixel diamond-exit decision (D3D and Vulkan Bresenham), line strips,
// and an explanation of one pixel's decision for tools.
// Implements: LINE.MAJOR.AXIS, LINE.D3D.EXIT, LINE.VK.EXIT, LINE.ZERO_LENGTH,
//             LINE.STRIP.SEQUENCE, LINE.ORDER.TRAVEL (spec/rules/line.md)

#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/line.hpp"
#include "rastrules/name_table.hpp"
#include "rastrules/rules.hpp"

namespace rastrules {

// Returns whether the line from a to b is x-major: |dx| >= |dy| (slope in [-1, 1], including
// exactly 45 degrees). A zero-length line counts as x-major (it covers nothing either way).
// rule: LINE.MAJOR.AXIS
[[nodiscard]] constexpr bool is_x_major(Vec2 a, Vec2 b) {
  const std::int64_t dx = std::int64_t{b.x.raw()} - a.x.raw();
  const std::int64_t dy = std::int64_t{b.y.raw()} - a.y.raw();
  return (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
}

// Returns whether the aliased line from a to b covers pixel (px, py) under `mode`
// (kD3DDiamond or kVulkanBresenham). Independent of any render target.
// Preconditions: a, b in SNAP.VERTEX.RANGE; |px|, |py| <= kMaxTargetSide.
[[nodiscard]] bool aliased_line_covers(Vec2 a, Vec2 b, LineMode mode, std::int32_t px,
                                       std::int32_t py);

// Calls rasterize_aliased_line for each segment (v[i], v[i+1]) in order: a strip draws exactly
// as the sequence of independent lines in the same direction. Fewer than two vertices draw
// nothing.
// rule: LINE.STRIP.SEQUENCE
void rasterize_aliased_line_strip(const std::vector<Vec2>& vertices, LineMode mode,
                                  std::int32_t width, std::int32_t height, const PixelEmit& emit);

// What part of the diamond's boundary (or interior) the segment met. Bit flags.
enum DiamondFeature : std::uint32_t {
  kFeatureInterior = 1u << 0,
  kFeatureEdgeLowerRight = 1u << 1,
  kFeatureEdgeLowerLeft = 1u << 2,
  kFeatureEdgeUpperRight = 1u << 3,
  kFeatureEdgeUpperLeft = 1u << 4,
  kFeatureCornerBottom = 1u << 5,
  kFeatureCornerRight = 1u << 6,
  kFeatureCornerTop = 1u << 7,
  kFeatureCornerLeft = 1u << 8,
};
template <> struct Names<DiamondFeature> {
  static constexpr NameTable<9, DiamondFeature> table{{{"interior", kFeatureInterior},
                                                       {"lower-right edge", kFeatureEdgeLowerRight},
                                                       {"lower-left edge", kFeatureEdgeLowerLeft},
                                                       {"upper-right edge", kFeatureEdgeUpperRight},
                                                       {"upper-left edge", kFeatureEdgeUpperLeft},
                                                       {"bottom corner", kFeatureCornerBottom},
                                                       {"right corner", kFeatureCornerRight},
                                                       {"top corner", kFeatureCornerTop},
                                                       {"left corner", kFeatureCornerLeft}}};
};

// The decision for one pixel and one aliased line, for `rastrules explain`.
struct LineDiamondDecision {
  LineMode mode = LineMode::kD3DDiamond;
  bool x_major = true;      // LINE.MAJOR.AXIS
  bool zero_length = false; // LINE.ZERO_LENGTH
  // Features of the closed diamond the unperturbed closed segment meets (DiamondFeature bits).
  std::uint32_t met_features = 0;
  // Features whose points belong to the test area of this mode and axis (D3D), or to the
  // perturbed open diamond's limit set (Vulkan); see LINE.D3D.TEST_AREA / LINE.VK.TEST_AREA.
  std::uint32_t included_features = 0;
  bool entered = false;    // the segment meets the test area (Vulkan: perturbed segment)
  bool end_inside = false; // the end point lies in the test area (Vulkan: perturbed end)
  bool covered = false;    // entered && !end_inside: the line exits the diamond
  // The rule that decided: LINE.ZERO_LENGTH, LINE.D3D.TEST_AREA or LINE.VK.TEST_AREA (the
  // segment meets the diamond outside the test area only), else LINE.D3D.EXIT or LINE.VK.EXIT.
  RuleId rule;
  // A one-line reason, naming `rule` when it is not the exit rule.
  std::string reason;
};

// Explains the decision of aliased_line_covers(a, b, mode, px, py).
[[nodiscard]] LineDiamondDecision explain_aliased_line_pixel(Vec2 a, Vec2 b, LineMode mode,
                                                             std::int32_t px, std::int32_t py);

// Returns "upper-left edge", "bottom corner", ... for one feature bit; "" for none or several.
[[nodiscard]] std::string_view to_string(DiamondFeature f);

} // namespace rastrules
