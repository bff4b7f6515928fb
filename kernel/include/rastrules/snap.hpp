// SPDX-License-Identifier: MIT
// Vertex snapping: float32 window coordinates to 16.8 fixed point.
// Implements: SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE, SNAP.VERTEX.INVALID, SNAP.D3D.SATURATE

#pragma once

#include <bit>
#include <cstdint>
#include <string_view>

#include "rastrules/fixed.hpp"
#include "rastrules/name_table.hpp"

namespace rastrules {

enum class SnapStatus {
  kOk,         // value snapped exactly (round half to even)
  kNaN,        // input is a NaN
  kInfinite,   // input is +Inf or -Inf
  kOutOfRange, // rounded value lies outside SNAP.VERTEX.RANGE
};
template <> struct Names<SnapStatus> {
  static constexpr auto table = in_enum_order<SnapStatus>(
      {"ok", "NaN", "infinite", "outside the supported range [-32768, 32767.99609375]"});
};

struct SnapResult {
  SnapStatus status = SnapStatus::kOk;
  Subpixel value; // meaningful only when status == kOk
};

// Returns v * 2^8 rounded to the nearest integer, ties to even, computed from the bits of v
// with integer arithmetic only (no floating-point operation, so no dependence on the FPU's
// rounding mode). NaN, infinities and results outside [kMinVertexRaw, kMaxVertexRaw] are
// reported, never clamped: a scene with such a vertex is rejected (SNAP.VERTEX.INVALID).
// Inline and branch-light (one snap per vertex is a large part of a small triangle's cost).
// rule: SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE, SNAP.VERTEX.INVALID
[[nodiscard]] constexpr SnapResult snap_to_subpixel(float v);

// Returns the D3D11.3 float-to-fixed conversion (functional spec 3.2.4.1 and its diagram) to
// signed 16.8: NaN -> 0; |v| < 2^-9 -> 0; v >= FixedMax (including +Inf) -> FixedMax;
// v <= FixedMin (including -Inf) -> FixedMin; otherwise round half to even. Offered for callers
// that emulate D3D's saturating behaviour; the scene path rejects instead.
// rule: SNAP.D3D.SATURATE
[[nodiscard]] Subpixel snap_d3d_saturate(float v);

namespace detail {

// Returns |v| * 2^8 rounded half to even when it is below 2^24, else a value >= 2^24.
// A finite float is sig * 2^(biased - 150) (normal: sig with the hidden bit) or
// mantissa * 2^-149 (zero, subnormal); times 2^8 that is sig * 2^-right with
// right = 142 - biased (141 for subnormals). right <= 0 means |v| * 2^8 >= 2^23 * 2^-right:
// exact for right == 0, and >= 2^24 beyond. For 1 <= right <= 25,
// floor((sig + 2^(right-1) - 1 + lsb) / 2^right), lsb the lowest bit of the quotient, is the
// quotient rounded half to even; for right > 25, sig < 2^24 <= 2^(right-1): below one half, 0.
// Preconditions: bits is not a NaN or an infinity (biased exponent < 255).
// rule: SNAP.VERTEX.ROUND
[[nodiscard]] constexpr std::uint64_t scaled_magnitude_rne(std::uint32_t bits) {
  const std::uint32_t biased = (bits >> 23) & 0xFFu;
  const std::uint32_t mantissa = bits & 0x7FFFFFu;
  const std::uint64_t sig = biased != 0 ? (mantissa | 0x800000u) : mantissa;
  const std::int32_t right = biased != 0 ? 142 - static_cast<std::int32_t>(biased) : 141;
  if (right < 0)
    return std::uint64_t{1} << 24;
  if (right == 0)
    return sig;
  if (right > 25)
    return 0;
  const auto r = static_cast<std::uint32_t>(right);
  const std::uint64_t lsb = (sig >> r) & 1u;
  return (sig + (std::uint64_t{1} << (r - 1)) - 1u + lsb) >> r;
}

} // namespace detail

constexpr SnapResult snap_to_subpixel(float v) {
  const auto bits = std::bit_cast<std::uint32_t>(v);
  if (((bits >> 23) & 0xFFu) == 0xFFu)
    return SnapResult{(bits & 0x7FFFFFu) != 0 ? SnapStatus::kNaN : SnapStatus::kInfinite,
                      Subpixel{}};
  const auto mag = static_cast<std::int64_t>(detail::scaled_magnitude_rne(bits));
  const std::int64_t raw = (bits >> 31) != 0 ? -mag : mag;
  if (raw < kMinVertexRaw || raw > kMaxVertexRaw)
    return SnapResult{SnapStatus::kOutOfRange, Subpixel{}};
  return SnapResult{SnapStatus::kOk, Subpixel::from_raw(static_cast<std::int32_t>(raw))};
}

} // namespace rastrules
