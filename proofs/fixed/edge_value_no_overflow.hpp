// SPDX-License-Identifier: MIT
// Obligation FIX.BUDGET.EDGE_VALUE, as a template over a kernel model (support/kernel_model.hpp).
// Used by edge_value_no_overflow.cpp (the kernel) and selftest/mutants.cpp (broken models).

#pragma once

#include <string>

#include "support/kernel_model.hpp"
#include "support/obligation.hpp"
#include "support/prover.hpp"

namespace rastrules::proofs {

// For all a, b, p with raw coordinates in [kMinVertexRaw, kMaxVertexRaw], every intermediate
// value the model's accumulator type computes fits that type:
//   edge_value(a, b, p): both differences per product, both products, the result;
//   twice_signed_area(a, b, p);
//   E + edge_bias(true) and E + edge_bias(false), as the traversal adds them (walk.hpp);
//   edge_step_x(a, b, kSubpixelOne) and edge_step_y(a, b, kSubpixelOne).
// rule: FIX.BUDGET.EDGE_VALUE
template <class F> void prove_edge_value_no_overflow(Prover& pr) {
  using S = typename F::Acc;
  Domain& dom = pr.domain();
  // Assumes: SNAP.VERTEX.RANGE
  std::vector<z3::expr> hyps;
  const auto [a, b, p] = points_in_range<F>(dom, {"a", "b", "p"}, hyps);
  const std::string type = type_name<typename S::rep>();

  {
    const std::size_t mark = dom.mark();
    const S e = F::edge_value(a, b, p);
    pr.watch("E_ab(p)", e.expr(), Unit::kEdgeRaw);
    pr.prove("edge_value(a, b, p): every intermediate fits " + type, hyps, dom.ctx().bool_val(true),
             dom.obligations_since(mark));
  }
  {
    const std::size_t mark = dom.mark();
    const S area = F::twice_signed_area(Triangle<S>{a, b, p});
    pr.watch("A(a, b, p)", area.expr(), Unit::kEdgeRaw);
    pr.prove("twice_signed_area(a, b, p): every intermediate fits " + type, hyps,
             dom.ctx().bool_val(true), dom.obligations_since(mark));
  }
  for (const bool inclusive : {true, false}) {
    const std::size_t mark = dom.mark();
    const S e = F::edge_value(a, b, p);
    const S biased = e + F::template edge_bias<S>(inclusive);
    pr.watch("E_ab(p)", e.expr(), Unit::kEdgeRaw);
    pr.watch("E + bias", biased.expr(), Unit::kEdgeRaw);
    pr.prove(std::string("E + edge_bias(") + (inclusive ? "true" : "false") +
                 "): every intermediate fits " + type,
             hyps, dom.ctx().bool_val(true), dom.obligations_since(mark));
  }
  {
    const std::size_t mark = dom.mark();
    const S one(F::kOne);
    const S sx = F::edge_step_x(a, b, one);
    const S sy = F::edge_step_y(a, b, one);
    pr.watch("step_x", sx.expr(), Unit::kEdgeRaw);
    pr.watch("step_y", sy.expr(), Unit::kEdgeRaw);
    pr.prove("edge_step_x/edge_step_y(a, b, kSubpixelOne): every intermediate fits " + type, hyps,
             dom.ctx().bool_val(true), dom.obligations_since(mark));
  }
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kEdgeValueNoOverflow{
    "fixed/edge_value_no_overflow",
    []<class F>(Prover& pr) { prove_edge_value_no_overflow<F>(pr); }};

} // namespace rastrules::proofs
