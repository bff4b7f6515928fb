// SPDX-License-Identifier: MIT
// Obligation TRI.SHARED_EDGE.EXACTLY_ONCE, as a template over a kernel model. Used by
// shared_edge_exactly_once.cpp and selftest/mutants.cpp.
//
// Encoding of "p on the open segment (a, b)" on integer raw coordinates: a step vector
// delta = (dx, dy) and integers 0 < k < n with b = a + n delta and p = a + k delta. Every
// integer point strictly between two distinct integer points a and b arises this way (take
// delta = (b - a) / g with g the gcd of the coordinate differences, n = g, 0 < k < g), and
// every such p is strictly between a and b. So the theorem covers exactly the integer
// samples on the open shared segment (pixel centres are integer raw points).
//
// The nonlinear core is split into lemmas, each proved here and then used, instantiated, as a
// hypothesis of the next (proofs-notes: one query with everything times out):
//   L0 (signs): 0 < K < N  =>  sign((N - K) V) = sign(K V) = sign(N V)    for all integers.
//   L1 (edge values on the segment): with U = (delta x (c - a)), the kernel's values satisfy
//      E_ab(p) = 0, E_ba(p) = 0, and E_bc(p), E_ca(p) have the sign of A(a, b, c) = n U,
//      E_cb(p), E_ac(p) the opposite sign; proved with L0 instantiated at (n, k, U).
//   M (exactly once): from L1 instantiated for both third vertices c and d.
// Overflow freedom of the kernel evaluations here is FIX.BUDGET.EDGE_VALUE (all points are in
// the vertex range), proved by fixed/edge_value_no_overflow for every such point.

#pragma once

#include <string>
#include <vector>

#include "support/kernel_model.hpp"
#include "support/obligation.hpp"
#include "support/prover.hpp"

namespace rastrules::proofs {

// The orientation of c relative to the directed line a -> b, written here from the spec's
// TRI.EDGE.FUNCTION text on exact integers (not through the kernel): > 0 when c is on the
// right of a -> b (y down), < 0 on the left, 0 on the line.
template <class S>
z3::expr spec_orientation(const Point<S>& a, const Point<S>& b, const Point<S>& c) {
  return (b.x.expr() - a.x.expr()) * (c.y.expr() - a.y.expr()) -
         (b.y.expr() - a.y.expr()) * (c.x.expr() - a.x.expr());
}

// L0 for integers n, k, v: 0 < k < n implies sign((n - k) v) = sign(k v) = sign(n v).
inline z3::expr sign_lemma(const z3::expr& n, const z3::expr& k, const z3::expr& v) {
  const z3::expr nv = n * v;
  const z3::expr rest = (n - k) * v;
  const z3::expr kv = k * v;
  return z3::implies(0 < k && k < n, (rest > 0) == (nv > 0) && (rest < 0) == (nv < 0) &&
                                         (kv > 0) == (nv > 0) && (kv < 0) == (nv < 0));
}

// L1's conclusion for third vertex c: the kernel's edge values at p of the six directed edges
// between a, b and c, related to the kernel's A(a, b, c).
template <class F, class S>
z3::expr segment_edge_values(const Point<S>& a, const Point<S>& b, const Point<S>& c,
                             const Point<S>& p) {
  const z3::expr area = F::twice_signed_area(Triangle<S>{a, b, c}).expr();
  auto same_sign = [&](const S& e) {
    return (e.expr() > 0) == (area > 0) && (e.expr() < 0) == (area < 0);
  };
  auto opposite_sign = [&](const S& e) {
    return (e.expr() > 0) == (area < 0) && (e.expr() < 0) == (area > 0);
  };
  return F::edge_value(a, b, p).expr() == 0 && F::edge_value(b, a, p).expr() == 0 &&
         same_sign(F::edge_value(b, c, p)) && same_sign(F::edge_value(c, a, p)) &&
         opposite_sign(F::edge_value(c, b, p)) && opposite_sign(F::edge_value(a, c, p));
}

// The shared edge a -> b = a + n delta and the sample p = a + k delta on it (0 < k < n: the
// open segment), with third vertices c and d: fresh variables "<prefix>delta_x", "delta_y",
// "n", "k", "c", "d" (the caller declares a).
template <class S> struct SharedSegment {
  Point<S> a;
  S dx, dy, n, k;
  Point<S> b, p, c, d;
  z3::expr on_segment;
};
template <class S>
SharedSegment<S> shared_segment(Domain& dom, const Point<S>& a, const std::string& prefix) {
  const S dx = dom.var<typename S::rep>(prefix + "delta_x", Unit::kCoordRaw);
  const S dy = dom.var<typename S::rep>(prefix + "delta_y", Unit::kCoordRaw);
  const S n = dom.var<typename S::rep>(prefix + "n", Unit::kInteger);
  const S k = dom.var<typename S::rep>(prefix + "k", Unit::kInteger);
  const Point<S> b{a.x + n * dx, a.y + n * dy};
  const Point<S> p{a.x + k * dx, a.y + k * dy};
  const Point<S> c = point_var<S>(dom, prefix + "c");
  const Point<S> d = point_var<S>(dom, prefix + "d");
  return SharedSegment<S>{a, dx, dy, n, k, b, p, c, d, 0 < k.expr() && k.expr() < n.expr()};
}

// Proves lemmas L0 and L1 (for the generic third vertex seg.c) and returns L1's status
// (UNKNOWN, skipped, when L0 is not proved).
template <class F, class S> Status prove_segment_lemmas(Prover& pr, const SharedSegment<S>& seg) {
  z3::context& ctx = pr.ctx();
  const z3::expr lemma_n = ctx.int_const("lemma_N");
  const z3::expr lemma_k = ctx.int_const("lemma_K");
  const z3::expr lemma_v = ctx.int_const("lemma_V");
  const Status l0 = pr.prove("lemma L0: 0 < K < N => sign((N - K) V) = sign(K V) = sign(N V)", {},
                             sign_lemma(lemma_n, lemma_k, lemma_v));
  const z3::expr u = seg.dx.expr() * (seg.c.y.expr() - seg.a.y.expr()) -
                     seg.dy.expr() * (seg.c.x.expr() - seg.a.x.expr());
  return l0 != Status::kProved
             ? pr.skip("lemma L1: kernel edge values at a sample on the open edge ab",
                       "relies on lemma L0, which was not proved")
             : pr.prove("lemma L1: kernel edge values at a sample on the open edge ab",
                        {seg.on_segment, sign_lemma(seg.n.expr(), seg.k.expr(), u)},
                        segment_edge_values<F>(seg.a, seg.b, seg.c, seg.p));
}

// Part 1, for every convention: for all a != b in the vertex range, exactly one of the directed
// edges a -> b and b -> a is inclusive.
// Part 2, for every convention: for all a, b, c, d in the vertex range with c and d strictly on
// opposite sides of the line ab, each triangle given in either vertex order ((a, b, c) or
// (b, a, c); (a, b, d) or (b, a, d)) and normalised as the kernel does (TRI.ORIENT.NORMALISE),
// every integer point p on the open segment (a, b) is covered by exactly one of the two.
// Any other vertex order is a rotation of one of these two, and the kernel's edges and
// twice_signed_area are invariant under rotation, so the two orders cover all six.
// rule: TRI.SHARED_EDGE.EXACTLY_ONCE, TRI.FILL.CONVENTION
template <class F> void prove_shared_edge_exactly_once(Prover& pr) {
  using S = typename F::Acc;
  Domain& dom = pr.domain();

  const Point<S> a = point_var<S>(dom, "a");

  // Part 1.
  {
    const Point<S> b = point_var<S>(dom, "b");
    // Assumes: SNAP.VERTEX.RANGE
    const z3::expr a_ne_b = !(a.x.expr() == b.x.expr() && a.y.expr() == b.y.expr());
    const std::vector<z3::expr> hyps = {in_vertex_range<F>(a), in_vertex_range<F>(b), a_ne_b};
    for_each_convention([&]<bool TopInclusive, bool LeftInclusive>(const char* convention) {
      const std::size_t mark = dom.mark();
      const SymBool forward = F::template is_inclusive_edge<TopInclusive, LeftInclusive>(a, b);
      const SymBool backward = F::template is_inclusive_edge<TopInclusive, LeftInclusive>(b, a);
      pr.watch("inclusive(a->b)", forward.expr(), Unit::kBool);
      pr.watch("inclusive(b->a)", backward.expr(), Unit::kBool);
      pr.prove(std::string(convention) + ": exactly one of a->b, b->a is inclusive (a != b)", hyps,
               forward.expr() != backward.expr(), dom.obligations_since(mark));
    });
  }

  // Part 2. The shared edge a -> b = a + n delta, the sample p = a + k delta.
  const SharedSegment<S> seg = shared_segment<S>(dom, a, "");
  const Point<S>&b = seg.b, &p = seg.p, &c = seg.c, &d = seg.d;
  const z3::expr order1 = dom.bool_var("first_is_abc");  // else (b, a, c)
  const z3::expr order2 = dom.bool_var("second_is_abd"); // else (b, a, d)
  const z3::expr& on_segment = seg.on_segment;
  auto show_points = [&] {
    pr.watch("bx", b.x.expr(), Unit::kCoordRaw);
    pr.watch("by", b.y.expr(), Unit::kCoordRaw);
    pr.watch("px", p.x.expr(), Unit::kCoordRaw);
    pr.watch("py", p.y.expr(), Unit::kCoordRaw);
  };

  // L1 for the generic third vertex c; M uses it at c and at d.
  show_points();
  const Status l1 = prove_segment_lemmas<F>(pr, seg);

  const z3::expr oc = spec_orientation(a, b, c);
  const z3::expr od = spec_orientation(a, b, d);
  // Assumes: SNAP.VERTEX.RANGE
  const std::vector<z3::expr> hyps = {
      in_vertex_range<F>(a),
      in_vertex_range<F>(b),
      in_vertex_range<F>(c),
      in_vertex_range<F>(d),
      in_vertex_range<F>(p),
      on_segment,
      (oc > 0 && od < 0) || (oc < 0 && od > 0),
      segment_edge_values<F>(a, b, c, p), // L1 at c
      segment_edge_values<F>(a, b, d, p), // L1 at d
  };

  for_each_convention([&]<bool TopInclusive, bool LeftInclusive>(const char* convention) {
    auto covered = [&](const z3::expr& first, const Point<S>& third) {
      // first ? (a, b, third) : (b, a, third), then normalised and tested as the kernel does.
      return select(SymBool(first),
                    covers_normalised<F, TopInclusive, LeftInclusive>(Triangle<S>{a, b, third}, p),
                    covers_normalised<F, TopInclusive, LeftInclusive>(Triangle<S>{b, a, third}, p));
    };
    const SymBool in1 = covered(order1, c);
    const SymBool in2 = covered(order2, d);
    const std::string name =
        std::string(convention) +
        ": each sample on the open shared edge is covered by exactly one triangle";
    if (l1 != Status::kProved) {
      pr.skip(name, "relies on lemma L1, which was not proved");
      return;
    }
    show_points();
    pr.watch("covered by first", in1.expr(), Unit::kBool);
    pr.watch("covered by second", in2.expr(), Unit::kBool);
    pr.prove(name, hyps, in1.expr() != in2.expr());
  });
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kSharedEdgeExactlyOnce{
    "tri/shared_edge_exactly_once",
    []<class F>(Prover& pr) { prove_shared_edge_exactly_once<F>(pr); }};

} // namespace rastrules::proofs
