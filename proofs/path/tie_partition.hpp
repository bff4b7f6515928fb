// SPDX-License-Identifier: MIT
// Obligation path/tie_partition (PATH.TIE.PARTITION) as a template over a path kernel model.
// Used by tie_partition.cpp and mutants.cpp.
//
// The winding number of a closed contour of line edges at a sample is the sum of the kernel's
// line contributions (line_contribution of path/line_crossing.hpp, which path/line_crossing
// proves equal to the spec's at s + (hx eps, hy delta)); PATH.WINDING sums contours.
// Two triangles sharing the edge ab in opposite directions, A = a -> b -> c and
// B = b -> a -> d, and their union contour U = a -> d -> b -> c (the shared edge left out):
//   W  (windings add): w_A(s) + w_B(s) = w_U(s) at every sample s, under every convention:
//      the shared edge's two directions cancel exactly (the same test decides both, with
//      opposite signs); any two contours sharing an edge in opposite directions work the same
//      way edge by edge, triangles are the case stated here;
//   X  (exactly once): for A and B clockwise (c and d on opposite sides of ab, each area > 0)
//      every integer sample on the open segment ab has w_A, w_B in {0, 1} and w_A + w_B = 1:
//      exactly one of the two paths covers it, under nonzero and under even-odd.
//   E, Q (curve ends): a cubic (cubic_end_crossings) or quadratic (rational_quadratic_crossings)
//      ending on the row, and its reverse: the end rules give the same crossing with opposite
//      directions and the same x (PathKernelModel::end_at_zero, end_at_one, quadratic_end
//      restate the kernel's loops over the formula templates). Interior crossings: properties.
// X uses the encoding and lemmas of tri/shared_edge_exactly_once.hpp: b = a + n delta,
// s = a + k delta, 0 < k < n (every integer point strictly between a and b), lemma L0 on signs
// and lemma L1 (the kernel's edge values at s: E_ab = E_ba = 0, E_bc and E_ca with the sign of
// A(a, b, c), E_cb and E_ac opposite), proved here again and instantiated at c and d.

#pragma once

#include <string>
#include <vector>

#include "path/line_crossing.hpp"
#include "support/kernel_model.hpp"
#include "support/obligation.hpp"
#include "support/prover.hpp"
#include "tri/shared_edge_exactly_once.hpp"

namespace rastrules::proofs {

// The winding number at s of the closed contour through the points v (in order), as the sum
// of model F's line contributions of its edges.
template <class F, bool XRight, bool YDown, class S, std::size_t N>
z3::expr contour_winding(const std::array<Point<S>, N>& v, const Point<S>& s) {
  z3::expr w = s.x.expr().ctx().int_val(0);
  for (std::size_t i = 0; i < N; ++i)
    w = w + line_contribution<F, XRight, YDown>(v[i], v[(i + 1) % N], s).expr();
  return w;
}

// W, for every convention: any a, b, c, d, s in range.
template <class F> void prove_windings_add(Prover& pr) {
  std::vector<z3::expr> hyps;
  const auto [a, b, c, d, s] = points_in_range<F>(pr.domain(), {"a", "b", "c", "d", "s"}, hyps);
  for_each_convention([&]<bool TopInclusive, bool LeftInclusive>(const char* name) {
    constexpr bool kXRight = LeftInclusive;
    constexpr bool kYDown = TopInclusive;
    const std::size_t mark = pr.domain().mark();
    const z3::expr wa = contour_winding<F, kXRight, kYDown>(std::array{a, b, c}, s);
    const z3::expr wb = contour_winding<F, kXRight, kYDown>(std::array{b, a, d}, s);
    const z3::expr wu = contour_winding<F, kXRight, kYDown>(std::array{a, d, b, c}, s);
    pr.watch("w_A", wa, Unit::kInteger);
    pr.watch("w_B", wb, Unit::kInteger);
    pr.watch("w_U", wu, Unit::kInteger);
    pr.prove(std::string("W: abc and bad sharing ab: w_A + w_B = w_U of adbc, no overflow (") +
                 name + ")",
             hyps, wa + wb == wu, pr.domain().obligations_since(mark));
  });
}

// E, for hy = +1 and -1: for every cubic (control y_i, x_i and the row s.y in range, y not
// constant) and its reverse (control points in the opposite order): where the curve ends on
// the row at t = 1, the reverse's decision at t = 0 is the same crossing with the opposite
// direction and the same x, and the same with the ends exchanged; power coefficients from
// formula::curve_power_coefficients on int64_t, the end rules on __int128 as the kernel.
template <class F> void prove_curve_end_reversal(Prover& pr) {
  using I = Sym<std::int64_t>;
  using W = Sym<Int128>;
  Domain& dom = pr.domain();
  std::vector<z3::expr> hyps;
  std::array<I, 4> ys{
      dom.var<std::int64_t>("ey0", Unit::kCoordRaw), dom.var<std::int64_t>("ey1", Unit::kCoordRaw),
      dom.var<std::int64_t>("ey2", Unit::kCoordRaw), dom.var<std::int64_t>("ey3", Unit::kCoordRaw)};
  std::array<I, 4> xs{
      dom.var<std::int64_t>("ex0", Unit::kCoordRaw), dom.var<std::int64_t>("ex1", Unit::kCoordRaw),
      dom.var<std::int64_t>("ex2", Unit::kCoordRaw), dom.var<std::int64_t>("ex3", Unit::kCoordRaw)};
  const I sy = dom.var<std::int64_t>("esy", Unit::kCoordRaw);
  for (std::size_t i = 0; i < 4; ++i) {
    hyps.push_back(in_closed(ys[i].expr(), F::kMinRaw, F::kMaxRaw));
    hyps.push_back(in_closed(xs[i].expr(), F::kMinRaw, F::kMaxRaw));
  }
  hyps.push_back(in_closed(sy.expr(), F::kMinRaw, F::kMaxRaw));
  hyps.push_back(!(ys[0].expr() == ys[1].expr() && ys[1].expr() == ys[2].expr() &&
                   ys[2].expr() == ys[3].expr())); // y constant: never crossed, no end rule
  const auto coefficients = [&](const std::array<I, 4>& q, bool is_y) {
    std::array<I, 4> c = formula::curve_power_coefficients(q, true);
    if (is_y)
      c[0] = c[0] - sy; // gi.c[0] -= sy
    return std::array<W, 4>{W(c[0]), W(c[1]), W(c[2]), W(c[3])};
  };
  const std::array<I, 4> ys_rev{ys[3], ys[2], ys[1], ys[0]};
  const std::array<I, 4> xs_rev{xs[3], xs[2], xs[1], xs[0]};
  const std::array<W, 4> g = coefficients(ys, true), e = coefficients(xs, false);
  const std::array<W, 4> gr = coefficients(ys_rev, true), er = coefficients(xs_rev, false);
  const auto exprs = [](const std::array<W, 4>& v) {
    return std::array<z3::expr, 4>{v[0].expr(), v[1].expr(), v[2].expr(), v[3].expr()};
  };
  for (const int hy : {1, -1}) {
    const std::string side = hy == 1 ? " (hy = +1)" : " (hy = -1)";
    const std::size_t mark = dom.mark();
    const EndCrossing one = F::end_at_one(g, e, hy);
    const EndCrossing zero_rev = F::end_at_zero(exprs(gr), exprs(er), hy);
    std::vector<z3::expr> h = hyps;
    h.push_back(formula::curve_at_one<W>(g).expr() == 0);
    pr.prove("E: a cubic ending on the row at t = 1 and its reverse at t = 0: the same crossing, "
             "opposite directions, the same x" +
                 side,
             h,
             gr[0].expr() == 0 && one.crossed == zero_rev.crossed &&
                 z3::implies(one.crossed, one.dir == -zero_rev.dir) && one.x == zero_rev.x,
             dom.obligations_since(mark));
    const EndCrossing zero = F::end_at_zero(exprs(g), exprs(e), hy);
    const EndCrossing one_rev = F::end_at_one(gr, er, hy);
    h = hyps;
    h.push_back(g[0].expr() == 0);
    pr.prove("E: a cubic starting on the row at t = 0 and its reverse at t = 1: the same crossing, "
             "opposite directions, the same x" +
                 side,
             h,
             formula::curve_at_one<W>(gr).expr() == 0 && zero.crossed == one_rev.crossed &&
                 z3::implies(zero.crossed, zero.dir == -one_rev.dir) && zero.x == one_rev.x);
  }
}

// Q, for hy = +1 and -1: the same for a quadratic's end roots as rational_quadratic_crossings
// decides them (the root at t = 1 as p / q with p = q > 0, its reverse's at t = 0 as 0 / q',
// q' > 0: any denominators, as the kernel's come from the discriminant): the same crossing,
// opposite directions, and x_c equal as fractions.
template <class F> void prove_quadratic_end_reversal(Prover& pr) {
  using I = Sym<std::int64_t>;
  using W = Sym<Int128>;
  Domain& dom = pr.domain();
  std::vector<z3::expr> hyps;
  std::array<I, 4> ys{dom.var<std::int64_t>("qy0", Unit::kCoordRaw),
                      dom.var<std::int64_t>("qy1", Unit::kCoordRaw),
                      dom.var<std::int64_t>("qy2", Unit::kCoordRaw), I(0)};
  std::array<I, 4> xs{dom.var<std::int64_t>("qx0", Unit::kCoordRaw),
                      dom.var<std::int64_t>("qx1", Unit::kCoordRaw),
                      dom.var<std::int64_t>("qx2", Unit::kCoordRaw), I(0)};
  const I sy = dom.var<std::int64_t>("qsy", Unit::kCoordRaw);
  const W q = dom.var<Int128>("qq", Unit::kInteger);
  const W qr = dom.var<Int128>("qqr", Unit::kInteger);
  for (std::size_t i = 0; i < 3; ++i) {
    hyps.push_back(in_closed(ys[i].expr(), F::kMinRaw, F::kMaxRaw));
    hyps.push_back(in_closed(xs[i].expr(), F::kMinRaw, F::kMaxRaw));
  }
  hyps.push_back(in_closed(sy.expr(), F::kMinRaw, F::kMaxRaw));
  hyps.push_back(q.expr() > 0 && qr.expr() > 0);
  hyps.push_back(!(ys[0].expr() == ys[1].expr() && ys[1].expr() == ys[2].expr()));
  const auto coefficients = [&](const std::array<I, 4>& v, bool is_y) {
    std::array<I, 4> c = formula::curve_power_coefficients(v, false);
    if (is_y)
      c[0] = c[0] - sy; // gi.c[0] -= sy
    return std::array<W, 4>{W(c[0]), W(c[1]), W(c[2]), W(c[3])};
  };
  const std::array<W, 4> g = coefficients(ys, true), e = coefficients(xs, false);
  const std::array<W, 4> gr = coefficients({ys[2], ys[1], ys[0], I(0)}, true);
  const std::array<W, 4> er = coefficients({xs[2], xs[1], xs[0], I(0)}, false);
  const W zero(0);
  for (const int hy : {1, -1}) {
    const std::string side = hy == 1 ? " (hy = +1)" : " (hy = -1)";
    for (const bool end_one : {true, false}) {
      // The original's root at t = 1 (p = q) and the reverse's at 0, or the other way round.
      const EndCrossing orig = F::quadratic_end(g, e, end_one ? q : zero, q, end_one, hy);
      const EndCrossing rev = F::quadratic_end(gr, er, end_one ? zero : qr, qr, !end_one, hy);
      std::vector<z3::expr> h = hyps;
      h.push_back(formula::curve_at_one<W>(end_one ? g : gr).expr() == 0);
      h.push_back((end_one ? gr : g)[0].expr() == 0);
      pr.prove(std::string("Q: a quadratic ending on the row at t = ") + (end_one ? "1" : "0") +
                   " and its reverse at t = " + (end_one ? "0" : "1") +
                   ": the same crossing, opposite directions, the same x" + side,
               h,
               orig.crossed == rev.crossed && z3::implies(orig.crossed, orig.dir == -rev.dir) &&
                   orig.x * qr.expr() * qr.expr() == rev.x * q.expr() * q.expr());
    }
  }
}

// rule: PATH.TIE.PARTITION
template <class F> void prove_tie_partition(Prover& pr) {
  using S = typename F::Acc;
  prove_windings_add<F>(pr);
  prove_curve_end_reversal<F>(pr);
  prove_quadratic_end_reversal<F>(pr);
  // X: the shared edge a -> b = a + n delta, the sample p = a + k delta.
  const SharedSegment<S> seg = shared_segment<S>(pr.domain(), point_var<S>(pr.domain(), "xa"), "x");
  const Point<S>&a = seg.a, &b = seg.b, &p = seg.p, &c = seg.c, &d = seg.d;
  const Status l1 = prove_segment_lemmas<F>(pr, seg);
  // Assumes: PATH.GEOMETRY (every point in range); A = abc and B = bad clockwise.
  const std::vector<z3::expr> hyps = {
      in_vertex_range<F>(a),
      in_vertex_range<F>(b),
      in_vertex_range<F>(c),
      in_vertex_range<F>(d),
      seg.on_segment,
      F::twice_signed_area(Triangle<S>{a, b, c}).expr() > 0,
      F::twice_signed_area(Triangle<S>{b, a, d}).expr() > 0,
      segment_edge_values<F>(a, b, c, p), // L1 at c
      segment_edge_values<F>(a, b, d, p), // L1 at d
  };
  for_each_convention([&]<bool TopInclusive, bool LeftInclusive>(const char* name) {
    constexpr bool kXRight = LeftInclusive;
    constexpr bool kYDown = TopInclusive;
    const std::string theorem =
        std::string("X: clockwise abc and bad: a sample on the open edge ab has w_A, w_B in "
                    "{0, 1} and w_A + w_B = 1 (") +
        name + ")";
    if (l1 != Status::kProved) {
      pr.skip(theorem, "relies on lemma L1, which was not proved");
      return;
    }
    const z3::expr wa = contour_winding<F, kXRight, kYDown>(std::array{a, b, c}, p);
    const z3::expr wb = contour_winding<F, kXRight, kYDown>(std::array{b, a, d}, p);
    pr.watch("px", p.x.expr(), Unit::kCoordRaw);
    pr.watch("py", p.y.expr(), Unit::kCoordRaw);
    pr.watch("w_A", wa, Unit::kInteger);
    pr.watch("w_B", wb, Unit::kInteger);
    pr.prove(theorem, hyps, 0 <= wa && wa <= 1 && 0 <= wb && wb <= 1 && wa + wb == 1);
  });
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kTiePartition{"path/tie_partition",
                                           []<class F>(Prover& pr) { prove_tie_partition<F>(pr); }};

} // namespace rastrules::proofs
