// SPDX-License-Identifier: MIT
// Aliased lines: D3D diamond exit and Vulkan Bresenham, exact integer arithmetic on snapped
// 16.8 coordinates. The per-pixel decision is formula/diamond.hpp; this file finds the candidate
// pixels (a walk along the major axis) and orders them as the line travels.
// Implements: LINE.MAJOR.AXIS, LINE.D3D.EXIT, LINE.VK.EXIT, LINE.ZERO_LENGTH,
//             LINE.STRIP.SEQUENCE, LINE.ORDER.TRAVEL, LINE.TARGET.CLIP

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/formula/diamond.hpp"
#include "rastrules/line.hpp"
#include "rastrules/line_aliased.hpp"

namespace rastrules {

std::string_view to_string(DiamondFeature f) {
  return name_of(f, "");
}

namespace {

constexpr std::int64_t kH = kSubpixelHalf; // half the diamond's diagonal: 1/2 px

struct Relative {
  std::int64_t au, av, bu, bv; // a and b relative to the pixel centre, raw 16.8
};

Relative relative(Vec2 a, Vec2 b, std::int32_t px, std::int32_t py) {
  const std::int64_t cx = std::int64_t{px} * kSubpixelOne + kSubpixelHalf;
  const std::int64_t cy = std::int64_t{py} * kSubpixelOne + kSubpixelHalf;
  return {a.x.raw() - cx, a.y.raw() - cy, b.x.raw() - cx, b.y.raw() - cy};
}

// rule: LINE.D3D.EXIT, LINE.VK.EXIT, LINE.MAJOR.AXIS
bool covers_relative(const Relative& r, LineMode mode, bool x_major) {
  if (mode == LineMode::kVulkanBresenham) {
    return formula::vk_exits<std::int64_t>(r.au, r.av, r.bu, r.bv, kH);
  }
  if (x_major)
    return formula::d3d_exits<false, std::int64_t>(r.au, r.av, r.bu, r.bv, kH);
  return formula::d3d_exits<true, std::int64_t>(r.au, r.av, r.bu, r.bv, kH);
}

} // namespace

bool aliased_line_covers(Vec2 a, Vec2 b, LineMode mode, std::int32_t px, std::int32_t py) {
  // rule: LINE.ZERO_LENGTH
  if (a == b)
    return false;
  return covers_relative(relative(a, b, px, py), mode, is_x_major(a, b));
}

// rule: LINE.ORDER.TRAVEL, LINE.TARGET.CLIP, LINE.ZERO_LENGTH
void rasterize_aliased_line(Vec2 a, Vec2 b, LineMode mode, std::int32_t width, std::int32_t height,
                            const PixelEmit& emit) {
  if (mode != LineMode::kD3DDiamond && mode != LineMode::kVulkanBresenham)
    return;
  if (a == b || width <= 0 || height <= 0)
    return;
  const bool x_major = is_x_major(a, b);
  // Work in (major, minor) coordinates: for y-major lines swap x and y.
  const std::int64_t ma = x_major ? a.x.raw() : a.y.raw(), na = x_major ? a.y.raw() : a.x.raw();
  const std::int64_t mb = x_major ? b.x.raw() : b.y.raw(), nb = x_major ? b.y.raw() : b.x.raw();
  const std::int64_t dm = mb - ma, dn = nb - na; // dm != 0 since |dm| >= |dn| and a != b
  const std::int64_t major_limit = x_major ? width : height;
  const std::int64_t minor_limit = x_major ? height : width;
  // A diamond lies in its closed pixel square, and the Vulkan perturbation is infinitesimal,
  // so a covered pixel's square meets the closed segment: the candidates of major index k are
  // the rows (columns) the segment spans over [256k, 256k + 256], one more on each side.
  const std::int64_t lo = std::min(ma, mb), hi = std::max(ma, mb);
  const std::int64_t k_first = std::max<std::int64_t>(floor_div(lo, kSubpixelOne) - 1, 0);
  const std::int64_t k_last =
      std::min<std::int64_t>(floor_div(hi, kSubpixelOne) + 1, major_limit - 1);
  if (k_first > k_last)
    return;
  const std::int64_t step_major = dm > 0 ? 1 : -1;
  const std::int64_t step_minor = dn >= 0 ? 1 : -1;
  // Minor coordinate of the segment's line at major coordinate m, floored to a pixel index:
  // n(m) = na + (m - ma) dn / dm.
  auto minor_pixel_at = [&](std::int64_t m) {
    std::int64_t num = na * dm + (m - ma) * dn;
    std::int64_t den = dm * kSubpixelOne;
    if (den < 0) {
      num = -num;
      den = -den;
    }
    return floor_div(num, den);
  };
  const std::int64_t k_begin = step_major > 0 ? k_first : k_last;
  const std::int64_t k_end = step_major > 0 ? k_last + 1 : k_first - 1;
  for (std::int64_t k = k_begin; k != k_end; k += step_major) {
    const std::int64_t m0 = std::max(lo, k * kSubpixelOne);
    const std::int64_t m1 = std::min(hi, k * kSubpixelOne + kSubpixelOne);
    if (m0 > m1)
      continue;
    const std::int64_t n0 = minor_pixel_at(m0), n1 = minor_pixel_at(m1);
    const std::int64_t j_first = std::max<std::int64_t>(std::min(n0, n1) - 1, 0);
    const std::int64_t j_last = std::min<std::int64_t>(std::max(n0, n1) + 1, minor_limit - 1);
    if (j_first > j_last)
      continue;
    const std::int64_t j_begin = step_minor > 0 ? j_first : j_last;
    const std::int64_t j_end = step_minor > 0 ? j_last + 1 : j_first - 1;
    for (std::int64_t j = j_begin; j != j_end; j += step_minor) {
      const auto px = static_cast<std::int32_t>(x_major ? k : j);
      const auto py = static_cast<std::int32_t>(x_major ? j : k);
      if (covers_relative(relative(a, b, px, py), mode, x_major))
        emit(px, py);
    }
  }
}

void rasterize_aliased_line_strip(const std::vector<Vec2>& vertices, LineMode mode,
                                  std::int32_t width, std::int32_t height, const PixelEmit& emit) {
  // rule: LINE.STRIP.SEQUENCE
  for (std::size_t i = 0; i + 1 < vertices.size(); ++i) {
    rasterize_aliased_line(vertices[i], vertices[i + 1], mode, width, height, emit);
  }
}

LineDiamondDecision explain_aliased_line_pixel(Vec2 a, Vec2 b, LineMode mode, std::int32_t px,
                                               std::int32_t py) {
  LineDiamondDecision d;
  d.mode = mode;
  d.x_major = is_x_major(a, b);
  d.zero_length = (a == b);
  const Relative r = relative(a, b, px, py);
  const std::int64_t du = r.bu - r.au, dv = r.bv - r.av;
  using C = formula::TConstraint<std::int64_t, std::int64_t>;
  // Interior: the open diamond.
  const auto open = formula::segment_in_diamond_constraints<std::int64_t, std::int64_t>(
      r.au, r.av, du, dv, {kH, kH, kH, kH}, {true, true, true, true}, 0, 1, 1);
  if (formula::t_feasible(open, std::int64_t{0}))
    d.met_features |= kFeatureInterior;
  // Open edge k: s_k·p = h with the two neighbouring half-planes strict (which excludes the
  // corners at its ends).
  constexpr std::array<DiamondFeature, 4> kEdgeBits = {
      kFeatureEdgeLowerRight, kFeatureEdgeLowerLeft, kFeatureEdgeUpperRight, kFeatureEdgeUpperLeft};
  for (std::size_t k = 0; k < 4; ++k) {
    const std::int64_t s1 = formula::kDiamondEdgeSigns[k][0], s2 = formula::kDiamondEdgeSigns[k][1];
    const std::int64_t a_k = s1 * r.au + s2 * r.av, m_k = s1 * du + s2 * dv;
    const std::int64_t a_p = s1 * r.au - s2 * r.av, m_p = s1 * du - s2 * dv;
    const std::int64_t a_q = -s1 * r.au + s2 * r.av, m_q = -s1 * du + s2 * dv;
    const std::array<C, 6> cs = {C{kH - a_k, m_k, false}, C{a_k - kH, -m_k, false},
                                 C{kH - a_p, m_p, true},  C{kH - a_q, m_q, true},
                                 C{0, -1, false},         C{1, 1, false}};
    if (formula::t_feasible(cs, std::int64_t{0}))
      d.met_features |= kEdgeBits[k];
  }
  constexpr std::array<std::array<std::int64_t, 2>, 4> kCorners = {
      {{{0, kH}}, {{kH, 0}}, {{0, -kH}}, {{-kH, 0}}}};
  constexpr std::array<DiamondFeature, 4> kCornerBits = {kFeatureCornerBottom, kFeatureCornerRight,
                                                         kFeatureCornerTop, kFeatureCornerLeft};
  for (std::size_t k = 0; k < 4; ++k) {
    if (formula::on_segment<std::int64_t>(kCorners[k][0], kCorners[k][1], r.au, r.av, du, dv)) {
      d.met_features |= kCornerBits[k];
    }
  }
  if (mode == LineMode::kVulkanBresenham) {
    d.included_features =
        kFeatureInterior | kFeatureEdgeLowerRight | kFeatureEdgeUpperRight | kFeatureCornerRight;
    d.entered = formula::vk_meets<std::int64_t>(r.au, r.av, du, dv, kH);
    d.end_inside = formula::vk_contains<std::int64_t>(r.bu, r.bv, kH);
  } else {
    d.included_features = kFeatureInterior | kFeatureEdgeLowerRight | kFeatureEdgeLowerLeft |
                          kFeatureCornerBottom | (d.x_major ? 0u : kFeatureCornerRight);
    if (d.x_major) {
      d.entered = formula::d3d_meets<false, std::int64_t>(r.au, r.av, du, dv, kH);
      d.end_inside = formula::d3d_contains<false, std::int64_t>(r.bu, r.bv, kH);
    } else {
      d.entered = formula::d3d_meets<true, std::int64_t>(r.au, r.av, du, dv, kH);
      d.end_inside = formula::d3d_contains<true, std::int64_t>(r.bu, r.bv, kH);
    }
  }
  d.covered = !d.zero_length && d.entered && !d.end_inside;
  // The rule that decided, and the reason; the reason names the rule (from the one table,
  // rastrules/rules.hpp) when it is not the exit rule itself.
  const RuleId exit_rule =
      mode == LineMode::kVulkanBresenham ? rules::kLineVkExit : rules::kLineD3DExit;
  std::string_view why;
  d.rule = exit_rule;
  if (d.zero_length) {
    d.rule = rules::kLineZeroLength;
    why = "zero-length line: covers nothing";
  } else if (!d.entered && d.met_features == 0) {
    why = "the segment misses the diamond";
  } else if (!d.entered) {
    const bool vk = mode == LineMode::kVulkanBresenham;
    d.rule = vk ? rules::kLineVkTestArea : rules::kLineD3DTestArea;
    why = vk ? "the perturbed segment misses the open diamond"
             : "the segment meets only excluded edges or corners";
  } else if (d.end_inside) {
    why = "the end point lies in the test area: the line does not exit";
  } else if ((d.met_features & kFeatureInterior) != 0) {
    why = "the line crosses the diamond's interior and exits";
  } else {
    why = (mode == LineMode::kVulkanBresenham)
              ? "the perturbed segment enters the open diamond at a boundary tie and exits"
              : "the line meets an included edge or corner only, and exits";
  }
  d.reason = std::string(why);
  if (d.rule != exit_rule)
    d.reason += " (" + std::string(d.rule.id) + ")";
  return d;
}

} // namespace rastrules
