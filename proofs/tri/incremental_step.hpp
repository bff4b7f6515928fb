// SPDX-License-Identifier: MIT
// Obligation FIX.STEP.INCREMENTAL, as a template over a kernel model. Used by
// incremental_step.cpp and selftest/mutants.cpp.

#pragma once

#include <string>
#include <vector>

#include "support/kernel_model.hpp"
#include "support/obligation.hpp"
#include "support/prover.hpp"

namespace rastrules::proofs {

// For all a, b, p in the vertex range with the stepped sample also in range, and
// one = kSubpixelOne (one pixel):
//   edge_value(a, b, p + (one, 0)) == edge_value(a, b, p) + edge_step_x(a, b, one),
//   edge_value(a, b, p + (0, one)) == edge_value(a, b, p) + edge_step_y(a, b, one),
// and, as the traversal accumulates it (walk.hpp: e = E(p) + bias; e += step_x), for both
// biases: (E(p) + edge_bias(f)) + edge_step_x == E(p + (one, 0)) + edge_bias(f);
// with every intermediate fitting the accumulator type.
// rule: FIX.STEP.INCREMENTAL
template <class F> void prove_incremental_step(Prover& pr) {
  using S = typename F::Acc;
  Domain& dom = pr.domain();
  // Assumes: SNAP.VERTEX.RANGE
  std::vector<z3::expr> base;
  const auto [a, b, p] = points_in_range<F>(dom, {"a", "b", "p"}, base);
  const S one(F::kOne);
  const Point<S> px{p.x + one, p.y};
  const Point<S> py{p.x, p.y + one};
  std::vector<z3::expr> hyps_x = base;
  hyps_x.push_back(in_vertex_range<F>(px));
  std::vector<z3::expr> hyps_y = base;
  hyps_y.push_back(in_vertex_range<F>(py));

  // Proves E(moved) == E(p) + step, where moved is p + `offset` (text, e.g. "(1 px, 0)") and
  // step is edge_step_x(a, b, one) when along_x, else edge_step_y(a, b, one).
  const auto prove_step = [&](const std::string& offset, bool along_x, const Point<S>& moved,
                              const std::vector<z3::expr>& hyps) {
    const std::string axis = along_x ? "x" : "y";
    const std::size_t mark = dom.mark();
    const S direct = F::edge_value(a, b, moved);
    const S stepped =
        F::edge_value(a, b, p) + (along_x ? F::edge_step_x(a, b, one) : F::edge_step_y(a, b, one));
    pr.watch("E(p + " + offset + ")", direct.expr(), Unit::kEdgeRaw);
    pr.watch("E(p) + step_" + axis, stepped.expr(), Unit::kEdgeRaw);
    pr.prove("edge_value(p + " + offset + ") == edge_value(p) + edge_step_" + axis, hyps,
             direct.expr() == stepped.expr(), dom.obligations_since(mark));
  };
  prove_step("(1 px, 0)", true, px, hyps_x);
  prove_step("(0, 1 px)", false, py, hyps_y);
  for (const bool inclusive : {true, false}) {
    const std::size_t mark = dom.mark();
    const S direct = F::edge_value(a, b, px) + F::template edge_bias<S>(inclusive);
    const S accumulated =
        (F::edge_value(a, b, p) + F::template edge_bias<S>(inclusive)) + F::edge_step_x(a, b, one);
    pr.watch("E(p + (1 px, 0)) + bias", direct.expr(), Unit::kEdgeRaw);
    pr.watch("(E(p) + bias) + step_x", accumulated.expr(), Unit::kEdgeRaw);
    pr.prove(std::string("walk accumulator: (E(p) + edge_bias(") + (inclusive ? "true" : "false") +
                 ")) + edge_step_x == E(p + (1 px, 0)) + edge_bias",
             hyps_x, direct.expr() == accumulated.expr(), dom.obligations_since(mark));
  }
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kIncrementalStep{
    "tri/incremental_step", []<class F>(Prover& pr) { prove_incremental_step<F>(pr); }};

} // namespace rastrules::proofs
