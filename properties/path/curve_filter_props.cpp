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

// The quadratic rows of the filter (quadratic_crossings: the quadratic formula's error bound,
// PATH.CURVE.FILTER): a quadratic curve's crossings of a sample row by the integer paths (the
// filter first) equal the rational path's, with every tie sign, on rows chosen where the filter
// is most likely to be wrong: next to the y-extremum (two roots close together, a tiny
// discriminant), one raw unit from an end's y (a root next to t = 0 or 1), through the point at
// t = 1/2 made a whole raw point (x_c an integer: only the tie sign decides), and anywhere. Found
// necessary 2026-11-28, when the quadratic rows stopped being confined on the 2^30 grid.
// rule: PATH.CURVE.FILTER, PATH.CURVE.SAMPLE
RC_GTEST_PROP(PathCurveFilter, QuadraticRowsGiveTheRationalPathsCrossings, ()) {
  std::array<std::int64_t, 4> xs = controls(), ys = controls();
  const int kind = *rc::gen::element(0, 1, 2, 3);
  if (kind == 3) { // q0 + 2 q1 + q2 = 0 mod 4: the point at t = 1/2 is a raw point
    for (std::array<std::int64_t, 4>* q : {&xs, &ys}) {
      std::array<std::int64_t, 4>& v = *q;
      v[0] = std::clamp(v[0], -kMaxRaw + 4, kMaxRaw - 4);
      v[1] = std::clamp(v[1], -kMaxRaw + 4, kMaxRaw - 4);
      v[2] = std::clamp(v[2], -kMaxRaw + 4, kMaxRaw - 4);
      if ((v[0] + v[2]) % 2 != 0)
        ++v[2];
      if (((v[0] + v[2]) / 2 + v[1]) % 2 != 0)
        ++v[1];
    }
  }
  kd::Curve c;
  c.degree = 2;
  for (std::size_t k = 0; k < 3; ++k)
    c.p[k] =
        rastrules::path::Point{static_cast<std::int32_t>(std::clamp(xs[k], -kMaxRaw, kMaxRaw - 1)),
                               static_cast<std::int32_t>(std::clamp(ys[k], -kMaxRaw, kMaxRaw - 1))};
  c.p[3] = c.p[2];
  const std::int64_t y0 = c.p[0].y, y1 = c.p[1].y, y2 = c.p[2].y;
  const std::int64_t lo = std::min({y0, y1, y2}), hi = std::max({y0, y1, y2});
  // The y-extremum at t = (y0 - y1) / (y0 - 2 y1 + y2), where the rows' two roots meet.
  const std::int64_t a = y0 - 2 * y1 + y2;
  std::int64_t extremum = lo + (hi - lo) / 2;
  if (a != 0) {
    const long double t = static_cast<long double>(y0 - y1) / static_cast<long double>(a);
    if (t > 0 && t < 1)
      extremum = std::llround((1 - t) * (1 - t) * y0 + 2 * t * (1 - t) * y1 + t * t * y2);
  }
  std::int64_t sy = 0;
  if (kind == 3)
    sy = (y0 + 2 * y1 + y2) / 4;
  else if (kind == 0)
    sy = extremum + *rc::gen::inRange<std::int64_t>(-3, 4);
  else if (kind == 1)
    sy = *rc::gen::element(y0, y2) + *rc::gen::element<std::int64_t>(-1, 1);
  else
    sy = *rc::gen::inRange<std::int64_t>(lo, hi + 1);
  const kd::Tie t{*rc::gen::arbitrary<bool>(), *rc::gen::arbitrary<bool>()};
  std::vector<kd::Crossing> fast = kd::curve_crossings(c, sy, t);
  std::vector<kd::Crossing> exact = kd::curve_crossings_exact(c, sy, t);
  const auto key = [](const kd::Crossing& p, const kd::Crossing& q) {
    return std::tie(p.threshold, p.dir) < std::tie(q.threshold, q.dir);
  };
  std::sort(fast.begin(), fast.end(), key);
  std::sort(exact.begin(), exact.end(), key);
  RC_CLASSIFY(kind == 0, "row next to the y-extremum");
  RC_CLASSIFY(kind == 1, "row next to an end");
  RC_CLASSIFY(kind == 3, "row through the raw point at t = 1/2");
  RC_CLASSIFY(exact.size() == 2, "two crossings");
  RC_CLASSIFY(exact.size() == 1, "one crossing");
  RC_ASSERT(fast.size() == exact.size());
  for (std::size_t i = 0; i < fast.size(); ++i) {
    RC_ASSERT(fast[i].threshold == exact[i].threshold);
    RC_ASSERT(fast[i].dir == exact[i].dir);
  }
}

} // namespace
