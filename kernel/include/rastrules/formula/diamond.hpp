// SPDX-License-Identifier: MIT
// Diamond-exit formulas for aliased lines, on raw 16.8 integers relative to a pixel centre.
// Generic over the number type so that the kernel evaluates them with std::int64_t and the
// proofs with Z3 terms: branch-free in every input value (the only C++ branches are on
// compile-time parameters and on the constant strictness flags of a constraint).
//
// Geometry (spec/rules/line.md). A pixel's diamond, relative to its centre, is
// |u| + |v| <= h with h = 128 raw (1/2 px); y (and v) grow down the screen. Its four edges are
// the lines s1 u + s2 v = h with (s1, s2) in
//   kLowerRight = (+1, +1), kLowerLeft = (-1, +1), kUpperRight = (+1, -1), kUpperLeft = (-1, -1),
// and the diamond is the intersection of the four half-planes s1 u + s2 v <= h. A segment
// p(t) = a + t d, t in [0, 1], meets a set cut out by such half-planes iff the one-variable
// linear system { t m_k  (< or <=)  r_k } (m_k = s·d, r_k = h - s·a) has a solution: that is
// decided exactly, without division, by Fourier-Motzkin elimination of t (t_feasible).
// Implements: LINE.DIAMOND.GEOMETRY, LINE.D3D.TEST_AREA, LINE.D3D.EXIT, LINE.VK.TEST_AREA,
//             LINE.VK.EXIT

#pragma once

#include <array>
#include <cstddef>

namespace rastrules::formula {

// The four diamond edges as sign pairs (s1, s2): the edge is s1 u + s2 v = h.
inline constexpr std::array<std::array<int, 2>, 4> kDiamondEdgeSigns = {{
    {{+1, +1}}, // lower-right (y down)
    {{-1, +1}}, // lower-left
    {{+1, -1}}, // upper-right
    {{-1, -1}}, // upper-left
}};
inline constexpr std::size_t kLowerRight = 0, kLowerLeft = 1, kUpperRight = 2, kUpperLeft = 3;

// One linear constraint on the segment parameter t: m t < r (strict) or m t <= r.
// R is the type of the bound (a number, or an EpsPoly for the Vulkan perturbation), M the
// type of the slope (a number). `strict` is a constant of the rule, never a value of the input.
template <class R, class M> struct TConstraint {
  R r;
  M m;
  bool strict;
};

// Returns whether constraint c allows t when its slope is zero: 0 < r (strict) or 0 <= r.
// `zero` is the value 0 of type R.
template <class R, class M> auto zero_slope_ok(const TConstraint<R, M>& c, const R& zero) {
  if (c.strict)
    return (c.m != M(0)) || (c.r > zero);
  return (c.m != M(0)) || (c.r >= zero);
}

// Returns whether the lower bound of ci (when ci.m < 0: t > or >= ci.r / ci.m) lies below the
// upper bound of cj (when cj.m > 0: t < or <= cj.r / cj.m), so that together they leave some t.
// ri/mi < rj/mj  <=>  ri mj > rj mi  (multiplying by mi mj < 0); equal bounds leave exactly one
// t, allowed only when neither inequality is strict.
template <class R, class M>
auto bounds_compatible(const TConstraint<R, M>& ci, const TConstraint<R, M>& cj) {
  const auto applies = (ci.m < M(0)) && (cj.m > M(0));
  const R lhs = ci.r * cj.m;
  const R rhs = cj.r * ci.m;
  if (!ci.strict && !cj.strict)
    return !applies || (lhs > rhs) || (lhs == rhs);
  return !applies || (lhs > rhs);
}

// Returns whether some real t satisfies every constraint of cs (Fourier-Motzkin in one
// variable: every constraint with m = 0 holds, and every lower bound is below every upper
// bound, with equality only between non-strict bounds). Exact; no division.
// rule: LINE.DIAMOND.GEOMETRY
template <class R, class M, std::size_t N>
auto t_feasible(const std::array<TConstraint<R, M>, N>& cs, const R& zero) {
  auto ok = zero_slope_ok(cs[0], zero);
  for (std::size_t k = 1; k < N; ++k)
    ok = ok && zero_slope_ok(cs[k], zero);
  for (std::size_t i = 0; i < N; ++i) {
    for (std::size_t j = 0; j < N; ++j) {
      if (i != j)
        ok = ok && bounds_compatible(cs[i], cs[j]);
    }
  }
  return ok;
}

// Returns the six constraints "p(t) = a + t d lies in the half-planes s_k·p (<|<=) bound_k for
// the four edges, and 0 <= t <= 1". (au, av) is the start relative to the pixel centre, (du,
// dv) = b - a; bound_k and strict_k give edge k's threshold and strictness. zero and one are 0
// and 1 of type R; m_one is 1 of type M.
template <class R, class M>
std::array<TConstraint<R, M>, 6>
segment_in_diamond_constraints(const M& au, const M& av, const M& du, const M& dv,
                               const std::array<R, 4>& bound, const std::array<bool, 4>& strict,
                               const R& zero, const R& one, const M& m_one) {
  auto edge = [&](std::size_t k) {
    const int s1 = kDiamondEdgeSigns[k][0], s2 = kDiamondEdgeSigns[k][1];
    const M a_k = (s1 > 0 ? au : -au) + (s2 > 0 ? av : -av);
    const M m_k = (s1 > 0 ? du : -du) + (s2 > 0 ? dv : -dv);
    return TConstraint<R, M>{bound[k] - a_k, m_k, strict[k]};
  };
  return {edge(0),
          edge(1),
          edge(2),
          edge(3),
          TConstraint<R, M>{zero, -m_one, false}, // -t <= 0
          TConstraint<R, M>{one, m_one, false}};  // t <= 1
}

// ---------------------------------------------------------------------------------------------
// D3D: the half-open test area and the exit rule.

// Strictness of the D3D test area's edges: the lower-left and lower-right edges are included
// (<=), the upper-left and upper-right excluded (<). With these four half-planes the included
// corners are exactly the bottom one; the right corner of y-major lines is added separately.
inline constexpr std::array<bool, 4> kD3DEdgeStrict = {false, false, true, true};

// Returns whether point (pu, pv) (relative to the pixel centre) lies in the D3D test area:
// the open diamond, its open lower edges and its bottom corner, plus its right corner for
// y-major lines.
// rule: LINE.D3D.TEST_AREA
template <bool YMajor, class M> auto d3d_contains(const M& pu, const M& pv, const M& h) {
  const auto base = (pu + pv <= h) && (-pu + pv <= h) && (pu - pv < h) && (-pu - pv < h);
  if constexpr (YMajor) {
    return base || ((pu == h) && (pv == M(0)));
  } else {
    return base;
  }
}

// Returns whether point q lies on the closed segment a + t d, t in [0, 1] (all relative to the
// same origin). A zero-length segment contains only a.
template <class M>
auto on_segment(const M& qu, const M& qv, const M& au, const M& av, const M& du, const M& dv) {
  const M wu = qu - au, wv = qv - av;
  const M cross = wu * dv - wv * du;
  const M dot = wu * du + wv * dv;
  const M len2 = du * du + dv * dv;
  const M zero(0);
  const auto nonzero = (du != zero) || (dv != zero);
  return (cross == zero) && (dot >= zero) && (dot <= len2) &&
         (nonzero || ((wu == zero) && (wv == zero)));
}

// Returns whether the segment from a to a + d (relative to the pixel centre) meets the D3D test
// area of the pixel.
// rule: LINE.D3D.TEST_AREA
template <bool YMajor, class M>
auto d3d_meets(const M& au, const M& av, const M& du, const M& dv, const M& h) {
  const M zero(0);
  const M one(1);
  const auto meets = t_feasible(segment_in_diamond_constraints<M, M>(
                                    au, av, du, dv, {h, h, h, h}, kD3DEdgeStrict, zero, one, one),
                                zero);
  if constexpr (YMajor) {
    return meets || on_segment(h, zero, au, av, du, dv);
  } else {
    return meets;
  }
}

// Returns whether the line from a to b (relative to the pixel centre) covers the pixel under
// D3D's rule: it meets the test area and its end point is not in it (it exits).
// rule: LINE.D3D.EXIT
template <bool YMajor, class M>
auto d3d_exits(const M& au, const M& av, const M& bu, const M& bv, const M& h) {
  return d3d_meets<YMajor>(au, av, bu - au, bv - av, h) && !d3d_contains<YMajor>(bu, bv, h);
}

// ---------------------------------------------------------------------------------------------
// Vulkan: the open diamond and the (-e, -e^2) perturbation of both end points.

// A value c0 + c1 e + c2 e^2 for an infinitesimal e > 0: comparisons are lexicographic on
// (c0, c1, c2), which is the order of the values for every small enough e.
template <class Num> struct EpsPoly {
  Num c0;
  Num c1;
  Num c2;

  friend EpsPoly operator+(const EpsPoly& a, const EpsPoly& b) {
    return {a.c0 + b.c0, a.c1 + b.c1, a.c2 + b.c2};
  }
  friend EpsPoly operator-(const EpsPoly& a, const EpsPoly& b) {
    return {a.c0 - b.c0, a.c1 - b.c1, a.c2 - b.c2};
  }
  friend EpsPoly operator-(const EpsPoly& a, const Num& b) { return {a.c0 - b, a.c1, a.c2}; }
  friend EpsPoly operator*(const EpsPoly& a, const Num& k) {
    return {a.c0 * k, a.c1 * k, a.c2 * k};
  }
  friend auto operator==(const EpsPoly& a, const EpsPoly& b) {
    return (a.c0 == b.c0) && (a.c1 == b.c1) && (a.c2 == b.c2);
  }
  friend auto operator>(const EpsPoly& a, const EpsPoly& b) {
    return (a.c0 > b.c0) ||
           ((a.c0 == b.c0) && ((a.c1 > b.c1) || ((a.c1 == b.c1) && (a.c2 > b.c2))));
  }
  friend auto operator>=(const EpsPoly& a, const EpsPoly& b) { return (a > b) || (a == b); }
  friend auto operator<(const EpsPoly& a, const EpsPoly& b) { return b > a; }
};

// Returns whether the perturbed point (pu, pv) - (e, e^2) lies in the open diamond
// |u| + |v| < h, for every small enough e > 0. This is the test area of LINE.VK.TEST_AREA: the
// open diamond, its open right edges and its right corner.
// rule: LINE.VK.TEST_AREA
template <class M> auto vk_contains(const M& pu, const M& pv, const M& h) {
  const M zero(0);
  const M one(1);
  auto edge_ok = [&](std::size_t k) {
    const int s1 = kDiamondEdgeSigns[k][0], s2 = kDiamondEdgeSigns[k][1];
    // s1 (pu - e) + s2 (pv - e^2) < h  <=>  s1 pu + s2 pv < h + s1 e + s2 e^2.
    const EpsPoly<M> lhs{(s1 > 0 ? pu : -pu) + (s2 > 0 ? pv : -pv), zero, zero};
    const EpsPoly<M> rhs{h, s1 > 0 ? one : -one, s2 > 0 ? one : -one};
    return lhs < rhs;
  };
  return edge_ok(0) && edge_ok(1) && edge_ok(2) && edge_ok(3);
}

// Returns whether the perturbed segment a - (e, e^2) + t d, t in [0, 1], meets the open
// diamond of the pixel for every small enough e > 0.
// rule: LINE.VK.TEST_AREA
template <class M> auto vk_meets(const M& au, const M& av, const M& du, const M& dv, const M& h) {
  const M zero(0);
  const M one(1);
  using P = EpsPoly<M>;
  // Edge k: s·(p(t) - (e, e^2)) < h  <=>  t m_k < h + s1 e + s2 e^2 - s·a.
  auto bound = [&](std::size_t k) {
    return P{h, kDiamondEdgeSigns[k][0] > 0 ? one : -one, kDiamondEdgeSigns[k][1] > 0 ? one : -one};
  };
  const P pzero{zero, zero, zero};
  const P pone{one, zero, zero};
  return t_feasible(
      segment_in_diamond_constraints<P, M>(au, av, du, dv, {bound(0), bound(1), bound(2), bound(3)},
                                           {true, true, true, true}, pzero, pone, one),
      pzero);
}

// Returns whether the line from a to b (relative to the pixel centre) produces the pixel
// under Vulkan's Bresenham rule: the perturbed segment meets the open diamond, except when the
// perturbed end point lies in it.
// rule: LINE.VK.EXIT
template <class M> auto vk_exits(const M& au, const M& av, const M& bu, const M& bv, const M& h) {
  return vk_meets(au, av, bu - au, bv - av, h) && !vk_contains(bu, bv, h);
}

} // namespace rastrules::formula
