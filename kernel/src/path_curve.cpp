// SPDX-License-Identifier: MIT
// 2D paths: the crossings of quadratic and cubic Bézier curves with a sample row, exactly
// (PATH.CURVE.SAMPLE). No flattening: the roots of y(t) - s.y in [0, 1] are found exactly
// (multiple roots are rational for degree <= 3; simple roots are isolated by Bernstein
// subdivision of the square-free part), and each crossing's x is compared with integers by
// exact sign determination at the root (a gcd decides x(t_c) == k; otherwise the isolating
// interval is refined until x - k has one sign on it). All arithmetic in cpp_rational.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "path_detail.hpp"
#include "rastrules/fixed.hpp"
#include "rastrules/formula/path_curve.hpp"

namespace rastrules::path::detail {
namespace {

using Rational = boost::multiprecision::cpp_rational;
using BigInt = boost::multiprecision::cpp_int;

// A polynomial in t with rational coefficients, lowest degree first, no trailing zeros (the
// zero polynomial is empty).
using Poly = std::vector<Rational>;

void trim(Poly& p) {
  while (!p.empty() && p.back() == 0)
    p.pop_back();
}

int degree(const Poly& p) {
  return static_cast<int>(p.size()) - 1;
} // -1 for zero

Rational eval(const Poly& p, const Rational& t) {
  Rational v = 0;
  for (std::size_t k = p.size(); k-- > 0;)
    v = v * t + p[k];
  return v;
}

int sign(const Rational& v) {
  return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

Poly derivative(const Poly& p) {
  Poly d;
  for (std::size_t k = 1; k < p.size(); ++k)
    d.push_back(p[k] * static_cast<long long>(k));
  trim(d);
  return d;
}

// Returns (quotient, remainder) of a / b, b != 0.
std::pair<Poly, Poly> divide(Poly a, const Poly& b) {
  const int db = degree(b);
  Poly q(static_cast<std::size_t>(std::max(0, degree(a) - db + 1)));
  while (degree(a) >= db) {
    const int shift = degree(a) - db;
    const Rational c = a.back() / b.back();
    q[static_cast<std::size_t>(shift)] = c;
    for (int k = 0; k <= db; ++k)
      a[static_cast<std::size_t>(k + shift)] -= c * b[static_cast<std::size_t>(k)];
    a.pop_back(); // the leading term is now zero by construction
    trim(a);
  }
  trim(q);
  return {q, a};
}

// Returns the monic greatest common divisor (the zero polynomial when both are zero).
Poly gcd(Poly a, Poly b) {
  while (!b.empty()) {
    Poly r = divide(a, b).second;
    a = std::move(b);
    b = std::move(r);
  }
  if (!a.empty()) {
    const Rational lead = a.back();
    for (Rational& c : a)
      c /= lead;
  }
  return a;
}

// Returns p(t) / (t - r) for a root r of p.
Poly deflate(const Poly& p, const Rational& r) {
  return divide(p, Poly{-r, Rational(1)}).first;
}

// C(n, k) for n <= 3.
long long binomial(int n, int k) {
  static constexpr long long kTable[4][4] = {
      {1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
  return kTable[n][k];
}

// Returns the Bernstein coefficients of p (degree n >= 0) on [lo, hi]: p(lo + (hi - lo) s) in
// the Bernstein basis of degree n in s. Their signs bound the number of roots in (lo, hi)
// (Descartes' rule of signs), and their range contains p's values on [lo, hi].
std::vector<Rational> bernstein(const Poly& p, const Rational& lo, const Rational& hi) {
  const int n = degree(p);
  if (n < 0)
    return {Rational(0)};
  const Rational w = hi - lo;
  // Power coefficients in s: c_k = sum_{j >= k} p_j C(j, k) lo^(j - k) w^k.
  std::vector<Rational> c(static_cast<std::size_t>(n + 1), Rational(0));
  std::array<Rational, 4> lo_pow{Rational(1)}, w_pow{Rational(1)};
  for (int k = 1; k <= n; ++k) {
    lo_pow[static_cast<std::size_t>(k)] = lo_pow[static_cast<std::size_t>(k - 1)] * lo;
    w_pow[static_cast<std::size_t>(k)] = w_pow[static_cast<std::size_t>(k - 1)] * w;
  }
  for (int j = 0; j <= n; ++j)
    for (int k = 0; k <= j; ++k)
      c[static_cast<std::size_t>(k)] += p[static_cast<std::size_t>(j)] * binomial(j, k) *
                                        lo_pow[static_cast<std::size_t>(j - k)] *
                                        w_pow[static_cast<std::size_t>(k)];
  // Power to Bernstein: b_i = sum_{k <= i} C(i, k) / C(n, k) c_k.
  std::vector<Rational> b(static_cast<std::size_t>(n + 1), Rational(0));
  for (int i = 0; i <= n; ++i)
    for (int k = 0; k <= i; ++k)
      b[static_cast<std::size_t>(i)] +=
          Rational(binomial(i, k), binomial(n, k)) * c[static_cast<std::size_t>(k)];
  return b;
}

int sign_variations(const std::vector<Rational>& b) {
  int v = 0, last = 0;
  for (const Rational& c : b) {
    const int s = sign(c);
    if (s == 0)
      continue;
    if (last != 0 && s != last)
      ++v;
    last = s;
  }
  return v;
}

// A root of y(t) - s.y in [0, 1]: exact (lo == hi), or the only root of the square-free `iso`
// in (lo, hi), with iso(lo), iso(hi) != 0. Irrational roots are always of the second kind.
struct Root {
  Rational lo, hi;
  bool exact = false;
  Poly iso;
};

// A polynomial rounded to double, for guesses only (never for a decision).
class Approximation {
public:
  explicit Approximation(const Poly& p) {
    for (const Rational& q : p)
      c_.push_back(q.convert_to<double>());
  }
  double operator()(double t) const {
    double v = 0;
    for (std::size_t k = c_.size(); k-- > 0;)
      v = v * t + c_[k];
    return v;
  }

private:
  std::vector<double> c_;
};

// Returns an estimate of the only root of iso in (lo, hi) (where it changes sign), by
// bisection in double: only a guess, which tighten() certifies exactly.
double approximate_root(const Poly& iso, const Rational& lo, const Rational& hi) {
  const Approximation f(iso);
  double a = lo.convert_to<double>(), b = hi.convert_to<double>();
  const bool neg_a = f(a) < 0;
  for (int i = 0; i < 80; ++i) {
    const double m = 0.5 * (a + b);
    if (m <= a || m >= b)
      break;
    ((f(m) < 0) == neg_a ? a : b) = m;
  }
  return 0.5 * (a + b);
}

// Narrows a root's interval to a small dyadic one around a floating-point estimate, exactly:
// the new ends lie in [lo, hi] and iso changes sign between them (or one is the root). Leaves
// the interval as it was when no candidate is certified.
void tighten(Root& r) {
  if (r.exact)
    return;
  const Rational tc(approximate_root(r.iso, r.lo, r.hi)); // a double converts exactly
  const int s_lo = sign(eval(r.iso, r.lo));
  for (const unsigned e : {44u, 32u, 20u}) {
    const Rational eps(BigInt(1), BigInt(1) << e);
    const Rational l = std::max(r.lo, Rational(tc - eps));
    const Rational u = std::min(r.hi, Rational(tc + eps));
    if (!(l < u))
      continue;
    const int sl = sign(eval(r.iso, l));
    const int su = sign(eval(r.iso, u));
    if (sl == 0 || su == 0) {
      r.lo = r.hi = sl == 0 ? l : u;
      r.exact = true;
      return;
    }
    if (sl == s_lo && su == -s_lo) {
      r.lo = l;
      r.hi = u;
      return;
    }
  }
}

// Returns the sign of h at the root (exact; refines the root's interval).
int sign_at(const Poly& h, Root& r) {
  if (r.exact)
    return sign(eval(h, r.lo));
  if (h.empty())
    return 0;
  if (degree(h) == 0)
    return sign(h[0]);
  tighten(r);
  if (r.exact)
    return sign(eval(h, r.lo));
  // Usually h has one strict sign on the tight interval already: no gcd needed.
  {
    const std::vector<Rational> b = bernstein(h, r.lo, r.hi);
    if (std::all_of(b.begin(), b.end(), [](const Rational& c) { return c > 0; }))
      return 1;
    if (std::all_of(b.begin(), b.end(), [](const Rational& c) { return c < 0; }))
      return -1;
  }
  // h(t_c) == 0 iff t_c is a root of gcd(iso, h): a simple root there, so a sign change.
  const Poly g = gcd(r.iso, h);
  if (degree(g) >= 1 && sign(eval(g, r.lo)) * sign(eval(g, r.hi)) < 0)
    return 0;
  // h(t_c) != 0: refine until h has one strict sign on [lo, hi] (it does near t_c).
  const int s_lo = sign(eval(r.iso, r.lo));
  for (;;) {
    const std::vector<Rational> b = bernstein(h, r.lo, r.hi);
    if (std::all_of(b.begin(), b.end(), [](const Rational& c) { return c > 0; }))
      return 1;
    if (std::all_of(b.begin(), b.end(), [](const Rational& c) { return c < 0; }))
      return -1;
    const Rational m = (r.lo + r.hi) / 2;
    const int s_m = sign(eval(r.iso, m));
    if (s_m == 0) {
      r.lo = r.hi = m;
      r.exact = true;
      return sign(eval(h, m));
    }
    (s_m == s_lo ? r.lo : r.hi) = m;
  }
}

// Returns the intervals [i/64, (i+1)/64] of [0, 1] where p changes sign, exactly (ends where p
// is 0 are left out), found by a scan in double and then checked in rationals.
std::vector<std::pair<Rational, Rational>> sign_change_candidates(const Poly& p) {
  const Approximation f(p);
  constexpr int kSteps = 64;
  std::vector<std::pair<Rational, Rational>> out;
  for (int i = 0; i < kSteps; ++i) {
    const double a = static_cast<double>(i) / kSteps, b = static_cast<double>(i + 1) / kSteps;
    if ((f(a) < 0) == (f(b) < 0))
      continue;
    Rational lo(i, kSteps), hi(i + 1, kSteps);
    const int sa = sign(eval(p, lo));
    const int sb = sign(eval(p, hi));
    if (sa != 0 && sb != 0 && sa != sb)
      out.emplace_back(std::move(lo), std::move(hi));
  }
  return out;
}

// Returns every distinct root of g (not the zero polynomial, degree <= 3) in [0, 1].
std::vector<Root> roots_in_unit_interval(const Poly& g) {
  std::vector<Root> out;
  if (degree(g) < 1)
    return out;
  // Fast path, no gcd: when 0 and 1 are not roots, V (the sign variations of g's Bernstein
  // coefficients on [0, 1]) bounds the roots in (0, 1) counted with multiplicity; V disjoint
  // intervals with an exact sign change of g each then hold exactly one simple root.
  if (eval(g, Rational(0)) != 0 && eval(g, Rational(1)) != 0) {
    const int v = sign_variations(bernstein(g, Rational(0), Rational(1)));
    if (v == 0)
      return out;
    const std::vector<std::pair<Rational, Rational>> c = sign_change_candidates(g);
    if (static_cast<int>(c.size()) == v) {
      for (const auto& [lo, hi] : c)
        out.push_back(Root{lo, hi, false, g});
      return out;
    }
  }
  // Multiple roots are the roots of gcd(g, g'): rational for degree <= 3.
  const Poly common = gcd(g, derivative(g));
  Poly free = divide(g, common).first; // square-free, the same distinct roots
  std::vector<Rational> exact;
  if (degree(common) == 1)
    exact.push_back(-common[0] / common[1]);
  else if (degree(common) == 2) // (t - r)^2, monic
    exact.push_back(-common[1] / 2);
  for (const Rational& r : exact)
    free = deflate(free, r);
  std::vector<Rational> found;
  for (const Rational& r : exact)
    if (r >= 0 && r <= 1)
      found.push_back(r);
  for (const Rational& e : {Rational(0), Rational(1)}) {
    if (degree(free) >= 1 && eval(free, e) == 0) {
      found.push_back(e);
      free = deflate(free, e);
    }
  }
  // Isolate the remaining (simple) roots in (0, 1); a midpoint that is a root is deflated
  // and the isolation restarts (at most three times).
  std::vector<std::pair<Rational, Rational>> isolated;
  // Fast path: the Bernstein coefficients on [0, 1] bound the number of roots in (0, 1) by
  // their sign variations V (and have its parity); V disjoint intervals with an exact sign
  // change each hold exactly one root each. Candidates come from a scan in double.
  if (degree(free) >= 1) {
    const int v = sign_variations(bernstein(free, Rational(0), Rational(1)));
    if (v == 0) {
      for (const Rational& r : found)
        out.push_back(Root{r, r, true, {}});
      return out;
    }
    const std::vector<std::pair<Rational, Rational>> candidates = sign_change_candidates(free);
    const bool certified = static_cast<int>(candidates.size()) == v;
    if (certified) {
      for (const Rational& r : found)
        out.push_back(Root{r, r, true, {}});
      for (const auto& [lo, hi] : candidates)
        out.push_back(Root{lo, hi, false, free});
      return out;
    }
  }
  bool restart = true;
  while (restart) {
    restart = false;
    isolated.clear();
    if (degree(free) < 1)
      break;
    std::vector<std::pair<Rational, Rational>> todo{{Rational(0), Rational(1)}};
    while (!todo.empty() && !restart) {
      const auto [lo, hi] = todo.back();
      todo.pop_back();
      const int v = sign_variations(bernstein(free, lo, hi));
      if (v == 0)
        continue;
      if (v == 1) {
        isolated.emplace_back(lo, hi);
        continue;
      }
      const Rational m = (lo + hi) / 2;
      if (eval(free, m) == 0) {
        found.push_back(m);
        free = deflate(free, m);
        restart = true;
        break;
      }
      todo.emplace_back(lo, m);
      todo.emplace_back(m, hi);
    }
  }
  for (const Rational& r : found)
    out.push_back(Root{r, r, true, {}});
  for (const auto& [lo, hi] : isolated)
    out.push_back(Root{lo, hi, false, free});
  return out;
}

// Returns the power-basis coefficients (integers) of one coordinate of a Bézier curve.
Poly power_basis(const std::array<std::int64_t, 4>& c, int deg) {
  const std::array<std::int64_t, 4> w = formula::curve_power_coefficients(c, deg == 3);
  Poly p{Rational(w[0]), Rational(w[1]), Rational(w[2]), Rational(w[3])};
  trim(p);
  return p;
}

// Returns floor(q) for a rational q.
BigInt floor_of(const Rational& q) {
  const BigInt n = boost::multiprecision::numerator(q);
  const BigInt d = boost::multiprecision::denominator(q);
  BigInt f = n / d;
  if (n < 0 && f * d != n)
    f -= 1;
  return f;
}

// Returns the threshold of a crossing at x(t_c): the largest integer X it counts for (x_c > X,
// or x_c == X and hx = -1).
std::int64_t threshold_at(const Poly& x, Root& r, Tie t) {
  BigInt f;
  bool integral = false;
  if (r.exact) {
    const Rational xc = eval(x, r.lo);
    f = floor_of(xc);
    integral = Rational(f) == xc;
  } else {
    // Narrow the root until x varies by less than 1 on its interval, so that floor(x_c) is
    // k or k + 1 with k = floor(min), then decide exactly.
    tighten(r);
    if (r.exact)
      return threshold_at(x, r, t);
    std::vector<Rational> b = bernstein(x, r.lo, r.hi);
    while (!r.exact &&
           *std::max_element(b.begin(), b.end()) - *std::min_element(b.begin(), b.end()) >= 1) {
      const Rational m = (r.lo + r.hi) / 2;
      const int s_m = sign(eval(r.iso, m));
      if (s_m == 0) {
        r.lo = r.hi = m;
        r.exact = true;
        break;
      }
      (s_m == sign(eval(r.iso, r.lo)) ? r.lo : r.hi) = m;
      b = bernstein(x, r.lo, r.hi);
    }
    if (r.exact)
      return threshold_at(x, r, t);
    const BigInt k = floor_of(*std::min_element(b.begin(), b.end()));
    Poly shifted = x;
    if (shifted.empty())
      shifted.push_back(Rational(0));
    shifted[0] -= Rational(k + 1);
    trim(shifted);
    const int s1 = sign_at(shifted, r);
    if (s1 >= 0) {
      f = k + 1;
      integral = s1 == 0;
    } else {
      shifted = x;
      if (shifted.empty())
        shifted.push_back(Rational(0));
      shifted[0] -= Rational(k);
      trim(shifted);
      f = k;
      integral = sign_at(shifted, r) == 0;
    }
  }
  if (integral && t.x_right)
    f -= 1;
  return f.convert_to<std::int64_t>();
}

// The fast path of curve_crossings: integer arithmetic on dyadic parameters t = k / 2^30,
// exact, for the common case (every root of g in (0, 1) simple, none at 0 or 1, each crossing's
// x at least a fraction of a raw unit from an integer). Returns false, having decided nothing,
// whenever a check does not pass; the rational path then decides.
//
// Budget (PATH.CURVE.SAMPLE, proved by proofs/path/curve_budget.cpp on the templates of
// rastrules/formula/path_curve.hpp): power coefficients |c| < 2^27; with k <= 2^30,
// |P(k / 2^30) * 2^90| < 2^118, and the Bernstein coefficients of x on [k, k + 1] / 2^30, scaled
// by 3 * 2^90, are at most 2^120 in magnitude: all in __int128.
using Wide = CurveWide; // __int128 (path_detail.hpp)
constexpr int kFastBits = formula::kCurveFastBits;
// |raw| <= 2^23: a power coefficient is a sum of raw values with weights |w| summing to at
// most 12 (the cubic's 3 (y0 - 2 y1 + y2)), so |c| <= 12 * 2^23 < 2^27.
constexpr int kCoefficientBits = kVertexMagBits + 4;
// Every term c_j k^(j - i) C(j, i) 2^(30 (3 - j)) is below 2^(27 + 90 + 2) (C <= 3 < 2^2), and
// the largest sum, 3 times four coefficients each of at most three terms, has 36 < 2^6 terms.
static_assert(kCoefficientBits + 3 * kFastBits + 2 + 6 <= 126,
              "curve fast path must fit __int128 (PATH.CURVE.SAMPLE)");
static_assert(kCoefficientBits + 2 <= 62, "3 * (a0 + a1 + a2 + a3) must fit int64_t");

struct Cubic {
  std::array<std::int64_t, 4> c{}; // power basis, degree <= 3 (a quadratic has c[3] = 0)
  // Returns P(k / 2^30) * 2^90, exactly.
  [[nodiscard]] Wide scaled(std::int64_t k) const { return formula::curve_scaled<Wide>(wide(), k); }
  [[nodiscard]] std::array<Wide, 4> wide() const { return {c[0], c[1], c[2], c[3]}; }
  [[nodiscard, gnu::always_inline]] double approx(double t) const {
    return ((static_cast<double>(c[3]) * t + static_cast<double>(c[2])) * t +
            static_cast<double>(c[1])) *
               t +
           static_cast<double>(c[0]);
  }
  // Returns P'(t) and P''(t) in double (the estimates' Halley steps and their starts).
  [[nodiscard]] std::array<double, 2> slopes(double t) const {
    const double c1 = static_cast<double>(c[1]), c2 = static_cast<double>(c[2]),
                 c3 = static_cast<double>(c[3]);
    return {(3.0 * c3 * t + 2.0 * c2) * t + c1, 6.0 * c3 * t + 2.0 * c2};
  }
};

// A row s.y on the scale of Cubic::scaled is s.y 2^90 (formula::curve_row_scaled).
constexpr int kRowShift = 3 * kFastBits;
static_assert(kRowShift == 90, "rows on the 2^30 grid's cube (PATH.CURVE.SAMPLE)");

// The key of a piece's end Y = y 2^90 against integer rows (MonotonePieces): 2 floor(y), plus 1
// where y is not an integer. For an integer row r, key - 2 r has the sign of y - r: both are 0
// together (y = r), and otherwise floor(y) >= r iff y > r.
std::int64_t row_key(Wide y_scaled) {
  const Wide f = y_scaled >> kRowShift; // floor (C++20: arithmetic shift)
  return static_cast<std::int64_t>(2 * f + ((f << kRowShift) == y_scaled ? 0 : 1));
}

int wide_sign(Wide v) {
  return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

Wide wide_floor_div(Wide n, Wide d) { // d > 0
  const Wide q = n / d;
  return (n % d != 0 && n < 0) ? q - 1 : q;
}

// The threshold of a crossing at x_c = num / den (den > 0): the largest sample x it counts for,
// floor(x_c), less one when x_c is an integer and hx = +1 (PATH.SAMPLE.TIE).
std::int64_t threshold_of(Wide num, Wide den, Tie t) {
  const Wide f = wide_floor_div(num, den);
  return static_cast<std::int64_t>(f * den == num && t.x_right ? f - 1 : f);
}

// The floating-point filter of PATH.CURVE.FILTER: Horner's rule in double on integer power
// coefficients |c_j| < 2^27 at t in [0, 1] (t a double) is within gamma_6 sum |c_j| t^j of the
// exact value (Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed., eq. 5.3, for
// degree n <= 3: gamma_2n = 2n u / (1 - 2n u), u = 2^-53, with or without fused multiply-adds;
// no underflow: every nonzero product is at least 2^-30), and gamma_6 < 2^-50. Returns
// 2^-50 sum |c_j| (exact: the sum is an integer below 2^29).
double horner_error_bound(const Cubic& p) {
  std::int64_t s = 0;
  for (const std::int64_t c : p.c)
    s += c < 0 ? -c : c;
  return static_cast<double>(s) * 0x1p-50;
}

// horner_error_bound(g) for g = y - s.y of a prepared curve: g's coefficients are y's but the
// constant, whose |y1| + |y2| + |y3| the curve keeps (y_abs_rest).
double row_error_bound(const Cubic& g, std::int64_t y_abs_rest) {
  return static_cast<double>((g.c[0] < 0 ? -g.c[0] : g.c[0]) + y_abs_rest) * 0x1p-50;
}

// Returns floor(v) for |v| < 2^62 (no call into the C library: the conversion truncates).
std::int64_t floor_to_int(double v) {
  const auto i = static_cast<std::int64_t>(v);
  return static_cast<double>(i) > v ? i - 1 : i;
}

// Returns k / 2^30 as a double, exactly (k < 2^53).
static_assert(kFastBits == 30, "grid_point scales by 2^-30");
double grid_point(std::int64_t k) {
  return static_cast<double>(k) * 0x1p-30;
}

// The filter's sign of P(k / 2^30): from the double value when it lies farther from 0 than
// `bound` (horner_error_bound(p)); nothing where it does not.
// rule: PATH.CURVE.FILTER
std::optional<int> filter_sign(const Cubic& p, std::int64_t k, double bound) {
  const double v = p.approx(grid_point(k));
  if (v > bound)
    return 1;
  if (v < -bound)
    return -1;
  return std::nullopt;
}

// Returns the sign of P(k / 2^30), exactly: the filter's, else from P(k / 2^30) 2^90 in
// __int128.
// rule: PATH.CURVE.FILTER
int sign_at_grid(const Cubic& p, std::int64_t k, double bound) {
  if (const std::optional<int> s = filter_sign(p, k, bound))
    return *s;
  return wide_sign(p.scaled(k));
}

// The signs of P(k0 / 2^30) and P(k1 / 2^30), exactly (0 <= k0, k1 <= 2^30): both values by
// Horner's rule in the two lanes of one vector of doubles (the filter's bound holds lane by
// lane), each sign the filter's where it decides, else from scaled().
// rule: PATH.CURVE.FILTER
[[gnu::always_inline]] inline void signs_at_points(const Cubic& p, std::int64_t k0, std::int64_t k1,
                                                   double bound, int& s0, int& s1) {
  typedef double Pair __attribute__((vector_size(16)));
  const Pair t = Pair{static_cast<double>(k0), static_cast<double>(k1)} * 0x1p-30;
  const Pair v = ((static_cast<double>(p.c[3]) * t + static_cast<double>(p.c[2])) * t +
                  static_cast<double>(p.c[1])) *
                     t +
                 static_cast<double>(p.c[0]);
  s0 = v[0] > bound ? 1 : (v[0] < -bound ? -1 : wide_sign(p.scaled(k0)));
  s1 = v[1] > bound ? 1 : (v[1] < -bound ? -1 : wide_sign(p.scaled(k1)));
}

// The signs at both ends of the cell [k, k + 1] / 2^30.
void signs_at_cell(const Cubic& p, std::int64_t k, double bound, int& s0, int& s1) {
  signs_at_points(p, k, k + 1, bound, s0, s1);
}

// The crossing of a root confined to [k, k + 1] / 2^30 (g changes sign there exactly, from
// -dir to dir): false unless the Bernstein coefficients of x on that interval lie strictly
// between two consecutive integers F and F + 1 (then F < x_c < F + 1: the crossing counts for a
// sample x <= F under either hx).
// Returns L = |e1| + 2 |e2| + 3 |e3|, which bounds |x'| on [0, 1] (below 2^31).
std::int64_t lipschitz(const Cubic& x) {
  return (x.c[1] < 0 ? -x.c[1] : x.c[1]) + 2 * (x.c[2] < 0 ? -x.c[2] : x.c[2]) +
         3 * (x.c[3] < 0 ? -x.c[3] : x.c[3]);
}

// The double filter (PATH.CURVE.FILTER) of a crossing's x at a root t_c within 2^-30 of t
// (t in [0, 1] a double: on [k, k + 1] / 2^30 with t = k / 2^30, or near a computed root):
// x_c lies within L 2^-30 of x(t) (lip = L, the Lipschitz bound), which lies within
// E = 2^-50 sum |e_j| (bound) of the double value v. With F = floor(v), the computed v - F is
// within 2^-53 of the exact difference d (rounded to nearest, |d| < 1), so a computed value
// above m = 2^-40 + 2 max(L 2^-30, E) makes d > L 2^-30 + E, and one below 1 - m makes
// d < 1 - (L 2^-30 + E): then F < x_c < F + 1, F is written to
// floor_out and true returned; false where it cannot tell. m and 1 - m are exact (their bits
// lie within 2^-49 .. 2^1). (A bool and an integer, not an optional: one returned in two
// registers was stored and reloaded as 16 bytes, stalling on store forwarding.)
// rule: PATH.CURVE.FILTER
bool filter_floor_at(const Cubic& x, std::int64_t lip, double bound, double t,
                     std::int64_t& floor_out) {
  const double v = x.approx(t);
  const std::int64_t f = floor_to_int(v);
  const double m = 0x1p-40 + 2.0 * std::max(grid_point(lip), bound);
  const double frac = v - static_cast<double>(f); // |f| < 2^27: exact as a double
  floor_out = f;
  return frac > m && frac < 1.0 - m;
}

// The same at t = k / 2^30.
bool filter_floor(const Cubic& x, std::int64_t lip, double bound, std::int64_t k,
                  std::int64_t& floor_out) {
  return filter_floor_at(x, lip, bound, grid_point(k), floor_out);
}

// lip = lipschitz(x) and bound = horner_error_bound(x), which do not depend on the row. Returns
// whether the crossing's threshold F (floor(x_c), x_c not an integer) is found, F in threshold.
// (A plain bool and integer: a Crossing built in a local, or an optional, was stored in two
// halves and reloaded as 16 bytes, a store-forwarding stall that was a sixth of the row
// estimates' time.)
bool crossing_on(const Cubic& x, std::int64_t lip, double bound, std::int64_t k,
                 std::int64_t& threshold) {
  if (filter_floor(x, lip, bound, k, threshold))
    return true;
  // First a Lipschitz bound: |x'| <= L = |e1| + 2 |e2| + 3 |e3| on [0, 1], so x_c lies within
  // L 2^-30 of x(k / 2^30), which scaled() gives exactly (times 2^90); B = L 2^60 < 2^90.
  {
    const Wide lip_scaled = formula::curve_lipschitz_scaled<std::int64_t, Wide>(x.c, kSelect);
    const Wide xk = x.scaled(k);
    const Wide one = Wide{1} << (3 * kFastBits);
    const Wide f = xk >> (3 * kFastBits); // floor(xk / 2^90): >> is arithmetic on __int128
    if (formula::curve_strictly_between<Wide>(xk - lip_scaled, xk + lip_scaled, f, one)) {
      threshold = static_cast<std::int64_t>(f);
      return true;
    }
  }
  // x on [k, k + 1] / 2^30 lies between its Bernstein coefficients (scaled by 3 * 2^90).
  const std::array<Wide, 4> xb = formula::curve_interval_bernstein3<Wide>(x.wide(), k);
  const Wide xmin = *std::min_element(xb.begin(), xb.end());
  const Wide xmax = *std::max_element(xb.begin(), xb.end());
  const Wide scale = Wide{3} << (3 * kFastBits);
  const Wide f = wide_floor_div(xmin, scale);
  if (!formula::curve_strictly_between<Wide>(xmin, xmax, f, scale))
    return false; // an integer in reach of x_c: decide exactly on the rational path
  threshold = static_cast<std::int64_t>(f);
  return true;
}

// Double estimates of the roots of g in (0, 1): [0, 1] cut at the roots of g' (quadratic
// formula) into pieces on which g is monotone, and on each piece whose ends have opposite signs
// in double, Newton's method kept inside the bracket by bisection. Only proposes: every
// estimate is checked exactly by the caller. Returns the number of estimates (at most 3).
// [0, 1] cut at the roots of g' (estimates): at[0 .. n], which do not depend on g's constant
// term (the row).
struct Cuts {
  std::array<double, 4> at{0.0, 1.0, 1.0, 1.0};
  int n = 1;
};

Cuts derivative_cuts(const Cubic& g) {
  const double c1 = static_cast<double>(g.c[1]), c2 = static_cast<double>(g.c[2]),
               c3 = static_cast<double>(g.c[3]);
  Cuts cs;
  std::array<double, 4>& cut = cs.at;
  int& cuts = cs.n;
  const auto add_cut = [&](double u) {
    if (u > 0.0 && u < 1.0)
      cut[static_cast<std::size_t>(cuts++)] = u;
  };
  if (c3 == 0.0) {
    if (c2 != 0.0)
      add_cut(-c1 / (2.0 * c2));
  } else {
    const double disc = 4.0 * c2 * c2 - 12.0 * c3 * c1;
    if (disc > 0.0) {
      const double q = -0.5 * (2.0 * c2 + std::copysign(std::sqrt(disc), c2));
      add_cut(q / (3.0 * c3));
      if (q != 0.0)
        add_cut(c1 / q);
    }
  }
  if (cuts == 3 && cut[1] > cut[2])
    std::swap(cut[1], cut[2]);
  cut[static_cast<std::size_t>(cuts)] = 1.0;
  return cs;
}

// Whether root_estimates() takes g's roots by the quadratic formula (no cuts needed).
bool estimated_as_quadratic(const Cubic& g) {
  return g.c[3] == 0 && g.c[2] != 0;
}

// An estimate of the root of g in (lo, hi), on which g is monotone, rising or not, with g
// about glo and ghi at the ends (doubles: only the start depends on them): Halley's method
// from u (NaN or outside: where the chord meets 0, else the midpoint), kept inside the bracket
// by bisection. Only proposes: the caller confines the estimate by exact signs.
double halley_root(const Cubic& g, double lo, double hi, double glo, double ghi, bool rising,
                   double u, double settle = 0x1p-13) {
  if (!(u > lo && u < hi))
    u = lo + (hi - lo) * (glo / (glo - ghi));
  if (!(u > lo && u < hi))
    u = 0.5 * (lo + hi);
  for (int it = 0; it < 100; ++it) {
    const double gu = g.approx(u);
    if (gu == 0.0)
      break;
    ((gu < 0.0) == rising ? lo : hi) = u;
    // Halley's step (cubic convergence: the start, from the rows before or the chord, is
    // typically 2^-6 off, which Newton's method took three or four steps to settle).
    const auto [d, dd] = g.slopes(u);
    const double den = 2.0 * d * d - gu * dd;
    double next = den != 0.0 ? u - 2.0 * gu * d / den : lo;
    bool halley = true;
    if (!(next > lo && next < hi)) {
      next = 0.5 * (lo + hi);
      halley = false;
    }
    // A Halley step s leaves an error of the order of s^3 (times a ratio of g's derivatives
    // of order one on glyph curves): settled when s <= 2^-13, or when s <= 2^-24 whatever the
    // step was. The check on the 2^-30 grid that follows takes a neighbour's cell too; an
    // estimate left outside them only sends the row to the exact paths.
    const double step = next - u;
    const bool settled = std::abs(step) <= 0x1p-24 || (halley && std::abs(step) <= settle);
    u = next;
    if (settled)
      break;
  }
  return u;
}

// cuts: derivative_cuts(g), unless estimated_as_quadratic(g). hints (or null): where the
// Newton steps of each cut interval start, from the rows before (RootHints::start), and where
// this row's roots are recorded.
int root_estimates(const Cubic& g, const Cuts& cs, std::array<double, 3>& t,
                   RootHints* hints = nullptr, std::int64_t row = 0) {
  const double c1 = static_cast<double>(g.c[1]), c2 = static_cast<double>(g.c[2]),
               c3 = static_cast<double>(g.c[3]);
  if (c3 == 0.0 && c2 != 0.0) { // a quadratic: the roots by the stable quadratic formula
    const double c0 = static_cast<double>(g.c[0]), disc = c1 * c1 - 4.0 * c2 * c0;
    if (disc < 0.0)
      return 0;
    const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
    std::array<double, 2> r{q / c2, q != 0.0 ? c0 / q : q / c2};
    if (r[0] > r[1])
      std::swap(r[0], r[1]);
    int n = 0;
    for (int i = 0; i < 2; ++i)
      if (r[static_cast<std::size_t>(i)] > 0.0 && r[static_cast<std::size_t>(i)] < 1.0 &&
          (i == 0 || r[1] != r[0]))
        t[static_cast<std::size_t>(n++)] = r[static_cast<std::size_t>(i)];
    return n;
  }
  const std::array<double, 4>& cut = cs.at;
  const int cuts = cs.n;
  int n = 0;
  for (int i = 0; i < cuts; ++i) {
    const double lo = cut[static_cast<std::size_t>(i)], hi = cut[static_cast<std::size_t>(i) + 1];
    const double glo = g.approx(lo), ghi = g.approx(hi);
    if (!((glo < 0.0 && ghi > 0.0) || (glo > 0.0 && ghi < 0.0)))
      continue;
    const bool rising = ghi > 0.0;
    // Start where the rows before put the root (a few steps fewer: the roots of consecutive
    // rows lie close), else where the chord meets 0 (g is monotone on the piece): nearer than
    // the midpoint. Only the start: the steps, their end and the checks after are the same.
    const double u = halley_root(g, lo, hi, glo, ghi, rising,
                                 hints != nullptr ? hints->start(i, row) : std::nan(""));
    t[static_cast<std::size_t>(n++)] = u;
    if (hints != nullptr)
      hints->found_at(i, u);
  }
  return n;
}

// The crossings of a quadratic g (c3 = 0, c2 != 0, no root at t = 0 or 1) certified by the
// quadratic formula's own error bound (PATH.CURVE.FILTER): the discriminant D is exact in
// integers and, below 2^53, in double; sqrt, the same-sign sum c1 + sgn(c1) sqrt(D), the halving
// and one division leave each computed root within 3.01 u < 2^-51 of the true one relatively
// (u = 2^-53; no cancellation), so within 2^-50 max(1, |r|) absolutely. A root farther than
// 2^-40 inside (0, 1) or outside [0, 1] is known to lie there; two roots inside more than 2^-40
// apart are distinct, the smaller one crossed in direction -sgn(c2), the larger +sgn(c2) (times
// dir_sign); each x_c is within L 2^-50 < L 2^-30 of x at the computed root, so filter_floor's
// test decides its floor as on a grid cell. D < 0 (exact): no real root, so no crossing.
// Returns whether it decided (crossings appended); false (nothing appended) leaves the row to
// the grid estimates. Tried before g's sign variations are counted (12-14 % of the kernel's
// instructions on DejaVu glyphs at 24-64 px went to counting them for every quadratic row).
// rule: PATH.CURVE.FILTER, PATH.CURVE.SAMPLE
// Out: std::vector<Crossing> or RowCrossings (push_back).
template <class Out>
bool quadratic_crossings(const Cubic& g, const Cubic& x, std::int64_t x_lip, double x_bound,
                         Out& found, int dir_sign) {
  // |c_j| < 2^27: |D| < 2^57, exact in int64_t.
  static_assert(2 * kCoefficientBits + 3 <= 62, "the discriminant must fit int64_t");
  const std::int64_t disc = formula::curve_discriminant(g.c[0], g.c[1], g.c[2]);
  constexpr std::int64_t kExact = std::int64_t{1} << 53;
  if (disc < 0)
    return true; // no real root: g keeps its sign, the row is not crossed
  if (disc == 0 || disc >= kExact)
    return false; // a double root, or D not exact in double: the other paths
  const double c0 = static_cast<double>(g.c[0]), c1 = static_cast<double>(g.c[1]),
               c2 = static_cast<double>(g.c[2]);
  const double q = -0.5 * (c1 + std::copysign(std::sqrt(static_cast<double>(disc)), c1));
  double r0 = q / c2, r1 = c0 / q; // q != 0: |q| >= sqrt(D) / 2 > 0
  if (r0 > r1)
    std::swap(r0, r1);
  constexpr double kMargin = 0x1p-40;
  const auto inside = [](double r) { return r > kMargin && r < 1.0 - kMargin; };
  const auto outside = [](double r) { return r < -kMargin || r > 1.0 + kMargin; };
  const bool in0 = inside(r0), in1 = inside(r1); // each test once
  if (!(in0 || outside(r0)) || !(in1 || outside(r1)) || (in0 && in1 && !(r1 - r0 > kMargin)))
    return false;
  const int first_dir = (g.c[2] > 0 ? -1 : 1) * dir_sign;
  std::int64_t f0 = 0, f1 = 0;
  if ((in0 && !filter_floor_at(x, x_lip, x_bound, r0, f0)) ||
      (in1 && !filter_floor_at(x, x_lip, x_bound, r1, f1)))
    return false;
  if (in0)
    found.push_back(Crossing{f0, first_dir});
  if (in1)
    found.push_back(Crossing{f1, -first_dir});
  return true;
}

// Finds the v crossings from root_estimates(): each estimate must be confined by exact signs
// of g to a region of the 2^30 grid, (k, k + 1) / 2^30 where g changes sign, or (k - 1, k + 1)
// / 2^30 where g(k / 2^30) = 0 and g changes sign from k - 1 to k + 1 (a dyadic root, t = 1/2
// on many glyph rows); the regions pairwise disjoint, and their number v: then they hold
// exactly the v roots of g in (0, 1), one simple root each (Descartes: v bounds the roots
// counted with multiplicity and has their parity; each region holds an odd number), and a
// dyadic root is the region's root, where x is exact. The direction is the sign of g after the
// root (times dir_sign). Signs come through the double filter (sign_at_grid). A quadratic g is
// first given to quadratic_crossings, which needs no signs where it decides.
// rule: PATH.CURVE.SAMPLE, PATH.CURVE.FILTER
bool estimated_crossings(const Cubic& g, double bound, const Cuts& cuts, const Cubic& x,
                         std::int64_t x_lip, double x_bound, int v, Tie t,
                         std::vector<Crossing>& found, int dir_sign = 1, RootHints* hints = nullptr,
                         std::int64_t row = 0) {
  if (g.c[3] == 0 && g.c[2] != 0 && quadratic_crossings(g, x, x_lip, x_bound, found, dir_sign))
    return true;
  constexpr std::int64_t kOne = std::int64_t{1} << kFastBits;
  std::array<double, 3> est{};
  const int n = root_estimates(g, cuts, est, hints, row);
  if (hints != nullptr)
    hints->record(row);
  if (n != v)
    return false;
  std::array<std::pair<std::int64_t, std::int64_t>, 3> regions{};
  for (int r = 0; r < v; ++r) {
    const std::int64_t k0 =
        std::clamp(floor_to_int(est[static_cast<std::size_t>(r)] * static_cast<double>(kOne)),
                   std::int64_t{0}, kOne - 1);
    bool confined = false;
    for (const std::int64_t k : {k0, k0 - 1, k0 + 1}) {
      if (k < 0 || k >= kOne)
        continue;
      const int s0 = sign_at_grid(g, k, bound), s1 = sign_at_grid(g, k + 1, bound);
      std::int64_t a = k, b = k + 1, root = -1; // the region (a, b); root: a dyadic root in it
      int sb = s1;                              // the sign of g at b
      if (s0 == 0 || s1 == 0) {
        root = s0 == 0 ? k : k + 1;
        a = root - 1;
        b = root + 1;
        if (a < 0 || b > kOne)
          return false;
        sb = sign_at_grid(g, b, bound);
        if (sign_at_grid(g, a, bound) * sb >= 0)
          return false; // no sign change around the root: a multiple root, or none counted
      } else if (s0 == s1) {
        continue;
      }
      for (int q = 0; q < r; ++q) {
        const auto [qa, qb] = regions[static_cast<std::size_t>(q)];
        if (a < qb && qa < b)
          return false; // regions must be disjoint
      }
      const int dir = dir_sign * sb; // the sign at b, known: not evaluated again
      std::int64_t threshold = 0;
      if (root >= 0) {
        // x at t = root / 2^30 exactly: P(k / 2^30) 2^90, then floor and integrality.
        threshold = threshold_of(x.scaled(root), Wide{1} << (3 * kFastBits), t);
      } else if (!crossing_on(x, x_lip, x_bound, k, threshold)) {
        return false;
      }
      regions[static_cast<std::size_t>(r)] = {a, b};
      found.push_back(Crossing{threshold, dir});
      confined = true;
      break;
    }
    if (!confined)
      return false;
  }
  return true;
}

// The monotone pieces of a cubic y (c3 != 0; PATH.CURVE.SAMPLE), from the estimated roots cs
// of y' (derivative_cuts): each estimate inside (0, 1) is bracketed by the grid points
// a = k - 1 and b = k + 2 (k = floor(u 2^30)) where the exact signs of y' differ; the pieces
// are the rest of [0, 1], and the sign of y' must be one and the same at both ends of each
// (inside the piece: at t = 0 or 1 where y' = 0 there, the sign of y' just after 0 or just
// before 1, from the first nonzero derivative; glyph cubics mostly start and end at a
// y-extremum). Then y' has no root inside a piece: with D = c2^2 - 3 c1 c3 <= 0 it has no two
// simple real roots, so it keeps one sign on [0, 1] but at one point at most. With D > 0 it
// has exactly two, both simple: a bracket (a sign change) holds an odd number, so one; a piece
// holds an even number; so once the brackets and the zeros of y' at t = 0 and 1 account for
// one root or both, no piece holds one. With none accounted for, the vertex of y' outside
// (0, 1), or y' at the ends of the sign opposite to c3 (y' curved away from 0 between them),
// keeps both out. Otherwise mono.n stays 0 and every row takes the estimates.
// rule: PATH.CURVE.SAMPLE, PATH.CURVE.FILTER
void prepare_monotone(const Cubic& y, const Cuts& cs, MonotonePieces& mono) {
  mono.n = 0;
  if (y.c[3] == 0)
    return;
  constexpr std::int64_t kOne = std::int64_t{1} << kFastBits;
  const Cubic dy{formula::curve_derivative_coefficients(y.c)};
  const auto sgn = [](std::int64_t v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); };
  // The sign of y' just after 0 and just before 1: y'(0) = d0, else d1 t, else d2 t^2 near 0;
  // y'(1), else -y''(1) (1 - t), else d2 (1 - t)^2 near 1 (d2 = 3 c3 != 0).
  const std::int64_t at1 = formula::curve_at_one(dy.c);
  const std::array<std::int64_t, 3> der1 = formula::curve_derivatives_at_one(dy.c);
  const int s0 = dy.c[0] != 0 ? sgn(dy.c[0]) : (dy.c[1] != 0 ? sgn(dy.c[1]) : sgn(dy.c[2]));
  const int s1 = at1 != 0 ? sgn(at1) : (der1[0] != 0 ? -sgn(der1[0]) : sgn(dy.c[2]));
  const int end_zeros = (dy.c[0] == 0 ? 1 : 0) + (at1 == 0 ? 1 : 0);
  const double dbound = horner_error_bound(dy);
  // Piece j runs from the grid point lo[j] to hi[j], with y' of sign slo[j] and shi[j] there.
  std::array<std::int64_t, 3> lo{0, 0, 0}, hi{kOne, kOne, kOne};
  std::array<int, 3> slo{s0, 0, 0}, shi{s1, s1, s1};
  int nb = 0;
  if (formula::curve_derivative_discriminant(y.c) > 0) {
    for (int i = 1; i < cs.n; ++i) {
      const std::int64_t k = floor_to_int(cs.at[static_cast<std::size_t>(i)] * 0x1p30);
      const std::int64_t ka = k - 1, kb = k + 2; // the bracket [a, b]: a piece ends, one starts
      const auto j = static_cast<std::size_t>(nb);
      if (ka <= lo[j] || kb > kOne - 1)
        return;
      const int sa = sign_at_grid(dy, ka, dbound), sb = sign_at_grid(dy, kb, dbound);
      if (sa == 0 || sb == 0 || sa == sb)
        return;
      hi[j] = ka;
      shi[j] = sa;
      lo[j + 1] = kb;
      slo[j + 1] = sb;
      ++nb;
    }
    if (nb + end_zeros == 0 && s0 == sgn(dy.c[2]) && formula::curve_vertex_inside(dy.c, kSelect))
      return; // both roots of y' may lie inside (0, 1)
  }
  // One sign of y' at both ends of each piece.
  for (int j = 0; j <= nb; ++j)
    if (slo[static_cast<std::size_t>(j)] != shi[static_cast<std::size_t>(j)])
      return;
  // y at t = 0 and 1: the integers c0 and c0 + c1 + c2 + c3, keys 2 y (every piece has an end
  // there; the others on the grid inside, through scaled()).
  const std::int64_t y_at1 = formula::curve_at_one(y.c);
  for (int j = 0; j <= nb; ++j) {
    const auto i = static_cast<std::size_t>(j);
    mono.lo[i] = lo[i];
    mono.hi[i] = hi[i];
    mono.ylo[i] = lo[i] == 0 ? 2 * y.c[0] : row_key(y.scaled(lo[i]));
    const Wide yhi = hi[i] == kOne ? Wide{0} : y.scaled(hi[i]); // inside: exact, on 2^90
    mono.yhi[i] = hi[i] == kOne ? 2 * y_at1 : row_key(yhi);
    mono.ylo_d[i] = lo[i] == 0 ? static_cast<double>(y.c[0]) : y.approx(grid_point(lo[i]));
    mono.yhi_d[i] = hi[i] == kOne ? static_cast<double>(y_at1) : y.approx(grid_point(hi[i]));
    mono.last[i].valid = false;
    if (j < nb) { // the bracket after piece j: y within 3 cells of its start
      const Wide lip = formula::curve_lipschitz_scaled<std::int64_t, Wide>(y.c, kSelect);
      const std::array<Wide, 2> r =
          formula::curve_bracket_range<Wide>(yhi, lip, Wide{lo[i + 1] - hi[i]});
      // The rows s.y with r0 <= s.y 2^90 <= r1: ceil(r0 / 2^90) .. floor(r1 / 2^90).
      mono.near_lo[i] = static_cast<std::int64_t>(-((-r[0]) >> kRowShift));
      mono.near_hi[i] = static_cast<std::int64_t>(r[1] >> kRowShift);
    }
  }
  mono.brackets = nb;
  mono.n = nb + 1;
}

// Where the next row's root on a piece starts (MonotonePieces::Last): from the root u of row sy
// and y' = d, y'' = dd there, the inverse Taylor coefficients 1 / y' and -y'' / (2 y'^3).
MonotonePieces::Last next_row_start(double u, double d, double dd, std::int64_t sy) {
  const double inv = 1.0 / d;
  return {u, inv, -0.5 * dd * inv * inv * inv, sy, std::isfinite(inv)};
}

// The half-width of PATH.CURVE.COARSE's bracket around a root estimate, in cells of 2^-30
// (2^-14: one Halley step from the start lands that close on most glyph rows; x then moves by
// at most L 2^-14, a fraction of a raw unit on glyphs).
constexpr std::int64_t kCoarseCells = std::int64_t{1} << 16;

// PATH.CURVE.COARSE on the piece (lo, hi) / 2^30 of a monotone cubic (g from sign sl at lo to
// sh at hi): true, with threshold = 256 q + sample_x, where g changes sign exactly between the
// grid points k0 = K - D and k1 = K + D + 1 around the estimate u (K = floor(u 2^30),
// D = kCoarseCells, both strictly inside the piece) and x there provably lies strictly between
// the samples 256 q + sample_x and 256 (q + 1) + sample_x. Then the root t_c lies in
// (k0, k1) / 2^30, within (D + 1) 2^-30 of u, so |x_c - x(u)| < L (D + 1) 2^-30 = R (L the
// Lipschitz bound of x'), and x(u) lies within E (x_bound) of the double value v. With
// F = floor(v) and the sample below F at 256 q + sample_x, the computed distance
// rel = (F - 256 q - sample_x) + (v - F) is within 2^-40 of v's distance above that sample (the
// integer part exact, v - F within 2^-53, the sum below 2^9); rel > m and rel < 256 - m with
// m = 2^-30 + 2 (E + R) (twice: the sum E + R rounded; coarse_margin, once a curve) put x_c
// strictly between the two.
// rule: PATH.CURVE.COARSE, PATH.CURVE.FILTER
[[gnu::always_inline]] inline bool coarse_crossing(const Cubic& g, double g_bound, const Cubic& x,
                                                   double m, std::int64_t lo, std::int64_t hi,
                                                   int sl, int sh, double u, std::int64_t sample_x,
                                                   std::int64_t& threshold) {
  if (!(u > 0.0 && u < 1.0))
    return false; // NaN too
  const std::int64_t kf = floor_to_int(u * 0x1p30);
  const std::int64_t k0 = kf - kCoarseCells, k1 = kf + kCoarseCells + 1;
  if (k0 <= lo || k1 >= hi)
    return false;
  int s0 = 0, s1 = 0;
  signs_at_points(g, k0, k1, g_bound, s0, s1);
  if (s0 != sl || s1 != sh)
    return false;
  const double v = x.approx(u);
  const std::int64_t f = floor_to_int(v);
  constexpr std::int64_t kPixel = kSubpixelOne; // the samples' spacing: 256 raw units
  // q = floor((F - sample_x) / 256) and F - 256 q - sample_x, by shift and mask (C++20: two's
  // complement, arithmetic shift).
  const std::int64_t q = (f - sample_x) >> kSubpixelBits;
  const double rel =
      static_cast<double>((f - sample_x) & (kPixel - 1)) + (v - static_cast<double>(f));
  if (!(rel > m && rel < static_cast<double>(kPixel) - m))
    return false;
  threshold = kPixel * q + sample_x;
  return true;
}

// The crossings of row sy with a cubic whose monotone pieces are proved (mono.n > 0): false,
// having appended nothing, where they do not decide (the row near a bracket, through a piece's
// end, or an estimate not confined to its cell or a neighbour). A piece whose ends lie on
// either side of the row (exact: their keys against 2 s.y, MonotonePieces) holds exactly one
// root, simple, crossed in the direction of the sign of g after it; its estimate is
// confined by exact signs of g to (k, k + 1) / 2^30, or found at a grid point (then x there
// exactly), and crossing_on decides its x. No sign variations are counted and no piece without
// a crossing is evaluated. With a sample_x (not kExactThresholds), a crossing whose samples'
// class coarse_crossing decides carries that class's threshold (PATH.CURVE.COARSE).
// rule: PATH.CURVE.SAMPLE, PATH.CURVE.FILTER, PATH.CURVE.COARSE
// x is the curve's x (p.x, copied once by the caller for all its rows). Inlined into the band
// loop (curve_crossings_band), so that a row costs no call.
// Out: std::vector<Crossing> or RowCrossings (size, resize to forget, push_back).
template <class Out>
[[gnu::always_inline]] inline bool monotone_crossings(const PreparedCurve& p, const Cubic& x,
                                                      std::int64_t sy, Tie t, Out& out,
                                                      std::int64_t sample_x) {
  const MonotonePieces& m = p.mono;
  for (int j = 0; j < m.brackets; ++j)
    if (sy >= m.near_lo[static_cast<std::size_t>(j)] &&
        sy <= m.near_hi[static_cast<std::size_t>(j)])
      return false;
  const std::int64_t s = 2 * sy; // against the pieces' ends' keys
  Cubic g{p.y};
  g.c[0] -= sy;
  const double bound = row_error_bound(g, p.y_abs_rest);
  const std::size_t mark = out.size();
  const auto give_up = [&] {
    out.resize(mark);
    return false;
  };
  const double syd = static_cast<double>(sy);
  for (int j = 0; j < m.n; ++j) {
    const auto i = static_cast<std::size_t>(j);
    const int sl = m.ylo[i] > s ? 1 : (m.ylo[i] < s ? -1 : 0);
    const int sh = m.yhi[i] > s ? 1 : (m.yhi[i] < s ? -1 : 0);
    if (sl == sh)
      continue; // the piece lies on one side of the row (never both ends on it: monotone)
    if (sl == 0 || sh == 0)
      return give_up(); // the row through a piece's end
    MonotonePieces::Last& last = m.last[i];
    double start = std::numeric_limits<double>::quiet_NaN();
    if (last.valid) {
      const double dy = static_cast<double>(sy - last.row);
      start = last.t + (last.d1 + last.d2 * dy) * dy;
    } else {
      // The piece's first row (rows come in increasing y): from its lower end, where y' is
      // often 0 (a glyph's extremum), y's Taylor polynomial of degree 2 there solved for the
      // row (NaN where it has no root: halley_root then starts from the chord).
      const double te = grid_point(sh > 0 ? m.lo[i] : m.hi[i]);
      const double r = syd - (sh > 0 ? m.ylo_d[i] : m.yhi_d[i]);
      const auto [d1, d2] = g.slopes(te);
      const double e = sh > 0 ? d1 : -d1;
      const double tau = 2.0 * r / (e + std::sqrt(e * e + 2.0 * d2 * r));
      start = sh > 0 ? te + tau : te - tau;
    }
    // The samples' class alone (PATH.CURVE.COARSE): one Halley step from the start, and a
    // bracket 2^-14 wide around it instead of a cell of 2^-30. The next row's start takes
    // the slopes at the start (not at the step's end: one evaluation fewer; only a start).
    if (sample_x != kExactThresholds) {
      std::int64_t threshold = 0;
      const double gu = g.approx(start);
      const auto [d0, dd0] = g.slopes(start);
      const double u1 = start - 2.0 * gu * d0 / (2.0 * d0 * d0 - gu * dd0);
      if (coarse_crossing(g, bound, x, p.coarse_margin, m.lo[i], m.hi[i], sl, sh, u1, sample_x,
                          threshold)) {
        out.push_back(Crossing{threshold, sh});
        last = next_row_start(u1, d0, dd0, sy);
        continue;
      }
      start = u1; // Halley's steps go on from there (halley_root restarts outside the piece)
    }
    // Halley's steps settle after a step of 2^-10 (an error of the order of 2^-30 where g's
    // derivatives are of one order); where the exact signs find the root farther than the
    // cell's neighbours (near a y-extremum), the steps go on from there until they stop moving
    // (2^-24), and the signs are asked again.
    bool found = false;
    double u = start;
    for (int round = 0; round < 2 && !found; ++round) {
      u = halley_root(g, grid_point(m.lo[i]), grid_point(m.hi[i]), m.ylo_d[i] - syd,
                      m.yhi_d[i] - syd, sh > 0, u, round == 0 ? 0x1p-10 : 0.0);
      std::int64_t k = std::clamp(floor_to_int(u * 0x1p30), m.lo[i], m.hi[i] - 1);
      for (int attempt = 0; attempt < 3 && !found; ++attempt) {
        if (k < m.lo[i] || k >= m.hi[i])
          return give_up();
        int s0 = 0, s1 = 0;
        signs_at_cell(g, k, bound, s0, s1);
        s0 = k == m.lo[i] ? sl : s0;
        s1 = k + 1 == m.hi[i] ? sh : s1;
        std::int64_t threshold = 0;
        if (s0 == 0 || s1 == 0) { // the root at a grid point: x there exactly
          threshold = threshold_of(x.scaled(s0 == 0 ? k : k + 1), Wide{1} << (3 * kFastBits), t);
        } else if (s0 == sh) { // g has passed the root at k already: it lies before k
          --k;
          continue;
        } else if (s1 == sl) { // not yet at k + 1: after it
          ++k;
          continue;
        } else if (!crossing_on(x, p.x_lipschitz, p.x_bound, k, threshold)) {
          return give_up();
        }
        out.push_back(Crossing{threshold, sh});
        found = true;
      }
    }
    if (!found)
      return give_up();
    const auto [d, dd] = g.slopes(u);
    last = next_row_start(u, d, dd, sy);
  }
  return true;
}

// The same, everything that does not depend on the row computed here.
bool estimated_crossings(const Cubic& g, const Cubic& x, int v, Tie t, std::vector<Crossing>& found,
                         int dir_sign = 1) {
  return estimated_crossings(g, horner_error_bound(g),
                             estimated_as_quadratic(g) ? Cuts{} : derivative_cuts(g), x,
                             lipschitz(x), horner_error_bound(x), v, t, found, dir_sign);
}

// The exact crossings of a quadratic (or linear) g whose roots are rational (a linear g, or a
// discriminant that is a perfect square, which covers every root at t = 0 or 1): each root
// t = p / q exactly, its order and direction from the integer derivatives there, its x as the
// fraction (e0 q^2 + e1 p q + e2 p^2) / q^2, floor and integrality exact (PATH.CURVE.SAMPLE).
// Returns false, having decided nothing, when the roots are irrational.
//
// Budget (proved by proofs/path/curve_budget.cpp): a quadratic's |c_j|, |e_j| <= 2^25;
// |D| <= 2^52; 0 <= p <= q <= 2^26; |numerator of x| <= 2^79: all in __int128.
// The sign variations of Bernstein coefficients, zeros skipped (Descartes' bound on the roots
// in the open interval, with their parity).
template <class T> int sign_variations(const std::array<T, 4>& b) {
  int v = 0, last = 0;
  for (const T bi : b) {
    const int si = bi > 0 ? 1 : (bi < 0 ? -1 : 0);
    if (si != 0 && last != 0 && si != last)
      ++v;
    if (si != 0)
      last = si;
  }
  return v;
}

// The sign variations of 3 times the Bernstein coefficients of g on [0, 1].
int bernstein_variations(const Cubic& g) {
  return sign_variations(formula::curve_bernstein3(g.c));
}

static_assert(2 * kCoefficientBits + 3 <= 62,
              "the discriminant must fit int64_t (PATH.CURVE.SAMPLE)");
static_assert(kCoefficientBits + 2 * (kCoefficientBits + 3) + 2 <= 126,
              "x at a rational root must fit __int128 (PATH.CURVE.SAMPLE)");
// rule: PATH.CURVE.SAMPLE
bool rational_quadratic_crossings(const Cubic& g, const Cubic& x, Tie t,
                                  std::vector<Crossing>& out) {
  if (g.c[3] != 0 || x.c[3] != 0)
    return false;
  const Wide c0 = g.c[0], c1 = g.c[1], c2 = g.c[2];
  const int hy = t.y_down ? 1 : -1;
  // The roots as p / q, q > 0, with their multiplicity.
  std::array<std::pair<Wide, Wide>, 2> roots{};
  int n = 0;
  bool twice = false;
  if (c2 == 0) {
    if (c1 == 0)
      return true; // y constant: on the row (never crossed) or off it
    roots[0] = c1 > 0 ? std::pair{-c0, c1} : std::pair{c0, -c1};
    n = 1;
  } else {
    const Wide d = formula::curve_discriminant(c0, c1, c2);
    if (d < 0)
      return true;                                                         // no real root
    Wide s = static_cast<std::int64_t>(std::sqrt(static_cast<double>(d))); // d < 2^57
    while (s * s > d)
      --s;
    while ((s + 1) * (s + 1) <= d)
      ++s;
    if (s * s != d)
      return false; // irrational roots
    const Wide q = 2 * c2;
    const auto normal = [](Wide num, Wide den) {
      return den > 0 ? std::pair{num, den} : std::pair{-num, -den};
    };
    roots[0] = normal(-c1 - s, q);
    roots[1] = normal(-c1 + s, q);
    n = s == 0 ? 1 : 2;
    twice = s == 0;
  }
  for (int i = 0; i < n; ++i) {
    const auto [p, q] = roots[static_cast<std::size_t>(i)];
    if (p < 0 || p > q)
      continue; // outside [0, 1]
    // g' and g'' at p / q, scaled by q and q^0: their signs.
    const int d1 = wide_sign(formula::curve_slope_at(c1, c2, p, q)), d2 = wide_sign(c2);
    // x(p / q) = (e0 q^2 + e1 p q + e2 p^2) / q^2.
    const Wide num = formula::curve_numerator2(x.wide(), p, q);
    const std::int64_t threshold = threshold_of(num, q * q, t);
    // Order m and sign a of the first non-zero derivative at the root.
    const int m = d1 != 0 ? 1 : 2;
    const int a = d1 != 0 ? d1 : d2;
    if (p == 0) { // t = 0: crossed iff a = hy, in direction hy
      if (a == hy)
        out.push_back(Crossing{threshold, hy});
    } else if (p == q) { // t = 1: crossed iff a (-1)^m = hy, in direction -hy
      if ((m % 2 == 1 ? -a : a) == hy)
        out.push_back(Crossing{threshold, -hy});
    } else if (!twice) { // inside, simple: crosses in the direction of g'
      out.push_back(Crossing{threshold, d1});
    } // inside, double: touches the row; its two crossings cancel
  }
  return true;
}

// The crossings of a cubic g with a root at t = 0 or 1 (a curve end on the row), in integers:
// each end root by the order and sign of g's first non-zero derivative there (PATH.CURVE.SAMPLE),
// then g = t^m0 (t - 1)^m1 h with h(0), h(1) != 0 and degree <= 2 divided out exactly, and the
// roots of h in (0, 1), which are g's, as rationals p / q (h linear, or a perfect-square
// discriminant) or confined from root estimates; the direction at a simple root is that of
// g' = t^m0 (t - 1)^m1 h' there, (-1)^m1 sgn h'. x at p / q is the fraction
// (e0 q^3 + e1 p q^2 + e2 p^2 q + e3 p^3) / q^3. Returns false when g has no end root or a check
// fails; the caller then clears `out`.
//
// Budget (proved by proofs/path/curve_budget.cpp): h's coefficients are sums of g's
// (|h_j| <= 14 * 2^24 < 2^28), so |D| <= 2^58, sqrt(D) <= 2^29, 0 < p < q = 2 |h2| < 2^29, and
// |x's numerator| <= 2^115: __int128; |h.scaled()| < 2^120.
// rule: PATH.CURVE.SAMPLE
bool cubic_end_crossings(const Cubic& g, const Cubic& x, Tie t, std::vector<Crossing>& out) {
  const int hy = t.y_down ? 1 : -1;
  const std::array<Wide, 4> c = g.wide();
  const Wide g_at_1 = formula::curve_at_one(c);
  if ((c[0] != 0 && g_at_1 != 0) || (c[1] == 0 && c[2] == 0 && c[3] == 0))
    return false;  // no end root, or y constant
  if (c[0] == 0) { // t = 0: crossed iff a = hy, in direction hy
    std::size_t m = 1;
    while (c[m] == 0)
      ++m;
    if (wide_sign(c[m]) == hy)
      out.push_back(Crossing{threshold_of(x.c[0], 1, t), hy});
  }
  if (g_at_1 == 0) { // t = 1: crossed iff a (-1)^m = hy, in direction -hy
    const std::array<Wide, 3> d = formula::curve_derivatives_at_one(c);
    std::size_t m = 0; // the order is m + 1
    while (d[m] == 0)
      ++m;
    if ((m % 2 == 0 ? -wide_sign(d[m]) : wide_sign(d[m])) == hy)
      out.push_back(Crossing{threshold_of(formula::curve_at_one(x.wide()), 1, t), -hy});
  }
  // Divide out t^m0, then (t - 1)^m1.
  std::array<Wide, 4> h = c;
  std::size_t deg = 3;
  while (h[deg] == 0)
    --deg;
  while (deg > 0 && h[0] == 0) {
    for (std::size_t i = 0; i < deg; ++i)
      h[i] = h[i + 1];
    h[deg--] = 0;
  }
  int flips = 1; // (-1)^m1
  while (deg > 0) {
    Wide sum = 0;
    const std::array<Wide, 4> q =
        formula::curve_divide_by_t_minus_one(h, static_cast<int>(deg), sum);
    if (sum != 0)
      break;
    h = q;
    --deg;
    flips = -flips;
  }
  if (deg >= 3)
    return false; // not reached: an end root is divided out above
  if (deg == 0)
    return true; // no root inside
  // x at t = p / q (q > 0) as a crossing in direction dir.
  const auto at = [&](Wide p, Wide q, int dir) {
    const Wide num = formula::curve_numerator3(x.wide(), p, q);
    out.push_back(Crossing{threshold_of(num, q * q * q, t), dir});
  };
  if (deg == 1) {
    const Wide p = h[1] > 0 ? -h[0] : h[0], q = h[1] > 0 ? h[1] : -h[1];
    if (p > 0 && p < q)
      at(p, q, flips * wide_sign(h[1]));
    return true;
  }
  const Wide disc = formula::curve_discriminant(h[0], h[1], h[2]);
  if (disc < 0)
    return true;
  Wide s = static_cast<std::int64_t>(std::sqrt(static_cast<double>(disc))); // disc < 2^61
  while (s * s > disc)
    --s;
  while ((s + 1) * (s + 1) <= disc)
    ++s;
  if (s * s == disc) {
    if (s == 0)
      return true; // a double root: touches the row (its crossings cancel) or lies outside
    for (const Wide num : {-h[1] - s, -h[1] + s}) {
      const Wide p = h[2] > 0 ? num : -num, q = 2 * (h[2] > 0 ? h[2] : -h[2]);
      if (p > 0 && p < q)
        at(p, q, flips * wide_sign(formula::curve_slope_at(h[1], h[2], p, q)));
    }
    return true;
  }
  // Irrational roots: confine the estimates of h's roots (h(0), h(1) != 0, |h_j| < 2^29).
  const Cubic hc{{static_cast<std::int64_t>(h[0]), static_cast<std::int64_t>(h[1]),
                  static_cast<std::int64_t>(h[2]), 0}};
  const int v = bernstein_variations(hc);
  return v == 0 || estimated_crossings(hc, x, v, t, out, flips);
}

// The crossings of g with no root at an end (g(0), g(1) != 0) where the root estimates gave
// up, by a scan of 64 intervals; `out` is empty here and left to the caller to clear when false
// is returned.
bool scan_crossings(const Cubic& g, const Cubic& x, std::vector<Crossing>& out) {
  constexpr std::int64_t kOne = std::int64_t{1} << kFastBits;
  std::vector<Crossing>& found = out;
  // The scan: on each interval [i, i + 1] / 64, Descartes' rule on g's Bernstein coefficients
  // there (exact, in __int128) counts its roots: no sign variation, no root; one, exactly one
  // simple root, which is confined below; more (roots closer than 1/64 apart, a multiple root,
  // or complex roots near the interval), not decided here. A zero first coefficient is a root
  // at the interval's start. Where v over-counts the roots in (0, 1) (complex roots near [0, 1],
  // an oscillating control polygon), the estimates give up and this decides: every root in
  // (0, 1) lies in exactly one interval (g(0), g(1) != 0), so those found are all.
  constexpr int kSteps = 1 << formula::kCurveScanBits;
  constexpr std::int64_t kStep = kOne / kSteps;
  const std::array<Wide, 4> gw = g.wide();
  for (int i = 0; i < kSteps; ++i) {
    const std::array<Wide, 4> b =
        formula::curve_interval_bernstein3<Wide, formula::kCurveScanBits>(gw, Wide{i});
    if (b[0] == 0)
      return false; // a root at i / 64
    const int vi = sign_variations(b);
    if (vi == 0)
      continue;
    if (vi > 1)
      return false;
    // One root: b[0] and b[3] are 3 2^18 g at the interval's ends, of opposite signs.
    const double ta = static_cast<double>(i) / kSteps, tb = static_cast<double>(i + 1) / kSteps;
    const std::int64_t ka = i * kStep, kb = (i + 1) * kStep;
    const int sa = wide_sign(b[0]), sb = wide_sign(b[3]);
    // A root estimate by bisection in double, then an exact sign change on [k, k + 1] / 2^30.
    double lo = ta, hi = tb;
    for (int it = 0; it < 64; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi)
        break;
      ((g.approx(mid) < 0) == (sa < 0) ? lo : hi) = mid;
    }
    const std::int64_t k = std::clamp(
        static_cast<std::int64_t>(std::floor(lo * static_cast<double>(kOne))), ka, kb - 1);
    const int s0 = wide_sign(g.scaled(k)), s1 = wide_sign(g.scaled(k + 1));
    if (s0 != sa || s1 != sb)
      return false;
    std::int64_t threshold = 0;
    if (!crossing_on(x, lipschitz(x), horner_error_bound(x), k, threshold))
      return false;
    found.push_back(Crossing{threshold, sb});
  }
  return true;
}

} // namespace

// rule: PATH.CURVE.SAMPLE, PATH.SAMPLE.TIE
std::vector<Crossing> curve_crossings(const Curve& c, std::int64_t sy, Tie t) {
  std::vector<Crossing> out;
  curve_crossings_into(c, sy, t, true, out);
  return out;
}

// rule: PATH.CURVE.SAMPLE, PATH.SAMPLE.TIE
std::vector<Crossing> curve_crossings_exact(const Curve& c, std::int64_t sy, Tie t) {
  std::vector<Crossing> out;
  curve_crossings_into(c, sy, t, false, out);
  return out;
}

// rule: PATH.CURVE.SAMPLE
void prepare_curve(const Curve& c, PreparedCurve& p) {
  const int n = c.degree;
  p.curve = &c;
  p.hints.reset(); // a walk's own rows (the vector of prepared curves is reused)
  // The control points written out (no loop on the degree; a quadratic's fourth is unused).
  const std::array<Point, 4>& q = c.p;
  const std::array<std::int64_t, 4> xs{q[0].x, q[1].x, q[2].x, n == 3 ? q[3].x : 0},
      ys{q[0].y, q[1].y, q[2].y, n == 3 ? q[3].y : 0};
  p.ymin = std::min({ys[0], ys[1], ys[2], n == 3 ? ys[3] : ys[2]});
  p.ymax = std::max({ys[0], ys[1], ys[2], n == 3 ? ys[3] : ys[2]});
  // Computed from locals and stored once: read back from p right after its stores, the
  // coefficients stalled on store forwarding (a fifth of cover_samples on DejaVu glyphs, whose
  // quadratics meet few rows each).
  const Cubic x{formula::curve_power_coefficients(xs, n == 3)},
      y{formula::curve_power_coefficients(ys, n == 3)};
  p.y = y.c;
  p.x = x.c;
  p.x_lipschitz = lipschitz(x);
  p.y_abs_rest = (y.c[1] < 0 ? -y.c[1] : y.c[1]) + (y.c[2] < 0 ? -y.c[2] : y.c[2]) +
                 (y.c[3] < 0 ? -y.c[3] : y.c[3]);
  p.x_bound = horner_error_bound(x);
  // g = y - s.y has y's coefficients but the constant: the same derivative, the same cuts.
  const Cuts cs = estimated_as_quadratic(y) ? Cuts{} : derivative_cuts(y);
  p.cut = cs.at;
  p.cuts = cs.n;
  prepare_monotone(y, cs, p.mono);
  if (p.mono.n > 0) // only the pieces' rows use it
    p.coarse_margin = 0x1p-30 + 2.0 * (p.x_bound + grid_point(p.x_lipschitz * (kCoarseCells + 1)));
}

// rule: PATH.CURVE.SAMPLE, PATH.SAMPLE.TIE
namespace {

// The estimates, else the exact paths of curve_crossings_into, for a row of curve_crossings_left
// (g = y - s.y): the crossings, in found or in scratch. Out of line: the rarer rows.
// rule: PATH.CURVE.SAMPLE, PATH.CURVE.FILTER
[[gnu::noinline]] const std::vector<Crossing>&
crossings_estimated_or_exact(const PreparedCurve& p, const Cubic& g, const Cubic& x,
                             std::int64_t sy, Tie t, std::vector<Crossing>& found,
                             std::vector<Crossing>& scratch) {
  if (g.c[0] != 0 && formula::curve_at_one(g.c) != 0) {
    const int v = bernstein_variations(g);
    found.clear();
    if (v == 0)
      return found;
    const double bound = row_error_bound(g, p.y_abs_rest);
    if (estimated_crossings(g, bound, Cuts{p.cut, p.cuts}, x, p.x_lipschitz, p.x_bound, v, t, found,
                            1, &p.hints, sy))
      return found;
  }
  curve_crossings_into(*p.curve, sy, t, true, scratch);
  return scratch;
}

// The rows the monotone pieces leave: with no root at an end, the quadratic formula (straight
// into out; most rows of a glyph's quadratics), else crossings_estimated_or_exact's, appended.
// x is the curve's x (p.x). Out: std::vector<Crossing> or RowCrossings, whose room holds three
// a curve: more is a logic error (a cubic and a line meet in three points at most, counted
// with multiplicity).
// rule: PATH.CURVE.SAMPLE, PATH.CURVE.FILTER
template <class Out>
[[gnu::always_inline]] inline void
curve_crossings_left(const PreparedCurve& p, const Cubic& x, std::int64_t sy, Tie t, Out& out,
                     std::vector<Crossing>& found, std::vector<Crossing>& scratch) {
  Cubic g{p.y};
  g.c[0] -= sy;
  // Before the sign variations (estimated_crossings tries it again on the rows it leaves,
  // which are few).
  if (g.c[3] == 0 && g.c[2] != 0 && g.c[0] != 0 && formula::curve_at_one(g.c) != 0 &&
      quadratic_crossings(g, x, p.x_lipschitz, p.x_bound, out, 1))
    return;
  const std::vector<Crossing>& decided =
      crossings_estimated_or_exact(p, g, x, sy, t, found, scratch);
  if (decided.size() > 3)
    throw std::logic_error("path: more than three crossings of one curve with a row");
  for (const Crossing& c : decided)
    out.push_back(c);
}

} // namespace

// rule: PATH.CURVE.SAMPLE, PATH.SAMPLE.TIE
void curve_crossings_prepared(const PreparedCurve& p, std::int64_t sy, Tie t,
                              std::vector<Crossing>& out, std::vector<Crossing>& scratch,
                              std::int64_t sample_x) {
  if (sy < p.ymin || sy > p.ymax)
    return; // the curve lies in the convex hull of its control points
  const Cubic x{p.x};
  if (p.mono.n > 0 && monotone_crossings(p, x, sy, t, out, sample_x))
    return;
  std::vector<Crossing> found;
  curve_crossings_left(p, x, sy, t, out, found, scratch);
}

// rule: PATH.CURVE.SAMPLE
void RowCrossings::overflow() {
  throw std::logic_error("path: more crossings of a sample row than its room holds (one a line, "
                         "three a curve; PATH.CURVE.SAMPLE)");
}

// rule: PATH.CURVE.SAMPLE
void curve_crossings_band(const PreparedCurve& p, std::span<const BandRow> rows, Tie t,
                          std::span<RowCrossings> out, std::vector<Crossing>& scratch,
                          std::vector<Crossing>& left) {
  const Cubic x{p.x};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::int64_t sy = rows[i].sy;
    if (sy < p.ymin)
      continue; // the curve lies in the convex hull of its control points
    if (sy > p.ymax)
      return; // and the rows come in increasing y
    if (p.mono.n > 0 && monotone_crossings(p, x, sy, t, out[i], rows[i].sample_x))
      continue;
    curve_crossings_left(p, x, sy, t, out[i], left, scratch);
  }
}

// rule: PATH.CURVE.SAMPLE
bool curve_crossings_monotone(const PreparedCurve& p, std::int64_t sy, Tie t,
                              std::vector<Crossing>& out, std::int64_t sample_x) {
  return p.mono.n > 0 && sy >= p.ymin && sy <= p.ymax &&
         monotone_crossings(p, Cubic{p.x}, sy, t, out, sample_x);
}

namespace {

// The control points' coordinates of c, and whether the row sy meets their y-range (the curve
// lies in the convex hull of its control points).
bool control_coordinates(const Curve& c, std::int64_t sy, std::array<std::int64_t, 4>& xs,
                         std::array<std::int64_t, 4>& ys) {
  std::int64_t ymin = c.p[0].y, ymax = c.p[0].y;
  for (int k = 0; k <= c.degree; ++k) {
    xs[static_cast<std::size_t>(k)] = c.p[static_cast<std::size_t>(k)].x;
    ys[static_cast<std::size_t>(k)] = c.p[static_cast<std::size_t>(k)].y;
    ymin = std::min(ymin, ys[static_cast<std::size_t>(k)]);
    ymax = std::max(ymax, ys[static_cast<std::size_t>(k)]);
  }
  return sy >= ymin && sy <= ymax;
}

// The integer paths, in turn, on a row the curve's control points reach: true when one
// decides (its crossings in out), false (out cleared) when all leave it to the rational path.
bool integer_crossings(int n, const std::array<std::int64_t, 4>& xs,
                       const std::array<std::int64_t, 4>& ys, std::int64_t sy, Tie t,
                       std::vector<Crossing>& out) {
  Cubic gi, xi;
  gi.c = formula::curve_power_coefficients(ys, n == 3);
  gi.c[0] -= sy;
  xi.c = formula::curve_power_coefficients(xs, n == 3);
  // No root at an end: the estimates first (most rows of a glyph's curves), whose regions
  // also take the dyadic roots; the scan last.
  const bool no_end_root = gi.c[0] != 0 && formula::curve_at_one(gi.c) != 0;
  if (no_end_root) {
    const int v = bernstein_variations(gi);
    if (v == 0 || estimated_crossings(gi, xi, v, t, out))
      return true;
    out.clear();
  }
  if (n == 2 && rational_quadratic_crossings(gi, xi, t, out))
    return true;
  out.clear();
  if (n == 3 && cubic_end_crossings(gi, xi, t, out))
    return true;
  out.clear();
  if (no_end_root && scan_crossings(gi, xi, out))
    return true;
  out.clear();
  return false;
}

} // namespace

// rule: PATH.CURVE.SAMPLE, PATH.SAMPLE.TIE
bool curve_crossings_integer(const Curve& c, std::int64_t sy, Tie t, std::vector<Crossing>& out) {
  out.clear();
  std::array<std::int64_t, 4> xs{}, ys{};
  if (!control_coordinates(c, sy, xs, ys))
    return true;
  return integer_crossings(c.degree, xs, ys, sy, t, out);
}

void curve_crossings_into(const Curve& c, std::int64_t sy, Tie t, bool fast,
                          std::vector<Crossing>& out) {
  out.clear(); // the integer paths count what they found in out
  const int n = c.degree;
  std::array<std::int64_t, 4> xs{}, ys{};
  if (!control_coordinates(c, sy, xs, ys))
    return;
  if (fast && integer_crossings(n, xs, ys, sy, t, out))
    return;
  Poly g = power_basis(ys, n);
  if (g.empty())
    g.push_back(Rational(0));
  g[0] -= sy;
  trim(g);
  if (degree(g) < 1)
    return; // y constant: on the row (never crossed, PATH.DEGENERATE) or off it
  const Poly x = power_basis(xs, n);
  const int hy = t.y_down ? 1 : -1;
  std::vector<Root> roots = roots_in_unit_interval(g);
  for (Root& r : roots) {
    // Multiplicity m and the sign a of the first non-zero derivative at the root.
    int m = 1;
    int a = 0;
    Poly d = derivative(g);
    if (!r.exact) {
      a = sign_at(d, r); // a simple root: g' != 0 there
    } else {
      while (true) {
        a = sign(eval(d, r.lo));
        if (a != 0 || d.empty())
          break;
        d = derivative(d);
        ++m;
      }
    }
    int dir = 0;
    if (r.exact && r.lo == 0) {
      // g ~ a t^m after 0: the line y = s.y + hy delta is crossed iff a == hy, going that way.
      dir = a == hy ? hy : 0;
    } else if (r.exact && r.lo == 1) {
      // g ~ a (t - 1)^m before 1, of sign a (-1)^m: crossed iff that is hy, going back.
      const int before = (m % 2 == 0) ? a : -a;
      dir = before == hy ? -hy : 0;
    } else {
      // Inside: an odd multiplicity crosses once in the direction of a; an even one touches
      // the line, and its two crossings (same x in the limit) cancel.
      dir = (m % 2 == 1) ? a : 0;
    }
    if (dir != 0)
      out.push_back(Crossing{threshold_at(x, r, t), dir});
  }
}

// rule: PATH.CURVE.FILTER
std::optional<int> curve_filter_sign(const std::array<std::int64_t, 4>& c, std::int64_t k) {
  const Cubic p{c};
  return filter_sign(p, k, horner_error_bound(p));
}

// rule: PATH.CURVE.FILTER
std::optional<std::int64_t> curve_filter_floor(const std::array<std::int64_t, 4>& e,
                                               std::int64_t k) {
  const Cubic x{e};
  std::int64_t f = 0;
  if (filter_floor(x, lipschitz(x), horner_error_bound(x), k, f))
    return f;
  return std::nullopt;
}

} // namespace rastrules::path::detail
