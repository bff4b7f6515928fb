// SPDX-License-Identifier: MIT
// D3D11.3's saturating float-to-fixed conversion (3.2.4.1) to signed 16.8, offered as a
// library function (the scene path rejects instead, SNAP.VERTEX.INVALID).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "rastrules/fixed.hpp"
#include "rastrules/snap.hpp"

namespace rastrules {
namespace {

std::int32_t sat(float v) {
  return snap_d3d_saturate(v).raw();
}

// rule: SNAP.D3D.SATURATE
TEST(SnapD3DSaturate, NaNGivesZero) {
  EXPECT_EQ(sat(std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(sat(-std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(sat(std::numeric_limits<float>::signaling_NaN()), 0);
}

// rule: SNAP.D3D.SATURATE
TEST(SnapD3DSaturate, InfinitiesGiveFixedMaxAndFixedMin) {
  EXPECT_EQ(sat(std::numeric_limits<float>::infinity()), 8388607);   // FixedMax = 2^15 - 2^-8
  EXPECT_EQ(sat(-std::numeric_limits<float>::infinity()), -8388608); // FixedMin = -2^15
}

// rule: SNAP.D3D.SATURATE
TEST(SnapD3DSaturate, OutOfRangeValuesSaturate) {
  EXPECT_EQ(sat(32768.0f), 8388607);
  EXPECT_EQ(sat(1e10f), 8388607);
  EXPECT_EQ(sat(std::numeric_limits<float>::max()), 8388607);
  EXPECT_EQ(sat(-32768.00390625f), -8388608);
  EXPECT_EQ(sat(-1e10f), -8388608);
  EXPECT_EQ(sat(std::numeric_limits<float>::lowest()), -8388608);
  // 2^15 - 2^-9 is above FixedMax: saturates (rounding alone would give 2^23).
  EXPECT_EQ(sat(32767.998046875f), 8388607);
}

// rule: SNAP.D3D.SATURATE
TEST(SnapD3DSaturate, LimitsAreKept) {
  EXPECT_EQ(sat(32767.99609375f), 8388607);
  EXPECT_EQ(sat(-32768.0f), -8388608);
  EXPECT_EQ(sat(32767.9921875f), 8388606);
  EXPECT_EQ(sat(-32767.99609375f), -8388607);
}

// rule: SNAP.D3D.SATURATE
TEST(SnapD3DSaturate, TinyValuesGiveZero) {
  EXPECT_EQ(sat(std::numeric_limits<float>::denorm_min()), 0);
  EXPECT_EQ(sat(-std::numeric_limits<float>::denorm_min()), 0);
  EXPECT_EQ(sat(std::ldexp(1.0f, -10)), 0); // below 2^-9: early exit
  EXPECT_EQ(sat(-std::ldexp(1.0f, -10)), 0);
  EXPECT_EQ(sat(std::ldexp(1.0f, -9)), 0); // exactly 2^-9: 0.5 raw, tie to even 0
  EXPECT_EQ(sat(-0.0f), 0);
}

// rule: SNAP.D3D.SATURATE
TEST(SnapD3DSaturate, InRangeValuesRoundHalfToEven) {
  EXPECT_EQ(sat(1.5f / 256), 2);
  EXPECT_EQ(sat(2.5f / 256), 2);
  EXPECT_EQ(sat(-1.5f / 256), -2);
  EXPECT_EQ(sat(0.75f / 256), 1);
  EXPECT_EQ(sat(1.25f), 320);
  EXPECT_EQ(sat(16384.001953125f), 4194304);
  // Agrees with snap_to_subpixel wherever that one succeeds.
  for (const float v : {0.1f, -7.3f, 100.125f, -32000.5f, 1234.5678f}) {
    EXPECT_EQ(sat(v), snap_to_subpixel(v).value.raw()) << v;
  }
}

} // namespace
} // namespace rastrules
