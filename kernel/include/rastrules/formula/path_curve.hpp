// SPDX-License-Identifier: MIT
// The integer expressions of the path kernel's curve crossing test (kernel/src/path_curve.cpp,
// PATH.CURVE.SAMPLE): power coefficients of a Bézier coordinate, its value at t = k / 2^30
// scaled by 2^90, Bernstein coefficients, a Lipschitz bound, and the fractions that give x at a
// rational root. Generic over the integer types I (the kernel's std::int64_t) and W (its
// __int128) and branch-free (`select(c, t, f)` is c ? t : f), so that the kernel evaluates them
// on integers and the proofs (proofs/path/curve_budget.cpp) on z3 terms, with an obligation
// that every result fits its type.
// Implements: PATH.CURVE.SAMPLE

#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace rastrules::formula {

// The dyadic grid of the fast path: parameters t = k / 2^kCurveFastBits.
inline constexpr int kCurveFastBits = 30;
// The scan of the fast path: [0, 1] cut into the 2^kCurveScanBits intervals [i, i + 1] / 64,
// each with its roots counted by the Bernstein coefficients of g there.
inline constexpr int kCurveScanBits = 6;

// Returns the power-basis coefficients (lowest degree first) of one coordinate of a quadratic
// (q[0..2], cubic = false; the last coefficient is 0) or cubic (q[0..3]) Bézier curve.
// Units: raw 16.8; |c_j| <= 2^24, 3 2^24, 3 2^25, 2^26 for |q_i| <= 2^23 (PATH.CURVE.SAMPLE).
// rule: PATH.CURVE.SAMPLE
template <class I>
constexpr std::array<I, 4> curve_power_coefficients(const std::array<I, 4>& q, bool cubic) {
  if (!cubic)
    return {q[0], I(2) * (q[1] - q[0]), q[0] - I(2) * q[1] + q[2], I(0)};
  return {q[0], I(3) * (q[1] - q[0]), I(3) * (q[0] - I(2) * q[1] + q[2]),
          q[3] - I(3) * q[2] + I(3) * q[1] - q[0]};
}

// Returns 3 times the Bernstein coefficients of degree 3 on [0, 1] of the polynomial with power
// coefficients a (degree <= 3): their sign variations bound its roots in (0, 1).
// rule: PATH.CURVE.SAMPLE
template <class I> constexpr std::array<I, 4> curve_bernstein3(const std::array<I, 4>& a) {
  return {I(3) * a[0], I(3) * a[0] + a[1], I(3) * a[0] + I(2) * a[1] + a[2],
          I(3) * (a[0] + a[1] + a[2] + a[3])};
}

// Returns P(k / 2^30) * 2^90 for the polynomial with power coefficients c, exactly (Horner in
// k with the powers of 2^30 folded in).
// rule: PATH.CURVE.SAMPLE
template <class W> constexpr W curve_scaled(const std::array<W, 4>& c, W k) {
  const W u1 = W(std::int64_t{1} << kCurveFastBits);
  const W u2 = u1 * u1;
  const W u3 = u2 * u1;
  return ((c[3] * k + c[2] * u1) * k + c[1] * u2) * k + c[0] * u3;
}

// Returns L 2^60 with L = |e1| + 2 |e2| + 3 |e3| (computed in I): L bounds |x'| on [0, 1], so a
// root in [k, k + 1] / 2^30 has x within L 2^-30 of x(k / 2^30), that is within L 2^60 of
// curve_scaled(e, k).
// rule: PATH.CURVE.SAMPLE
template <class I, class W, class Select>
constexpr W curve_lipschitz_scaled(const std::array<I, 4>& e, Select select) {
  const I zero(0);
  const I a1 = select(e[1] < zero, -e[1], e[1]);
  const I a2 = select(e[2] < zero, -e[2], e[2]);
  const I a3 = select(e[3] < zero, -e[3], e[3]);
  const W u1 = W(std::int64_t{1} << kCurveFastBits);
  return static_cast<W>(a1 + I(2) * a2 + I(3) * a3) * (u1 * u1);
}

// Returns 3 times the Bernstein coefficients of degree 3 of x on [k, k + 1] / 2^B, scaled by
// 2^(3 B) (B = Bits: 30, the fast path's grid; 6, its scan): the power coefficients in s of
// x((k + s) / 2^B) 2^(3 B) are p_i = sum_{j >= i} e_j C(j, i) k^(j - i) 2^(B (3 - j)), and
// 3 b = (3 p0, 3 p0 + p1, 3 p0 + 2 p1 + p2, 3 (p0 + p1 + p2 + p3)).
// rule: PATH.CURVE.SAMPLE
template <class W, int Bits = kCurveFastBits>
constexpr std::array<W, 4> curve_interval_bernstein3(const std::array<W, 4>& e, W k) {
  constexpr int kBinom[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};
  const W u1 = W(std::int64_t{1} << Bits);
  const std::array<W, 4> pow{u1 * u1 * u1, u1 * u1, u1, W(1)}; // 2^(30 (3 - j))
  std::array<W, 4> p{W(0), W(0), W(0), W(0)};
  for (int j = 0; j <= 3; ++j) {
    W kpow(1);
    for (int i = j; i >= 0; --i) {
      p[static_cast<std::size_t>(i)] =
          p[static_cast<std::size_t>(i)] + e[static_cast<std::size_t>(j)] * W(kBinom[j][i]) * kpow *
                                               pow[static_cast<std::size_t>(j)];
      kpow = kpow * k;
    }
  }
  return {W(3) * p[0], W(3) * p[0] + p[1], W(3) * p[0] + W(2) * p[1] + p[2],
          W(3) * (p[0] + p[1] + p[2] + p[3])};
}

// Returns whether lo > f unit and hi < (f + 1) unit: every value in [lo, hi] lies strictly
// between the consecutive integers f and f + 1 (values scaled by unit).
// rule: PATH.CURVE.SAMPLE
template <class W> constexpr auto curve_strictly_between(W lo, W hi, W f, W unit) {
  return lo > f * unit && hi < (f + W(1)) * unit;
}

// Returns the discriminant c1^2 - 4 c2 c0 of c0 + c1 t + c2 t^2.
// rule: PATH.CURVE.SAMPLE
template <class W> constexpr W curve_discriminant(W c0, W c1, W c2) {
  return c1 * c1 - W(4) * c2 * c0;
}

// Returns q g'(p / q) = c1 q + 2 c2 p for g = c0 + c1 t + c2 t^2: its sign is g's slope at the
// root p / q (q > 0).
// rule: PATH.CURVE.SAMPLE
template <class W> constexpr W curve_slope_at(W c1, W c2, W p, W q) {
  return c1 * q + W(2) * c2 * p;
}

// Returns q^2 x(p / q) = e0 q^2 + e1 p q + e2 p^2 for a quadratic x (q > 0).
// rule: PATH.CURVE.SAMPLE
template <class W> constexpr W curve_numerator2(const std::array<W, 4>& e, W p, W q) {
  return e[0] * q * q + e[1] * p * q + e[2] * p * p;
}

// Returns q^3 x(p / q) = ((e3 p + e2 q) p + e1 q^2) p + e0 q^3 for a cubic x (q > 0).
// rule: PATH.CURVE.SAMPLE
template <class W> constexpr W curve_numerator3(const std::array<W, 4>& e, W p, W q) {
  return ((e[3] * p + e[2] * q) * p + e[1] * q * q) * p + e[0] * q * q * q;
}

// Returns the power coefficients of y' for y with power coefficients c: (c1, 2 c2, 3 c3, 0),
// within |.| <= 14 2^24 (kH) for |c_j| within PATH.CURVE.SAMPLE's bounds, so that `scaled()`
// and the filter take them as they take h's (the monotone pieces of a cubic).
// rule: PATH.CURVE.SAMPLE
template <class I>
constexpr std::array<I, 4> curve_derivative_coefficients(const std::array<I, 4>& c) {
  return {c[1], I(2) * c[2], I(3) * c[3], I(0)};
}

// Returns c2^2 - 3 c1 c3, a quarter of the discriminant of y' = c1 + 2 c2 t + 3 c3 t^2: y' has
// two simple real roots iff it is positive (|.| <= 18 2^50 < 2^55 within PATH.CURVE.SAMPLE's
// bounds).
// rule: PATH.CURVE.SAMPLE
template <class I> constexpr I curve_derivative_discriminant(const std::array<I, 4>& c) {
  return c[2] * c[2] - I(3) * c[1] * c[3];
}

// Returns whether the vertex -d1 / (2 d2) of the parabola d0 + d1 t + d2 t^2 (d2 != 0) lies in
// the open interval (0, 1): 0 < -d1 sgn(d2) < 2 |d2|.
// rule: PATH.CURVE.SAMPLE
template <class I, class Select>
constexpr auto curve_vertex_inside(const std::array<I, 4>& d, Select select) {
  const I zero(0);
  const I num = select(d[2] > zero, -d[1], d[1]);
  const I den = I(2) * select(d[2] > zero, d[2], -d[2]);
  return num > zero && num < den;
}

// Returns curve_scaled(c, 0) = c0 2^90 (at_one false) or curve_scaled(c, 2^30) = (c0 + c1 + c2
// + c3) 2^90 (at_one true) without its Horner steps: the ends of a cubic's monotone pieces.
// rule: PATH.CURVE.SAMPLE
template <class W> constexpr W curve_scaled_end(const std::array<W, 4>& c, bool at_one) {
  const W u1 = W(std::int64_t{1} << kCurveFastBits);
  return (at_one ? c[0] + c[1] + c[2] + c[3] : c[0]) * (u1 * u1 * u1);
}

// Returns s.y 2^90, the row on the scale of curve_scaled (|.| <= 2^113 for |s.y| <= 2^23).
// rule: PATH.CURVE.SAMPLE
template <class W> constexpr W curve_row_scaled(W sy) {
  const W u1 = W(std::int64_t{1} << kCurveFastBits);
  return sy * (u1 * u1 * u1);
}

// Returns the range [Y - G, Y + G] (G = lip cells) that holds y(t) 2^90 for every t within
// `cells` grid cells after a grid point where y(t) 2^90 = Y, lip = L 2^60 being y's Lipschitz
// bound (curve_lipschitz_scaled): a bracket of the monotone pieces.
// rule: PATH.CURVE.SAMPLE
template <class W> constexpr std::array<W, 2> curve_bracket_range(W y_scaled, W lip, W cells) {
  const W g = lip * cells;
  return {y_scaled - g, y_scaled + g};
}

// Returns g(1) = c0 + c1 + c2 + c3.
// rule: PATH.CURVE.SAMPLE
template <class W> constexpr W curve_at_one(const std::array<W, 4>& c) {
  return c[0] + c[1] + c[2] + c[3];
}

// Returns g'(1), g''(1) / 2 ... as the kernel orders them: (c1 + 2 c2 + 3 c3, 2 c2 + 6 c3,
// 6 c3), whose first non-zero gives the order and sign of g at t = 1 up to positive factors.
// rule: PATH.CURVE.SAMPLE
template <class W> constexpr std::array<W, 3> curve_derivatives_at_one(const std::array<W, 4>& c) {
  return {c[1] + W(2) * c[2] + W(3) * c[3], W(2) * c[2] + W(6) * c[3], W(6) * c[3]};
}

// Returns h / (t - 1) for h of degree deg (1 <= deg <= 3) with h(1) = 0, by synthetic division
// (q_{deg-1} = h_deg, q_{i-1} = h_i + q_i), and h's coefficient sum in `sum` (its value at 1,
// which the caller tests before dividing).
// rule: PATH.CURVE.SAMPLE
template <class W>
constexpr std::array<W, 4> curve_divide_by_t_minus_one(const std::array<W, 4>& h, int deg, W& sum) {
  sum = W(0);
  for (int i = 0; i <= deg; ++i)
    sum = sum + h[static_cast<std::size_t>(i)];
  std::array<W, 4> q{W(0), W(0), W(0), W(0)};
  q[static_cast<std::size_t>(deg - 1)] = h[static_cast<std::size_t>(deg)];
  for (int i = deg - 1; i >= 1; --i)
    q[static_cast<std::size_t>(i - 1)] =
        h[static_cast<std::size_t>(i)] + q[static_cast<std::size_t>(i)];
  return q;
}

} // namespace rastrules::formula
