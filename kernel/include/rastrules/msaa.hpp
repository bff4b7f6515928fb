// SPDX-License-Identifier: MIT
// Multisampling: sample patterns, per-sample coverage, the sample mask, centroid evaluation
// points, 2x2 quads with helper lanes, derivatives and resolve.
// Implements: MSAA.PATTERN.GRID, MSAA.PATTERN.STANDARD, MSAA.PATTERN.CENTER,
//             MSAA.PATTERN.CUSTOM, MSAA.SAMPLE.POSITION, MSAA.COVER.SAMPLE, MSAA.MASK.AND,
//             MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10, MSAA.QUAD.ALIGN, MSAA.QUAD.LANE,
//             MSAA.DERIV.FINE, MSAA.DERIV.COARSE, MSAA.RESOLVE.AVERAGE
// Rules: spec/rules/msaa.md. Every position here is exact: a sample offset is a multiple of
// 1/16 px, which is 16 raw units of the 16.8 grid.

#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "rastrules/fixed.hpp"
#include "rastrules/name_table.hpp"
#include "rastrules/triangle.hpp"

namespace rastrules {

// The largest sample count of any pattern (standard, centre or custom).
// rule: MSAA.LIMITS
inline constexpr std::uint32_t kMaxSamples = 16;

// Raw 16.8 units in one step (1/16 px) of the sample grid.
// rule: MSAA.PATTERN.GRID
inline constexpr std::int32_t kSampleGridUnit = kSubpixelOne / 16;
inline constexpr std::int32_t kSampleGridMin = -8;
inline constexpr std::int32_t kSampleGridMax = 7;

// A sample position relative to its pixel's centre, in 1/16 px, +y down; each coordinate in
// [kSampleGridMin, kSampleGridMax] (the pixel's left and top edges are reachable, its right and
// bottom edges are not).
// rule: MSAA.PATTERN.GRID
struct SampleOffset {
  std::int8_t x = 0;
  std::int8_t y = 0;
  friend constexpr bool operator==(const SampleOffset&, const SampleOffset&) = default;
};

[[nodiscard]] constexpr bool on_sample_grid(std::int32_t x, std::int32_t y) {
  return x >= kSampleGridMin && x <= kSampleGridMax && y >= kSampleGridMin && y <= kSampleGridMax;
}

// rule: MSAA.PATTERN.STANDARD, MSAA.PATTERN.CENTER, MSAA.PATTERN.CUSTOM
enum class PatternKind { kStandard, kCenter, kCustom };
template <> struct Names<PatternKind> {
  static constexpr auto table = in_enum_order<PatternKind>({"standard", "center", "custom"});
};

struct SamplePattern {
  PatternKind kind = PatternKind::kStandard;
  std::vector<SampleOffset> positions = {SampleOffset{}}; // in sample-index order
  [[nodiscard]] std::uint32_t count() const { return static_cast<std::uint32_t>(positions.size()); }
  friend bool operator==(const SamplePattern&, const SamplePattern&) = default;
};

// Returns whether n is a count with a standard pattern: 1, 2, 4, 8 or 16.
// rule: MSAA.PATTERN.STANDARD
[[nodiscard]] constexpr bool is_standard_count(std::uint32_t n) {
  return n == 1 || n == 2 || n == 4 || n == 8 || n == 16;
}

// Returns the D3D/Vulkan standard pattern of n samples, in sample-index order.
// Preconditions: is_standard_count(n).
// rule: MSAA.PATTERN.STANDARD
[[nodiscard]] SamplePattern standard_pattern(std::uint32_t n);

// Returns the centre pattern of n samples: every sample at the pixel centre.
// Preconditions: is_standard_count(n).
// rule: MSAA.PATTERN.CENTER
[[nodiscard]] SamplePattern center_pattern(std::uint32_t n);

// Returns the custom (programmable) pattern with these positions in sample-index order.
// Preconditions: 1 <= positions.size() <= kMaxSamples; every position on_sample_grid. Scenes
// are checked by prepare() (MSAA.LIMITS), which names the offending field.
// rule: MSAA.PATTERN.CUSTOM
[[nodiscard]] SamplePattern custom_pattern(std::vector<SampleOffset> positions);

// Returns the mask with the low n bits set (n <= 32).
[[nodiscard]] constexpr std::uint32_t full_mask(std::uint32_t n) {
  return n >= 32 ? 0xFFFFFFFFu : ((std::uint32_t{1} << n) - 1u);
}

// Returns the exact 16.8 position of the sample at offset o of pixel (px, py):
// pixel_center(px, py) + o * kSampleGridUnit.
// Preconditions: 0 <= px, py < kMaxTargetSide; on_sample_grid(o.x, o.y).
// rule: MSAA.SAMPLE.POSITION
[[nodiscard]] constexpr Vec2 sample_position(std::int32_t px, std::int32_t py, SampleOffset o) {
  const Vec2 c = pixel_center(px, py);
  return Vec2{Subpixel::from_raw(c.x.raw() + std::int32_t{o.x} * kSampleGridUnit),
              Subpixel::from_raw(c.y.raw() + std::int32_t{o.y} * kSampleGridUnit)};
}

// Returns the coverage mask of triangle t in pixel (px, py): bit i set when t covers sample i of
// the pattern under TRI.COVER.SAMPLE (before the sample mask).
// rule: MSAA.COVER.SAMPLE
[[nodiscard]] std::uint32_t sample_coverage(const TriangleSetup& t, std::int32_t px,
                                            std::int32_t py, const SamplePattern& pattern);

// How the centroid evaluation point is chosen (MSAA.CENTROID.*).
enum class CentroidRule { kD3D11, kD3D10 };
template <> struct Names<CentroidRule> {
  static constexpr auto table = in_enum_order<CentroidRule>({"d3d11", "d3d10"});
};

// Which branch of its rule chose a centroid (for explain and for the per-branch examples).
enum class CentroidBranch {
  kFullCoverageCenter,    // D3D11 (1) / D3D10: every sample covered -> pixel centre
  kFirstCovered,          // D3D11 (2): first covered sample (after the mask) in index order
  kNearestCovered,        // D3D10: covered sample nearest the centre (after the mask)
  kNoneCoveredMaskSample, // D3D11 (3) / D3D10: nothing covered, partial mask -> a mask sample
  kNoneCoveredCenter,     // D3D11 (3) / D3D10: nothing covered, full mask -> pixel centre
};
template <> struct Names<CentroidBranch> {
  static constexpr auto table = in_enum_order<CentroidBranch>(
      {"full coverage: pixel centre", "first covered sample in index order",
       "covered sample nearest the centre", "nothing covered: a sample of the mask",
       "nothing covered: pixel centre"});
};

struct Centroid {
  SampleOffset offset; // the evaluation point relative to the pixel centre, in 1/16 px
  CentroidBranch branch = CentroidBranch::kFullCoverageCenter;
  friend bool operator==(const Centroid&, const Centroid&) = default;
};

// Returns the centroid evaluation point of a pixel whose coverage before the sample mask is
// `coverage` (bit i: sample i covered), under the sample mask `sample_mask` (only the low
// pattern.count() bits are meaningful).
// rule: MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
[[nodiscard]] Centroid centroid(CentroidRule rule, std::uint32_t coverage,
                                std::uint32_t sample_mask, const SamplePattern& pattern);

// Returns the sample indices of a pattern ordered outward from the pixel centre: by squared
// distance x^2 + y^2 in 1/16 px, ties by lower index (MSAA.CENTROID.D3D10).
[[nodiscard]] std::vector<std::uint32_t> outward_order(const SamplePattern& pattern);

// The lane of pixel (px, py) in its even-aligned 2x2 quad: 0 top-left, 1 top-right,
// 2 bottom-left, 3 bottom-right.
// rule: MSAA.QUAD.ALIGN, MSAA.QUAD.LANE
[[nodiscard]] constexpr std::uint32_t quad_lane(std::int32_t px, std::int32_t py) {
  return static_cast<std::uint32_t>((px & 1) | ((py & 1) << 1));
}

// The derivatives of one value over a quad.
template <class T> struct Derivatives {
  T ddx{};
  T ddy{};
  friend bool operator==(const Derivatives&, const Derivatives&) = default;
};

// Fine derivatives at lane `lane` of the values p[0..3] of a quad (MSAA.QUAD.LANE order):
// ddx is the difference across the lane's row, ddy across its column.
// rule: MSAA.DERIV.FINE
template <class T>
[[nodiscard]] constexpr Derivatives<T> fine_derivatives(const std::array<T, 4>& p,
                                                        std::uint32_t lane) {
  const std::uint32_t row = lane & 2u; // 0 (top row) or 2 (bottom row)
  const std::uint32_t col = lane & 1u; // 0 (left column) or 1 (right column)
  return Derivatives<T>{p[row + 1] - p[row], p[col + 2] - p[col]};
}

// Coarse derivatives of a quad: the fine derivatives of lane 0, the same for every lane.
// rule: MSAA.DERIV.COARSE
template <class T>
[[nodiscard]] constexpr Derivatives<T> coarse_derivatives(const std::array<T, 4>& p) {
  return fine_derivatives(p, 0);
}

// How often the pixel shader runs (MSAA.SHADING.*).
enum class ShadingRate { kPixel, kSample };
template <> struct Names<ShadingRate> {
  static constexpr auto table = in_enum_order<ShadingRate>({"pixel", "sample"});
};

enum class DerivativeMode { kNone, kFine, kCoarse };
template <> struct Names<DerivativeMode> {
  static constexpr auto table = in_enum_order<DerivativeMode>({"none", "fine", "coarse"});
};

// The multisample state of a scene. The defaults are single-sample rendering: one sample at the
// pixel centre, full mask, pixel shading, no centroid, no quads: coverage only.
// rule: SCENE.MSAA
struct MultisampleState {
  SamplePattern pattern;                   // standard_pattern(1) by default
  std::uint32_t sample_mask = 0xFFFFFFFFu; // ANDed with coverage; bits >= count() ignored
  bool has_centroid = false; // fragments carry a centroid evaluation point (Conventions::centroid)
  ShadingRate shading = ShadingRate::kPixel;
  bool quads = false;                                 // emit helper lanes of touched 2x2 quads
  DerivativeMode derivatives = DerivativeMode::kNone; // implies quads

  [[nodiscard]] std::uint32_t count() const { return pattern.count(); }
  [[nodiscard]] std::uint32_t effective_mask() const {
    return sample_mask & full_mask(pattern.count());
  }
  [[nodiscard]] bool wants_quads() const { return quads || derivatives != DerivativeMode::kNone; }
};

// Returns whether a scene with this state renders coverage only: one sample at the pixel
// centre, full mask, pixel shading, no centroid, no quads (the single-sample path of
// rasterize_primitive; any other state takes the multisampled path).
[[nodiscard]] inline bool is_single_sample(const MultisampleState& ms) {
  return ms.count() == 1 && ms.pattern.positions[0] == SampleOffset{} &&
         ms.effective_mask() == 1u && ms.shading == ShadingRate::kPixel && !ms.has_centroid &&
         !ms.wants_quads();
}

// Returns the fragment mask of a pixel whose coverage before the sample mask is `coverage`:
// coverage & the effective sample mask. The multisampled path and the decision records
// (rastrules/decision.hpp) both decide with this function.
// rule: MSAA.MASK.AND
[[nodiscard]] inline std::uint32_t fragment_mask(std::uint32_t coverage,
                                                 const MultisampleState& ms) {
  return coverage & ms.effective_mask();
}

// Returns the centroid evaluation point of a pixel whose coverage before the sample mask is
// `coverage`, under the centroid rule and the state's sample mask and pattern. The
// multisampled path and the decision records both decide with this function.
// rule: MSAA.CENTROID.D3D11, MSAA.CENTROID.D3D10
[[nodiscard]] inline Centroid fragment_centroid(std::uint32_t coverage, const MultisampleState& ms,
                                                CentroidRule rule) {
  return centroid(rule, coverage, ms.effective_mask(), ms.pattern);
}

// The derivatives of a fragment's evaluation point (pixel centre, centroid or sample) across
// its quad, in 1/16 px: ddx = (ddx_x, ddx_y), ddy = (ddy_x, ddy_y). With the pixel centre or a
// fixed sample the result is ddx = (16, 0), ddy = (0, 16); centroid evaluation makes it vary
// (D3D11.3 3.5.7 warns of exactly this).
// rule: MSAA.DERIV.FINE, MSAA.DERIV.COARSE
struct EvalDerivatives {
  std::int32_t ddx_x = 0, ddx_y = 0, ddy_x = 0, ddy_y = 0;
  friend bool operator==(const EvalDerivatives&, const EvalDerivatives&) = default;
};

// An RGBA8 colour.
using Rgba8 = std::array<std::uint8_t, 4>;

// Returns the resolve of the n samples of one pixel: per channel the exact average
// sum / n rounded to the nearest integer, ties to even.
// Preconditions: 1 <= samples.size() <= kMaxSamples.
// rule: MSAA.RESOLVE.AVERAGE
[[nodiscard]] Rgba8 resolve_pixel(const std::vector<Rgba8>& samples);

} // namespace rastrules
