// SPDX-License-Identifier: MIT
// Obligation FIX.BIAS.FORM, as a template over a kernel model. Used by bias_form.cpp and
// selftest/mutants.cpp.

#pragma once

#include <string>
#include <vector>

#include "support/kernel_model.hpp"
#include "support/obligation.hpp"
#include "support/prover.hpp"

namespace rastrules::proofs {

// For every edge value E = edge_value(a, b, p) of points in the vertex range and each value of
// the C++ flag `inclusive` (formula::edge_bias takes a bool, so its two cases are the two
// constant calls):
//   E + edge_bias(inclusive) >= 0  <=>  E > 0 || (E == 0 && inclusive),
// and E + edge_bias(inclusive) does not overflow the accumulator.
// Also the traversal's combined test (walk.hpp): for int64_t e0, e1, e2,
//   (e0 | e1 | e2) >= 0  <=>  e0 >= 0 && e1 >= 0 && e2 >= 0,
// on 64-bit two's-complement bit-vectors (this expression is restated from walk.hpp, which
// evaluates it on concrete integers; the query has no multiplication).
// rule: FIX.BIAS.FORM
template <class F> void prove_bias_form(Prover& pr) {
  using S = typename F::Acc;
  Domain& dom = pr.domain();
  z3::context& ctx = dom.ctx();
  // Assumes: SNAP.VERTEX.RANGE
  std::vector<z3::expr> hyps;
  const auto [a, b, p] = points_in_range<F>(dom, {"a", "b", "p"}, hyps);
  for (const bool inclusive : {true, false}) {
    const std::size_t mark = dom.mark();
    const S e = F::edge_value(a, b, p);
    const S biased = e + F::template edge_bias<S>(inclusive);
    const z3::expr flag = ctx.bool_val(inclusive);
    // The rule side, as TRI.FILL.TOP_LEFT states it.
    const z3::expr rule = e.expr() > 0 || (e.expr() == 0 && flag);
    pr.watch("E_ab(p)", e.expr(), Unit::kEdgeRaw);
    pr.watch("E + bias", biased.expr(), Unit::kEdgeRaw);
    pr.prove(std::string("E + edge_bias(") + (inclusive ? "true" : "false") +
                 ") >= 0 <=> E > 0 || (E == 0 && " + (inclusive ? "true" : "false") + ")",
             hyps, (biased.expr() >= 0) == rule, dom.obligations_since(mark));
  }

  const z3::expr e0 = ctx.bv_const("e0", 64);
  const z3::expr e1 = ctx.bv_const("e1", 64);
  const z3::expr e2 = ctx.bv_const("e2", 64);
  const z3::expr zero = ctx.bv_val(0, 64);
  // z3::expr's < and >= on bit-vectors are the signed comparisons (proofs-notes pitfall 5).
  pr.prove("walk test: (e0 | e1 | e2) >= 0 <=> e0 >= 0 && e1 >= 0 && e2 >= 0 (int64_t)", {},
           ((e0 | e1 | e2) >= zero) == (e0 >= zero && e1 >= zero && e2 >= zero));
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kBiasForm{"tri/bias_form",
                                       []<class F>(Prover& pr) { prove_bias_form<F>(pr); }};

} // namespace rastrules::proofs
