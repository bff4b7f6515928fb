// SPDX-License-Identifier: MIT
// Obligation path/curve_budget (PATH.CURVE.SAMPLE) as a template over a curve model. Used by
// curve_budget.cpp and mutants.cpp.
//
// CurveKernelModel instantiates the kernel's own integer expressions of the curve crossing
// test, rastrules/formula/path_curve.hpp, on Sym<std::int64_t> (I) and Sym<__int128> (W), as
// kernel/src/path_curve.cpp calls them. What the kernel writes on concrete types and this file
// restates, next to the kernel line it mirrors:
//   - `gi.c[0] -= sy` (curve_crossings_impl) and the int64_t sum g(1) of integer_crossings;
//   - the floors: `xk >> 90` (crossing_on) and wide_floor_div(n, d) (n / d, less one when
//     n % d != 0 and n < 0; d > 0), entering as f d <= n < (f + 1) d;
//   - the integer square root s of a discriminant d >= 0 (the double estimate corrected by
//     `while (s * s > d) --s; while ((s + 1) (s + 1) <= d) ++s;`), entering as
//     s >= 0, s^2 <= d < (s + 1)^2 for the result, and every value the loops try in
//     [0, floor(sqrt(dmax)) + 1] (assumed: d <= 2^58 rounds to a double with relative error
//     2^-53 and IEEE 754 rounds its square root correctly, so the truncated estimate is within
//     1 of floor(sqrt(d)));
//   - the roots p / q (q > 0) that rational_quadratic_crossings and cubic_end_crossings form
//     from the coefficients and s, and the divisions by t of cubic_end_crossings (a shift of
//     the coefficient array: no arithmetic);
//   - the narrowing static_cast<std::int64_t> of thresholds and of h's coefficients.
// Every theorem ranges over a superset of what the kernel computes: coefficients anywhere in
// the bounds the first theorems prove, every k of the grid, every root p / q of the stated
// form, so each budget holds whatever path through the code reaches it.

#pragma once

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "path/line_crossing.hpp"
#include "rastrules/formula/path_curve.hpp"
#include "support/obligation.hpp"
#include "support/prover.hpp"
#include "support/sym.hpp"

namespace rastrules::proofs {

// 2^n as an Int128.
constexpr Int128 pow2(int n) {
  return static_cast<Int128>(1) << n;
}

// Returns a b, refusing (std::logic_error) a product beyond __int128: a bound that wrapped
// around would make a hypothesis false and a theorem vacuous where it matters.
inline Int128 mul128(Int128 a, Int128 b) {
  Int128 r = 0;
  if (__builtin_mul_overflow(a, b, &r))
    throw std::logic_error("proof bound beyond __int128");
  return r;
}

// Returns v as "2^n" when it is a power of two, else in decimal (for theorem names).
inline std::string magnitude(Int128 v) {
  for (int n = 0; n < 127; ++n)
    if (v == pow2(n))
      return "2^" + std::to_string(n);
  std::string digits;
  for (Int128 u = v; u != 0; u /= 10)
    digits.insert(digits.begin(), static_cast<char>('0' + static_cast<int>(u % 10)));
  return v == 0 ? "0" : digits;
}

// Returns |v| <= bound.
inline z3::expr abs_at_most(const z3::expr& v, Int128 bound) {
  const z3::expr b = int128_val(v.ctx(), bound);
  return -b <= v && v <= b;
}

// Lemma P (proved first by prove_curve_budget): |x| <= X, |y| <= Y => |x y| <= X Y for all
// integers. Its instance for terms x, y and constants X, Y, as an implication to add to a
// theorem's hypotheses: with it the solver reasons linearly over the monomials.
inline z3::expr product_bound128(const z3::expr& x, Int128 bx, const z3::expr& y, Int128 by) {
  return z3::implies(abs_at_most(x, bx) && abs_at_most(y, by), abs_at_most(x * y, mul128(bx, by)));
}

struct CurveKernelModel : PathKernelModel {
  static constexpr const char* kName = "kernel";
  using I = Sym<std::int64_t>; // the kernel's std::int64_t
  using W = Sym<Int128>;       // the kernel's __int128 (Wide)
  static constexpr int kFastBits = formula::kCurveFastBits;

  // The bounds the theorems prove and then assume, in raw units (PATH.CURVE.SAMPLE):
  // |c_j| of a coordinate's power coefficients (any degree; y's c0 is y0 - s.y, x's c0 is x0),
  static constexpr std::array<Int128, 4> kCoef{pow2(24), 3 * pow2(24), 3 * pow2(25), pow2(26)};
  // of a quadratic's,
  static constexpr std::array<Int128, 4> kCoefQuad{pow2(24), pow2(25), pow2(25), 0};
  // |3 b_i|, the Bernstein coefficients on [0, 1] times 3 (of g),
  static constexpr Int128 kBern = 3 * pow2(24);
  // |h_j| after cubic_end_crossings divides out t^m0 (t - 1)^m1,
  static constexpr Int128 kH = 14 * pow2(24);
  // |P(k / 2^30) 2^90| for coefficients within kCoef, and within kH,
  static constexpr Int128 kScaled = pow2(118);
  static constexpr Int128 kScaledH = pow2(120);
  // L 2^60 (Lipschitz), the interval Bernstein coefficients times 3 * 2^90,
  static constexpr Int128 kLip = pow2(89);
  static constexpr Int128 kInterval = pow2(120);
  // g's Bernstein coefficients on the scan's [i, i + 1] / 64 times 3 2^18 (at most 3 (14 2^42 +
  // 27 2^36 + 6 2^31 + 2^26) < 2^47.5 for i <= 63),
  static constexpr Int128 kScan = pow2(48);
  // the quadratic path's discriminant and numerator, the cubic end path's.
  static constexpr Int128 kDiscQuad = pow2(52);
  static constexpr Int128 kNum2 = pow2(79);
  static constexpr Int128 kDiscH = pow2(58);
  static constexpr Int128 kNum3 = pow2(115);
  // the monotone pieces: c2^2 - 3 c1 c3 (at most 9 2^50 + 9 2^50), and s.y 2^90.
  static constexpr Int128 kDiscDeriv = pow2(55);
  static constexpr Int128 kRowScaled = pow2(113);

  static std::vector<Constant> constants() {
    return kernel_constants_and({{"path kMinRaw", kMinRaw, Unit::kCoordRaw},
                                 {"path kMaxRaw", kMaxRaw, Unit::kCoordRaw},
                                 {"kCurveFastBits", kFastBits, Unit::kInteger}});
  }

  template <class S> static std::array<S, 4> power_coefficients(const std::array<S, 4>& q, bool c) {
    return formula::curve_power_coefficients(q, c);
  }
  template <class S> static std::array<S, 4> bernstein3(const std::array<S, 4>& a) {
    return formula::curve_bernstein3(a);
  }
  template <class S> static S scaled(const std::array<S, 4>& c, const S& k) {
    return formula::curve_scaled<S>(c, k);
  }
  template <class S, class T> static T lipschitz(const std::array<S, 4>& e) {
    return formula::curve_lipschitz_scaled<S, T>(
        e, [](const SymBool& c, const S& t, const S& f) { return select(c, t, f); });
  }
  template <class S, int Bits = kFastBits>
  static std::array<S, 4> interval_bernstein3(const std::array<S, 4>& e, const S& k) {
    return formula::curve_interval_bernstein3<S, Bits>(e, k);
  }
  template <class S>
  static SymBool strictly_between(const S& lo, const S& hi, const S& f, const S& unit) {
    return formula::curve_strictly_between<S>(lo, hi, f, unit);
  }
  template <class S> static S discriminant(const S& c0, const S& c1, const S& c2) {
    return formula::curve_discriminant<S>(c0, c1, c2);
  }
  template <class S> static S slope_at(const S& c1, const S& c2, const S& p, const S& q) {
    return formula::curve_slope_at<S>(c1, c2, p, q);
  }
  template <class S> static S numerator2(const std::array<S, 4>& e, const S& p, const S& q) {
    return formula::curve_numerator2<S>(e, p, q);
  }
  template <class S> static S numerator3(const std::array<S, 4>& e, const S& p, const S& q) {
    return formula::curve_numerator3<S>(e, p, q);
  }
  template <class S> static S at_one(const std::array<S, 4>& c) {
    return formula::curve_at_one<S>(c);
  }
  template <class S> static std::array<S, 3> derivatives_at_one(const std::array<S, 4>& c) {
    return formula::curve_derivatives_at_one<S>(c);
  }
  template <class S>
  static std::array<S, 4> divide_by_t_minus_one(const std::array<S, 4>& h, int deg, S& sum) {
    return formula::curve_divide_by_t_minus_one<S>(h, deg, sum);
  }
  template <class S> static std::array<S, 4> derivative_coefficients(const std::array<S, 4>& c) {
    return formula::curve_derivative_coefficients<S>(c);
  }
  template <class S> static S derivative_discriminant(const std::array<S, 4>& c) {
    return formula::curve_derivative_discriminant<S>(c);
  }
  template <class S> static SymBool vertex_inside(const std::array<S, 4>& d) {
    return formula::curve_vertex_inside<S>(
        d, [](const SymBool& c, const S& t, const S& f) { return select(c, t, f); });
  }
  template <class S> static std::array<S, 2> bracket_range(const S& y, const S& lip, const S& n) {
    return formula::curve_bracket_range<S>(y, lip, n);
  }
  template <class S> static S row_scaled(const S& sy) { return formula::curve_row_scaled<S>(sy); }
  template <class S> static S scaled_end(const std::array<S, 4>& c, bool at_one) {
    return formula::curve_scaled_end<S>(c, at_one);
  }
};

// Lemmas (proved first; a theorem that takes their instances as hypotheses is skipped, UNKNOWN,
// when they are not PROVED):
//   P.  |x| <= X, |y| <= Y => |x y| <= X Y;
//   M.  0 <= x <= X, 0 <= y <= Y => 0 <= x y <= X Y (X, Y terms, not only constants);
//   L.  0 <= X <= x, 0 <= Y <= y => X Y <= x y;
//   A.  |x| <= X, 0 <= y <= Y => |x y| <= X Y (X a constant, y and Y terms);
//   D.  d >= 1, f d <= n, |n| <= B d => f <= B, and n < (f + 1) d => f >= -B - 1.
// Instances of them turn the nonlinear budgets into linear reasoning over monomials.
inline z3::expr lemma_m(const z3::expr& x, const z3::expr& bx, const z3::expr& y,
                        const z3::expr& by) {
  return z3::implies(0 <= x && x <= bx && 0 <= y && y <= by, 0 <= x * y && x * y <= bx * by);
}
inline z3::expr lemma_l(const z3::expr& bx, const z3::expr& x, const z3::expr& by,
                        const z3::expr& y) {
  return z3::implies(0 <= bx && bx <= x && 0 <= by && by <= y, bx * by <= x * y);
}
inline z3::expr lemma_a(const z3::expr& x, Int128 bx, const z3::expr& y, const z3::expr& by) {
  const z3::expr b = int128_val(x.ctx(), bx);
  return z3::implies(abs_at_most(x, bx) && 0 <= y && y <= by,
                     -(b * by) <= x * y && x * y <= b * by);
}
inline z3::expr lemma_d(const z3::expr& f, const z3::expr& d, const z3::expr& n, Int128 bound) {
  const z3::expr b = int128_val(f.ctx(), bound);
  return z3::implies(d >= 1 && f * d <= n && n < (f + 1) * d && -(b * d) <= n && n <= b * d,
                     -b - 1 <= f && f <= b);
}

// Proves lemmas P, M, L, A and D (above) on fresh variables; returns whether all are PROVED.
// The budget theorems take instances of them as hypotheses.
inline bool prove_product_lemmas(Prover& pr) {
  z3::context& ctx = pr.ctx();
  const z3::expr x = ctx.int_const("lx"), y = ctx.int_const("ly");
  const z3::expr bx = ctx.int_const("lX"), by = ctx.int_const("lY");
  const z3::expr f = ctx.int_const("lf"), d = ctx.int_const("ld"), n = ctx.int_const("ln");
  bool lemmas = true;
  lemmas &= pr.prove("lemma P: |x| <= X, |y| <= Y => |x y| <= X Y",
                     {-bx <= x, x <= bx, -by <= y, y <= by},
                     -(bx * by) <= x * y && x * y <= bx * by) == Status::kProved;
  lemmas &= pr.prove("lemma M: 0 <= x <= X, 0 <= y <= Y => 0 <= x y <= X Y",
                     {0 <= x, x <= bx, 0 <= y, y <= by},
                     0 <= x * y && x * y <= bx * by) == Status::kProved;
  lemmas &= pr.prove("lemma L: 0 <= X <= x, 0 <= Y <= y => X Y <= x y",
                     {0 <= bx, bx <= x, 0 <= by, by <= y}, bx * by <= x * y) == Status::kProved;
  lemmas &= pr.prove("lemma A: |x| <= X, 0 <= y <= Y => |x y| <= X Y",
                     {-bx <= x, x <= bx, 0 <= y, y <= by},
                     -(bx * by) <= x * y && x * y <= bx * by) == Status::kProved;
  lemmas &= pr.prove("lemma D: d >= 1, f d <= n < (f + 1) d, |n| <= B d => -B - 1 <= f <= B",
                     {d >= 1, f * d <= n, n < (f + 1) * d, -(bx * d) <= n, n <= bx * d},
                     -bx - 1 <= f && f <= bx) == Status::kProved;
  return lemmas;
}

// For model F (ranges from F::kMinRaw, F::kMaxRaw; bounds F::kCoef ...):
//   C1. power coefficients (quadratic, cubic) of q_i, and g = y - s.y, in [kMinRaw, kMaxRaw]:
//       every step fits int64_t, |c_j| <= kCoef (kCoefQuad), |3 b_i(g)| <= kBern, g(1) fits;
//   C2. curve_scaled for |c_j| <= kCoef, 0 <= k <= 2^30: fits __int128, |.| <= kScaled; the
//       same for h (|h_j| <= kH, h3 = 0): |.| <= kScaledH;
//   C3. crossing_on's Lipschitz test: 0 <= L 2^60 <= kLip; xk -+ L 2^60, f 2^90 and
//       (f + 1) 2^90 with f = floor(xk / 2^90) fit __int128, f fits int64_t;
//   C4. crossing_on's Bernstein test: curve_interval_bernstein3 for 0 <= k < 2^30 fits
//       __int128 (k^4 included), |3 b 2^90| <= kInterval; the floor f of the smallest over
//       3 2^90, f 3 2^90, (f + 1) 3 2^90 fit, f fits int64_t; scan_crossings:
//       curve_interval_bernstein3 at 6 bits of g for 0 <= i < 64 fits, |3 b 2^18| <= kScan;
//   C5. rational_quadratic_crossings: |discriminant| <= kDiscQuad, the square root's steps,
//       p, q, the slope, |numerator| <= kNum2, q^2, and the threshold's floor f, f q^2, f - 1
//       fit (f in int64_t), for a root p / q in [0, 1] of either form (two roots, or linear);
//   C6. cubic_end_crossings: g(1), g's derivatives at 1, x(1) fit; after dividing out t^m0
//       (t - 1)^m1 (every case), |h_j| <= kH; then h's discriminant (<= kDiscH), the square
//       root, p, q, the slope, |numerator| <= kNum3, q^3 and the threshold fit; h narrowed to
//       int64_t and its Bernstein coefficients fit;
//   C7. the monotone pieces of a cubic (prepare_monotone, monotone_crossings): y' = (c1, 2 c2,
//       3 c3, 0) fits int64_t with |.| <= kH (so C2's theorem for h covers its scaled values
//       and the filter's bound covers it), y'(1), y''(1) and the vertex test fit, c2^2 - 3 c1 c3
//       fits with |.| <= kDiscDeriv; a bracket's range Y -+ 3 L 2^60 (|Y| <= kScaled,
//       0 <= L 2^60 <= kLip), the row s.y 2^90 (|.| <= kRowScaled) and y 2^90 at t = 0 and 1
//       (curve_scaled_end, |.| <= kScaled) fit __int128.
// The theorem groups C1 .. C7, for running some of them (the mutation self-check runs the group
// a mutant targets; the proof runs all).
enum CurvePart : unsigned {
  kC1 = 1,
  kC2 = 2,
  kC3 = 4,
  kC4 = 8,
  kC5 = 16,
  kC6 = 32,
  kC7 = 64,
  kAllCurveParts = 127
};

template <class F> void prove_curve_budget(Prover& pr, unsigned parts = kAllCurveParts) {
  using I = typename F::I;
  using W = typename F::W;
  using IR = typename I::rep;
  using WR = typename W::rep;
  Domain& dom = pr.domain();
  z3::context& ctx = pr.ctx();
  const auto big = [&](Int128 v) { return int128_val(ctx, v); };
  const auto show = [&](Int128 v) { return big(v).to_string(); };
  const auto wvar = [&](const std::string& n, Unit u) { return dom.var<WR>(n, u); };
  const auto ivar = [&](const std::string& n, Unit u) { return dom.var<IR>(n, u); };
  const auto all = [&](const std::vector<z3::expr>& v) {
    z3::expr r = ctx.bool_val(true);
    for (const z3::expr& e : v)
      r = r && e;
    return r;
  };

  // Results cast to void below are computed for the "fits" obligations they record.

  // Lemmas P, M, L, A, D on fresh variables (C2 .. C6 use them).
  const bool lemmas = (parts & ~unsigned{kC1}) == 0 || prove_product_lemmas(pr);
  const auto needs_lemmas = [&](const std::string& name) {
    if (!lemmas)
      pr.skip(name, "lemma P, M, L, A or D not proved");
    return lemmas;
  };

  // C1: power coefficients and g's Bernstein coefficients, from raw coordinates.
  for (const bool cubic : {false, true}) {
    if ((parts & kC1) == 0)
      break;
    const std::string tag = cubic ? "c" : "q";
    std::vector<z3::expr> h;
    std::array<I, 4> q{ivar(tag + "q0", Unit::kCoordRaw), ivar(tag + "q1", Unit::kCoordRaw),
                       ivar(tag + "q2", Unit::kCoordRaw), ivar(tag + "q3", Unit::kCoordRaw)};
    const I sy = ivar(tag + "sy", Unit::kCoordRaw);
    for (const I& v : q)
      h.push_back(in_closed(v.expr(), F::kMinRaw, F::kMaxRaw));
    h.push_back(in_closed(sy.expr(), F::kMinRaw, F::kMaxRaw));
    if (!cubic)
      h.push_back(q[3].expr() == 0); // the kernel's unused fourth point of a quadratic
    const std::size_t mark = dom.mark();
    const std::array<I, 4> c = F::power_coefficients(q, cubic);
    const std::array<I, 4> g{c[0] - sy, c[1], c[2], c[3]}; // gi.c[0] -= sy
    const std::array<I, 4> b = F::bernstein3(g);
    const I g1 = F::at_one(g); // integer_crossings' g(1)
    const std::array<Int128, 4>& bound = cubic ? F::kCoef : F::kCoefQuad;
    std::vector<z3::expr> goal;
    for (std::size_t j = 0; j < 4; ++j) {
      goal.push_back(abs_at_most(c[j].expr(), bound[j]));
      goal.push_back(abs_at_most(g[j].expr(), bound[j]));
      goal.push_back(abs_at_most(b[j].expr(), F::kBern));
    }
    (void)g1;
    pr.prove(std::string("C1: ") + (cubic ? "cubic" : "quadratic") +
                 " power coefficients within kCoef, 3 b(g) within kBern, all int64_t",
             h, all(goal), dom.obligations_since(mark));
  }

  // Coefficient variables within bounds.
  const auto coef_vars = [&](const std::string& tag, const std::array<Int128, 4>& bound,
                             std::vector<z3::expr>& h) {
    std::array<W, 4> c{wvar(tag + "0", Unit::kInteger), wvar(tag + "1", Unit::kInteger),
                       wvar(tag + "2", Unit::kInteger), wvar(tag + "3", Unit::kInteger)};
    for (std::size_t j = 0; j < 4; ++j)
      h.push_back(abs_at_most(c[j].expr(), bound[j]));
    return c;
  };
  // Instances of lemma P for k^m (0 <= k <= 2^bits, bits 30 unless given), m = 2..4, and for
  // c_j k^m, m = 1..3.
  const auto power_hints = [&](const std::array<W, 4>& c, const std::array<Int128, 4>& bound,
                               const z3::expr& k, std::vector<z3::expr>& h, int bits = 30) {
    z3::expr km = k;
    for (int m = 1; m <= 4; ++m) {
      if (m > 1) {
        h.push_back(product_bound128(km, pow2(bits * (m - 1)), k, pow2(bits)));
        km = km * k;
      }
      for (std::size_t j = 0; m < 4 && j < 4; ++j)
        h.push_back(product_bound128(c[j].expr(), bound[j], km, pow2(bits * m)));
    }
  };

  // C2: curve_scaled.
  for (const bool of_h : {false, true}) {
    if ((parts & kC2) == 0)
      break;
    const std::string name = of_h ? "C2: scaled P(k / 2^30) 2^90 of h (|h_j| <= kH, h3 = 0)"
                                  : "C2: scaled P(k / 2^30) 2^90 (|c_j| <= kCoef)";
    if (!needs_lemmas(name))
      continue;
    std::vector<z3::expr> h;
    const std::array<Int128, 4> bound =
        of_h ? std::array<Int128, 4>{F::kH, F::kH, F::kH, 0} : F::kCoef;
    const std::array<W, 4> c = coef_vars(of_h ? "sh" : "sc", bound, h);
    const W k = wvar(of_h ? "shk" : "sck", Unit::kInteger);
    h.push_back(0 <= k.expr() && k.expr() <= big(pow2(F::kFastBits)));
    power_hints(c, bound, k.expr(), h);
    const std::size_t mark = dom.mark();
    const W v = F::scaled(c, k);
    pr.prove(name + ": __int128, |.| <= " + magnitude(of_h ? F::kScaledH : F::kScaled), h,
             abs_at_most(v.expr(), of_h ? F::kScaledH : F::kScaled), dom.obligations_since(mark));
  }

  // Power coefficients in int64_t (I) within kCoef, as in C1's results.
  const auto icoef_vars = [&](const std::string& tag, std::vector<z3::expr>& h) {
    std::array<I, 4> c{ivar(tag + "0", Unit::kInteger), ivar(tag + "1", Unit::kInteger),
                       ivar(tag + "2", Unit::kInteger), ivar(tag + "3", Unit::kInteger)};
    for (std::size_t j = 0; j < 4; ++j)
      h.push_back(abs_at_most(c[j].expr(), F::kCoef[j]));
    return c;
  };

  // C3: the Lipschitz test of crossing_on.
  if ((parts & kC3) != 0 && needs_lemmas("C3: Lipschitz test")) {
    std::vector<z3::expr> h;
    const std::array<I, 4> e = icoef_vars("le", h);
    const W xk = wvar("lxk", Unit::kInteger);
    const W f = wvar("lf90", Unit::kInteger);
    const z3::expr one = big(pow2(3 * F::kFastBits));
    h.push_back(abs_at_most(xk.expr(), F::kScaled));                              // C2
    h.push_back(f.expr() * one <= xk.expr() && xk.expr() < (f.expr() + 1) * one); // xk >> 90
    const std::size_t mark = dom.mark();
    const W lip = F::template lipschitz<I, W>(e);
    const W unit = W(std::int64_t{1} << F::kFastBits) * W(std::int64_t{1} << F::kFastBits) *
                   W(std::int64_t{1} << F::kFastBits); // Wide{1} << 90
    const SymBool between = F::strictly_between(xk - lip, xk + lip, f, unit);
    (void)between;
    const I narrowed(f); // static_cast<std::int64_t>(f)
    (void)narrowed;
    pr.prove("C3: Lipschitz: 0 <= L 2^60 <= " + magnitude(F::kLip) +
                 ", xk -+ L 2^60, f 2^90, (f + 1) 2^90 fit "
                 "__int128, f fits int64_t",
             h, 0 <= lip.expr() && lip.expr() <= big(F::kLip) && abs_at_most(f.expr(), pow2(28)),
             dom.obligations_since(mark));
  }

  // C4: the Bernstein test of crossing_on, on [k, k + 1] / 2^30, and the scan of
  // scan_crossings, on [i, i + 1] / 64: the Bernstein coefficients (from `bernstein`) of a
  // coordinate with |c_j| <= kCoef on [k, k + 1] / 2^bits, 0 <= k < 2^bits, fit __int128 with
  // |.| <= bound.
  const auto interval_theorem = [&](const std::string& name, const std::string& tag, int bits,
                                    Int128 bound, const auto& bernstein) {
    if ((parts & kC4) == 0 || !needs_lemmas(name))
      return;
    std::vector<z3::expr> h;
    const std::array<W, 4> e = coef_vars(tag + "e", F::kCoef, h);
    const W k = wvar(tag + "k", Unit::kInteger);
    h.push_back(0 <= k.expr() && k.expr() < big(pow2(bits)));
    power_hints(e, F::kCoef, k.expr(), h, bits);
    const std::size_t mark = dom.mark();
    std::vector<z3::expr> goal;
    for (const W& v : bernstein(e, k))
      goal.push_back(abs_at_most(v.expr(), bound));
    pr.prove(name + " fit __int128, |.| <= " + magnitude(bound), h, all(goal),
             dom.obligations_since(mark));
  };
  interval_theorem("C4: Bernstein coefficients on [k, k + 1] / 2^30 (times 3 2^90, k^4 included)",
                   "b", F::kFastBits, F::kInterval, [](const std::array<W, 4>& e, const W& k) {
                     return F::interval_bernstein3(e, k);
                   });
  interval_theorem("C4: the scan's Bernstein coefficients of g on [i, i + 1] / 64 (times 3 2^18)",
                   "g", formula::kCurveScanBits, F::kScan,
                   [](const std::array<W, 4>& e, const W& k) {
                     return F::template interval_bernstein3<W, formula::kCurveScanBits>(e, k);
                   });
  if ((parts & kC4) != 0) {
    std::vector<z3::expr> h;
    const W xmin = wvar("bxmin", Unit::kInteger), xmax = wvar("bxmax", Unit::kInteger);
    const W f = wvar("bf", Unit::kInteger);
    const z3::expr scale = big(3 * pow2(3 * F::kFastBits));
    h.push_back(abs_at_most(xmin.expr(), F::kInterval));
    h.push_back(abs_at_most(xmax.expr(), F::kInterval));
    h.push_back(f.expr() * scale <= xmin.expr() && xmin.expr() < (f.expr() + 1) * scale);
    const std::size_t mark = dom.mark();
    const W s3 = W(3) * W(std::int64_t{1} << F::kFastBits) * W(std::int64_t{1} << F::kFastBits) *
                 W(std::int64_t{1} << F::kFastBits); // Wide{3} << 90
    (void)F::strictly_between(xmin, xmax, f, s3);
    const I narrowed(f);
    (void)narrowed;
    pr.prove("C4: the floor f of xmin / (3 2^90): f 3 2^90, (f + 1) 3 2^90 fit __int128, f fits "
             "int64_t",
             h, abs_at_most(f.expr(), pow2(29)), dom.obligations_since(mark));
  }

  // The threshold of a crossing at num / den (threshold_of): f = floor(num / den), f den, f - 1,
  // and f narrowed to int64_t; with lemma D's instance for |num| <= bound den.
  const auto threshold_steps = [&](const std::string& tag, const W& num, const W& den, Int128 bound,
                                   Int128 den_max, std::vector<z3::expr>& h) {
    const W f = wvar(tag + "f", Unit::kInteger);
    h.push_back(f.expr() * den.expr() <= num.expr() && num.expr() < (f.expr() + 1) * den.expr());
    h.push_back(lemma_d(f.expr(), den.expr(), num.expr(), bound));
    h.push_back(lemma_a(f.expr(), bound + 1, den.expr(), big(den_max)));
    const W fd = f * den;
    const W fm = f - W(1);
    const I a(f), b(fm);
    (void)fd;
    (void)a;
    (void)b;
    return f;
  };

  // The integer square root of a discriminant 0 <= d <= dmax (the kernel's correction loops):
  // every value t they try lies in [0, tmax] and t^2, (t + 1)^2 fit; the result s <= smax.
  const auto sqrt_steps = [&](const std::string& tag, Int128 dmax, Int128 tmax, Int128 smax) {
    const std::string name = "C5/C6: integer square root (" + tag + ")";
    if (!needs_lemmas(name))
      return;
    std::vector<z3::expr> h;
    const W d = wvar(tag + "d", Unit::kInteger);
    const W s = wvar(tag + "s", Unit::kInteger);
    const W t = wvar(tag + "t", Unit::kInteger); // a value the loops try
    h.push_back(0 <= d.expr() && d.expr() <= big(dmax));
    h.push_back(0 <= t.expr() && t.expr() <= big(tmax));
    h.push_back(0 <= s.expr() && s.expr() * s.expr() <= d.expr() &&
                d.expr() < (s.expr() + 1) * (s.expr() + 1));
    h.push_back(lemma_l(big(smax + 1), s.expr(), big(smax + 1), s.expr()));
    h.push_back(lemma_m(t.expr(), big(tmax), t.expr(), big(tmax)));
    h.push_back(lemma_m(t.expr() + 1, big(tmax + 1), t.expr() + 1, big(tmax + 1)));
    const std::size_t mark = dom.mark();
    const W sq = t * t;
    const W sq1 = (t + W(1)) * (t + W(1));
    (void)sq;
    (void)sq1;
    pr.prove(name + ": t^2, (t + 1)^2 fit __int128 for t <= " + show(tmax) + "; s <= " + show(smax),
             h, s.expr() <= big(smax), dom.obligations_since(mark));
  };

  // The discriminant c1^2 - 4 c2 c0 for |c_j| within `bound`: fits, |.| <= dbound.
  const auto discriminant_theorem = [&](const std::string& label, const std::string& tag,
                                        const std::array<Int128, 4>& bound, Int128 dbound) {
    if (!needs_lemmas(label + " discriminant"))
      return;
    std::vector<z3::expr> h;
    const std::array<W, 4> c = coef_vars(tag, bound, h);
    h.push_back(product_bound128(c[1].expr(), bound[1], c[1].expr(), bound[1]));
    h.push_back(product_bound128(c[2].expr(), bound[2], c[0].expr(), bound[0]));
    const std::size_t mark = dom.mark();
    const W d = F::discriminant(c[0], c[1], c[2]);
    pr.prove(label + " discriminant c1^2 - 4 c2 c0 fits __int128, |.| <= " + magnitude(dbound), h,
             abs_at_most(d.expr(), dbound), dom.obligations_since(mark));
  };

  // A crossing at a rational root p / q of c0 + c1 t + c2 t^2 (|c_j| within cb; linear: c2 = 0,
  // the root -c0 / c1; else (-c1 -+ s) / (2 c2) with 0 <= s <= smax), x with coefficients
  // within eb: the kernel goes on only for p / q in [0, 1] (C5) or (0, 1) (C6); then p, q, the
  // slope, x's numerator of degree n (2: numerator2, 3: numerator3; |.| <= nbound), q^n and the
  // threshold fit, |floor(x_c)| <= sum eb + 1.
  struct RootCase {
    std::string label; // "C5" or "C6"
    bool cubic_end;    // C6: q = 2 |c2| and the open interval; C5: q = |2 c2|, closed
    std::array<Int128, 4> cb, eb;
    Int128 smax, qmax, nbound;
  };
  const auto root_theorem = [&](const RootCase& rc, bool linear) {
    const std::string name = rc.label + ": " +
                             (linear ? "linear: root -c0 / c1" : "roots (-c1 -+ s) / (2 c2)") +
                             ", p / q in " + (rc.cubic_end ? "(0, 1)" : "[0, 1]") +
                             ": p, q, slope, numerator (<= " + magnitude(rc.nbound) + "), q^" +
                             (rc.cubic_end ? "3" : "2") + ", threshold fit";
    if (!needs_lemmas(name))
      return;
    const std::string tag = rc.label + (linear ? "l" : "q");
    std::vector<z3::expr> h;
    const std::array<W, 4> c = coef_vars(tag + "c", rc.cb, h);
    const std::array<W, 4> e = coef_vars(tag + "e", rc.eb, h);
    const W s = wvar(tag + "s", Unit::kInteger);
    const z3::expr sign = ctx.bool_const((tag + "minus").c_str());
    h.push_back(0 <= s.expr() && s.expr() <= big(rc.smax)); // the square root (sqrt_steps)
    const std::size_t mark = dom.mark();
    W p = c[0], q = c[1];
    if (linear) { // C5: roots[0] = c1 > 0 ? (-c0, c1) : (c0, -c1); C6: the same with h
      h.push_back(c[2].expr() == 0 && c[1].expr() != 0);
      p = select(SymBool(c[1].expr() > 0), -c[0], c[0]);
      q = select(SymBool(c[1].expr() > 0), c[1], -c[1]);
    } else {
      h.push_back(c[2].expr() != 0);
      const W num = select(SymBool(sign), -c[1] - s, -c[1] + s);
      if (rc.cubic_end) { // p = h2 > 0 ? num : -num, q = 2 (h2 > 0 ? h2 : -h2)
        p = select(SymBool(c[2].expr() > 0), num, -num);
        q = W(2) * select(SymBool(c[2].expr() > 0), c[2], -c[2]);
      } else { // normal(num, 2 c2)
        const W den = W(2) * c[2];
        p = select(SymBool(den.expr() > 0), num, -num);
        q = select(SymBool(den.expr() > 0), den, -den);
      }
    }
    const z3::expr pe = p.expr(), qe = q.expr();
    h.push_back(rc.cubic_end ? (0 < pe && pe < qe) : (0 <= pe && pe <= qe));
    // Monomials p^a q^b (a + b <= 3) between 0 and q^(a + b) <= qmax^(a + b), then e_j times them.
    const z3::expr q2 = qe * qe, q3 = qe * qe * qe;
    h.push_back(lemma_m(pe, qe, qe, qe));
    h.push_back(lemma_m(pe, qe, pe, qe));
    h.push_back(lemma_m(pe * pe, q2, pe, qe));
    h.push_back(lemma_m(pe * qe, q2, pe, qe));
    h.push_back(lemma_m(pe * qe, q2, qe, qe));
    h.push_back(lemma_m(qe, big(rc.qmax), qe, big(rc.qmax)));
    h.push_back(lemma_m(q2, big(rc.qmax * rc.qmax), qe, big(rc.qmax)));
    for (std::size_t j = 0; j < 4; ++j) {
      for (const z3::expr& m : {pe, qe})
        h.push_back(lemma_a(e[j].expr(), rc.eb[j], m, qe));
      for (const z3::expr& m : {pe * pe, pe * qe, q2})
        h.push_back(lemma_a(e[j].expr(), rc.eb[j], m, q2));
      for (const z3::expr& m : {pe * pe * pe, pe * pe * qe, pe * q2, q3})
        h.push_back(lemma_a(e[j].expr(), rc.eb[j], m, q3));
    }
    h.push_back(lemma_a(c[1].expr(), rc.cb[1], qe, big(rc.qmax)));
    h.push_back(lemma_a(c[2].expr(), rc.cb[2], pe, big(rc.qmax)));
    h.push_back(lemma_l(big(1), qe, big(1), qe)); // q^2 >= 1
    h.push_back(lemma_l(big(1), q2, big(1), qe)); // q^3 >= 1
    const W slope = F::slope_at(c[1], c[2], p, q);
    (void)slope;
    const W num = rc.cubic_end ? F::numerator3(e, p, q) : F::numerator2(e, p, q);
    const W den = rc.cubic_end ? q * q * q : q * q;
    const Int128 xbound = rc.eb[0] + rc.eb[1] + rc.eb[2] + rc.eb[3];
    const Int128 den_max = rc.cubic_end ? rc.qmax * rc.qmax * rc.qmax : rc.qmax * rc.qmax;
    const W f = threshold_steps(tag, num, den, xbound, den_max, h);
    pr.prove(name, h,
             abs_at_most(num.expr(), rc.nbound) && -(big(xbound) * den.expr()) <= num.expr() &&
                 num.expr() <= big(xbound) * den.expr() && abs_at_most(f.expr(), xbound + 1),
             dom.obligations_since(mark));
  };

  // C5: rational_quadratic_crossings (a quadratic: |c_j|, |e_j| within kCoefQuad). sqrt(2^52) =
  // 2^26; the double estimate is within 1 of the root.
  if ((parts & kC5) != 0) {
    discriminant_theorem("C5: quadratic", "rc", F::kCoefQuad, F::kDiscQuad);
    sqrt_steps("quadratic", F::kDiscQuad, pow2(26) + 1, pow2(26));
    const RootCase rc{"C5", false, F::kCoefQuad, F::kCoefQuad, pow2(26), pow2(26), F::kNum2};
    root_theorem(rc, false);
    root_theorem(rc, true);
  }

  // C7: the monotone pieces.
  if ((parts & kC7) != 0 && needs_lemmas("C7: monotone pieces")) {
    std::vector<z3::expr> h;
    const std::array<I, 4> c = icoef_vars("mc", h);
    h.push_back(product_bound128(c[2].expr(), F::kCoef[2], c[2].expr(), F::kCoef[2]));
    h.push_back(product_bound128(c[1].expr(), F::kCoef[1], c[3].expr(), F::kCoef[3]));
    const I sy = ivar("msy", Unit::kCoordRaw);
    h.push_back(in_closed(sy.expr(), F::kMinRaw, F::kMaxRaw));
    const W y = wvar("my", Unit::kInteger), lip = wvar("mlip", Unit::kInteger);
    h.push_back(abs_at_most(y.expr(), F::kScaled));             // C2
    h.push_back(0 <= lip.expr() && lip.expr() <= big(F::kLip)); // C3
    const std::size_t mark = dom.mark();
    const std::array<I, 4> d = F::derivative_coefficients(c);
    const I disc = F::derivative_discriminant(c);
    (void)F::at_one(d);
    (void)F::derivatives_at_one(d);
    (void)F::vertex_inside(d);
    const std::array<W, 2> range = F::bracket_range(y, lip, W(3));
    const W row = F::row_scaled(W(sy));
    const std::array<W, 4> cw{W(c[0]), W(c[1]), W(c[2]), W(c[3])};
    const W end0 = F::scaled_end(cw, false), end1 = F::scaled_end(cw, true);
    std::vector<z3::expr> goal;
    for (const I& v : d)
      goal.push_back(abs_at_most(v.expr(), F::kH));
    goal.push_back(abs_at_most(disc.expr(), F::kDiscDeriv));
    for (const W& v : range)
      goal.push_back(abs_at_most(v.expr(), F::kScaled + 3 * F::kLip));
    goal.push_back(abs_at_most(row.expr(), F::kRowScaled));
    goal.push_back(abs_at_most(end0.expr(), F::kScaled) && abs_at_most(end1.expr(), F::kScaled));
    pr.prove("C7: monotone pieces: y' within kH, c2^2 - 3 c1 c3 within " +
                 magnitude(F::kDiscDeriv) +
                 ", y'(1), y''(1), the vertex test, a bracket's range, s.y 2^90 (<= " +
                 magnitude(F::kRowScaled) + ") and y 2^90 at t = 0, 1 fit",
             h, all(goal), dom.obligations_since(mark));
  }

  // C6: cubic_end_crossings. First g(1), the derivatives at 1, x(1), and every division.
  if ((parts & kC6) == 0)
    return;
  {
    std::vector<z3::expr> h;
    const std::array<W, 4> c = coef_vars("ec", F::kCoef, h);
    const std::array<W, 4> e = coef_vars("ee", F::kCoef, h);
    const std::size_t mark = dom.mark();
    (void)F::at_one(c);
    (void)F::derivatives_at_one(c);
    (void)F::at_one(e);
    std::vector<z3::expr> goal;
    // g of degree deg0 (the kernel drops zero leading coefficients first), m0 divisions by t
    // (shifts), then m1 by (t - 1): every case the loops can take.
    for (int deg0 = 1; deg0 <= 3; ++deg0) {
      for (int m0 = 0; m0 < deg0; ++m0) {
        for (int m1 = 0; m0 + m1 <= deg0; ++m1) {
          std::array<W, 4> hh = c;
          for (int j = deg0 + 1; j < 4; ++j)
            hh[static_cast<std::size_t>(j)] = W(0);
          int deg = deg0;
          for (int i = 0; i < m0; ++i) {
            hh = {hh[1], hh[2], hh[3], W(0)};
            --deg;
          }
          for (int i = 0; i < m1 && deg > 0; ++i) {
            W sum(0);
            hh = F::divide_by_t_minus_one(hh, deg, sum);
            --deg;
          }
          for (std::size_t j = 0; j < 3; ++j)
            goal.push_back(abs_at_most(hh[j].expr(), F::kH));
          goal.push_back(hh[3].expr() == 0 || deg == 3);
        }
      }
    }
    pr.prove("C6: g(1), g's derivatives at 1, x(1) and every division by t^m0 (t - 1)^m1 fit "
             "__int128; the quotient h has degree <= 2 and |h_j| <= " +
                 magnitude(F::kH) + " (kH)",
             h, all(goal), dom.obligations_since(mark));
  }
  {
    std::vector<z3::expr> h;
    std::array<W, 4> hw = coef_vars("nh", {F::kH, F::kH, F::kH, 0}, h);
    const std::size_t mark = dom.mark();
    const std::array<I, 4> hi{I(hw[0]), I(hw[1]), I(hw[2]), I(std::int64_t{0})}; // hc
    const std::array<I, 4> b = F::bernstein3(hi);
    (void)b;
    pr.prove("C6: h narrowed to int64_t, its Bernstein coefficients fit int64_t", h,
             ctx.bool_val(true), dom.obligations_since(mark));
  }
  const std::array<Int128, 4> hb{F::kH, F::kH, F::kH, 0};
  discriminant_theorem("C6: h's", "dh", hb, F::kDiscH);
  // sqrt(2^58) = 2^29; the double estimate is within 1 of the root.
  sqrt_steps("cubic end", F::kDiscH, pow2(29) + 1, pow2(29));
  const RootCase rc{"C6", true, hb, F::kCoef, pow2(29), 2 * F::kH, F::kNum3};
  root_theorem(rc, false);
  root_theorem(rc, true);
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kCurveBudget{"path/curve_budget",
                                          []<class F>(Prover& pr) { prove_curve_budget<F>(pr); }};
// Some of its groups (CurvePart), for the mutants that target them.
template <unsigned Parts>
inline const ProofObligation kCurveBudgetPart{
    "path/curve_budget", []<class F>(Prover& pr) { prove_curve_budget<F>(pr, Parts); }};

} // namespace rastrules::proofs
