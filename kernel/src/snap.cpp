// SPDX-License-Identifier: MIT
// Vertex snapping with integer arithmetic on the float32 bit pattern.
// Implements: SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE, SNAP.VERTEX.INVALID, SNAP.D3D.SATURATE

#include "rastrules/snap.hpp"

#include <bit>
#include <cstdint>

namespace rastrules {

// rule: SNAP.D3D.SATURATE
Subpixel snap_d3d_saturate(float v) {
  const auto bits = std::bit_cast<std::uint32_t>(v);
  const bool negative = (bits >> 31) != 0;
  if (((bits >> 23) & 0xFFu) == 0xFFu) {
    if ((bits & 0x7FFFFFu) != 0)
      return Subpixel::from_raw(0);                                      // NaN
    return Subpixel::from_raw(negative ? kMinVertexRaw : kMaxVertexRaw); // +-Inf
  }
  const auto mag = static_cast<std::int64_t>(detail::scaled_magnitude_rne(bits));
  // The early exits compare the unrounded value with FixedMax = 2^15 - 2^-8 and
  // FixedMin = -2^15; rounding can only move a value inside them onto them, never past, so
  // clamping the rounded value gives the same result.
  const std::int64_t raw = negative ? -mag : mag;
  if (raw >= kMaxVertexRaw)
    return Subpixel::from_raw(kMaxVertexRaw);
  if (raw <= kMinVertexRaw)
    return Subpixel::from_raw(kMinVertexRaw);
  return Subpixel::from_raw(static_cast<std::int32_t>(raw));
}

} // namespace rastrules
