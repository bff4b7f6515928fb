// SPDX-License-Identifier: MIT
// Strong fixed-point types and the kernel's bit budgets.
// Implements: SNAP.VERTEX.FORMAT, SNAP.VERTEX.RANGE, FIX.BUDGET.EDGE_VALUE

#pragma once

#include <compare>
#include <concepts>
#include <cstdint>

namespace rastrules {

// A signed fixed-point number whose real value is raw() / 2^FracBits.
// Different (FracBits, Rep) pairs are different types; there are no implicit
// conversions between formats or to floating point.
template <int FracBits, std::signed_integral Rep> class Fixed {
public:
  static constexpr int kFracBits = FracBits;
  using rep = Rep;

  constexpr Fixed() = default;

  [[nodiscard]] static constexpr Fixed from_raw(Rep raw) { return Fixed(raw); }
  [[nodiscard]] static constexpr Fixed from_int(Rep whole) {
    return Fixed(static_cast<Rep>(whole * (Rep{1} << FracBits)));
  }
  [[nodiscard]] constexpr Rep raw() const { return raw_; }

  friend constexpr auto operator<=>(const Fixed&, const Fixed&) = default;

  // Same-format sum and difference. Overflow is a precondition violation, excluded by the
  // FIX.BUDGET.* rules for every format the kernel uses.
  friend constexpr Fixed operator+(Fixed a, Fixed b) {
    return Fixed(static_cast<Rep>(a.raw_ + b.raw_));
  }
  friend constexpr Fixed operator-(Fixed a, Fixed b) {
    return Fixed(static_cast<Rep>(a.raw_ - b.raw_));
  }

private:
  constexpr explicit Fixed(Rep raw) : raw_(raw) {}
  Rep raw_ = 0;
};

// Returns floor(n / d) and ceil(n / d) for d > 0 (C++ division truncates toward zero): pixel
// and sample indices of subpixel coordinates.
[[nodiscard]] constexpr std::int64_t floor_div(std::int64_t n, std::int64_t d) {
  const std::int64_t q = n / d;
  return (n % d != 0 && n < 0) ? q - 1 : q;
}
[[nodiscard]] constexpr std::int64_t ceil_div(std::int64_t n, std::int64_t d) {
  return -floor_div(-n, d);
}

// Snapped positions: signed 16.8, units of 1/256 pixel.
// rule: SNAP.VERTEX.FORMAT
inline constexpr int kSubpixelBits = 8;
inline constexpr std::int32_t kSubpixelOne = std::int32_t{1} << kSubpixelBits;
inline constexpr std::int32_t kSubpixelHalf = kSubpixelOne / 2;
using Subpixel = Fixed<kSubpixelBits, std::int32_t>;

// Edge values: twice a signed area, units of 1/65536 pixel^2.
using EdgeValue = Fixed<2 * kSubpixelBits, std::int64_t>;

// The supported range of snapped coordinates: raw values in [kMinVertexRaw, kMaxVertexRaw],
// that is [-32768, 32767.99609375] pixels (D3D11.3's 16.8 format, FixedMin..FixedMax).
// rule: SNAP.VERTEX.RANGE
inline constexpr int kVertexIntBits = 16;
inline constexpr int kVertexMagBits = kVertexIntBits - 1 + kSubpixelBits; // 23
inline constexpr std::int32_t kMinVertexRaw = -(std::int32_t{1} << kVertexMagBits);
inline constexpr std::int32_t kMaxVertexRaw = (std::int32_t{1} << kVertexMagBits) - 1;

// rule: FIX.BUDGET.EDGE_VALUE
// Raw coordinates lie in [-2^23, 2^23). A difference of two needs 24 magnitude bits, a product
// of two differences 48, and the difference of two products 49. That fits int64_t with room to
// spare (proofs/fixed/edge_value_no_overflow.cpp proves it for every input, not by this sum).
inline constexpr int kEdgeValueMagBits = 2 * (kVertexMagBits + 1) + 1;
static_assert(kEdgeValueMagBits <= 63, "edge value must fit in int64_t (FIX.BUDGET.EDGE_VALUE)");
// Steps by one pixel: |dy| * 256 < 2^32, also well inside int64_t.
inline constexpr int kEdgeStepMagBits = (kVertexMagBits + 1) + kSubpixelBits;
static_assert(kEdgeStepMagBits <= 62, "edge steps must fit in int64_t (FIX.STEP.INCREMENTAL)");

// Largest render target side accepted (SCENE.TARGET.LIMITS). Pixel centres of such a target
// lie inside the vertex range, so samples obey the same budget as vertices.
inline constexpr std::int32_t kMaxTargetSide = 16384;
static_assert(std::int64_t{kMaxTargetSide} * kSubpixelOne + kSubpixelHalf <= kMaxVertexRaw,
              "pixel centres must lie in SNAP.VERTEX.RANGE");

// A point in snapped (16.8) window coordinates: origin top-left, y down.
// rule: COORD.PIXEL.ORIGIN
struct Vec2 {
  Subpixel x;
  Subpixel y;
  friend constexpr bool operator==(const Vec2&, const Vec2&) = default;
};

// Returns the sample position of the centre of pixel (px, py): (px + 0.5, py + 0.5).
// Preconditions: 0 <= px, py < kMaxTargetSide.
// rule: COORD.PIXEL.CENTER
[[nodiscard]] constexpr Vec2 pixel_center(std::int32_t px, std::int32_t py) {
  return Vec2{Subpixel::from_raw(px * kSubpixelOne + kSubpixelHalf),
              Subpixel::from_raw(py * kSubpixelOne + kSubpixelHalf)};
}

} // namespace rastrules
