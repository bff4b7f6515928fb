// SPDX-License-Identifier: MIT
// Obligation TRI.DEGENERATE.ZERO_AREA (the coverage half), as a template over a kernel model.
// Used by degenerate_covers_nothing.cpp and selftest/mutants.cpp.

#pragma once

#include <string>
#include <vector>

#include "support/kernel_model.hpp"
#include "support/obligation.hpp"
#include "support/prover.hpp"

namespace rastrules::proofs {

// For all a, b, c, p in the vertex range with twice_signed_area(a, b, c) == 0, and every
// convention, p is not inside all three edges (a b), (b c), (c a) under the kernel's per-edge
// rule. The kernel returns early for zero area (setup_triangle), so this shows that early
// return is not what keeps degenerate triangles empty: evaluating them as if clockwise, in
// any vertex order (the theorem quantifies over all a, b, c, so (a, c, b) is an instance too),
// covers nothing either.
// rule: TRI.DEGENERATE.ZERO_AREA
template <class F> void prove_degenerate_covers_nothing(Prover& pr) {
  using S = typename F::Acc;
  Domain& dom = pr.domain();
  // Assumes: SNAP.VERTEX.RANGE, TRI.ORIENT.AREA
  std::vector<z3::expr> hyps;
  const auto [a, b, c, p] = points_in_range<F>(dom, {"a", "b", "c", "p"}, hyps);
  const S area = F::twice_signed_area(Triangle<S>{a, b, c});
  hyps.push_back(area.expr() == 0);
  for_each_convention([&]<bool TopInclusive, bool LeftInclusive>(const char* convention) {
    const std::size_t mark = dom.mark();
    const SymBool in = covers<F, TopInclusive, LeftInclusive>(Triangle<S>{a, b, c}, p);
    pr.watch("E_ab(p)", F::edge_value(a, b, p).expr(), Unit::kEdgeRaw);
    pr.watch("E_bc(p)", F::edge_value(b, c, p).expr(), Unit::kEdgeRaw);
    pr.watch("E_ca(p)", F::edge_value(c, a, p).expr(), Unit::kEdgeRaw);
    pr.prove(std::string(convention) + ": a zero-area triangle covers no sample", hyps, !in.expr(),
             dom.obligations_since(mark));
  });
}

// The obligation as its proof and the self-check run it.
inline const ProofObligation kDegenerateCoversNothing{
    "tri/degenerate_covers_nothing",
    []<class F>(Prover& pr) { prove_degenerate_covers_nothing<F>(pr); }};

} // namespace rastrules::proofs
