// SPDX-License-Identifier: MIT
// Snapping float32 window coordinates to 16.8 fixed point: format, round half to even at
// exact ties, signed zero, subnormals and the limits of the supported range.
// Raw values are in units of 1/256 px.

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "rastrules/fixed.hpp"
#include "rastrules/snap.hpp"

namespace rastrules {
namespace {

// Returns the raw value of a snap that must succeed.
std::int32_t raw_ok(float v) {
  const SnapResult r = snap_to_subpixel(v);
  EXPECT_EQ(r.status, SnapStatus::kOk) << "v = " << v;
  return r.value.raw();
}

SnapStatus status_of(float v) {
  return snap_to_subpixel(v).status;
}

// Every exponent that can reach the range (and the ones just beyond it), with a stride of
// mantissas plus every bit pattern one step around each rounding tie, both signs, against a
// computation in double (exact: |v| * 256 < 2^40 fits its 53 bits) rounded by the FPU's default
// round-half-to-even. The kernel's integer code and this one share nothing.
// rule: SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE
TEST(SnapVertexRound, EqualsDoubleRoundingOverEveryExponentAndEveryTieNeighbourhood) {
  std::uint64_t checked = 0;
  const auto check = [&checked](std::uint32_t bits) {
    const float v = std::bit_cast<float>(bits);
    const double want = std::nearbyint(static_cast<double>(v) * 256.0);
    const SnapResult r = snap_to_subpixel(v);
    ++checked;
    if (want < kMinVertexRaw || want > kMaxVertexRaw) {
      ASSERT_EQ(r.status, SnapStatus::kOutOfRange) << "bits 0x" << std::hex << bits;
    } else {
      ASSERT_EQ(r.status, SnapStatus::kOk) << "bits 0x" << std::hex << bits;
      ASSERT_EQ(static_cast<double>(r.value.raw()), want) << "bits 0x" << std::hex << bits;
    }
  };
  for (std::uint32_t sign : {0u, 0x80000000u}) {
    for (std::uint32_t biased = 0; biased <= 145; ++biased) {
      const std::uint32_t e = sign | (biased << 23);
      for (std::uint32_t m = 0; m <= 0x7FFFFFu; m += 997)
        check(e | m);
      check(e | 0x7FFFFFu);
      // Ties: the bits below the rounding point equal one half (right = 142 - biased).
      const int right = biased == 0 ? 141 : 142 - static_cast<int>(biased);
      if (right >= 1 && right <= 23) {
        const std::uint32_t half = 1u << (right - 1);
        for (std::uint32_t q = 0; q < (0x800000u >> right); q += 1 + (q / 64)) {
          const std::uint32_t m = (q << right) | half;
          for (std::uint32_t d : {m - 1, m, m + 1})
            check(e | (d & 0x7FFFFFu));
        }
      }
    }
  }
  EXPECT_GT(checked, 2'000'000u);
}

// rule: SNAP.VERTEX.FORMAT
TEST(SnapVertexFormat, SubpixelIsSigned16Dot8) {
  static_assert(std::is_same_v<Subpixel, Fixed<8, std::int32_t>>);
  static_assert(Subpixel::kFracBits == 8 && kSubpixelOne == 256);
  EXPECT_EQ(raw_ok(1.0f), 256);
  EXPECT_EQ(raw_ok(1.25f), 320);
  EXPECT_EQ(raw_ok(-3.5f), -896);
  EXPECT_EQ(raw_ok(0.00390625f), 1); // 2^-8 px, the grid step
  EXPECT_EQ(Subpixel::from_int(5).raw(), 1280);
}

// rule: SNAP.VERTEX.ROUND
TEST(SnapVertexRound, ExactTiesGoToTheEvenInteger) {
  // v * 256 = k + 1/2 exactly.
  EXPECT_EQ(raw_ok(0.5f / 256), 0);
  EXPECT_EQ(raw_ok(1.5f / 256), 2);
  EXPECT_EQ(raw_ok(2.5f / 256), 2);
  EXPECT_EQ(raw_ok(3.5f / 256), 4);
  EXPECT_EQ(raw_ok(1000.5f / 256), 1000);
  EXPECT_EQ(raw_ok(1001.5f / 256), 1002);
  // Between two pixel-centre positions: 0.5 + 1/512 px = 128.5 raw -> 128.
  EXPECT_EQ(raw_ok(0.501953125f), 128);
}

// rule: SNAP.VERTEX.ROUND
TEST(SnapVertexRound, NegativeTiesGoToTheEvenIntegerToo) {
  EXPECT_EQ(raw_ok(-0.5f / 256), 0);
  EXPECT_EQ(raw_ok(-1.5f / 256), -2);
  EXPECT_EQ(raw_ok(-2.5f / 256), -2);
  EXPECT_EQ(raw_ok(-3.5f / 256), -4);
}

// rule: SNAP.VERTEX.ROUND
TEST(SnapVertexRound, JustOffATieRoundsToTheNearer) {
  // 2^-9 is the tie 0.5 raw; the floats next to it are just above and just below.
  const float tie = 0.5f / 256;
  EXPECT_EQ(raw_ok(std::nextafter(tie, 1.0f)), 1);
  EXPECT_EQ(raw_ok(std::nextafter(tie, 0.0f)), 0);
  EXPECT_EQ(raw_ok(-std::nextafter(tie, 1.0f)), -1);
  // 0.1f = 13421773 * 2^-27, times 256 = 25.6000003814697...: 26.
  EXPECT_EQ(raw_ok(0.1f), 26);
  // 1/3 as float, times 256 = 85.33333587646484: 85.
  EXPECT_EQ(raw_ok(1.0f / 3.0f), 85);
  EXPECT_EQ(raw_ok(0.75f / 256), 1);
  EXPECT_EQ(raw_ok(-0.75f / 256), -1);
}

// rule: SNAP.VERTEX.ROUND
TEST(SnapVertexRound, TiesWhereTheFloatGridIsAsCoarseAsHalfASubpixel) {
  // In [2^14, 2^15) the float spacing is 2^-9 px, half a subpixel step: v * 256 is an
  // integer or an exact tie. 16384 + 2^-9 -> 2^22 + 0.5 -> 2^22 (even).
  EXPECT_EQ(raw_ok(16384.001953125f), 4194304);
  EXPECT_EQ(raw_ok(16384.005859375f), 4194306); // 2^22 + 1.5 -> 2^22 + 2
  EXPECT_EQ(raw_ok(-16384.001953125f), -4194304);
  EXPECT_EQ(raw_ok(-16384.005859375f), -4194306);
}

// rule: SNAP.VERTEX.ROUND
TEST(SnapVertexRound, NegativeZeroSnapsToZero) {
  EXPECT_EQ(raw_ok(-0.0f), 0);
  EXPECT_EQ(raw_ok(0.0f), 0);
  EXPECT_EQ(snap_to_subpixel(-0.0f).value, snap_to_subpixel(0.0f).value);
}

// rule: SNAP.VERTEX.ROUND
TEST(SnapVertexRound, SubnormalsSnapToZero) {
  const float smallest = std::numeric_limits<float>::denorm_min(); // 2^-149
  const float largest_subnormal = std::nextafter(std::numeric_limits<float>::min(), 0.0f);
  ASSERT_EQ(std::fpclassify(largest_subnormal), FP_SUBNORMAL);
  EXPECT_EQ(raw_ok(smallest), 0);
  EXPECT_EQ(raw_ok(-smallest), 0);
  EXPECT_EQ(raw_ok(largest_subnormal), 0);
  EXPECT_EQ(raw_ok(-largest_subnormal), 0);
  EXPECT_EQ(raw_ok(std::numeric_limits<float>::min()), 0); // smallest normal, 2^-126
}

// rule: SNAP.VERTEX.RANGE
TEST(SnapVertexRange, LimitsOfTheRangeAreInside) {
  EXPECT_EQ(kMinVertexRaw, -8388608); // -2^23
  EXPECT_EQ(kMaxVertexRaw, 8388607);  // 2^23 - 1
  EXPECT_EQ(raw_ok(-32768.0f), -8388608);
  EXPECT_EQ(raw_ok(32767.99609375f), 8388607); // 2^15 - 2^-8
  EXPECT_EQ(raw_ok(32767.0f), 8388352);
  // 2^15 - 3 * 2^-9 = 32767.994140625 -> 2^23 - 1.5 -> tie -> 2^23 - 2 (even).
  EXPECT_EQ(raw_ok(32767.994140625f), 8388606);
}

// rule: SNAP.VERTEX.RANGE
TEST(SnapVertexRange, ValuesRoundingOutsideTheRangeAreRejected) {
  // 2^15 - 2^-9 is the largest float below 2^15; times 256 it is 2^23 - 0.5, a tie that
  // goes to the even 2^23: one past the largest raw value.
  EXPECT_EQ(status_of(32767.998046875f), SnapStatus::kOutOfRange);
  EXPECT_EQ(status_of(32768.0f), SnapStatus::kOutOfRange);
  EXPECT_EQ(status_of(-32768.00390625f), SnapStatus::kOutOfRange); // -2^23 - 1 raw
  EXPECT_EQ(status_of(1e10f), SnapStatus::kOutOfRange);
  EXPECT_EQ(status_of(std::numeric_limits<float>::max()), SnapStatus::kOutOfRange);
  EXPECT_EQ(status_of(std::numeric_limits<float>::lowest()), SnapStatus::kOutOfRange);
}

// rule: SNAP.VERTEX.RANGE
TEST(SnapVertexRange, MinusHalfASubpixelBelowTheMinimumIsNotAFloat) {
  // Above 2^15 the float spacing is 2^-8, so the decimal -32768.001953125 (= -2^15 - 2^-9)
  // is not a float32: it lies half-way between -32768 and -32768.00390625 and reads, ties to
  // even, as -32768.0f (even significand), which is in range. Scenes read decimal text
  // this way (SCENE.NUMBER.FLOAT32), so such a coordinate is accepted as -32768.
  constexpr float v = -32768.001953125f;
  static_assert(v == -32768.0f);
  EXPECT_EQ(raw_ok(v), kMinVertexRaw);
  // Its neighbour below is a float and is out of range.
  EXPECT_EQ(std::nextafter(v, -1e9f), -32768.00390625f);
  EXPECT_EQ(status_of(std::nextafter(v, -1e9f)), SnapStatus::kOutOfRange);
}

// rule: SNAP.VERTEX.INVALID
TEST(SnapVertexInvalid, NaNAndInfinitiesHaveTheirOwnStatus) {
  EXPECT_EQ(status_of(std::numeric_limits<float>::quiet_NaN()), SnapStatus::kNaN);
  EXPECT_EQ(status_of(-std::numeric_limits<float>::quiet_NaN()), SnapStatus::kNaN);
  EXPECT_EQ(status_of(std::numeric_limits<float>::signaling_NaN()), SnapStatus::kNaN);
  EXPECT_EQ(status_of(std::numeric_limits<float>::infinity()), SnapStatus::kInfinite);
  EXPECT_EQ(status_of(-std::numeric_limits<float>::infinity()), SnapStatus::kInfinite);
  EXPECT_EQ(to_string(SnapStatus::kNaN), "NaN");
  EXPECT_EQ(to_string(SnapStatus::kInfinite), "infinite");
}

} // namespace
} // namespace rastrules
