// SPDX-License-Identifier: MIT
// Obligation: the kernel's edge classification equals the spec's words (TRI.FILL.TOP_EDGE,
// TRI.FILL.LEFT_EDGE, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION), as a template over a kernel
// model. Used by top_left_matches_spec.cpp and selftest/mutants.cpp.

#pragma once

#include <array>
#include <string>
#include <vector>

#include "support/kernel_model.hpp"
#include "support/obligation.hpp"
#include "support/prover.hpp"

namespace rastrules::proofs {

// The spec's classification of edge a -> b of a triangle whose third vertex is c, written from
// the spec's words on exact values, without the kernel's shortcuts (no edge function, no
// assumption about the winding). Positions are raw 16.8 integers; y grows down the screen.
struct SpecEdgeClass {
  z3::expr top;    // exactly horizontal, third vertex below it (the edge is above the others)
  z3::expr bottom; // exactly horizontal, third vertex above it
  z3::expr left;   // not horizontal, third vertex strictly on the +x side of the edge's line
  z3::expr right;  // not horizontal, third vertex strictly on the -x side of the edge's line
};

// rule: TRI.FILL.TOP_EDGE, TRI.FILL.LEFT_EDGE
template <class S>
SpecEdgeClass spec_edge_class(const Point<S>& a, const Point<S>& b, const Point<S>& c) {
  const z3::expr ax = a.x.expr(), ay = a.y.expr(), bx = b.x.expr(), by = b.y.expr();
  const z3::expr cx = c.x.expr(), cy = c.y.expr();
  const z3::expr horizontal = (ay == by);
  // The line through a and b, when not horizontal, has x = ax + (bx - ax) (y - ay) / (by - ay)
  // at height y. "c lies strictly on its +x side" is cx > that x at y = cy, that is
  //   cx - ax > (bx - ax) (cy - ay) / (by - ay),
  // which with d = by - ay != 0 is multiplied out by cases on the sign of d (the step is the
  // lemma proved by prove_division_free_side below):
  //   d > 0: (cx - ax) d > (bx - ax) (cy - ay);   d < 0: (cx - ax) d < (bx - ax) (cy - ay).
  const z3::expr d = by - ay;
  const z3::expr lhs = (cx - ax) * d;
  const z3::expr rhs = (bx - ax) * (cy - ay);
  const z3::expr plus_x = (d > 0 && lhs > rhs) || (d < 0 && lhs < rhs);
  const z3::expr minus_x = (d > 0 && lhs < rhs) || (d < 0 && lhs > rhs);
  return SpecEdgeClass{
      horizontal && cy > ay,
      horizontal && cy < ay,
      !horizontal && plus_x,
      !horizontal && minus_x,
  };
}

// The algebra step used by spec_edge_class, over the rationals: for all x, y and d != 0,
//   x > y / d  <=>  (d > 0 and x d > y) or (d < 0 and x d < y),   and likewise for <.
inline void prove_division_free_side(Prover& pr) {
  z3::context& ctx = pr.ctx();
  const z3::expr x = ctx.real_const("lemma_x");
  const z3::expr y = ctx.real_const("lemma_y");
  const z3::expr d = ctx.real_const("lemma_d");
  const z3::expr above = (x > y / d) == ((d > 0 && x * d > y) || (d < 0 && x * d < y));
  const z3::expr below = (x < y / d) == ((d > 0 && x * d < y) || (d < 0 && x * d > y));
  pr.prove(
      "lemma: x > y/d <=> (d > 0 and xd > y) or (d < 0 and xd < y), and for < (rationals, d != 0)",
      {d != 0}, above && below);
}

// For every triangle (a, b, c) in the vertex range with twice_signed_area(a, b, c) > 0
// (clockwise, non-degenerate) and each of its edges a -> b (third vertex c), b -> c (a),
// c -> a (b):
//   is_top_edge  <=> spec top;   is_left_edge <=> spec left;
//   is_inclusive_edge<true, true> == is_top_edge || is_left_edge (for every directed edge);
//   is_inclusive_edge<T, L> <=> (T ? top : bottom) || (L ? left : right), for all four
//   conventions (TRI.FILL.CONVENTION; <true, true> is TRI.FILL.TOP_LEFT's "top or left").
// rule: TRI.FILL.TOP_EDGE, TRI.FILL.LEFT_EDGE, TRI.FILL.TOP_LEFT, TRI.FILL.CONVENTION
template <class F> void prove_top_left_matches_spec(Prover& pr) {
  using S = typename F::Acc;
  Domain& dom = pr.domain();
  z3::context& ctx = dom.ctx();
  // Assumes: SNAP.VERTEX.RANGE, TRI.ORIENT.AREA
  std::vector<z3::expr> hyps;
  const auto [a, b, c] = points_in_range<F>(dom, {"a", "b", "c"}, hyps);
  const S area = F::twice_signed_area(Triangle<S>{a, b, c});
  hyps.push_back(area.expr() > 0);

  struct Edge {
    const Point<S>* from;
    const Point<S>* to;
    const Point<S>* other;
    const char* name;
  };
  prove_division_free_side(pr);
  const std::array<Edge, 3> edges = {{{&a, &b, &c, "ab"}, {&b, &c, &a, "bc"}, {&c, &a, &b, "ca"}}};

  auto for_all_edges = [&](const std::string& name, auto&& matches) {
    const std::size_t mark = dom.mark();
    z3::expr goal = ctx.bool_val(true);
    for (const Edge& e : edges) {
      goal = goal && matches(*e.from, *e.to, *e.other, e.name);
    }
    pr.watch("A(a, b, c)", area.expr(), Unit::kEdgeRaw);
    pr.prove(name, hyps, goal, dom.obligations_since(mark));
  };

  for_all_edges("is_top_edge <=> horizontal and third vertex below (each edge)",
                [&](const Point<S>& p, const Point<S>& q, const Point<S>& r, const char* en) {
                  const z3::expr kernel = F::is_top_edge(p, q).expr();
                  pr.watch(std::string("is_top_edge(") + en + ")", kernel, Unit::kBool);
                  return kernel == spec_edge_class(p, q, r).top;
                });
  for_all_edges("is_left_edge <=> not horizontal and third vertex strictly on +x side (each edge)",
                [&](const Point<S>& p, const Point<S>& q, const Point<S>& r, const char* en) {
                  const z3::expr kernel = F::is_left_edge(p, q).expr();
                  pr.watch(std::string("is_left_edge(") + en + ")", kernel, Unit::kBool);
                  return kernel == spec_edge_class(p, q, r).left;
                });
  {
    // The kernel's own composition, for every directed edge (no triangle needed).
    const std::size_t mark = dom.mark();
    const z3::expr inclusive = F::template is_inclusive_edge<true, true>(a, b).expr();
    const z3::expr top_or_left = (F::is_top_edge(a, b) || F::is_left_edge(a, b)).expr();
    pr.watch("is_inclusive_edge<true, true>(a, b)", inclusive, Unit::kBool);
    pr.watch("is_top_edge(a, b) || is_left_edge(a, b)", top_or_left, Unit::kBool);
    pr.prove("is_inclusive_edge<true, true>(a, b) == is_top_edge(a, b) || is_left_edge(a, b)",
             {in_vertex_range<F>(a), in_vertex_range<F>(b)}, inclusive == top_or_left,
             dom.obligations_since(mark));
  }
  for_each_convention([&]<bool TopInclusive, bool LeftInclusive>(const char* convention) {
    for_all_edges(std::string("is_inclusive_edge ") + convention + " <=> " +
                      (TopInclusive ? "top" : "bottom") + " or " +
                      (LeftInclusive ? "left" : "right") + " (each edge)",
                  [&](const Point<S>& p, const Point<S>& q, const Point<S>& r, const char* en) {
                    const z3::expr kernel =
                        F::template is_inclusive_edge<TopInclusive, LeftInclusive>(p, q).expr();
                    pr.watch(std::string("is_inclusive_edge(") + en + ")", kernel, Unit::kBool);
                    const SpecEdgeClass spec = spec_edge_class(p, q, r);
                    return kernel == ((TopInclusive ? spec.top : spec.bottom) ||
                                      (LeftInclusive ? spec.left : spec.right));
                  });
  });
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kTopLeftMatchesSpec{
    "tri/top_left_matches_spec", []<class F>(Prover& pr) { prove_top_left_matches_spec<F>(pr); }};

} // namespace rastrules::proofs
