// SPDX-License-Identifier: MIT
// Proof: the kernel's edge values never overflow.
// For all a, b, p with raw coordinates in [kMinVertexRaw, kMaxVertexRaw], evaluating
// formula::edge_value, formula::twice_signed_area, E + formula::edge_bias (both flags) and
// formula::edge_step_x/y (one = kSubpixelOne) in std::int64_t, as the kernel does, never
// overflows: every intermediate's exact integer value fits int64_t, so the int64_t result
// equals the mathematical value.
// Method: the templates are instantiated on Sym<std::int64_t> (exact integers that record a
// "fits int64_t" obligation per + - *); hypotheses AND NOT(all obligations) must be unsat.
// rule: FIX.BUDGET.EDGE_VALUE, TRI.EDGE.FUNCTION
// Assumes: SNAP.VERTEX.RANGE
// Expected: PROVED. Exit status 0 iff every theorem is PROVED; a counterexample is printed
// otherwise.

#include "fixed/edge_value_no_overflow.hpp"
#include "support/kernel_model.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<KernelModel>(kEdgeValueNoOverflow, "FIX.BUDGET.EDGE_VALUE",
                                     {"SNAP.VERTEX.RANGE"});
}
