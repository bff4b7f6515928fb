// SPDX-License-Identifier: MIT
// Properties: the floating-point filter of the curve crossing test (PATH.CURVE.FILTER) never
// decides wrongly. For power coefficients of a curve coordinate from random control points
// (quadratic and cubic, small and full-range, with a sample row subtracted), polynomials
// tangent to 0, and grid points t = k / 2^30, chosen at random and next to the polynomial's
// roots (where P(k / 2^30) is tiny) or where x is next to an integer: wherever the filter gives a
// sign, it is the sign of P(k / 2^30) computed exactly here (cpp_int, not the kernel's templates);
// wherever it gives a floor F, F < x(t) < F + 1 holds exactly at both ends of [k, k + 1] / 2^30 and
// at its midpoint. Each case is classified decided / deferred, so that a filter that always defers
// (which would be correct and useless) shows in the tie classes.
// Implements (properties for): PATH.CURVE.FILTER

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "path_detail.hpp"

namespace {

using BigInt = boost::multiprecision::cpp_int;
using Coefs = std::array<std::int64_t, 4>;
namespace kd = rastrules::path::detail;

constexpr std::int64_t kMaxRaw = std::int64_t{1} << 23;
constexpr std::int64_t kGrid = std::int64_t{1} << 30;

// The power coefficients of one coordinate of a quadratic (q[3] unused) or cubic with control
// values q (PATH.CURVE.SAMPLE, written from the Bernstein form), less `shift` in c0.
Coefs power(const std::array<std::int64_t, 4>& q, bool cubic, std::int64_t shift) {
  if (!cubic)
    return {q[0] - shift, 2 * (q[1] - q[0]), q[0] - 2 * q[1] + q[2], 0};
  return {q[0] - shift, 3 * (q[1] - q[0]), 3 * (q[0] - 2 * q[1] + q[2]),
          q[3] - 3 * q[2] + 3 * q[1] - q[0]};
}

// P(n / 2^bits) 2^(3 bits), exactly.
BigInt scaled(const Coefs& c, const BigInt& n, int bits) {
  BigInt r = 0;
  BigInt np = 1;
  for (int j = 0; j <= 3; ++j) {
    BigInt term = c[static_cast<std::size_t>(j)];
    term *= np;
    term <<= static_cast<unsigned>(bits * (3 - j));
    r += term;
    np *= n;
  }
  return r;
}

int sign_of(const BigInt& v) {
  return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

long double value(const Coefs& c, long double t) {
  return ((static_cast<long double>(c[3]) * t + static_cast<long double>(c[2])) * t +
          static_cast<long double>(c[1])) *
             t +
         static_cast<long double>(c[0]);
}

// The roots of P in [0, 1] (long double estimates: sign changes on a fine grid, bisected).
std::vector<long double> roots_of(const Coefs& c) {
  std::vector<long double> out;
  constexpr int kSteps = 256;
  long double a = 0, fa = value(c, 0);
  for (int i = 1; i <= kSteps; ++i) {
    long double b = static_cast<long double>(i) / kSteps, fb = value(c, b);
    if (fa == 0) {
      out.push_back(a);
    } else if ((fa < 0) != (fb < 0) && fb != 0) {
      long double lo = a, hi = b, flo = fa;
      for (int it = 0; it < 80; ++it) {
        const long double mid = (lo + hi) / 2, fm = value(c, mid);
        if ((fm < 0) == (flo < 0)) {
          lo = mid;
          flo = fm;
        } else {
          hi = mid;
        }
      }
      out.push_back(lo);
    }
    a = b;
    fa = fb;
  }
  return out;
}

// Control values of one coordinate: full-range, small, or clustered (nearly constant).
std::array<std::int64_t, 4> controls() {
  const int scale = *rc::gen::element(23, 12, 4);
  const std::int64_t m = std::int64_t{1} << scale;
  const std::int64_t base = *rc::gen::inRange<std::int64_t>(-kMaxRaw + m, kMaxRaw - m + 1);
  std::array<std::int64_t, 4> q{};
  for (std::int64_t& v : q)
    v = scale == 23 ? *rc::gen::inRange<std::int64_t>(-kMaxRaw, kMaxRaw + 1)
                    : base + *rc::gen::inRange<std::int64_t>(-m, m + 1);
  return q;
}

// Grid points to test: two anywhere, and the 33 nearest each estimate t (clamped to
// [0, hi]): where the polynomial is smallest, so where rounding matters.
std::vector<std::int64_t> grid_points(const std::vector<long double>& targets, std::int64_t hi) {
  std::vector<std::int64_t> ks{*rc::gen::inRange<std::int64_t>(0, hi + 1),
                               *rc::gen::inRange<std::int64_t>(0, hi + 1)};
  for (const long double t : targets) {
    const auto k0 = static_cast<std::int64_t>(std::floor(t * static_cast<long double>(kGrid)));
    for (std::int64_t d = -16; d <= 16; ++d)
      ks.push_back(std::min(std::max(k0 + d, std::int64_t{0}), hi));
  }
  return ks;
}

// A polynomial tangent to 0 in [0, 1]: (a t - b)^2 (c t + d), |c_j| <= 2^27. Next to its double
// root b / a (not on the grid unless a is a power of two), P(k / 2^30) is of the order of
// P'' 2^-60: far below the rounding error of Horner's rule in double, where only the error
// bound keeps the filter from guessing a sign.
// Returns its coefficients and the double root b / a.
std::pair<Coefs, long double> tangent() {
  // a^2 |c|, a^2 |d| <= 2^26: large roots' factors with small linear ones, or the reverse.
  const int bits = *rc::gen::inRange(0, 13);
  const std::int64_t a = *rc::gen::inRange<std::int64_t>(1, (std::int64_t{1} << bits) + 1);
  const std::int64_t m = std::int64_t{1} << (24 - 2 * bits);
  const std::int64_t b = *rc::gen::inRange<std::int64_t>(0, a + 1);
  const std::int64_t c = *rc::gen::inRange<std::int64_t>(-m, m + 1);
  std::int64_t d = *rc::gen::inRange<std::int64_t>(-m, m + 1);
  if (c == 0 && d == 0)
    d = 1;
  return {Coefs{b * b * d, b * b * c - 2 * a * b * d, a * a * d - 2 * a * b * c, a * a * c},
          static_cast<long double>(b) / static_cast<long double>(a)};
}

// rule: PATH.CURVE.FILTER
RC_GTEST_PROP(PathCurveFilter, SignIsExactWhereItDecides, ()) {
  const bool cubic = *rc::gen::arbitrary<bool>();
  const std::array<std::int64_t, 4> q = controls();
  const std::int64_t row =
      *rc::gen::element(q[0], q[1], q[2], q[3], (q[0] + q[3]) / 2,
                        *rc::gen::inRange<std::int64_t>(-kMaxRaw, kMaxRaw + 1));
  const bool tangent_case = *rc::gen::arbitrary<bool>();
  Coefs c = power(q, cubic, row);
  std::vector<long double> targets;
  if (tangent_case) {
    long double root = 0;
    std::tie(c, root) = tangent();
    targets.push_back(root); // a sign change would not find it
  }
  RC_CLASSIFY(tangent_case, "tangent polynomial");
  for (const long double r : roots_of(c))
    targets.push_back(r);
  int decided = 0, zero = 0, near = 0;
  for (const std::int64_t k : grid_points(targets, kGrid)) {
    const int exact = sign_of(scaled(c, BigInt(k), 30));
    const std::optional<int> filtered = kd::curve_filter_sign(c, k);
    if (!filtered) {
      ++(exact == 0 ? zero : near);
      continue;
    }
    ++decided;
    RC_LOG() << "coefficients " << c[0] << " " << c[1] << " " << c[2] << " " << c[3] << ", k " << k
             << ": filter " << *filtered << ", exact " << exact << "\n";
    RC_ASSERT(*filtered == exact);
  }
  RC_CLASSIFY(decided > 0, "the filter decides");
  RC_CLASSIFY(zero > 0, "deferred: P(k / 2^30) = 0");
  RC_CLASSIFY(near > 0, "deferred: P(k / 2^30) near 0");
}

// rule: PATH.CURVE.FILTER
RC_GTEST_PROP(PathCurveFilter, FloorHoldsOnTheWholeIntervalWhereItDecides, ()) {
  const bool cubic = *rc::gen::arbitrary<bool>();
  const Coefs e = power(controls(), cubic, 0);
  // Where x is next to an integer: the roots of x - F for F near x at a random t.
  const double t0 = *rc::gen::inRange(0, 1000) / 1000.0;
  const auto f0 = static_cast<std::int64_t>(std::floor(value(e, t0)));
  std::vector<long double> near;
  for (const std::int64_t f : {f0, f0 + 1}) {
    Coefs shifted = e;
    shifted[0] -= f;
    for (const long double r : roots_of(shifted))
      near.push_back(r);
  }
  int decided = 0, deferred = 0;
  for (const std::int64_t k : grid_points(near, kGrid - 1)) {
    const std::optional<std::int64_t> f = kd::curve_filter_floor(e, k);
    if (!f) {
      ++deferred;
      continue;
    }
    ++decided;
    RC_LOG() << "coefficients " << e[0] << " " << e[1] << " " << e[2] << " " << e[3] << ", k " << k
             << ": floor " << *f << "\n";
    // F < x(t) < F + 1 at t = k / 2^30, (k + 1) / 2^30 (30 bits) and (2 k + 1) / 2^31.
    const std::array<std::pair<BigInt, int>, 3> points{
        {{BigInt(k), 30}, {BigInt(k + 1), 30}, {BigInt(2 * k + 1), 31}}};
    for (const auto& [n, bits] : points) {
      const BigInt x = scaled(e, n, bits);
      BigInt lo = *f, hi = *f + 1;
      lo <<= static_cast<unsigned>(3 * bits);
      hi <<= static_cast<unsigned>(3 * bits);
      RC_ASSERT(lo < x);
      RC_ASSERT(x < hi);
    }
  }
  RC_CLASSIFY(decided > 0, "the filter decides");
  RC_CLASSIFY(deferred > 0, "deferred: x within its error bound of an integer");
}

} // namespace
