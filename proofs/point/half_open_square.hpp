// SPDX-License-Identifier: MIT
// Obligation POINT.COVER.HALF_OPEN (with POINT.RANGE and POINT.SHAPE.TWO_TRIANGLES), as a
// template over a point model. Used by half_open_square.cpp and mutants.cpp.

#pragma once

#include <array>
#include <string>
#include <vector>

#include "point/point_model.hpp"
#include "support/kernel_model.hpp"
#include "support/obligation.hpp"
#include "support/prover.hpp"

namespace rastrules::proofs {

// Returns "c lies in POINT.RANGE" for model F.
template <class F, class S> z3::expr in_point_range(const Point<S>& c) {
  z3::context& ctx = c.x.expr().ctx();
  const z3::expr lo = ctx.int_val(F::kMinPointCentreRaw);
  const z3::expr hi = ctx.int_val(F::kMaxPointCentreRaw);
  return lo <= c.x.expr() && c.x.expr() <= hi && lo <= c.y.expr() && c.y.expr() <= hi;
}

// For every centre c in POINT.RANGE, every sample p of the 16.8 grid in the vertex range
// (pixel centres are such samples), and each fill convention:
//   1. every corner of both triangles lies in SNAP.VERTEX.RANGE and both triangles are
//      clockwise (twice_signed_area > 0): they are rasterized, never degenerate;
//   2. p is covered by the first or the second triangle (each after the winding normalisation
//      of setup_triangle) iff p lies in the square of side 256 raw centred on c, half-open as
//      the convention says (spec words, written here directly on c, not via the formula);
//   3. p is never covered by both triangles;
//   4. the square split along the other diagonal (TL, TR, BR) + (TL, BR, BL) covers exactly
//      the same samples (the diagonal does not matter for coverage).
// rule: POINT.COVER.HALF_OPEN, POINT.RANGE, POINT.SHAPE.TWO_TRIANGLES
template <class F> void prove_point_half_open_square(Prover& pr) {
  using S = typename F::Acc;
  Domain& dom = pr.domain();
  const Point<S> c = point_var<S>(dom, "c");
  const Point<S> p = point_var<S>(dom, "p");
  z3::context& ctx = pr.ctx();
  // Assumes: POINT.RANGE, SNAP.VERTEX.RANGE
  const std::vector<z3::expr> hyps = {in_point_range<F>(c), in_vertex_range<F>(p)};
  {
    const std::size_t mark = dom.mark();
    const std::array<Triangle<S>, 2> t = F::template point_triangles<S>(c);
    z3::expr goal = ctx.bool_val(true);
    for (const Triangle<S>& tri : t) {
      for (const Point<S>& v : tri)
        goal = goal && in_vertex_range<F>(v);
      goal = goal && F::twice_signed_area(tri).expr() > 0;
    }
    pr.prove("both triangles lie in the vertex range and are clockwise", hyps, goal,
             dom.obligations_since(mark));
  }
  for_each_convention([&]<bool TopInclusive, bool LeftInclusive>(const char* convention) {
    const std::size_t mark = dom.mark();
    const std::array<Triangle<S>, 2> t = F::template point_triangles<S>(c);
    const z3::expr in0 = covers_normalised<F, TopInclusive, LeftInclusive>(t[0], p).expr();
    const z3::expr in1 = covers_normalised<F, TopInclusive, LeftInclusive>(t[1], p).expr();
    // The spec's half-open square, on c directly (h = 128 raw).
    const z3::expr cx = c.x.expr(), cy = c.y.expr(), px = p.x.expr(), py = p.y.expr();
    const z3::expr l = cx - 128, r = cx + 128, top = cy - 128, bot = cy + 128;
    const z3::expr in_x = LeftInclusive ? (l <= px && px < r) : (l < px && px <= r);
    const z3::expr in_y = TopInclusive ? (top <= py && py < bot) : (top < py && py <= bot);
    const std::vector<Obligation> obl = dom.obligations_since(mark);
    pr.watch("covered by (TL, TR, BL)", in0, Unit::kBool);
    pr.watch("covered by (BL, TR, BR)", in1, Unit::kBool);
    pr.prove(std::string(convention) + ": the two triangles cover exactly the half-open square",
             hyps, (in0 || in1) == (in_x && in_y), obl);
    pr.watch("covered by (TL, TR, BL)", in0, Unit::kBool);
    pr.watch("covered by (BL, TR, BR)", in1, Unit::kBool);
    pr.prove(std::string(convention) + ": no sample is covered by both triangles", hyps,
             !(in0 && in1), obl);
    // The other diagonal, built from the same corners.
    const Point<S> tl = t[0][0], tr = t[0][1], bl = t[0][2], br = t[1][2];
    const z3::expr alt0 =
        covers_normalised<F, TopInclusive, LeftInclusive>(Triangle<S>{tl, tr, br}, p).expr();
    const z3::expr alt1 =
        covers_normalised<F, TopInclusive, LeftInclusive>(Triangle<S>{tl, br, bl}, p).expr();
    pr.prove(std::string(convention) + ": the other diagonal covers the same samples", hyps,
             (alt0 || alt1) == (in0 || in1), dom.obligations_since(mark));
  });
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kHalfOpenSquare{
    "point/half_open_square", []<class F>(Prover& pr) { prove_point_half_open_square<F>(pr); }};

} // namespace rastrules::proofs
