// SPDX-License-Identifier: MIT
// Vertex snapping with integer arithmetic on the float32 bit pattern.
// Implements: SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE, SNAP.VERTEX.INVALID, SNAP.D3D.SATURATE

#include "rastrules/snap.hpp"

#include <bit>
#include <cstdint>

namespace rastrules {
namespace {

struct Decoded {
  bool negative;
  bool nan;
  bool infinite;
  std::uint32_t significand;  // with the hidden bit for normal numbers
  int exponent;               // value = significand * 2^exponent
};

Decoded decode(float v) {
  const auto bits = std::bit_cast<std::uint32_t>(v);
  const bool negative = (bits >> 31) != 0;
  const auto biased = static_cast<int>((bits >> 23) & 0xFFu);
  const std::uint32_t mantissa = bits & 0x7FFFFFu;
  if (biased == 0xFF) {
    return Decoded{negative, mantissa != 0, mantissa == 0, 0, 0};
  }
  if (biased == 0) {  // zero or subnormal
    return Decoded{negative, false, false, mantissa, -149};
  }
  return Decoded{negative, false, false, mantissa | 0x800000u, biased - 150};
}

// Returns |significand * 2^(exponent + 8)| rounded half to even, or a value larger than
// 2^31 when the magnitude is that large. Integer arithmetic only.
// rule: SNAP.VERTEX.ROUND
std::int64_t round_scaled_magnitude(std::uint32_t significand, int exponent) {
  const int shift = exponent + kSubpixelBits;  // result = significand * 2^shift
  if (shift >= 0) {
    if (shift > 8) return std::int64_t{1} << 40;  // >= 2^33: certainly out of range
    return std::int64_t{significand} << shift;
  }
  const int right = -shift;
  if (right > 25) return 0;  // significand < 2^24 <= 2^(right-1): below one half
  const std::uint64_t s = significand;
  const std::uint64_t whole = s >> right;
  const std::uint64_t rem = s & ((std::uint64_t{1} << right) - 1);
  const std::uint64_t half = std::uint64_t{1} << (right - 1);
  std::uint64_t q = whole;
  if (rem > half || (rem == half && (whole & 1u) != 0)) ++q;
  return static_cast<std::int64_t>(q);
}

}  // namespace

std::string_view to_string(SnapStatus s) {
  switch (s) {
    case SnapStatus::kOk: return "ok";
    case SnapStatus::kNaN: return "NaN";
    case SnapStatus::kInfinite: return "infinite";
    case SnapStatus::kOutOfRange: return "outside the supported range [-32768, 32767.99609375]";
  }
  return "unknown";
}

// rule: SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE, SNAP.VERTEX.INVALID
SnapResult snap_to_subpixel(float v) {
  const Decoded d = decode(v);
  if (d.nan) return SnapResult{SnapStatus::kNaN, Subpixel{}};
  if (d.infinite) return SnapResult{SnapStatus::kInfinite, Subpixel{}};
  const std::int64_t mag = round_scaled_magnitude(d.significand, d.exponent);
  const std::int64_t raw = d.negative ? -mag : mag;
  if (raw < kMinVertexRaw || raw > kMaxVertexRaw) {
    return SnapResult{SnapStatus::kOutOfRange, Subpixel{}};
  }
  return SnapResult{SnapStatus::kOk, Subpixel::from_raw(static_cast<std::int32_t>(raw))};
}

// rule: SNAP.D3D.SATURATE
Subpixel snap_d3d_saturate(float v) {
  const Decoded d = decode(v);
  if (d.nan) return Subpixel::from_raw(0);
  if (d.infinite) return Subpixel::from_raw(d.negative ? kMinVertexRaw : kMaxVertexRaw);
  const std::int64_t mag = round_scaled_magnitude(d.significand, d.exponent);
  // The early exits compare the unrounded value with FixedMax = 2^15 - 2^-8 and
  // FixedMin = -2^15; rounding can only move a value inside them onto them, never past, so
  // clamping the rounded value gives the same result.
  const std::int64_t raw = d.negative ? -mag : mag;
  if (raw >= kMaxVertexRaw) return Subpixel::from_raw(kMaxVertexRaw);
  if (raw <= kMinVertexRaw) return Subpixel::from_raw(kMinVertexRaw);
  return Subpixel::from_raw(static_cast<std::int32_t>(raw));
}

}  // namespace rastrules
