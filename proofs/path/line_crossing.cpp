// SPDX-License-Identifier: MIT
// Proof: the path kernel's line crossing test is the tie rule, exactly and without overflow.
// For all a, b, s with raw coordinates in [-2^23, 2^23] and each fill convention:
// formula::path_edge_spans and formula::path_crossing_right on the kernel's edge_value, combined
// as kernel/src/path.cpp's line_contribution does, equal the spec's contribution of edge a -> b
// at s + (hx eps, hy delta), delta << eps (PATH.SAMPLE.TIE, derived here as a lexicographic
// sign test); the contribution is -1, 0 or +1 (so |w| is at most the number of edges:
// PATH.WINDING.BOUND); reversing the edge negates it (PATH.TIE.PARTITION); and the row
// walk's integer threshold from formula::path_crossing_numerator decides every sample of the
// row as the direct test does, with N in int64_t (PATH.BUDGET.LINE).
// Method: the templates on Sym<std::int64_t> (exact integers with "fits int64_t"
// obligations); hypotheses AND NOT(goal AND obligations) must be unsat.
// rule: PATH.SAMPLE.TIE, PATH.BUDGET.LINE, PATH.WINDING.BOUND, PATH.TIE.PARTITION
// Assumes: PATH.GEOMETRY, PATH.WINDING
// Expected: PROVED. Exit status 0 iff every theorem is PROVED.

#include "path/line_crossing.hpp"
#include "support/obligation.hpp"

int main() {
  using namespace rastrules::proofs;
  return run_obligation<PathKernelModel>(
      kLineCrossing, "PATH.SAMPLE.TIE, PATH.BUDGET.LINE, PATH.WINDING.BOUND, PATH.TIE.PARTITION",
      {"PATH.GEOMETRY", "PATH.WINDING"});
}
