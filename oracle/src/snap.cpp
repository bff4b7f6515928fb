// SPDX-License-Identifier: MIT
// Oracle snapping: a float32 to 16.8 fixed point with exact rationals (GMP via CGAL::Gmpq).
// Written from spec/rules/snap.md only; shares no code or formula with kernel/src/snap.cpp,
// which works on the float's bit pattern.
// Implements (as oracle): SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE, SNAP.D3D.SATURATE

#include <cmath>
#include <cstdint>
#include <optional>

#include <CGAL/Gmpq.h>
#include <CGAL/Gmpz.h>

#include "rastrules/oracle/triangle.hpp"

namespace rastrules::oracle {
namespace {

using Q = CGAL::Gmpq;
using Z = CGAL::Gmpz;

// FixedMin and FixedMax of signed 16.8 (D3D11.3 3.2.4.1), as raw integers.
constexpr std::int64_t kRawMin = -(std::int64_t{1} << 23);
constexpr std::int64_t kRawMax = (std::int64_t{1} << 23) - 1;

// Returns the exact rational value of a finite float. A float converts to double exactly, and
// mpq_set_d (behind Gmpq(double)) is exact, so no rounding happens anywhere.
Q exact_value(float v) {
  return Q(static_cast<double>(v));
}

// Returns floor(n / d) for d > 0, using only truncating division and a correction.
Z floor_div(const Z& n, const Z& d) {
  Z q = n / d; // truncates towards zero
  if (q * d > n)
    q -= Z(1);
  return q;
}

// Returns the integer nearest to r, ties to the even integer, exactly.
// rule: SNAP.VERTEX.ROUND
Z round_half_even(const Q& r) {
  const Z fl = floor_div(r.numerator(), r.denominator());
  const Q frac = r - Q(fl); // in [0, 1)
  const Q half(1, 2);
  if (frac < half)
    return fl;
  if (frac > half)
    return fl + Z(1);
  const bool fl_even = (fl % Z(2)) == Z(0); // % truncates; 0 means even for either sign
  return fl_even ? fl : fl + Z(1);
}

// Returns z as int64, for |z| small enough (checked by the callers' range tests).
std::int64_t to_int64(const Z& z) {
  return static_cast<std::int64_t>(z.to_double());
}

} // namespace

// rule: SNAP.VERTEX.ROUND, SNAP.VERTEX.RANGE
std::optional<std::int64_t> snap(float v) {
  if (std::isnan(v) || std::isinf(v))
    return std::nullopt;
  const Z r = round_half_even(exact_value(v) * Q(256));
  if (r < Z(kRawMin) || r > Z(kRawMax))
    return std::nullopt;
  return to_int64(r);
}

// rule: SNAP.D3D.SATURATE
std::int64_t snap_d3d_saturate(float v) {
  if (std::isnan(v))
    return 0;
  if (std::isinf(v))
    return v > 0 ? kRawMax : kRawMin;
  const Q x = exact_value(v);
  // |v| < 2^-9 gives 0.
  const Q tiny(1, 512);
  if (x < tiny && x > -tiny)
    return 0;
  // v >= FixedMax = 2^15 - 2^-8 gives FixedMax; v <= FixedMin = -2^15 gives FixedMin.
  if (x >= Q(Z(kRawMax), Z(256)))
    return kRawMax;
  if (x <= Q(Z(kRawMin), Z(256)))
    return kRawMin;
  return to_int64(round_half_even(x * Q(256)));
}

} // namespace rastrules::oracle
