// SPDX-License-Identifier: MIT
// Obligation TRI.SHARED_EDGE.EXACTLY_ONCE, as a template over a kernel model. Used by
// shared_edge_exactly_once.cpp and selftest/mutants.cpp.

#pragma once

#include <string>
#include <vector>

#include "support/kernel_model.hpp"
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

// Returns "p lies on the open segment (a, b)": collinear with a and b, within their bounding
// box, and equal to neither. On integer points this is exactly p = a + t (b - a), 0 < t < 1.
template <class S>
z3::expr on_open_segment(const Point<S>& a, const Point<S>& b, const Point<S>& p) {
  const z3::expr ax = a.x.expr(), ay = a.y.expr(), bx = b.x.expr(), by = b.y.expr();
  const z3::expr px = p.x.expr(), py = p.y.expr();
  const z3::expr between_x = (ax <= px && px <= bx) || (bx <= px && px <= ax);
  const z3::expr between_y = (ay <= py && py <= by) || (by <= py && py <= ay);
  const z3::expr not_a = !(px == ax && py == ay);
  const z3::expr not_b = !(px == bx && py == by);
  return spec_orientation(a, b, p) == 0 && between_x && between_y && not_a && not_b;
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
template <class F>
void prove_shared_edge_exactly_once(Prover& pr) {
  using S = typename F::Acc;
  Domain& dom = pr.domain();
  const Point<S> a = point_var<S>(dom, "a");
  const Point<S> b = point_var<S>(dom, "b");
  const Point<S> c = point_var<S>(dom, "c");
  const Point<S> d = point_var<S>(dom, "d");
  const Point<S> p = point_var<S>(dom, "p");
  const z3::expr order1 = dom.bool_var("first_is_abc");   // else (b, a, c)
  const z3::expr order2 = dom.bool_var("second_is_abd");  // else (b, a, d)

  // rule: SNAP.VERTEX.RANGE
  const z3::expr a_ne_b = !(a.x.expr() == b.x.expr() && a.y.expr() == b.y.expr());
  const std::vector<z3::expr> edge_hyps = {in_vertex_range<F>(a), in_vertex_range<F>(b), a_ne_b};

  for_each_convention([&]<bool TopInclusive, bool LeftInclusive>(const char* convention) {
    const std::size_t mark = dom.mark();
    const SymBool forward = F::template is_inclusive_edge<TopInclusive, LeftInclusive>(a, b);
    const SymBool backward = F::template is_inclusive_edge<TopInclusive, LeftInclusive>(b, a);
    pr.watch("inclusive(a->b)", forward.expr(), Unit::kBool);
    pr.watch("inclusive(b->a)", backward.expr(), Unit::kBool);
    pr.prove(std::string(convention) + ": exactly one of a->b, b->a is inclusive (a != b)",
             edge_hyps, forward.expr() != backward.expr(), dom.obligations_since(mark));
  });

  const z3::expr oc = spec_orientation(a, b, c);
  const z3::expr od = spec_orientation(a, b, d);
  const std::vector<z3::expr> hyps = {
      in_vertex_range<F>(a),
      in_vertex_range<F>(b),
      in_vertex_range<F>(c),
      in_vertex_range<F>(d),
      (oc > 0 && od < 0) || (oc < 0 && od > 0),
      on_open_segment(a, b, p),
  };
  auto ordered = [](const z3::expr& first, const Point<S>& x, const Point<S>& y,
                    const Point<S>& z) {
    // first ? (x, y, z) : (y, x, z)
    const SymBool f(first);
    return Triangle<S>{Point<S>{select(f, x.x, y.x), select(f, x.y, y.y)},
                       Point<S>{select(f, y.x, x.x), select(f, y.y, x.y)}, z};
  };

  for_each_convention([&]<bool TopInclusive, bool LeftInclusive>(const char* convention) {
    const std::size_t mark = dom.mark();
    const Triangle<S> t1 = F::normalise(ordered(order1, a, b, c));
    const Triangle<S> t2 = F::normalise(ordered(order2, a, b, d));
    const SymBool in1 = covers<F, TopInclusive, LeftInclusive>(t1, p);
    const SymBool in2 = covers<F, TopInclusive, LeftInclusive>(t2, p);
    pr.watch("covered by first", in1.expr(), Unit::kBool);
    pr.watch("covered by second", in2.expr(), Unit::kBool);
    pr.prove(std::string(convention) +
                 ": each point on the open shared edge is covered by exactly one triangle",
             hyps, in1.expr() != in2.expr(), dom.obligations_since(mark));
  });
}

}  // namespace rastrules::proofs
