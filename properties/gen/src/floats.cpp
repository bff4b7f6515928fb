// SPDX-License-Identifier: MIT
// Float32 generators for the snapping properties.
// Implements (generators for): SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE, SNAP.D3D.SATURATE

#include "rastrules/gen/floats.hpp"

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>

namespace rastrules::gen {
namespace {

float from_bits(std::uint32_t b) {
  return std::bit_cast<float>(b);
}

rc::Gen<float> any_bits() {
  return rc::gen::map(rc::gen::arbitrary<std::uint32_t>(), from_bits);
}

rc::Gen<float> subnormal() {
  return rc::gen::apply(
      [](bool negative, std::uint32_t mantissa) {
        return from_bits((negative ? 0x80000000u : 0u) | mantissa);
      },
      rc::gen::arbitrary<bool>(), rc::gen::inRange<std::uint32_t>(0u, 0x800000u));
}

rc::Gen<float> special() {
  return rc::gen::element(
      std::numeric_limits<float>::quiet_NaN(), -std::numeric_limits<float>::quiet_NaN(),
      std::numeric_limits<float>::signaling_NaN(), from_bits(0x7F800001u), from_bits(0xFFFFFFFFu),
      from_bits(0x7FC12345u), std::numeric_limits<float>::infinity(),
      -std::numeric_limits<float>::infinity(), 0.0f, -0.0f, std::numeric_limits<float>::min(),
      -std::numeric_limits<float>::min(), std::numeric_limits<float>::max(),
      std::numeric_limits<float>::lowest(), std::numeric_limits<float>::denorm_min(),
      -std::numeric_limits<float>::denorm_min());
}

// (2k + 1) / 512 with |2k + 1| < 2^24, so the float is exact and v * 256 = k + 1/2.
rc::Gen<float> tie() {
  return rc::gen::map(rc::gen::inRange<std::int32_t>(-(1 << 23), (1 << 23)),
                      [](std::int32_t k) { return static_cast<float>(2 * k + 1) / 512.0f; });
}

rc::Gen<float> near_tie() {
  return rc::gen::apply(
      [](float t, bool up) {
        return std::nextafter(t, up ? std::numeric_limits<float>::infinity()
                                    : -std::numeric_limits<float>::infinity());
      },
      tie(), rc::gen::arbitrary<bool>());
}

rc::Gen<float> exact_subpixel() {
  return rc::gen::map(rc::gen::inRange<std::int32_t>(-(1 << 23), (1 << 23)),
                      [](std::int32_t k) { return static_cast<float>(k) / 256.0f; });
}

// The ends of the range: FixedMax = 32767.99609375, the tie above it (32767.998046875, which
// rounds to 2^23 and is out), 32768, FixedMin = -32768, the tie below it (-32768.001953125,
// which rounds to -2^23 and is in), and the next tie (-32768.005859375, out).
rc::Gen<float> near_limit() {
  return rc::gen::apply(
      [](float base, std::int32_t ulps) {
        float v = base;
        const float dir = ulps < 0 ? -std::numeric_limits<float>::infinity()
                                   : std::numeric_limits<float>::infinity();
        for (std::int32_t i = 0; i < std::abs(ulps); ++i)
          v = std::nextafter(v, dir);
        return v;
      },
      rc::gen::element(32767.99609375f, 32767.998046875f, 32768.0f, 32767.994140625f, -32768.0f,
                       -32768.001953125f, -32768.00390625f, -32768.005859375f, -32767.998046875f),
      rc::gen::inRange<std::int32_t>(-3, 4));
}

rc::Gen<float> in_range() {
  // x / 65536 with |x| <= 2^31: the conversion to float rounds once to 24 bits and the
  // division by a power of two is exact, giving floats with up to 16 fractional bits.
  return rc::gen::map(
      rc::gen::inRange<std::int64_t>(-(std::int64_t{1} << 31), (std::int64_t{1} << 31) + 1),
      [](std::int64_t x) { return static_cast<float>(x) / 65536.0f; });
}

rc::Gen<FloatCase> tagged(rc::Gen<float> g, FloatClass c) {
  return rc::gen::map(std::move(g), [c](float v) { return FloatCase{v, c}; });
}

} // namespace

rc::Gen<FloatCase> float_case() {
  return rc::gen::weightedOneOf<FloatCase>({
      {3, tagged(any_bits(), FloatClass::kAnyBits)},
      {1, tagged(subnormal(), FloatClass::kSubnormal)},
      {1, tagged(special(), FloatClass::kSpecial)},
      {3, tagged(tie(), FloatClass::kTie)},
      {2, tagged(near_tie(), FloatClass::kNearTie)},
      {1, tagged(exact_subpixel(), FloatClass::kExactSubpixel)},
      {2, tagged(near_limit(), FloatClass::kNearLimit)},
      {3, tagged(in_range(), FloatClass::kInRange)},
  });
}

void show_float(float v, std::ostream& os) {
  if (std::isnan(v)) {
    os << "\"NaN\"";
  } else if (std::isinf(v)) {
    os << (v > 0 ? "\"Infinity\"" : "\"-Infinity\"");
  } else {
    std::array<char, 64> buf{};
    const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
    os.write(buf.data(), r.ptr - buf.data());
  }
}

void showValue(const FloatCase& f, std::ostream& os) {
  show_float(f.v, os);
  const auto flags = os.flags();
  os << " (bits 0x" << std::hex << std::setw(8) << std::setfill('0')
     << std::bit_cast<std::uint32_t>(f.v) << ", " << to_string(f.cls) << ")";
  os.flags(flags);
}

} // namespace rastrules::gen
