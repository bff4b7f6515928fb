// SPDX-License-Identifier: MIT
// Properties: the kernel's interpolated depth lies within 2^-50 S of the exact screen-linear
// depth; the clamped, converted value satisfies PIPE.DEPTH.BOUND for d16, d24 and d32f (the
// exactly rounded value, or one UNORM step off only next to a half-integer) and lies in the
// format's range; a float32 depth (the clear value) converts exactly; the depth test compares
// as the spec's table says. Depths at and next to 0 and 1, tiny, outside [0, 1]; depth ranges
// that are a point or one float step wide; triangles of every kind.
// Implements (properties for): PIPE.DEPTH.INTERP, PIPE.DEPTH.CLAMP, PIPE.DEPTH.FORMAT,
//   PIPE.DEPTH.BOUND, PIPE.DEPTH.TEST, PIPE.DEPTH.BIAS

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "pipe_gen.hpp"

namespace {

namespace pg = rastrules::pipe_gen;
namespace op = rastrules::oracle::pipe;
namespace kp = rastrules::pipe;

std::uint32_t unorm_max(kp::DepthFormat f) {
  return f == kp::DepthFormat::kD16 ? 0xFFFFu : 0xFFFFFFu;
}

// rule: PIPE.DEPTH.INTERP, PIPE.DEPTH.CLAMP, PIPE.DEPTH.FORMAT, PIPE.DEPTH.BOUND
RC_GTEST_PROP(PipeDepth, InterpolatedAndStoredWithinTheBound, ()) {
  const pg::RawTri t = *pg::full_size(pg::raw_triangle(false));
  const pg::Raw2 s = *pg::full_size(pg::sample_for(t));
  const std::array<float, 3> z = *pg::full_size(pg::depth_triple());
  const auto [lo, hi] = *pg::depth_range();
  const kp::DepthFormat f = *pg::depth_format();
  const std::string fname = pg::depth_format_name(f);
  const kp::Barycentrics b = kp::barycentrics(pg::to_vec2(t), pg::to_vec2(s));
  const op::Bary ob = op::barycentrics(t, s);
  const double zi = kp::interpolate_depth(b, z);
  const std::string where = "triangle " + pg::rs(t) + ", sample " + pg::rs(s) + ", Z " + pg::fs(z) +
                            ", range [" + pg::fs(lo) + ", " + pg::fs(hi) + "]";
  const op::DepthCheck ci = op::check_depth_interp(ob, z, zi);
  if (!ci.ok)
    RC_FAIL(where + ": interpolate_depth: " + ci.describe(fname));
  const kp::DepthValue v = kp::to_depth_format(zi, lo, hi, f);
  op::DepthCheck cs = op::check_depth_stored(ob, z, lo, hi, fname, pg::to_oracle(v));
  cs.got_z = zi;
  if (!cs.ok)
    RC_FAIL(where + ": to_depth_format: " + cs.describe(fname));
  if (f == kp::DepthFormat::kD32F) {
    RC_ASSERT(v.f >= lo);
    RC_ASSERT(v.f <= hi);
  } else {
    RC_ASSERT(v.unorm <= unorm_max(f));
  }
  RC_CLASSIFY(op::inside_closed(ob), "inside");
  RC_CLASSIFY(!(cs.expected == pg::to_oracle(v)), "one step off the exactly rounded value");
  RC_CLASSIFY(ci.exact < lo || ci.exact > hi, "clamped");
}

// Depths made to round on a knife's edge: the sample is the midpoint of an edge (the triangle's
// coordinates are even), so the exact depth is the mean of two vertex depths, which are chosen
// as two adjacent floats (an exact d32f tie) or around (k + 1/2) / (2^n - 1) (a UNORM half step).
rc::Gen<std::pair<float, float>> tie_depths() {
  return rc::gen::exec([] {
    if (*rc::gen::arbitrary<bool>()) {
      const float z = std::fabs(*pg::depth_value());
      return std::pair{z, std::nextafter(z, 2.0f)};
    }
    const double scale = *rc::gen::element(65535.0, 16777215.0);
    const double k =
        static_cast<double>(*rc::gen::inRange<std::int64_t>(0, static_cast<std::int64_t>(scale)));
    const double t = (k + 0.5) / scale;
    const int ulps = *rc::gen::inRange(0, 4);
    float lo = static_cast<float>(t), hi = lo;
    for (int i = 0; i < ulps; ++i) {
      lo = std::nextafter(lo, 0.0f);
      hi = std::nextafter(hi, 2.0f);
    }
    return std::pair{lo, hi};
  });
}

// rule: PIPE.DEPTH.INTERP, PIPE.DEPTH.FORMAT, PIPE.DEPTH.BOUND
RC_GTEST_PROP(PipeDepth, StoredWithinTheBoundAtTies, ()) {
  pg::RawTri t = *pg::full_size(pg::raw_triangle(false));
  for (auto& v : t) {
    for (auto& c : v)
      c = std::clamp<std::int64_t>(c / 2 * 2, pg::kRawMin, pg::kRawMax - 1);
  }
  RC_PRE(pg::twice_area(t) != 0);
  const auto k = static_cast<std::size_t>(*rc::gen::inRange(0, 3));
  const pg::Raw2 s{(t[k][0] + t[(k + 1) % 3][0]) / 2, (t[k][1] + t[(k + 1) % 3][1]) / 2};
  const auto [za, zb] = *tie_depths();
  std::array<float, 3> z{};
  z[k] = za;
  z[(k + 1) % 3] = zb;
  z[(k + 2) % 3] = *pg::depth_value();
  const kp::DepthFormat f = *pg::depth_format();
  const std::string fname = pg::depth_format_name(f);
  const kp::Barycentrics b = kp::barycentrics(pg::to_vec2(t), pg::to_vec2(s));
  const op::Bary ob = op::barycentrics(t, s);
  const double zi = kp::interpolate_depth(b, z);
  const kp::DepthValue v = kp::to_depth_format(zi, 0.0f, 1.0f, f);
  op::DepthCheck c = op::check_depth_stored(ob, z, 0.0f, 1.0f, fname, pg::to_oracle(v));
  c.got_z = zi;
  if (!c.ok)
    RC_FAIL("triangle " + pg::rs(t) + ", sample " + pg::rs(s) + ", Z " + pg::fs(z) + ": " +
            c.describe(fname));
  RC_CLASSIFY(!(c.lo == c.hi), "two stored values allowed");
  RC_CLASSIFY(!(c.expected == pg::to_oracle(v)), "one step off the exactly rounded value");
}

// Float32 depths (the clear value, vertex depths at a vertex) convert without error: the
// product z (2^n - 1) and the + 1/2 are exact in double.
// rule: PIPE.DEPTH.FORMAT, PIPE.DEPTH.CLAMP
RC_GTEST_PROP(PipeDepth, Float32DepthsConvertExactly, ()) {
  const float z = *pg::full_size(pg::depth_value());
  const auto [lo, hi] = *pg::depth_range();
  const kp::DepthFormat f = *pg::depth_format();
  const kp::DepthValue got = kp::to_depth_format(static_cast<double>(z), lo, hi, f);
  const op::Stored want = op::store_exact(static_cast<double>(z), lo, hi, pg::depth_format_name(f));
  if (!(pg::to_oracle(got) == want)) {
    RC_FAIL("z " + pg::fs(z) + ", range [" + pg::fs(lo) + ", " + pg::fs(hi) + "], " +
            pg::depth_format_name(f) + ": kernel (" + std::to_string(got.unorm) + ", " +
            pg::fs(got.f) + "), exact (" + std::to_string(want.unorm) + ", " + pg::fs(want.f) +
            ")");
  }
}

// rule: PIPE.DEPTH.BIAS
RC_GTEST_PROP(PipeDepth, BiasIsTheSpecFormula, ()) {
  const pg::RawTri t = *pg::full_size(pg::raw_triangle(true));
  // Sometimes every depth subnormal (where the d32f exponent is at its floor).
  const std::array<float, 3> z = *rc::gen::weightedOneOf<std::array<float, 3>>({
      {5, pg::full_size(pg::depth_triple())},
      {1, rc::gen::apply(
              [](float a, float b, float c) {
                return std::array<float, 3>{std::fabs(a), std::fabs(b), std::fabs(c)};
              },
              pg::scaled(-149, -127), pg::scaled(-149, -127), pg::scaled(-149, -127))},
  });
  const kp::DepthBias b = *pg::depth_bias_state();
  const int fi = *rc::gen::inRange(0, 4);
  const std::optional<kp::DepthFormat> f =
      fi == 3 ? std::nullopt : std::optional<kp::DepthFormat>(static_cast<kp::DepthFormat>(fi));
  const std::string fname = f ? pg::depth_format_name(*f) : "";
  const float got = kp::depth_bias(pg::to_vec2(t), z, b, f);
  const float want = op::depth_bias(t, z, b.bias, b.slope_scaled, b.clamp, fname);
  if (!pg::same_bits(got, want)) {
    RC_FAIL("triangle " + pg::rs(t) + ", Z " + pg::fs(z) + ", bias " + std::to_string(b.bias) +
            ", slope_scaled " + pg::fs(b.slope_scaled) + ", clamp " + pg::fs(b.clamp) +
            ", format '" + fname + "': kernel " + pg::fs(got) + ", oracle " + pg::fs(want));
  }
  RC_CLASSIFY(b.slope_scaled != 0.0f, "slope term");
  RC_CLASSIFY(pg::twice_area(t) == 0, "degenerate");
  RC_CLASSIFY(std::fabs(z[0]) < 0x1p-126f && std::fabs(z[1]) < 0x1p-126f &&
                  std::fabs(z[2]) < 0x1p-126f,
              "subnormal depths");
}

// rule: PIPE.DEPTH.TEST
RC_GTEST_PROP(PipeDepth, TestFollowsTheComparisonTable, ()) {
  const kp::DepthFormat f = *pg::depth_format();
  const kp::CompareFunc func = *pg::compare_func();
  const auto [lo, hi] = *pg::depth_range();
  const float a = *pg::depth_value();
  const bool same = *rc::gen::inRange(0, 3) == 0;
  const float b = same ? a : *pg::depth_value();
  const kp::DepthValue now = kp::to_depth_format(a, lo, hi, f);
  const kp::DepthValue old = kp::to_depth_format(b, lo, hi, f);
  const bool got = kp::depth_test(func, now, old, f);
  const bool want = op::depth_test(pg::compare_name(func), pg::to_oracle(now), pg::to_oracle(old),
                                   pg::depth_format_name(f));
  RC_ASSERT(got == want);
  RC_CLASSIFY(now == old, "equal values");
}

} // namespace
