// SPDX-License-Identifier: MIT
// Generators of float32 inputs for snapping: every bit pattern, and the values that break
// rounding rules on purpose (exact ties of 16.8, their neighbours, the range limits,
// subnormals, NaN payloads, infinities).
// Implements (generators for): SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE, SNAP.D3D.SATURATE

#pragma once

#include <ostream>
#include <string_view>

#include <rapidcheck.h>

#include "rastrules/name_table.hpp"

namespace rastrules::gen {

enum class FloatClass {
  kAnyBits,       // a uniformly random 32-bit pattern
  kSubnormal,     // exponent field 0
  kSpecial,       // NaN (any payload), +-Inf, +-0, FLT_MIN, FLT_MAX, the smallest subnormal
  kTie,           // (2k + 1) / 512: exactly half-way between two 16.8 values
  kNearTie,       // one ulp either side of a tie
  kExactSubpixel, // k / 256: snaps without rounding
  kNearLimit,     // within a few ulps of the ends of SNAP.VERTEX.RANGE
  kInRange,       // a random float in [-32768, 32768] with bits below 1/256
};
} // namespace rastrules::gen

namespace rastrules {
template <> struct Names<gen::FloatClass> {
  static constexpr auto table =
      in_enum_order<gen::FloatClass>({"any bits", "subnormal", "special", "tie", "near tie",
                                      "exact subpixel", "near range limit", "in range"});
};
} // namespace rastrules

namespace rastrules::gen {
using rastrules::to_string;

// A float and the class it was built as (for RC_TAG / RC_CLASSIFY).
struct FloatCase {
  float v = 0.0f;
  FloatClass cls = FloatClass::kAnyBits;
};

// Returns a generator mixing every FloatClass.
[[nodiscard]] rc::Gen<FloatCase> float_case();

void showValue(const FloatCase& f, std::ostream& os);

// Writes v so that it reads back as the same float32: shortest round-trip decimal, the bit
// pattern in hex, and "NaN"/"Infinity"/"-Infinity" for the special values.
void show_float(float v, std::ostream& os);

} // namespace rastrules::gen

template <> struct rc::Arbitrary<rastrules::gen::FloatCase> {
  static rc::Gen<rastrules::gen::FloatCase> arbitrary() { return rastrules::gen::float_case(); }
};
