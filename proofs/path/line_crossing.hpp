// SPDX-License-Identifier: MIT
// Obligation path/line_crossing (PATH.SAMPLE.TIE, PATH.BUDGET.LINE, PATH.WINDING.BOUND,
// PATH.TIE.PARTITION) as a template over a path kernel model. Used by
// line_crossing.cpp and mutants.cpp.
//
// PathKernelModel = KernelModel (support/kernel_model.hpp: formula::edge_value on Sym<int64_t>)
// plus the path formulas of rastrules/formula/path.hpp, instantiated (spans, crossing_right,
// crossing_numerator), and two one-line restatements of kernel/src/path.cpp, which writes them
// on concrete types:
//   - line_contribution (a free function below): +1 if spans && right && y1 > y0, -1 if
//     spans && right && y1 < y0, else 0 (path.cpp, line_contribution);
//   - line_threshold: T = ceil(N / D) - 1 (hx = +1) or floor(N / D) (hx = -1) on int64_t, D > 0
//     (path.cpp, line_threshold through ceil_div / floor_div of fixed.hpp), entering the proof
//     as N = q D + r, 0 <= r < D, T = q - 1 + [r > 0] or T = q.
//
// The spec side is written from PATH.SAMPLE.TIE's words, not through the kernel: the point
// s' = s + (hx eps, hy delta) with delta << eps << 1; "for all small enough eps, delta: P > 0"
// for a polynomial P = c0 + c1 eps + c2 delta is the lexicographic test on (c0, c1, c2). The
// edge crosses the line y = s.y + hy delta iff y_min < s.y + hy delta < y_max; its crossing is
// right of s' iff (X(y) - s.x - hx eps) > 0 at that y, and multiplying by dy = y1 - y0:
// (X(y) - s'.x) dy = E + hy dx delta - hx dy eps, with E = (x1 - x0)(s.y - y0) - dy (s.x - x0)
// written here on exact integers.

#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "rastrules/formula/path.hpp"
#include "rastrules/formula/path_curve.hpp"
#include "support/kernel_model.hpp"
#include "support/obligation.hpp"
#include "support/prover.hpp"
#include "support/sym.hpp"

namespace rastrules::proofs {

// The sign of v as an integer term.
inline z3::expr sign_of(const z3::expr& v) {
  z3::context& ctx = v.ctx();
  return z3::ite(v > 0, ctx.int_val(1), z3::ite(v < 0, ctx.int_val(-1), ctx.int_val(0)));
}

// One end decision: whether the displaced row is crossed there, its direction, and the x of
// the end (from which the threshold follows, the same function for both).
struct EndCrossing {
  z3::expr crossed;
  z3::expr dir;
  z3::expr x;
};

struct PathKernelModel : KernelModel {
  static constexpr const char* kName = "kernel";
  // Assumes: PATH.GEOMETRY (|raw| <= 2^23: the vertex range with 2^23 itself included)
  static constexpr std::int64_t kMinRaw = -(std::int64_t{1} << 23);
  static constexpr std::int64_t kMaxRaw = std::int64_t{1} << 23;

  static std::vector<Constant> constants() {
    return kernel_constants_and(
        {{"path kMinRaw", kMinRaw, Unit::kCoordRaw}, {"path kMaxRaw", kMaxRaw, Unit::kCoordRaw}});
  }

  template <bool YDown, class S> static SymBool spans(const S& y0, const S& y1, const S& sy) {
    return formula::path_edge_spans<YDown>(y0, y1, sy);
  }
  template <bool XRight, class S>
  static SymBool crossing_right(const S& e, const S& y0, const S& y1) {
    return formula::path_crossing_right<XRight>(e, y0, y1);
  }
  template <class S>
  static S crossing_numerator(const S& xa, const S& ya, const S& xb, const S& yb, const S& sy) {
    return formula::path_crossing_numerator<S>(xa, ya, xb, yb, sy);
  }

  // Mirrors line_threshold (kernel/src/path.cpp) given floor(N / D) = q and N = q D + r with
  // 0 <= r < D: ceil_div(N, D) - 1 = q - 1 + [r > 0] for hx = +1, floor_div(N, D) = q else.
  template <bool XRight, class S> static S threshold(const S& q, const S& r) {
    if constexpr (XRight)
      return select(r > S(0), q, q - S(1));
    else
      return q;
  }

  // Mirrors cubic_end_crossings (kernel/src/path_curve.cpp) at t = 0, for g with c0 = 0 and not
  // constant: m = the first j >= 1 with c_j != 0 (the kernel's loop); crossed iff sgn c_m = hy,
  // in direction hy; x = x.c[0].
  static EndCrossing end_at_zero(const std::array<z3::expr, 4>& c, const std::array<z3::expr, 4>& e,
                                 int hy) {
    z3::context& ctx = c[0].ctx();
    const z3::expr a =
        z3::ite(c[1] != 0, sign_of(c[1]), z3::ite(c[2] != 0, sign_of(c[2]), sign_of(c[3])));
    return {a == hy, ctx.int_val(hy), e[0]};
  }

  // Mirrors cubic_end_crossings at t = 1, for g with g(1) = 0: d = curve_derivatives_at_one(c),
  // m = the first index with d_m != 0 (order m + 1); crossed iff (m even ? -sgn d_m : sgn d_m)
  // = hy, in direction -hy; x = curve_at_one(e).
  template <class W>
  static EndCrossing end_at_one(const std::array<W, 4>& c, const std::array<W, 4>& e, int hy) {
    z3::context& ctx = c[0].expr().ctx();
    const std::array<W, 3> d = formula::curve_derivatives_at_one<W>(c);
    const z3::expr before =
        z3::ite(d[0].expr() != 0, -sign_of(d[0].expr()),
                z3::ite(d[1].expr() != 0, sign_of(d[1].expr()), -sign_of(d[2].expr())));
    return {before == hy, ctx.int_val(-hy), formula::curve_at_one<W>(e).expr()};
  }

  // Mirrors rational_quadratic_crossings at an end root p / q (q > 0; p = 0 at t = 0, p = q at
  // t = 1): d1 = sgn curve_slope_at(c1, c2, p, q), m = d1 != 0 ? 1 : 2, a = d1 or sgn c2;
  // crossed iff a = hy (t = 0, direction hy) or (m odd ? -a : a) = hy (t = 1, direction -hy);
  // x = curve_numerator2(e, p, q) / q^2, returned as the numerator (the caller compares
  // fractions).
  template <class W>
  static EndCrossing quadratic_end(const std::array<W, 4>& c, const std::array<W, 4>& e, const W& p,
                                   const W& q, bool at_one, int hy) {
    z3::context& ctx = c[0].expr().ctx();
    const z3::expr d1 = sign_of(formula::curve_slope_at<W>(c[1], c[2], p, q).expr());
    const z3::expr a = z3::ite(d1 != 0, d1, sign_of(c[2].expr()));
    const z3::expr num = formula::curve_numerator2<W>(e, p, q).expr();
    if (!at_one)
      return {a == hy, ctx.int_val(hy), num};
    return {z3::ite(d1 != 0, -a, a) == hy, ctx.int_val(-hy), num};
  }
};

// Mirrors line_contribution (kernel/src/path.cpp): +1 down, -1 up, 0 when not counted, on
// model F's formulas (a free function, so that a mutant's member is the one used).
// Mirrors (assumed, not proved here): PATH.WINDING (the sum over the edges)
template <class F, bool XRight, bool YDown, class S>
S line_contribution(const Point<S>& a, const Point<S>& b, const Point<S>& s) {
  const SymBool counted = F::template spans<YDown>(a.y, b.y, s.y) &&
                          F::template crossing_right<XRight>(F::edge_value(a, b, s), a.y, b.y);
  return select(counted && (b.y > a.y), S(1), select(counted && (b.y < a.y), S(-1), S(0)));
}

// Returns "for all small enough infinitesimals, c0 + c1 eps + c2 delta > 0" with
// delta << eps: the first non-zero of (c0, c1, c2) is positive.
inline z3::expr lex_positive(const z3::expr& c0, const z3::expr& c1, const z3::expr& c2) {
  return c0 > 0 || (c0 == 0 && (c1 > 0 || (c1 == 0 && c2 > 0)));
}

// The spec's contribution of edge a -> b at s' (PATH.SAMPLE.TIE, PATH.WINDING): +1, -1 or 0.
inline z3::expr spec_contribution(const z3::expr& ax, const z3::expr& ay, const z3::expr& bx,
                                  const z3::expr& by, const z3::expr& sx, const z3::expr& sy,
                                  int hx, int hy) {
  z3::context& ctx = ax.ctx();
  const z3::expr zero = ctx.int_val(0);
  const z3::expr hxv = ctx.int_val(hx);
  const z3::expr hyv = ctx.int_val(hy);
  const z3::expr dx = bx - ax;
  const z3::expr dy = by - ay;
  // y_min < s.y + hy delta < y_max, for the two orders of the ends (a horizontal edge: never).
  const auto between = [&](const z3::expr& lo, const z3::expr& hi) {
    return lex_positive(sy - lo, zero, hyv) && lex_positive(hi - sy, zero, -hyv);
  };
  const z3::expr crosses = (ay < by && between(ay, by)) || (by < ay && between(by, ay));
  // (X(y) - s'.x) dy = E - hx dy eps + hy dx delta; its sign times sgn(dy) says "right of s'".
  const z3::expr e = dx * (sy - ay) - dy * (sx - ax);
  const z3::expr right_down = lex_positive(e, -hxv * dy, hyv * dx);  // dy > 0
  const z3::expr right_up = lex_positive(-e, hxv * dy, -(hyv * dx)); // dy < 0
  const z3::expr down = crosses && dy > 0 && right_down;
  const z3::expr up = crosses && dy < 0 && right_up;
  return z3::ite(down, ctx.int_val(1), z3::ite(up, ctx.int_val(-1), zero));
}

// For model F and every convention (hx, hy):
//   budget: for all a, b, s with |raw| <= 2^23, the contribution (edge_value and the tests)
//     and, for a top-first edge (ya < yb), crossing_numerator fit int64_t;
//   matches spec: the model's contribution equals the spec's at every a, b, s;
//   bound: it is -1, 0 or +1;
//   reverse: the contributions of a -> b and b -> a sum to 0 at every s;
//   threshold: for a top-first edge spanning s.y, with N = q D + r, 0 <= r < D (D = yb - ya),
//     a sample at raw x (|x| <= 2^23) counts the crossing (crossing_right on the kernel's E)
//     iff x <= threshold(q, r);
// (Not here: "one-triangle path == triangle rule" over all triangles times out as one query;
// PATH.TIE.TRIANGLE rests on the examples and the properties.)
// rule: PATH.SAMPLE.TIE, PATH.BUDGET.LINE, PATH.WINDING.BOUND, PATH.TIE.PARTITION
template <class F> void prove_line_crossing(Prover& pr) {
  using S = typename F::Acc;
  Domain& dom = pr.domain();
  // Assumes: PATH.GEOMETRY (every point in [-2^23, 2^23]); the edge a -> b, the sample s.
  std::vector<z3::expr> hyps;
  const auto [a, b, s] = points_in_range<F>(dom, {"a", "b", "s"}, hyps);

  for_each_convention([&]<bool TopInclusive, bool LeftInclusive>(const char* name) {
    constexpr bool kXRight = LeftInclusive; // hx = +1: left edges inclusive
    constexpr bool kYDown = TopInclusive;   // hy = +1: top edges inclusive
    const int hx = kXRight ? 1 : -1;
    const int hy = kYDown ? 1 : -1;
    const std::string conv = std::string(" (") + name + ")";
    {
      const std::size_t mark = dom.mark();
      const S c = line_contribution<F, kXRight, kYDown>(a, b, s);
      const z3::expr spec = spec_contribution(a.x.expr(), a.y.expr(), b.x.expr(), b.y.expr(),
                                              s.x.expr(), s.y.expr(), hx, hy);
      pr.watch("contribution", c.expr(), Unit::kInteger);
      pr.watch("spec", spec, Unit::kInteger);
      pr.prove("line contribution equals the spec's at s + (hx eps, hy delta), fits int64_t" + conv,
               hyps, c.expr() == spec, dom.obligations_since(mark));
      pr.prove("line contribution is -1, 0 or +1" + conv, hyps, c.expr() >= -1 && c.expr() <= 1);
      const S back = line_contribution<F, kXRight, kYDown>(b, a, s);
      pr.prove("reversing an edge negates its contribution" + conv, hyps,
               c.expr() + back.expr() == 0);
    }
    {
      const std::size_t mark = dom.mark();
      std::vector<z3::expr> h = hyps;
      h.push_back(a.y.expr() < b.y.expr()); // top end first, as the kernel orients
      h.push_back(F::template spans<kYDown>(a.y, b.y, s.y).expr());
      const S n = F::crossing_numerator(a.x, a.y, b.x, b.y, s.y);
      const S d = b.y - a.y;
      const S q = dom.var<typename S::rep>(std::string("q_") + name, Unit::kCoordRaw);
      const S r = dom.var<typename S::rep>(std::string("r_") + name, Unit::kEdgeRaw);
      const S x = dom.var<typename S::rep>(std::string("x_") + name, Unit::kCoordRaw);
      h.push_back(n.expr() == q.expr() * d.expr() + r.expr());
      h.push_back(0 <= r.expr() && r.expr() < d.expr());
      h.push_back(in_closed(x.expr(), F::kMinRaw, F::kMaxRaw));
      const S t = F::template threshold<kXRight>(q, r);
      const Point<S> sample{x, s.y};
      const SymBool right =
          F::template crossing_right<kXRight>(F::edge_value(a, b, sample), a.y, b.y);
      pr.watch("N", n.expr(), Unit::kEdgeRaw);
      pr.watch("T", t.expr(), Unit::kCoordRaw);
      pr.prove("row threshold: x <= T iff the crossing counts at x; N fits int64_t" + conv, h,
               (x.expr() <= t.expr()) == right.expr(), dom.obligations_since(mark));
    }
  });
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kLineCrossing{"path/line_crossing",
                                           []<class F>(Prover& pr) { prove_line_crossing<F>(pr); }};

} // namespace rastrules::proofs
