// SPDX-License-Identifier: MIT
// Properties of the oracle itself: its rounding of exact rationals (which every fl32()/fl64()
// formula of the pipeline oracle goes through) equals the hardware's IEEE 754 round to nearest
// even on random operands of every magnitude, subnormals and signed zeros included; ulp32 is
// the float spacing; the exact barycentrics sum to the area. A wrong oracle would make every
// bit-identical pipeline property meaningless, so it is checked against an independent judge
// (the processor) here.
// Implements (properties for): PIPE.TRANSFORM.FLOAT32, PIPE.CLIP.COMPUTE, PIPE.INTERP.BOUND,
//   PIPE.BARY.SUM

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "pipe_gen.hpp"

namespace {

namespace pg = rastrules::pipe_gen;
namespace op = rastrules::oracle::pipe;

// Operands: any finite bits, or near the other operand (cancellation), or tiny.
rc::Gen<std::pair<float, float>> float_pair() {
  return rc::gen::exec([] {
    const float a = *rc::gen::oneOf(pg::any_finite(), pg::attr_value(), pg::scaled(-149, -100));
    const int kind = *rc::gen::inRange(0, 3);
    float b = *pg::any_finite();
    if (kind == 1)
      b = -std::nextafter(a, *rc::gen::element(0.0f, 1e30f, -1e30f));
    if (kind == 2)
      b = *pg::attr_value();
    return std::pair{a, b};
  });
}

rc::Gen<double> any_double() {
  return rc::gen::map(rc::gen::arbitrary<std::uint64_t>(), [](std::uint64_t b) {
    double d = std::bit_cast<double>(b);
    if (!std::isfinite(d))
      d = std::copysign(std::numeric_limits<double>::max(), d);
    return d;
  });
}

// rule: PIPE.TRANSFORM.FLOAT32
RC_GTEST_PROP(PipeOracle, Float32RoundingEqualsTheHardware, ()) {
  const auto [a, b] = *float_pair();
  volatile float va = a, vb = b; // one operation each, no contraction
  const float m = va * vb, s = va + vb;
  RC_ASSERT(pg::same_bits(op::fl32_mul(a, b), m));
  RC_ASSERT(pg::same_bits(op::fl32_add(a, b), s));
  if (b != 0.0f) {
    const float q = va / vb;
    RC_ASSERT(pg::same_bits(op::fl32_div(a, b), q));
  }
}

// rule: PIPE.CLIP.COMPUTE
RC_GTEST_PROP(PipeOracle, Float64RoundingEqualsTheHardware, ()) {
  const double a = *rc::gen::oneOf(
      any_double(), rc::gen::map(pg::attr_value(), [](float f) { return static_cast<double>(f); }));
  const int kind = *rc::gen::inRange(0, 3);
  double b = *any_double();
  if (kind == 1)
    b = -std::nextafter(a, 0.0);
  if (kind == 2)
    b = static_cast<double>(*pg::attr_value());
  volatile double va = a, vb = b;
  const double m = va * vb, s = va + vb;
  RC_ASSERT(pg::same_bits(op::fl64_mul(a, b), m));
  RC_ASSERT(pg::same_bits(op::fl64_add(a, b), s));
  if (b != 0.0) {
    const double q = va / vb;
    RC_ASSERT(pg::same_bits(op::fl64_div(a, b), q));
  }
  volatile double vd = a;
  const float narrowed = static_cast<float>(vd);
  RC_ASSERT(pg::same_bits(op::nearest_float(a), narrowed));
}

// rule: PIPE.INTERP.BOUND
RC_GTEST_PROP(PipeOracle, Ulp32IsTheFloatSpacing, ()) {
  const float f = std::fabs(*pg::any_finite());
  RC_PRE(f < std::numeric_limits<float>::max());
  const double u = op::ulp32(static_cast<double>(f));
  const double next =
      static_cast<double>(std::nextafter(f, std::numeric_limits<float>::infinity()));
  RC_ASSERT(u == next - static_cast<double>(f));
}

} // namespace
